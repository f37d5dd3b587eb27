// Degree elevation: the Bezier elevation formula (The NURBS Book eq. 5.36) and shape invariance.
#include "solvers/bspline/bspline_curve.h"
#include "test_curves.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::testing;

TEST(DegreeElevation, QuadraticBezierMatchesEquation536)
{
    // Given a quadratic Bezier segment
    const std::vector<Eigen::Vector3d> P = {{0, 0, 0}, {2, 4, 1}, {5, 1, -2}};
    const Curve3d c(2, {0, 0, 0, 1, 1, 1}, P);
    // When elevated once
    const Curve3d e = c.elevate(1);
    // Then Q_i = i/(p+1) P_{i-1} + (1 - i/(p+1)) P_i (The NURBS Book eq. 5.36 with p = 2)
    ASSERT_EQ(e.degree(), 3);
    ASSERT_EQ(e.pointCount(), 4);
    EXPECT_LT((e.points()[0] - P[0]).norm(), kExact);
    EXPECT_LT((e.points()[1] - (P[0] / 3 + 2 * P[1] / 3)).norm(), kExact);
    EXPECT_LT((e.points()[2] - (2 * P[1] / 3 + P[2] / 3)).norm(), kExact);
    EXPECT_LT((e.points()[3] - P[2]).norm(), kExact);
}

TEST(DegreeElevation, ShapeUnchangedAndKnotMultiplicitiesRaised)
{
    for (const Curve3d& c : {nurbsBookEx23Curve(), nurbsBookEx51Curve(), rationalCubic(), unitCircle()}) {
        for (int t : {1, 2, 3}) {
            const Curve3d e = c.elevate(t);
            EXPECT_EQ(e.degree(), c.degree() + t);
            EXPECT_LT(maxDistance(c, e, linspace(c.domainStart(), c.domainEnd(), 1500)), kExact);
            // Every distinct knot gains t in multiplicity (The NURBS Book §5.5).
            for (double k : interiorBreakpoints(c.degree(), c.knots())) {
                EXPECT_EQ(knotMultiplicity(e.knots(), k), knotMultiplicity(c.knots(), k) + t) << k;
            }
            EXPECT_EQ(static_cast<int>(e.knots().size()), e.pointCount() + e.degree() + 1);
        }
    }
}

TEST(DegreeElevation, ClosedCurveStaysClosed)
{
    const Curve3d c = closedCubic();
    const Curve3d e = c.elevate(1);
    EXPECT_TRUE(e.isClosed());
    EXPECT_EQ(e.degree(), 4);
    const double a = c.domainStart(), T = c.domainEnd() - a;
    EXPECT_LT(maxDistance(c, e, linspace(a - T, a + 2 * T, 3000)), 1e-11);
}
