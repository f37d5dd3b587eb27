// Lifting 2D strokes into minimum-curvature space curves (seed 004 §3). Given / When / Then.
#include "solvers/editing/lift.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/projection.h"

#include <gtest/gtest.h>
#include <cmath>

using namespace sculptline::solvers;
using namespace sculptline::solvers::editing;

namespace {

constexpr double kZ0 = 2.0;
constexpr double kZ1 = 12.0;

std::vector<Eigen::Vector2d> sample(const Curve2d& c, int count)
{
    std::vector<Eigen::Vector2d> out;
    for (int i = 0; i < count; ++i)
        out.push_back(c.evaluate(c.domainStart() + (c.domainEnd() - c.domainStart()) * i / (count - 1)));
    return out;
}

// Theorem 1 (seed 004, appendix): the curvature-minimising 3D Bezier over a 2D Bezier has equally
// spaced control depths. Returns the largest distance from a lifted point to that 3D Bezier.
double theoremOneDeviation(const std::vector<Eigen::Vector2d>& cps, const std::vector<Eigen::Vector3d>& lifted)
{
    std::vector<Eigen::Vector3d> q;
    for (size_t i = 0; i < cps.size(); ++i) {
        q.emplace_back(cps[i].x(), cps[i].y(), kZ0 + (kZ1 - kZ0) * double(i) / double(cps.size() - 1));
    }
    const CurveProjector<3> projector(makeClampedUniform<3>(static_cast<int>(q.size()) - 1, q));
    double worst = 0.0;
    for (const auto& p : lifted) worst = std::max(worst, projector.project(p).distance);
    return worst;
}

struct TheoremOneCase {
    std::vector<Eigen::Vector2d> controlPoints;
    double allowedFraction;  ///< of the depth range
    bool beatsArcLength;     ///< critical points must improve on plain arc-length interpolation
};

}  // namespace

class LiftTheoremOne : public ::testing::TestWithParam<TheoremOneCase> {};

TEST_P(LiftTheoremOne, GivenBezierStroke_WhenLifted_ThenCloseToEquallySpacedDepthBezier)
{
    const auto& cps = GetParam().controlPoints;
    const Curve2d bezier = makeClampedUniform<2>(static_cast<int>(cps.size()) - 1, cps);
    const auto stroke = sample(bezier, 400);

    const LiftResult lifted = liftStroke(stroke, kZ0, kZ1);
    LiftOptions naive;  // no critical point survives: plain arc-length depth interpolation
    naive.linearityThreshold = 10.0;
    naive.filterIterations = 0;
    const LiftResult baseline = liftStroke(stroke, kZ0, kZ1, naive);

    const double dev = theoremOneDeviation(cps, lifted.points);
    const double devBaseline = theoremOneDeviation(cps, baseline.points);
    std::printf("Theorem 1 deviation: lifted %.4f, arc-length baseline %.4f (depth range %.1f)\n", dev, devBaseline,
                kZ1 - kZ0);
    EXPECT_LT(dev, GetParam().allowedFraction * (kZ1 - kZ0));
    if (GetParam().beatsArcLength) {
        EXPECT_LT(dev, 0.5 * devBaseline);
    }
    EXPECT_DOUBLE_EQ(lifted.points.front().z(), kZ0);
    EXPECT_DOUBLE_EQ(lifted.points.back().z(), kZ1);
    const Eigen::Vector3d start(stroke.front().x(), stroke.front().y(), kZ0);
    EXPECT_LT((lifted.curve.evaluate(lifted.curve.domainStart()) - start).norm(), 1e-12);
}

// Tolerances: for a parabola and a symmetric cubic arc the critical points found by Alg. 1 are the
// key points of the proof (tangent parallel to the chord at parameter 1/2, recursively), so the lift
// is close to exact; measured 0.03 and 0.11 of a range of 10. For an asymmetric arc and an S curve
// the critical points are not the key points (the paper's stated approximation, §3.1); measured
// 0.20 and 0.89. Bounds leave ~50% margin over those measurements.
INSTANTIATE_TEST_SUITE_P(Beziers, LiftTheoremOne,
                         ::testing::Values(TheoremOneCase{{{0, 0}, {5, 10}, {10, 0}}, 0.005, true},
                                           TheoremOneCase{{{0, 0}, {2, 8}, {8, 8}, {10, 0}}, 0.02, true},
                                           TheoremOneCase{{{0, 0}, {2, 8}, {9, 9}, {10, 0}}, 0.03, false},
                                           TheoremOneCase{{{0, 0}, {1, 9}, {9, -9}, {10, 0}}, 0.13, false}));

TEST(Lift, GivenStraightStroke_WhenLifted_ThenNoCriticalPointsAndLinearDepth)
{
    std::vector<Eigen::Vector2d> stroke;
    for (int i = 0; i <= 50; ++i) stroke.emplace_back(0.2 * i, 0.1 * i);

    const LiftResult r = liftStroke(stroke, 0.0, 5.0);

    EXPECT_EQ(r.critical.size(), 2u);
    for (const auto& p : r.points) EXPECT_NEAR(p.z(), 5.0 * p.x() / 10.0, 1e-9);
}

TEST(Lift, GivenZigzag_WhenCriticalPointsSought_ThenEachTurnIsFound)
{
    // A saw-tooth with 4 sharp turns, amplitude 1 on a chord of length 10, plus pen jitter of 1e-3.
    std::vector<Eigen::Vector2d> pts;
    for (int i = 0; i <= 500; ++i) {
        const double x = i / 50.0;
        const double tri = std::abs(std::fmod(x + 1.0, 2.0) - 1.0);  // 0 at x = 1, 3, ...; peaks at 0, 2, ...
        pts.emplace_back(x, tri + 1e-3 * std::sin(37.0 * i));
    }

    const auto crit = criticalPoints(pts, 0.05);

    // Turns at x = 1, 2, ..., 9 (9 of them): each is an extremum of the distance from its chord.
    ASSERT_GE(crit.size(), 9u);
    for (double turn = 1; turn <= 9; turn += 1) {
        const bool found =
            std::any_of(crit.begin(), crit.end(), [&](int i) { return std::abs(pts[i].x() - turn) < 0.05; });
        EXPECT_TRUE(found) << "turn at x = " << turn;
    }
}

TEST(Lift, GivenViewFrame_WhenLifted_ThenCurveLivesInThatFrame)
{
    ViewFrame view;
    view.origin = Eigen::Vector3d(1, 2, 3);
    view.right = Eigen::Vector3d::UnitY();
    view.up = Eigen::Vector3d::UnitZ();
    view.depth = Eigen::Vector3d::UnitX();
    const std::vector<Eigen::Vector2d> stroke = {{0, 0}, {1, 2}, {3, 3}, {5, 2}, {6, 0}};

    const LiftResult r = liftStroke(stroke, -1.0, 4.0, {}, view);

    EXPECT_LT((r.curve.evaluate(r.curve.domainStart()) - Eigen::Vector3d(0, 2, 3)).norm(), 1e-12);
    EXPECT_LT((r.curve.evaluate(r.curve.domainEnd()) - Eigen::Vector3d(5, 8, 3)).norm(), 1e-12);
}

TEST(Lift, GivenDegenerateStroke_WhenLifted_ThenGeometryError)
{
    EXPECT_THROW(liftStroke({}, 0, 1), GeometryError);
    EXPECT_THROW(liftStroke({{1, 1}, {1, 1}, {1, 1}}, 0, 1), GeometryError);
    EXPECT_THROW(liftStroke({{0, 0}, {1, 1}}, 0, NAN), GeometryError);
    const LiftResult two = liftStroke({{0, 0}, {1, 1}}, 0, 1);
    EXPECT_NEAR(two.curve.evaluate(two.curve.domainEnd()).z(), 1.0, 1e-12);
}
