// Arc length against closed forms: segments, the exact circle, and the inverse map.
#include "solvers/bspline/arc_length.h"
#include "test_curves.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::testing;

namespace {
// The quadrature is asked for 1e-12 relative; closed-form comparisons allow a little more.
constexpr double kLengthTolerance = 1e-10;
}  // namespace

TEST(ArcLength, StraightLineWithUnevenParameterizationHasItsChordLength)
{
    // Collinear control points unevenly spaced: the speed varies, the length is the chord.
    const std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {0.1, 0.2, 0.2}, {2, 4, 4}, {3, 6, 6}};
    const Curve3d c(3, {0, 0, 0, 0, 1, 1, 1, 1}, pts);
    EXPECT_NEAR(arcLength(c), 9.0, kLengthTolerance);
    EXPECT_NEAR(arcLength(c, 0.0, 0.5), (c.evaluate(0.5) - c.evaluate(0.0)).norm(), kLengthTolerance);
}

TEST(ArcLength, UnitCircleCircumferenceIsTwoPi)
{
    // The rational circle is not arc-length parameterized; its length is still exactly 2 pi.
    const Curve3d c = unitCircle();
    EXPECT_NEAR(arcLength(c), 2 * M_PI, kLengthTolerance);
    EXPECT_NEAR(arcLength(c, 0.0, 0.25), M_PI / 2, kLengthTolerance);
}

TEST(ArcLength, ParameterAtLengthInvertsLengthAt)
{
    const Curve3d c = rationalCubic();
    const ArcLengthParameterization<3> s(c);
    EXPECT_NEAR(s.totalLength(), arcLength(c), kLengthTolerance * s.totalLength());
    for (double f : linspace(0, 1, 40)) {
        const double target = f * s.totalLength();
        const double u = s.parameterAt(target);
        EXPECT_NEAR(s.lengthAt(u), target, 1e-9 * s.totalLength()) << f;
        EXPECT_NEAR(arcLength(c, c.domainStart(), u), target, 1e-9 * s.totalLength());
    }
}

TEST(ArcLength, CircleArcLengthParameterIsTheAngle)
{
    const ArcLengthParameterization<3> s(unitCircle());
    for (double angle : {0.3, 1.0, 2.5, 4.0, 6.0}) {
        const Eigen::Vector3d p = unitCircle().evaluate(s.parameterAt(angle));
        EXPECT_NEAR(std::atan2(p.y(), p.x()) + (angle > M_PI ? 2 * M_PI : 0), angle, 1e-9);
    }
}

TEST(ArcLength, ClosedCurveLengthIsTheSameFromAnyStart)
{
    const Curve3d c = closedCubic();
    const double a = c.domainStart(), T = c.domainEnd() - a;
    const double whole = arcLength(c);
    EXPECT_NEAR(arcLength(c, a + 0.37 * T, a + 1.37 * T), whole, kLengthTolerance * whole);
}

namespace {
// A cubic whose control points agree to 1e-14 of their magnitude (1e3): its speed |C'| is
// round-off, so no relative accuracy can be reached on it.
Curve3d nearlyCollapsedCubic()
{
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < 7; ++i) pts.emplace_back(1e3 + 1e-11 * i, 2e3 + 1e-11 * ((i * 7) % 5), -1e3);
    return Curve3d(3, {0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1}, pts);
}
}  // namespace

TEST(ArcLength, NearlyCollapsedCurveIsMeasuredToItsRoundOffWithoutRecursingForever)
{
    // Arrange: the length is at most the control polygon's (convex hull property, The NURBS Book
    // P4.9 for non-rational curves), about 1e-10; round-off in the coordinates is ~1e-13 per sample.
    const Curve3d c = nearlyCollapsedCubic();
    double polygon = 0.0;
    for (size_t i = 1; i < c.points().size(); ++i) polygon += (c.points()[i] - c.points()[i - 1]).norm();

    // Act: the relative tolerance alone recursed to 2^30 panels per span here (hours).
    const double length = arcLength(c);
    const ArcLengthParameterization<3> table(c);
    const double u = table.parameterAt(0.5 * table.totalLength());

    // Assert: a finite length within round-off of the polygon bound, and a parameter in the domain.
    constexpr double kRoundOff = 1e-9;  // thousands of ulps of 1e3: a generous bound on noise
    EXPECT_GE(length, 0.0);
    EXPECT_LE(length, polygon + kRoundOff);
    EXPECT_GE(u, 0.0);
    EXPECT_LE(u, 1.0);
}
