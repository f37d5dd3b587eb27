// Fill with G1 conditions: along each chosen boundary the fill shares the tangent plane of an
// adjacent reference surface (normal angle below the tolerance at many samples), the boundaries are
// still met to 1e-9, and inconsistent input is refused with a message naming the condition.
#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/projection.h"
#include "solvers/surfaces/coons_fill.h"
#include "surface_checks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace sculptline::solvers;
using namespace sculptline::solvers::surfaces;
using namespace sculptline::surfaces_test;

namespace {

// The G1 tolerance the fill is asked for (the default, kDefaultFillAngleDegrees: the usual CAD
// tangent-continuity tolerance), checked at samples independent of the solver's own.
constexpr double kAngleDegrees = kDefaultFillAngleDegrees;
// Without the G1 conditions the Coons fill of these boundaries creases visibly (several degrees),
// so the checks below can fail.
constexpr double kVisibleCrease = 1.0;

// A bicubic hill over [0, 3]^2: curved in both directions, so its tangent plane turns along every edge.
Surface3d hill()
{
    std::vector<Vec3> pts;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j)
            pts.emplace_back(0.75 * i, 0.75 * j, 0.5 * std::sin(1.3 * i) * std::cos(0.9 * j) + 0.1 * i * j / 4.0);
    const KnotVector k{0, 0, 0, 0, 0.5, 1, 1, 1, 1};
    return Surface3d(3, 3, k, k, 5, 5, pts);
}

// Largest angle (degrees, between lines) of the normals of `fill` and `reference` at `samples`
// points of boundary c, both found by global projection (not the solver's parameters). Points
// where the fill's normal is undefined (a collapsed side) are skipped.
double g1AngleDegrees(const Surface3d& fill, const Surface3d& reference, const Curve3d& c, int samples = 201)
{
    const SurfaceProjector onFill(fill);
    const SurfaceProjector onReference(reference);
    double worst = 0.0;
    for (int k = 0; k < samples; ++k) {
        const Vec3 x = c.evaluate(c.domainStart() + (c.domainEnd() - c.domainStart()) * k / (samples - 1));
        const SurfaceProjection pf = onFill.project(x);
        const SurfaceProjection pr = onReference.project(x);
        const Vec3 nf = limitNormal(fill, pf.u, pf.v);
        const Vec3 nr = limitNormal(reference, pr.u, pr.v);
        if (nf.norm() < 0.5 || nr.norm() < 0.5) continue;
        worst = std::max(worst, std::acos(std::min(1.0, std::abs(nf.dot(nr)))) * 180.0 / kPi);
    }
    return worst;
}

// A patch hanging off the hill's edge v = 0 (y = 0) towards y < 0: the edge itself, two sides that
// leave its ends inside the hill's tangent plane (direction -S_v, tilted by `tiltDegrees` out of
// the plane at the first corner), and a far side. Returned as [edge, right, far, left].
std::vector<Curve3d> overhang(const Surface3d& h, double tiltDegrees = 0.0)
{
    const Curve3d edge = h.isoCurve(Direction::V, 0.0);
    const auto leave = [&](double u, double tilt) {
        const auto d = h.derivatives(u, 0.0, 1);
        const Vec3 out = -d[0][1].normalized();
        const Vec3 n = d[1][0].cross(d[0][1]).normalized();
        const double a = tilt * kPi / 180.0;
        return Vec3(std::cos(a) * out + std::sin(a) * n);
    };
    const Vec3 a = h.evaluate(0.0, 0.0), b = h.evaluate(1.0, 0.0);
    const Vec3 da = leave(0.0, tiltDegrees), db = leave(1.0, 0.0);
    const Vec3 farA = a + Vec3(0.2, -2.0, 0.4), farB = b + Vec3(-0.1, -2.2, -0.3);
    const Curve3d right = cubic({b, b + 0.6 * db, farB + Vec3(0.2, 0.6, 0.1), farB});
    const Curve3d far = cubic({farB, farB + Vec3(-1, -0.3, 0.2), farA + Vec3(1, 0.2, -0.1), farA});
    const Curve3d left = cubic({farA, farA + Vec3(-0.1, 0.7, 0.0), a + 0.7 * da, a});
    return {edge, right, far, left};
}

}  // namespace

TEST(FillTangents, GivenOverhangWithG1ToTheHill_WhenFilled_ThenBoundariesMetAndNormalsAgreeAlongTheEdge)
{
    // Given: four boundaries, the first the hill's edge, with G1 to the hill along it.
    const Surface3d h = hill();
    const std::vector<Curve3d> b = overhang(h);
    FillOptions options;
    options.tangents.push_back({0, h});

    // When
    const FillBuilder builder(b, options);
    const Surface3d& s = builder.surface();

    // Then: every boundary met, the edge tangent-continuous with the hill, the plain fill is not.
    for (const Curve3d& c : b) EXPECT_LT(boundaryDeviation(s, c), kExact);
    EXPECT_LT(g1AngleDegrees(s, h, b[0]), kAngleDegrees);
    EXPECT_LE(builder.maxTangentAngleDegrees(), kAngleDegrees);
    EXPECT_GT(g1AngleDegrees(fill(b), h, b[0]), kVisibleCrease);
    EXPECT_GT(minNeighbourNormalDot(s), 0.0);
}

TEST(FillTangents, GivenHoleCutFromTheHill_WhenFilledG1AllRound_ThenNormalsAgreeOnEveryBoundary)
{
    // Given: the hill's iso-curves around [0.1, 0.9]^2, reversed and shuffled, each G1 to the hill
    // (two G1 boundaries meet at every corner, so the corner twists must serve both).
    const Surface3d h = hill();
    const Surface3d inner = h.extract(0.1, 0.9, 0.1, 0.9);
    const std::vector<Curve3d> b{inner.isoCurve(Direction::V, 0.0), reversedCurve(inner.isoCurve(Direction::V, 1.0)),
                                 inner.isoCurve(Direction::U, 1.0), inner.isoCurve(Direction::U, 0.0)};
    FillOptions options;
    for (int k = 0; k < 4; ++k) options.tangents.push_back({k, h});

    // When
    const Surface3d s = fill(b, options);

    // Then: on every boundary; the plain fill creases visibly on at least one.
    double plainWorst = 0.0;
    for (const Curve3d& c : b) {
        EXPECT_LT(boundaryDeviation(s, c), kExact);
        EXPECT_LT(g1AngleDegrees(s, h, c), kAngleDegrees);
        plainWorst = std::max(plainWorst, g1AngleDegrees(fill(b), h, c));
    }
    EXPECT_GT(plainWorst, kVisibleCrease);
    EXPECT_GT(minNeighbourNormalDot(s), 0.0);
}

TEST(FillTangents, GivenThreeSidedFillWithOneG1Side_WhenFilled_ThenThatSideIsTangentContinuous)
{
    // Given: the hill's edge and two curves from its ends to an apex below it, leaving the ends in
    // the hill's tangent plane; the G1 side is curves[1] (the loop starts at curves[0], whose start
    // becomes the collapsed corner).
    const Surface3d h = hill();
    const std::vector<Curve3d> o = overhang(h);
    const Curve3d& edge = o[0];
    const Vec3 apex = h.evaluate(0.5, 0.0) + Vec3(0, -2.0, -0.2);
    const Curve3d toEdge = cubic({apex, apex + Vec3(-0.8, 0.3, 0.1), o[3].points()[2], o[3].points()[3]});
    const Curve3d fromEdge = cubic({o[1].points()[0], o[1].points()[1], apex + Vec3(0.8, 0.4, 0.0), apex});
    const std::vector<Curve3d> b{toEdge, edge, fromEdge};
    FillOptions options;
    options.tangents.push_back({1, h});

    // When
    const Surface3d s = fill(b, options);

    // Then
    for (const Curve3d& c : b) EXPECT_LT(boundaryDeviation(s, c), kExact);
    EXPECT_LT(g1AngleDegrees(s, h, edge), kAngleDegrees);
    EXPECT_GT(g1AngleDegrees(fill(b), h, edge), kVisibleCrease);

    // And: the same with the G1 side listed first (where a 3-sided fill would collapse its start):
    // the fill turns its loop so that the collapsed corner stays off the G1 side.
    FillOptions first;
    first.tangents.push_back({0, h});
    const std::vector<Curve3d> rotated{edge, fromEdge, toEdge};
    const Surface3d r = fill(rotated, first);
    for (const Curve3d& c : rotated) EXPECT_LT(boundaryDeviation(r, c), kExact);
    EXPECT_LT(g1AngleDegrees(r, h, edge), kAngleDegrees);
}

TEST(FillTangents, GivenBuilder_WhenFarSideDragged_ThenUpdateStaysG1)
{
    // Given
    const Surface3d h = hill();
    std::vector<Curve3d> b = overhang(h);
    FillOptions options;
    options.tangents.push_back({0, h});
    FillBuilder builder(b, options);

    // When: the far side and the ends of the sides that meet it move down by 0.5.
    const Vec3 drop(0, 0, -0.5);
    const auto moved = [&](const Curve3d& c, int from) {
        std::vector<Vec3> p = c.points();
        for (size_t k = from; k < p.size(); ++k) p[k] += drop;
        return Curve3d(c.degree(), c.knots(), p);
    };
    std::vector<Vec3> lp = b[3].points();
    lp[0] += drop;
    lp[1] += drop;
    b[1] = moved(b[1], 2);
    b[2] = moved(b[2], 0);
    b[3] = Curve3d(b[3].degree(), b[3].knots(), lp);
    const Surface3d& s = builder.update(b);

    // Then
    for (const Curve3d& c : b) EXPECT_LT(boundaryDeviation(s, c), kExact);
    EXPECT_LT(g1AngleDegrees(s, h, b[0]), kAngleDegrees);
    EXPECT_LE(builder.maxTangentAngleDegrees(), kAngleDegrees);
    EXPECT_GT(g1AngleDegrees(fill(b), h, b[0]), kVisibleCrease);
}

TEST(FillTangents, GivenInconsistentConditions_WhenFilled_ThenRefusedNamingTheCondition)
{
    const Surface3d h = hill();
    const auto message = [](const std::vector<Curve3d>& b, const FillOptions& o) {
        try {
            fill(b, o);
        } catch (const GeometryError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    FillOptions o;
    o.tangents.push_back({0, h});

    // A side leaving the corner 5 degrees out of the hill's tangent plane: no G1 fill exists.
    EXPECT_NE(message(overhang(h, 5.0), o).find("tangents[0]: where curves[3] meets curves[0]"), std::string::npos)
        << message(overhang(h, 5.0), o);
    // The G1 boundary is not on the reference (the hill lifted by 0.1).
    std::vector<Vec3> lifted = h.points();
    for (Vec3& p : lifted) p.z() += 0.1;
    FillOptions off;
    off.tangents.push_back({0, Surface3d(3, 3, h.knotsU(), h.knotsV(), 5, 5, lifted)});
    EXPECT_NE(message(overhang(h), off).find("does not lie on its reference"), std::string::npos);
    // A curve index that is not a boundary, and one used twice.
    FillOptions bad;
    bad.tangents.push_back({4, h});
    EXPECT_NE(message(overhang(h), bad).find("tangents[0]: curve 4 is not one of the 4"), std::string::npos);
    FillOptions twice;
    twice.tangents = {{0, h}, {0, h}};
    EXPECT_NE(message(overhang(h), twice).find("tangents[1]: curves[0] already has"), std::string::npos);
    FillOptions angle;
    angle.tangents.push_back({0, h});
    angle.angleToleranceDegrees = 0.0;
    EXPECT_NE(message(overhang(h), angle).find("angle tolerance"), std::string::npos);
}
