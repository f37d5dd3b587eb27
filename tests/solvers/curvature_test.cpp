// Curvature against closed forms: the exact rational circle, a parabola, a line, a cusp.
#include "solvers/bspline/curvature.h"
#include "solvers/bspline/geometry_error.h"
#include "test_curves.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace sculptline::solvers;
using namespace sculptline::solvers::testing;

namespace {
/// Derivatives of degree-2 rational curves at moderate parameters: a few ulps each, through the
/// quotient rule and one square root.
constexpr double kCurvatureTolerance = 1e-12;
}  // namespace

TEST(Curvature, TheExactCircleHasCurvatureOneOverItsRadiusEverywhere)
{
    // Given the rational unit circle (The NURBS Book §7.5), scaled to radius 2.5
    Curve3d c = unitCircle();
    std::vector<Eigen::Vector3d> points = c.points();
    for (Eigen::Vector3d& p : points) p *= 2.5;
    c = Curve3d(c.degree(), c.knots(), points, c.weights(), c.isClosed());

    // When sampled over its domain (knots included)
    const std::vector<double> kappa = sampleCurvature(c, c.domainStart(), c.domainEnd(), 41);

    // Then every sample is 1 / 2.5
    for (double k : kappa) EXPECT_NEAR(k, 0.4, kCurvatureTolerance);
}

TEST(Curvature, AParabolaMatchesItsClosedForm)
{
    // Given y = x^2 on [-1, 1] as a quadratic Bezier curve in 2D: x = 2t - 1, y = (2t - 1)^2
    const Curve2d c(2, {0, 0, 0, 1, 1, 1}, {{-1, 1}, {0, -1}, {1, 1}});

    // Then kappa(x) = 2 / (1 + 4 x^2)^(3/2): 2 at the vertex, 2 / 5^(3/2) at the ends
    EXPECT_NEAR(curvature(c, 0.5), 2.0, kCurvatureTolerance);
    EXPECT_NEAR(curvature(c, 1.0), 2.0 / std::pow(5.0, 1.5), kCurvatureTolerance);
    EXPECT_NEAR(curvature(c, 0.75), 2.0 / std::pow(2.0, 1.5), kCurvatureTolerance);  // x = 0.5
}

TEST(Curvature, ALineIsStraightAndACuspIsReportedAsZero)
{
    // A line with uneven speed: C'' is parallel to C', so kappa = 0 to round-off
    const Curve3d line(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0, 0}, {0.1, 0.2, 0.2}, {2, 4, 4}, {3, 6, 6}});
    for (double u : {0.0, 0.3, 0.7, 1.0}) EXPECT_NEAR(curvature(line, u), 0.0, kCurvatureTolerance);

    // A cubic whose middle control points coincide stops there (C'(0.5) = 0): undefined, 0
    const Curve2d cusp(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0}, {1, 1}, {1, 1}, {0, 0}});
    EXPECT_EQ(curvature(cusp, 0.5), 0.0);
    EXPECT_THROW(sampleCurvature(line, 0.0, 1.0, 1), GeometryError);
}
