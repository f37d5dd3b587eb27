// Editing a degenerate curve: over-sketching, pulling (constrainCurve) and the arc length they rest
// on either work or refuse with a std::invalid_argument naming the curve; they never hang or crash.
#include "solvers/bspline/geometry_error.h"
#include "solvers/editing/curve_manipulation.h"
#include "solvers/editing/oversketch.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

using namespace sculptline::solvers;
using namespace sculptline::solvers::editing;

namespace {

// A cubic whose 7 control points lie `spread` apart around (1, 2): spread 0 is a point, 1e-14 is a
// point up to round-off (a few ulps of the coordinates), 1e-10 is tiny but measurable.
Curve2d tinyCurve(double spread)
{
    std::vector<Eigen::Vector2d> pts;
    for (int i = 0; i < 7; ++i) pts.emplace_back(1 + spread * i, 2 + spread * ((i * 7) % 5));
    return Curve2d(3, {0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1}, pts);
}

// A straight stroke of 30 samples from (1, 2) to (3.9, 3.45), far longer than the curves.
std::vector<Eigen::Vector2d> stroke()
{
    std::vector<Eigen::Vector2d> s;
    for (int i = 0; i < 30; ++i) s.emplace_back(1 + 0.1 * i, 2 + 0.05 * i);
    return s;
}

std::string oversketchRefusal(const Curve2d& curve, OversketchMethod method)
{
    OversketchOptions o;
    o.method = method;
    try {
        oversketch(curve, stroke(), o);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

const std::string kDegenerate = "curve: degenerate, all control points coincide; nothing to over-sketch";

}  // namespace

TEST(DegenerateCurve, GivenAllControlPointsEqual_WhenOversketchedLocalC2_ThenRefusedAsDegenerate)
{
    EXPECT_EQ(oversketchRefusal(tinyCurve(0.0), OversketchMethod::LocalC2), kDegenerate);
}

TEST(DegenerateCurve, GivenAllControlPointsEqual_WhenOversketchedBlend_ThenRefusedAsDegenerate)
{
    // The blend divided by the curve's zero parameter speed: infinite knots, a misleading message.
    EXPECT_EQ(oversketchRefusal(tinyCurve(0.0), OversketchMethod::Blend), kDegenerate);
}

TEST(DegenerateCurve, GivenControlPointsEqualToRoundOff_WhenOversketched_ThenRefusedAsDegenerate)
{
    // 1e-14 apart at magnitude 2: the arc-length quadrature recursed forever on round-off.
    EXPECT_EQ(oversketchRefusal(tinyCurve(1e-14), OversketchMethod::LocalC2), kDegenerate);
    EXPECT_EQ(oversketchRefusal(tinyCurve(1e-14), OversketchMethod::Blend), kDegenerate);
}

TEST(DegenerateCurve, GivenATinyButMeasurableCurve_WhenOversketchedLocalC2_ThenTheStrokeReplacesIt)
{
    // Arrange: 1e-10 apart (5e5 ulps): not degenerate, but its speed carries 1e-6 relative noise,
    // which the relative-only quadrature could not resolve (it hung).
    const Curve2d curve = tinyCurve(1e-10);
    double maxError = -1.0;

    // Act
    const Curve2d out = oversketch(curve, stroke(), OversketchOptions{}, nullptr, &maxError);

    // Assert: the result follows the stroke (its far end) within the default tolerance, 0.2 % of
    // the stroke's length (3.24).
    constexpr double kStrokeTolerance = 0.002 * 3.25;
    EXPECT_LT((out.evaluate(out.domainEnd()) - stroke().back()).norm(), kStrokeTolerance);
    EXPECT_LE(maxError, kStrokeTolerance);
}

TEST(DegenerateCurve, GivenACurveAHundredMillionTimesShorterThanTheStroke_WhenOversketchedBlend_ThenTheStrokeReplacesIt)
{
    // Arrange: control points 1e-8 apart around (1, 2) (not degenerate: 5e-9 of their magnitude);
    // blend's density rule asked for stroke length / spacing ~ 3e8 control points.
    const Curve2d curve = tinyCurve(1e-8);
    OversketchOptions o;
    o.method = OversketchMethod::Blend;
    double maxError = -1.0;

    // Act
    const Curve2d out = oversketch(curve, stroke(), o, nullptr, &maxError);

    // Assert: a curve of a few control points per stroke sample at most, following the stroke
    // within the default tolerance (0.2 % of its length, 3.24).
    constexpr double kStrokeTolerance = 0.002 * 3.25;
    EXPECT_LE(out.pointCount(), static_cast<int>(stroke().size()) + 2 * 3 + 7);
    EXPECT_LT((out.evaluate(out.domainEnd()) - stroke().back()).norm(), kStrokeTolerance);
    EXPECT_LE(maxError, kStrokeTolerance);
}

TEST(DegenerateCurve, GivenAllControlPointsEqual_WhenPulled_ThenTheCurveReachesTheTarget)
{
    // Pulling is linear in the control points (least change, curve_manipulation.h): a point-curve
    // is as good a start as any, and the pulled point must land on the target.
    const Curve2d curve = tinyCurve(0.0);
    CurveConstraint<2> pull;
    pull.u = 0.5;
    pull.value = Eigen::Vector2d(3, 3);

    const Curve2d out = constrainCurve(curve, {pull});

    constexpr double kReached = 1e-9;
    EXPECT_LT((out.evaluate(0.5) - pull.value).norm(), kReached);
}
