// Split and extract: pieces coincide with the original on their parameter ranges.
#include "solvers/bspline/bspline_curve.h"
#include "solvers/bspline/geometry_error.h"
#include "test_curves.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::testing;

TEST(Split, PiecesMatchTheOriginalAndAreClamped)
{
    for (const Curve3d& c : {nurbsBookEx51Curve(), rationalCubic(), unitCircle()}) {
        const double a = c.domainStart(), b = c.domainEnd();
        for (double t : {0.05, 0.4, 0.5, 0.93}) {
            const double u = a + t * (b - a);
            const auto [left, right] = c.split(u);
            EXPECT_EQ(left.domainStart(), a);
            EXPECT_EQ(left.domainEnd(), u);
            EXPECT_EQ(right.domainStart(), u);
            EXPECT_EQ(right.domainEnd(), b);
            EXPECT_LT(maxDistance(c, left, linspace(a, u, 300)), kExact);
            EXPECT_LT(maxDistance(c, right, linspace(u, b, 300)), kExact);
            EXPECT_LT((left.points().back() - right.points().front()).norm(), kExact);
            EXPECT_EQ(knotMultiplicity(left.knots(), a), c.degree() + 1);
            EXPECT_EQ(knotMultiplicity(right.knots(), b), c.degree() + 1);
        }
    }
}

TEST(Split, AtAnExistingKnotAndRejectedOutside)
{
    const Curve3d c = nurbsBookEx23Curve();
    const auto [l, r] = c.split(4.0);  // the double knot
    EXPECT_LT(maxDistance(c, l, linspace(0, 4, 200)), kExact);
    EXPECT_LT(maxDistance(c, r, linspace(4, 5, 200)), kExact);
    EXPECT_THROW(c.split(0.0), GeometryError);
    EXPECT_THROW(c.split(6.0), GeometryError);
}

TEST(Extract, InteriorPieceAndClosedCurveAcrossTheSeam)
{
    const Curve3d c = rationalCubic();
    const Curve3d e = c.extract(-1.2, 2.9);
    EXPECT_LT(maxDistance(c, e, linspace(-1.2, 2.9, 500)), kExact);

    const Curve3d z = closedCubic();
    const double a = z.domainStart(), T = z.domainEnd() - a;
    const Curve3d across = z.extract(a + 0.8 * T, a + 1.3 * T);
    EXPECT_FALSE(across.isClosed());
    EXPECT_LT(maxDistance(z, across, linspace(a + 0.8 * T, a + 1.3 * T, 500)), 1e-11);
    const Curve3d opened = z.openAt(a + 0.25 * T);
    EXPECT_LT((opened.evaluate(opened.domainStart()) - opened.evaluate(opened.domainEnd())).norm(), 1e-11);
    EXPECT_LT(maxDistance(z, opened, linspace(a + 0.25 * T, a + 1.25 * T, 500)), 1e-11);
    EXPECT_THROW(z.extract(a, a + 1.5 * T), GeometryError);
}
