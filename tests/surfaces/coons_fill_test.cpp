// Fill: 2, 3 or 4 boundaries in any order and orientation are met to 1e-9; gaps are refused.
#include "solvers/bspline/geometry_error.h"
#include "solvers/surfaces/coons_fill.h"
#include "surface_checks.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::surfaces;
using namespace sculptline::surfaces_test;

namespace {

// Four curves around a saddle-like patch: corners (0,0,0), (4,0,1), (4,3,0), (0,3,1).
std::vector<Curve3d> saddleBoundary()
{
    const Curve3d bottom = cubic({{0, 0, 0}, {1, -0.5, 0.5}, {3, 0.5, 0.2}, {4, 0, 1}});
    const Curve3d right(2, {0, 0, 0, 0.5, 1, 1, 1}, {{4, 0, 1}, {4.5, 1, 1}, {4.2, 2, 0.5}, {4, 3, 0}});
    const Curve3d top = cubic({{4, 3, 0}, {3, 3.3, 0.3}, {2, 3, 0.8}, {1, 2.8, 1.2}, {0, 3, 1}});
    const Curve3d left = cubic({{0, 3, 1}, {-0.3, 2, 0.5}, {0.2, 1, 0.2}, {0, 0, 0}});
    return {bottom, right, top, left};
}

}  // namespace

TEST(Fill, GivenFourBoundariesShuffledAndReversed_WhenFilled_ThenEachBoundaryMet)
{
    const std::vector<Curve3d> b = saddleBoundary();
    const std::vector<Curve3d> shuffled{b[2].insertKnot(0.3), b[0], reversedCurve(normalizedCurve(b[3])),
                                        reversedCurve(normalizedCurve(b[1]))};
    const Surface3d s = fill(shuffled);
    for (const Curve3d& c : shuffled) EXPECT_LT(boundaryDeviation(s, c), kExact);
    EXPECT_GT(minNeighbourNormalDot(s), 0.0);
}

TEST(Fill, GivenThreeBoundaries_WhenFilled_ThenMetWithOneDegenerateSide)
{
    const Curve3d a = cubic({{0, 0, 0}, {1, -0.3, 0}, {2, 0.3, 0.2}, {3, 0, 0}});
    const Curve3d b = cubic({{3, 0, 0}, {2.8, 1, 0.5}, {2, 2, 0.3}, {1.5, 2.6, 0}});
    const Curve3d c(2, {0, 0, 0, 1, 1, 1}, {{1.5, 2.6, 0}, {0.5, 1.5, 0.6}, {0, 0, 0}});
    const Surface3d s = fill({c, a, b});
    for (const Curve3d& k : {a, b, c}) EXPECT_LT(boundaryDeviation(s, k), kExact);
    EXPECT_GT(minNeighbourNormalDot(s), 0.0);
}

TEST(Fill, GivenTwoBoundariesFormingALoop_WhenFilled_ThenLensMeetsBoth)
{
    const Curve3d a = cubic({{0, 0, 0}, {1, 1, 0.2}, {2, 1, 0.2}, {3, 0, 0}});
    const Curve3d b = cubic({{0, 0, 0}, {1, -1, 0.5}, {2, -1, 0.5}, {3, 0, 0}});  // same direction: reversed in the loop
    const Surface3d s = fill({a, b});
    EXPECT_LT(boundaryDeviation(s, a), kExact);
    EXPECT_LT(boundaryDeviation(s, b), kExact);
}

TEST(Fill, GivenSmallGapWithinTolerance_WhenFilled_ThenCornerClosedAndBoundariesWithinGap)
{
    std::vector<Curve3d> b = saddleBoundary();
    std::vector<Vec3> pts = b[1].points();
    pts.front() += Vec3(1e-5, 0, 0);  // gap 1e-5 at the bottom-right corner, below the default tolerance
    b[1] = Curve3d(b[1].degree(), b[1].knots(), pts);
    const Surface3d s = fill(b);
    for (const Curve3d& c : b) EXPECT_LT(boundaryDeviation(s, c), 1e-5);
    EXPECT_LT((s.evaluate(1.0, 0.0) - (b[0].evaluate(1.0) + b[1].evaluate(0.0)) / 2).norm(), kExact);
}

TEST(Fill, GivenCurvesThatDoNotMeet_WhenFilled_ThenClearError)
{
    std::vector<Curve3d> b = saddleBoundary();
    std::vector<Vec3> pts = b[2].points();
    pts.back() += Vec3(0, 0.5, 0);
    b[2] = Curve3d(b[2].degree(), b[2].knots(), pts);
    try {
        fill(b);
        FAIL() << "expected GeometryError";
    } catch (const GeometryError& e) {
        EXPECT_NE(std::string(e.what()).find("do not"), std::string::npos) << e.what();
    }
    EXPECT_THROW(fill({b[0]}), GeometryError);
    EXPECT_THROW(fill({b[0], b[1], b[2], b[3], b[0]}), GeometryError);
}

TEST(Fill, GivenBuilder_WhenInteriorHandleMoves_ThenUpdateMatchesFreshFill)
{
    std::vector<Curve3d> b = saddleBoundary();
    FillBuilder builder(b);
    std::vector<Vec3> pts = b[2].points();
    pts[2] += Vec3(0.2, 0.4, -0.6);
    b[2] = Curve3d(b[2].degree(), b[2].knots(), pts);
    const Surface3d& updated = builder.update(b);
    const Surface3d fresh = fill(b);
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 10; ++j)
            EXPECT_LT((updated.evaluate(i / 10.0, j / 10.0) - fresh.evaluate(i / 10.0, j / 10.0)).norm(), kExact);
    EXPECT_LT(boundaryDeviation(updated, b[2]), kExact);
}
