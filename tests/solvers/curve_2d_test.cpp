// The 2D instantiation and closed rational curves go through the same algorithms as the 3D ones.
#include "solvers/bspline/arc_length.h"
#include "solvers/bspline/projection.h"
#include "test_curves.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::testing;

namespace {

Curve2d planarCubic()
{
    const std::vector<Eigen::Vector2d> pts = {{0, 0}, {1, 2}, {3, 3}, {4, 1}, {6, 0}, {7, 2}};
    return Curve2d(3, {1, 1, 1, 1, 2, 4, 5, 5, 5, 5}, pts, {1, 2, 1, 0.5, 1, 1});
}

// A closed rational quadratic: an irregular pentagon with uneven weights.
Curve2d closedRational()
{
    const std::vector<Eigen::Vector2d> pts = {{0, 0}, {4, -1}, {6, 3}, {2, 6}, {-2, 3}};
    return makeClosedUniform<2>(2, pts, {1, 3, 0.5, 2, 1});
}

}  // namespace

TEST(Curve2d, OperationsKeepShape)
{
    for (const Curve2d& c : {planarCubic(), closedRational()}) {
        const auto us = linspace(c.domainStart(), c.domainEnd(), 800);
        const double mid = 0.5 * (c.domainStart() + c.domainEnd()) + 0.1;
        EXPECT_LT(maxDistance(c, c.insertKnot(mid), us), kExact);
        EXPECT_LT(maxDistance(c, c.elevate(2), us), kExact);
        EXPECT_LT(maxDistance(c, c.refine({mid - 0.3, mid, mid + 0.2}), us), kExact);
        int removed = 0;
        const Curve2d back = c.insertKnot(mid).removeKnots(1e-9, &removed);
        EXPECT_EQ(removed, 1);
        EXPECT_LT(maxDistance(c, back, us), 1e-10);
    }
}

TEST(Curve2d, ClosedRationalStaysClosedThroughElevation)
{
    const Curve2d c = closedRational();
    const Curve2d e = c.elevate(1);
    ASSERT_TRUE(e.isClosed());
    ASSERT_TRUE(e.isRational());
    const double a = c.domainStart(), T = c.domainEnd() - a;
    EXPECT_LT(maxDistance(c, e, linspace(a - T, a + 2 * T, 2000)), 1e-11);
}

TEST(Curve2d, ProjectionAndArcLength)
{
    const Curve2d c = planarCubic();
    const CurveProjector<2> proj(c);
    for (double u : linspace(1, 5, 17)) {
        const Eigen::Vector2d p = c.evaluate(u);
        const Eigen::Vector2d n = Eigen::Vector2d(-c.derivatives(u, 1)[1].y(), c.derivatives(u, 1)[1].x()).normalized();
        // A point a little way along the normal projects back to the foot point (small offset:
        // well inside the radius of curvature, so the foot point is the unique nearest point).
        const CurveProjection<2> r = proj.project(p + 1e-3 * n);
        EXPECT_NEAR(r.distance, 1e-3, 1e-9) << u;
    }
    // Length is additive over a split.
    const auto [l, r] = c.split(3.3);
    EXPECT_NEAR(arcLength(l) + arcLength(r), arcLength(c), 1e-10 * arcLength(c));
}
