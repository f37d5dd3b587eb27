// Closest-point projection: global optimality against dense sampling, ends, cusps, closed curves.
#include "solvers/bspline/projection.h"
#include "test_curves.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <random>

using namespace sculptline::solvers;
using namespace sculptline::solvers::testing;

namespace {

// Dense sampling finds the minimum only up to its spacing h: a sampled distance exceeds the true
// one by at most ~ h^2 |C''| / 8; the projection must never be worse than the sampled minimum.
constexpr int kDenseSamples = 20000;
constexpr double kOptimalitySlack = 1e-9;

double denseMinimum(const Curve3d& c, const Eigen::Vector3d& x)
{
    double best = std::numeric_limits<double>::infinity();
    for (double u : linspace(c.domainStart(), c.domainEnd(), kDenseSamples)) best = std::min(best, (c.evaluate(u) - x).norm());
    return best;
}

std::vector<Eigen::Vector3d> randomPoints(int n, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uni(0, 1);
    std::vector<Eigen::Vector3d> out;
    for (int i = 0; i < n; ++i)
        out.emplace_back(lo.x() + (hi.x() - lo.x()) * uni(rng), lo.y() + (hi.y() - lo.y()) * uni(rng),
                         lo.z() + (hi.z() - lo.z()) * uni(rng));
    return out;
}

void expectGlobal(const Curve3d& c, const std::vector<Eigen::Vector3d>& xs)
{
    const CurveProjector<3> proj(c);
    for (const auto& x : xs) {
        const CurveProjection<3> r = proj.project(x);
        EXPECT_LE(r.distance, denseMinimum(c, x) + kOptimalitySlack) << x.transpose();
        EXPECT_LT((c.evaluate(r.u) - r.point).norm(), kExact);
        EXPECT_NEAR((r.point - x).norm(), r.distance, kExact);
    }
}

}  // namespace

TEST(CurveProjection, GlobalMinimumOnOpenAndRationalCurves)
{
    expectGlobal(nurbsBookEx51Curve(), randomPoints(60, {-3, -3, -3}, {13, 7, 3}, 1));
    expectGlobal(rationalCubic(), randomPoints(60, {-2, -2, -2}, {11, 6, 2}, 2));
}

TEST(CurveProjection, ClosedCurveIncludingPointsNearTheSeam)
{
    const Curve3d c = closedCubic();
    std::vector<Eigen::Vector3d> xs = randomPoints(60, {-4, -3, -3}, {9, 9, 3}, 3);
    const Eigen::Vector3d seam = c.evaluate(c.domainStart());
    xs.push_back(seam + Eigen::Vector3d(0.01, -0.02, 0.03));
    expectGlobal(c, xs);
}

TEST(CurveProjection, PointsOnTheCurveProjectToThemselves)
{
    const Curve3d c = nurbsBookEx51Curve();
    const CurveProjector<3> proj(c);
    for (double u : linspace(0, 5, 51)) {
        const CurveProjection<3> r = proj.project(c.evaluate(u));
        EXPECT_LT(r.distance, 1e-12);
        EXPECT_NEAR(r.u, u, 1e-8);
    }
}

TEST(CurveProjection, EndPointIsTheAnswerBeyondTheEnds)
{
    const Curve3d c = nurbsBookEx51Curve();
    const CurveProjection<3> r = projectToCurve(c, Eigen::Vector3d(20, 8, 0));
    EXPECT_EQ(r.u, 5.0);
    const CurveProjection<3> s = projectToCurve(c, Eigen::Vector3d(-5, -5, 0));
    EXPECT_EQ(s.u, 0.0);
}

TEST(CurveProjection, CuspDoesNotTrapNewton)
{
    // A cubic Bezier with C'(1/2) = 0: P0 = (-1,0), P1 = (1,1), P2 = (-1,1), P3 = (1,0).
    const std::vector<Eigen::Vector3d> pts = {{-1, 0, 0}, {1, 1, 0}, {-1, 1, 0}, {1, 0, 0}};
    const Curve3d c(3, {0, 0, 0, 0, 1, 1, 1, 1}, pts);
    EXPECT_LT(c.derivatives(0.5, 1)[1].norm(), 1e-14);
    expectGlobal(c, randomPoints(80, {-1.5, -0.5, -0.5}, {1.5, 1.5, 0.5}, 4));
    // The cusp point itself.
    EXPECT_LT(projectToCurve(c, c.evaluate(0.5)).distance, 1e-12);
}

TEST(CurveProjection, PointEquidistantFromTwoBranchesFindsAGlobalOne)
{
    // The circle's centre is at distance 1 from every point: any answer must have distance 1.
    EXPECT_NEAR(projectToCurve(unitCircle(), Eigen::Vector3d(0, 0, 0)).distance, 1.0, kExact);
    // Slightly off-centre: the nearest point is on the near side (global, not a local minimum).
    const CurveProjection<3> r = projectToCurve(unitCircle(), Eigen::Vector3d(-0.1, 0, 0));
    EXPECT_NEAR(r.distance, 0.9, kExact);
    EXPECT_NEAR(r.point.x(), -1.0, kExact);
}

TEST(SurfaceProjection, GlobalMinimumAgainstDenseGrid)
{
    // A wavy bicubic on [0,2] x [-1,3].
    const int nu = 6, nv = 5;
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) pts.emplace_back(i, j, std::sin(1.7 * i) * std::cos(1.3 * j) * 1.5);
    const Surface3d s(3, 3, {0, 0, 0, 0, 0.8, 1.5, 2, 2, 2, 2}, {-1, -1, -1, -1, 1, 3, 3, 3, 3}, nu, nv, pts);
    const SurfaceProjector proj(s);
    for (const auto& x : randomPoints(25, {-1, -1, -2}, {6, 5, 2}, 5)) {
        const SurfaceProjection r = proj.project(x);
        double dense = std::numeric_limits<double>::infinity();
        for (double u : linspace(0, 2, 300))
            for (double v : linspace(-1, 3, 300)) dense = std::min(dense, (s.evaluate(u, v) - x).norm());
        EXPECT_LE(r.distance, dense + kOptimalitySlack) << x.transpose();
        EXPECT_LT((s.evaluate(r.u, r.v) - r.point).norm(), kExact);
    }
}

TEST(CurveProjection, BothSidesOfACornerKnotAreSearched)
{
    // Given a quadratic with a double knot at 4 (a C0 corner) and a point whose nearest point lies
    // just before the corner while the corner is the nearest sample (found by the CLI tests)
    const std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {1, 2, 0.5}, {2, 0, 1}, {3, 3, -1}, {4, 1, 2}, {5, 4, 0}, {6, 0, 1}, {7, 2, 3}};
    const Curve3d c(2, {0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5}, pts);
    const Eigen::Vector3d x(5, 4, 0.1);
    // When it is projected
    const CurveProjection<3> r = projectToCurve(c, x);
    // Then the global minimum (dense search: u ~ 3.99285, distance ~ 0.0845589) is found
    EXPECT_LE(r.distance, denseMinimum(c, x) + kOptimalitySlack);
    EXPECT_LT(r.u, 4.0);
}

TEST(SurfaceProjection, AFoldTheCoarseGridMissesIsSearchedCellByCell)
{
    // Given a loft-like bicubic through five sections (40 control points along u, 5 across v, as a
    // skin through five fitted strokes) whose last section is jittered by up to 2.5 across and 4 out
    // of its plane: near that end the surface wiggles within one grid cell (8 per span, 17 grid
    // lines across v), so the grid's local minima lie in other valleys of the distance. Seeded from
    // them alone (before the cell search) 7 of these 1,206 points on the surface were projected
    // 0.003 to 0.12 away from it.
    const int nu = 40, nv = 5;
    KnotVector ku = {0, 0, 0};
    for (int i = 0; i <= nu - 3; ++i) ku.push_back(double(i) / (nu - 3));
    ku.insert(ku.end(), {1, 1, 1});
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> jitter(-1, 1);
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < nu; ++i) {
        for (int j = 0; j < nv; ++j) {
            Eigen::Vector3d p(i, 10.0 * j, 0.2 * std::sin(0.3 * i));
            if (j == nv - 1) p += Eigen::Vector3d(2.5 * jitter(rng), 0.0, 4.0 * jitter(rng));
            pts.push_back(p);
        }
    }
    const Surface3d s(3, 3, ku, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}, nu, nv, pts);
    const SurfaceProjector proj(s);
    // When points on the surface near the jittered end are projected
    // Then each is found on the surface (its own foot point: distance 0 up to Newton's convergence)
    constexpr double kOnSurface = 1e-9;
    for (int a = 0; a <= 200; ++a) {
        for (double v : {0.9, 0.93, 0.95, 0.97, 0.98, 0.99}) {
            const Eigen::Vector3d x = s.evaluate(a / 200.0, v);
            EXPECT_LT(proj.project(x).distance, kOnSurface) << "u " << a / 200.0 << " v " << v;
        }
    }
    // And points off the surface there are projected no farther than a dense brute-force search
    // finds (500 x 200 samples over the end's strip v >= 0.85, where these points' feet lie).
    std::mt19937 pick(11);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int k = 0; k < 12; ++k) {
        const double u = unit(pick), v = 0.9 + 0.1 * unit(pick);
        const auto d = s.derivatives(u, v, 1);
        const Eigen::Vector3d n = d[1][0].cross(d[0][1]).normalized();
        const Eigen::Vector3d x = d[0][0] + 0.3 * (unit(pick) - 0.5) * n;
        double dense = std::numeric_limits<double>::infinity();
        for (double du : linspace(0, 1, 500))
            for (double dv : linspace(0.85, 1, 200)) dense = std::min(dense, (s.evaluate(du, dv) - x).norm());
        const SurfaceProjection r = proj.project(x);
        EXPECT_LE(r.distance, dense + kOptimalitySlack) << x.transpose();
        EXPECT_LT((s.evaluate(r.u, r.v) - r.point).norm(), kExact);
    }
}
