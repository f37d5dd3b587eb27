// Lifting 2D strokes into minimum-curvature space curves (seed 004 §3). Given / When / Then.
#include "solvers/editing/lift.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/projection.h"

#include "tests/editing/editing_fixtures.h"

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
};

}  // namespace

class LiftTheoremOne : public ::testing::TestWithParam<TheoremOneCase> {};

// Tolerance: 0.003 of the depth range. With the depth linear in the fitted parameter the lift is
// Theorem 1's curve up to the Laplacian filter (10 passes, λ = 0.5: ~0.0005 of the range where the
// depth is not linear in arc length) and the parameter correction's linear convergence (worst, the
// asymmetric arc: 0.0016 of the range after 200 passes). Measured 0.0001 / 0.0001 / 0.0016 /
// 0.0005 / 0.0002; before (depths equally spaced over Alg. 1's critical points) 0.003 / 0.011 /
// 0.020 / 0.089 / 0.087: the S curves were 9% off.
constexpr double kTheoremOneFraction = 0.003;

TEST_P(LiftTheoremOne, GivenBezierStroke_WhenLifted_ThenCloseToEquallySpacedDepthBezier)
{
    const auto& cps = GetParam().controlPoints;
    const Curve2d bezier = makeClampedUniform<2>(static_cast<int>(cps.size()) - 1, cps);
    const auto stroke = sample(bezier, 400);

    const LiftResult lifted = liftStroke(stroke, kZ0, kZ1);
    LiftOptions naive;  // no critical point survives: plain arc-length depth interpolation
    naive.depths = DepthModel::CriticalPoints;
    naive.linearityThreshold = 10.0;
    naive.filterIterations = 0;
    const LiftResult baseline = liftStroke(stroke, kZ0, kZ1, naive);

    const double dev = theoremOneDeviation(cps, lifted.points);
    const double devBaseline = theoremOneDeviation(cps, baseline.points);
    std::printf("Theorem 1 deviation: lifted %.4f, arc-length baseline %.4f (depth range %.1f)\n", dev, devBaseline,
                kZ1 - kZ0);
    EXPECT_LT(dev, kTheoremOneFraction * (kZ1 - kZ0));
    EXPECT_LT(dev, 0.5 * devBaseline);
    EXPECT_DOUBLE_EQ(lifted.points.front().z(), kZ0);
    EXPECT_DOUBLE_EQ(lifted.points.back().z(), kZ1);
    const Eigen::Vector3d start(stroke.front().x(), stroke.front().y(), kZ0);
    EXPECT_LT((lifted.curve.evaluate(lifted.curve.domainStart()) - start).norm(), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Beziers, LiftTheoremOne,
                         ::testing::Values(TheoremOneCase{{{0, 0}, {5, 10}, {10, 0}}},
                                           TheoremOneCase{{{0, 0}, {2, 8}, {8, 8}, {10, 0}}},
                                           TheoremOneCase{{{0, 0}, {2, 8}, {9, 9}, {10, 0}}},
                                           TheoremOneCase{{{0, 0}, {1, 9}, {9, -9}, {10, 0}}},
                                           TheoremOneCase{{{0, 0}, {3, 6}, {7, -6}, {10, 0}}}));

TEST(Lift, GivenSCurve_WhenDepthsFromCriticalPoints_ThenTheirDepthsNotTheInterpolationCauseTheError)
{
    // Given the S-shaped cubic of the issue, lifted with Alg. 2 as written (depths equally spaced
    // over Alg. 1's critical points, arc-length interpolation, no filter)
    const std::vector<Eigen::Vector2d> cps = {{0, 0}, {1, 9}, {9, -9}, {10, 0}};
    const Curve2d bezier = makeClampedUniform<2>(3, cps);
    LiftOptions literal;
    literal.depths = DepthModel::CriticalPoints;
    literal.filterIterations = 0;

    // When the same critical points get the depth of their true Bézier parameter instead
    const LiftResult r = liftStroke(sample(bezier, 400), kZ0, kZ1, literal);
    std::vector<Eigen::Vector3d> corrected = r.points;
    const CurveProjector<2> onBezier(bezier);
    std::vector<double> s(r.points.size(), 0.0);
    for (size_t i = 1; i < s.size(); ++i) s[i] = s[i - 1] + (r.points[i] - r.points[i - 1]).head<2>().norm();
    for (size_t j = 0; j + 1 < r.critical.size(); ++j) {
        const int a = r.critical[j], b = r.critical[j + 1];
        const double ta = a == 0 ? 0.0 : onBezier.project(r.points[a].head<2>()).u;
        const double tb = j + 2 == r.critical.size() ? 1.0 : onBezier.project(r.points[b].head<2>()).u;
        for (int i = a; i <= b; ++i) {
            const double f = (s[i] - s[a]) / (s[b] - s[a]);
            corrected[i].z() = kZ0 + (kZ1 - kZ0) * (ta + f * (tb - ta));
        }
    }

    // Then the literal lift is far from Theorem 1 (measured 0.091 of the range) while the corrected
    // critical depths with the same arc-length interpolation are close (0.007): the error sits in
    // the critical points' depths (Alg. 1's extrema of an S curve are at t = 0.211 / 0.789, not at
    // equally spaced t), which is what DepthModel::FittedParameter replaces.
    EXPECT_GT(theoremOneDeviation(cps, r.points), 0.05 * (kZ1 - kZ0));
    EXPECT_LT(theoremOneDeviation(cps, corrected), 0.01 * (kZ1 - kZ0));
}

TEST(Lift, GivenNoisyBezierStroke_WhenLifted_ThenStillCloseToTheoremOne)
{
    // Given the S cubic with pen jitter of 0.002 of its chord
    const std::vector<Eigen::Vector2d> cps = {{0, 0}, {1, 9}, {9, -9}, {10, 0}};
    auto stroke = sample(makeClampedUniform<2>(3, cps), 400);
    for (size_t i = 1; i + 1 < stroke.size(); ++i) {
        stroke[i] += 0.02 * Eigen::Vector2d(std::sin(37.0 * i), std::cos(53.0 * i));
    }

    // When lifted
    const LiftResult r = liftStroke(stroke, kZ0, kZ1);

    // Then the depths still follow Theorem 1 to 1% of the range (the jitter itself is 0.02 in x, y)
    const double dev = theoremOneDeviation(cps, r.points);
    std::printf("Theorem 1 deviation with jitter: %.4f (depth range %.1f)\n", dev, kZ1 - kZ0);
    EXPECT_LT(dev, 0.01 * (kZ1 - kZ0));
}

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

TEST(Lift, GivenTheBenchmarkedStroke_WhenLifted_ThenEndDepthsHeldAndCurveWithinTolerance)
{
    // Given bench/editing_bench.cpp's 300-sample stroke and depths 0 and 5
    const auto stroke = sculptline::editing_fixtures::liftStroke300();

    // When lifted
    const LiftResult r = liftStroke(stroke, 0.0, 5.0);

    // Then the ends keep their depths, the depth runs monotonically between them (a stroke with no
    // loop has a monotone parameter), and the output cubic is within its tolerance of the points
    EXPECT_DOUBLE_EQ(r.points.front().z(), 0.0);
    EXPECT_DOUBLE_EQ(r.points.back().z(), 5.0);
    for (size_t i = 1; i < r.points.size(); ++i) EXPECT_GE(r.points[i].z(), r.points[i - 1].z() - 1e-12);
    double length = 0.0;
    for (size_t i = 1; i < r.points.size(); ++i) length += (r.points[i] - r.points[i - 1]).norm();
    EXPECT_LE(r.fitError, LiftOptions{}.fitTolerance * length * (1.0 + 1e-9));
}
