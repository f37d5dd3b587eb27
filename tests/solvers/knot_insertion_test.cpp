// Knot insertion and refinement: The NURBS Book Ex. 5.1 reference and shape invariance.
#include "solvers/bspline/bspline_curve.h"
#include "solvers/bspline/geometry_error.h"
#include "test_curves.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::testing;

TEST(KnotInsertion, NurbsBookExample51NewControlPoints)
{
    // Given the cubic of Ex. 5.1 (U = {0,0,0,0,1,2,3,4,5,5,5,5})
    const Curve3d c = nurbsBookEx51Curve();
    const auto& P = c.points();
    // When u = 5/2 is inserted once
    const Curve3d q = c.insertKnot(2.5);
    // Then Q3 = 5/6 P3 + 1/6 P2, Q4 = 1/2 P4 + 1/2 P3, Q5 = 1/6 P5 + 5/6 P4 (Ex. 5.1), the rest unchanged
    ASSERT_EQ(q.pointCount(), 9);
    const auto& Q = q.points();
    EXPECT_LT((Q[3] - (5.0 / 6 * P[3] + 1.0 / 6 * P[2])).norm(), kExact);
    EXPECT_LT((Q[4] - (0.5 * P[4] + 0.5 * P[3])).norm(), kExact);
    EXPECT_LT((Q[5] - (1.0 / 6 * P[5] + 5.0 / 6 * P[4])).norm(), kExact);
    for (int i : {0, 1, 2}) EXPECT_EQ(Q[i], P[i]);
    for (int i : {6, 7, 8}) EXPECT_EQ(Q[i], P[i - 1]);
    const KnotVector expected = {0, 0, 0, 0, 1, 2, 2.5, 3, 4, 5, 5, 5, 5};
    EXPECT_EQ(q.knots(), expected);
}

TEST(KnotInsertion, ShapeUnchangedForOpenRationalAndClosedCurves)
{
    for (const Curve3d& c : {nurbsBookEx51Curve(), rationalCubic(), unitCircle(), closedCubic()}) {
        const double a = c.domainStart(), b = c.domainEnd();
        const auto us = linspace(a, b, 1000);
        for (double t : {0.137, 0.5, 0.91}) {
            const double u = a + t * (b - a);
            for (int times = 1; times <= c.degree() - knotMultiplicity(c.knots(), u); ++times) {
                const Curve3d q = c.insertKnot(u, times);
                EXPECT_EQ(q.pointCount(), c.pointCount() + times);
                EXPECT_EQ(q.isClosed(), c.isClosed());
                EXPECT_LT(maxDistance(c, q, us), kExact) << "u = " << u << " times = " << times;
            }
        }
    }
}

TEST(KnotInsertion, InsertingAnExistingKnotUpToTheDegreeMakesTheCurvePassThroughAPoint)
{
    const Curve3d c = nurbsBookEx51Curve();
    const Curve3d q = c.insertKnot(2.0, 2);  // 2 has multiplicity 1: now 3 = degree
    const Eigen::Vector3d at = c.evaluate(2.0);
    bool found = false;
    for (const auto& p : q.points()) found = found || (p - at).norm() < kExact;
    EXPECT_TRUE(found);
    EXPECT_THROW(q.insertKnot(2.0, 1), GeometryError);  // would exceed the degree
}

TEST(KnotInsertion, ClosedCurveInsertionNearTheSeamKeepsItClosed)
{
    const Curve3d c = closedCubic();
    const double a = c.domainStart(), T = c.domainEnd() - a;
    for (double u : {a + 1e-3, a + 0.5, a + T - 1e-3, a + T + 0.25 /* wraps */}) {
        const Curve3d q = c.insertKnot(u);
        ASSERT_TRUE(q.isClosed());
        EXPECT_EQ(q.pointCount(), c.pointCount() + 1);
        EXPECT_LT(maxDistance(c, q, linspace(a - T, a + 2 * T, 3000)), 1e-11) << u;
    }
}

TEST(KnotInsertion, OutsideTheDomainIsRejected)
{
    const Curve3d c = nurbsBookEx51Curve();
    EXPECT_THROW(c.insertKnot(5.0), GeometryError);
    EXPECT_THROW(c.insertKnot(-1.0), GeometryError);
    EXPECT_THROW(c.insertKnot(std::nan("")), GeometryError);
}

TEST(KnotRefinement, ManyKnotsAtOnceMatchRepeatedInsertion)
{
    const Curve3d c = rationalCubic();
    const std::vector<double> x = {-1.9, -1.0, -1.0, 0.3, 1.0, 1.0, 3.4};
    const Curve3d r = c.refine(x);
    Curve3d s = c;
    for (double u : x) s = s.insertKnot(u);
    ASSERT_EQ(r.pointCount(), c.pointCount() + static_cast<int>(x.size()));
    EXPECT_EQ(r.knots(), s.knots());
    for (int i = 0; i < r.pointCount(); ++i) {
        EXPECT_LT((r.points()[i] - s.points()[i]).norm(), kExact);
        EXPECT_NEAR(r.weights()[i], s.weights()[i], kExact);
    }
    EXPECT_LT(maxDistance(c, r, linspace(-2, 3.5, 2000)), kExact);
}

TEST(KnotRefinement, ClosedCurveRefinementKeepsShape)
{
    const Curve3d c = closedCubic();
    const double a = c.domainStart(), b = c.domainEnd();
    const Curve3d r = c.refine({a + 0.3, a + 1.7, b - 0.1});
    EXPECT_TRUE(r.isClosed());
    EXPECT_EQ(r.pointCount(), c.pointCount() + 3);
    EXPECT_LT(maxDistance(c, r, linspace(a, b, 2000)), 1e-11);
}
