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
