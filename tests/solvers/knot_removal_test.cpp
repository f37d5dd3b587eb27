// Knot removal within a tolerance (The NURBS Book A5.8): exact inverse of insertion, and the
// deviation bound holds when measured by dense sampling.
#include "solvers/bspline/bspline_curve.h"
#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/projection.h"
#include "test_curves.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::testing;

namespace {
// Removal of a knot that insertion put there is exact up to round-off of the A5.8 recurrences.
constexpr double kRoundOff = 1e-10;

// Largest distance from points of `a` to the curve `b` (a one-sided Hausdorff estimate).
double deviation(const Curve3d& a, const Curve3d& b)
{
    const CurveProjector<3> proj(b);
    double worst = 0;
    for (double u : linspace(a.domainStart(), a.domainEnd(), 2000)) worst = std::max(worst, proj.project(a.evaluate(u)).distance);
    return worst;
}
}  // namespace

TEST(KnotRemoval, RemovesWhatInsertionAddedAndRestoresThePoints)
{
    for (const Curve3d& c : {nurbsBookEx51Curve(), rationalCubic()}) {
        const double a = c.domainStart(), b = c.domainEnd();
        const Curve3d inserted = c.refine({a + 0.21 * (b - a), a + 0.33 * (b - a), a + 0.33 * (b - a), a + 0.77 * (b - a)});
        int removed = 0;
        const Curve3d back = inserted.removeKnots(1e-9, &removed);
        EXPECT_EQ(removed, 4);
        ASSERT_EQ(back.pointCount(), c.pointCount());
        EXPECT_EQ(back.knots(), c.knots());
        for (int i = 0; i < c.pointCount(); ++i) EXPECT_LT((back.points()[i] - c.points()[i]).norm(), kRoundOff);
        EXPECT_LT(maxDistance(c, back, linspace(a, b, 1000)), kRoundOff);
    }
}

TEST(KnotRemoval, ZeroToleranceKeepsAGenuineKnot)
{
    const Curve3d c = nurbsBookEx51Curve();
    int removed = -1;
    const Curve3d same = c.removeKnots(0.0, &removed);
    EXPECT_EQ(removed, 0);
    EXPECT_EQ(same.knots(), c.knots());
}

TEST(KnotRemoval, DeviationStaysWithinTheToleranceWhenShapeChanges)
{
    // Given a dense curve sampled from a smooth shape (many removable-within-tolerance knots)
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < 40; ++i) {
        const double t = i / 39.0;
        pts.emplace_back(10 * t, std::sin(6 * t) + 0.01 * std::cos(40 * t), 0.5 * t * t);
    }
    const Curve3d c = makeClampedUniform<3>(3, pts);
    for (double tol : {1e-4, 1e-2, 1e-1}) {
        // When knots are removed with tolerance tol
        int removed = 0;
        const Curve3d r = c.removeKnots(tol, &removed);
        // Then some knots go, and the curve moves by at most tol (both directions of Hausdorff)
        EXPECT_GT(removed, 0) << tol;
        EXPECT_EQ(r.pointCount(), c.pointCount() - removed);
        EXPECT_LE(deviation(c, r), tol) << tol;
        EXPECT_LE(deviation(r, c), tol) << tol;
    }
}

TEST(KnotRemoval, RationalDeviationBoundHolds)
{
    const Curve3d c = unitCircle().refine({0.1, 0.3, 0.6, 0.85});
    int removed = 0;
    const Curve3d r = c.removeKnots(1e-3, &removed);
    EXPECT_GE(removed, 4);  // at least the inserted ones
    for (double u : linspace(0, 1, 1000)) EXPECT_NEAR(r.evaluate(u).norm(), 1.0, 1e-3);
}

TEST(KnotRemoval, InvalidToleranceIsRejected)
{
    EXPECT_THROW(nurbsBookEx51Curve().removeKnots(-1.0), GeometryError);
    EXPECT_THROW(nurbsBookEx51Curve().removeKnots(std::nan("")), GeometryError);
}

TEST(KnotRemoval, ClosedCurveStaysClosedAndWithinTolerance)
{
    // Given a closed curve with knots inserted near and away from the seam
    const Curve3d c = closedCubic();
    const double a = c.domainStart(), T = c.domainEnd() - a;
    const Curve3d refined = c.refine({a + 0.01, a + 0.4 * T, a + T - 0.02});
    // When removable knots are removed
    int removed = 0;
    const Curve3d back = refined.removeKnots(1e-9, &removed);
    // Then the three inserted knots are gone, the curve is closed and unchanged
    EXPECT_EQ(removed, 3);
    EXPECT_TRUE(back.isClosed());
    EXPECT_EQ(back.pointCount(), c.pointCount());
    EXPECT_LT(maxDistance(c, back, linspace(a, a + T, 2000)), kRoundOff);
    // And with a coarse tolerance the deviation bound still holds.
    const Curve3d coarse = refined.removeKnots(0.05, &removed);
    EXPECT_TRUE(coarse.isClosed());
    EXPECT_LE(deviation(refined, coarse), 0.05);
}
