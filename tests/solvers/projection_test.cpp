// Closest-point projection: global optimality against dense sampling, ends, cusps, closed curves.
#include "solvers/bspline/projection.h"
#include "test_curves.h"

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
