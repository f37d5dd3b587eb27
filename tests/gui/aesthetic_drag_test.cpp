// The aesthetic handle's binding to the model (manipulators/aesthetic_drag.h): a drag factors the
// operator at the grab, each event puts the operator's curve for that amount into the model (the same curve
// the one-shot operator gives), the release reports the shape before; the handle sits on the operated
// point, along the displacement, in world coordinates of a tilted plane. Headless (Coin only).
#include "manipulators/aesthetic_drag.h"
#include "model/model.h"
#include "scene/update_scheduler.h"
#include "tests/aesthetics/graph_curves.h"

#include <Inventor/SoInteraction.h>
#include <gtest/gtest.h>

#include <cmath>

namespace sculptline {
namespace {

namespace aes = solvers::aesthetics;

// Round-off at the 100 mm scale.
constexpr double kTolerance = 1e-9;

// The flat-bottomed valley ("M+m+M+") scaled by 40, in plane-local coordinates (z = 0).
solvers::Curve3d valley() { return aes::spaceCurve(testcurves::flatValley(40.0), aes::PlaneFrame{}); }

struct ValleyScene {
    model::Model model;
    scene::UpdateScheduler scheduler{model};
    model::EntityId plane = 0, curve = 0;
    ValleyScene()
    {
        plane = model.addPlane(model::PlaneFrame::fromNormal(Eigen::Vector3d(5, 0, 10), Eigen::Vector3d(0, 1, 1).normalized(), 200));
        curve = model.addCurve(plane, valley());
        scheduler.flush();
    }
};

class AestheticDrag : public testing::Test {
protected:
    static void SetUpTestSuite() { SoInteraction::init(); }
};

TEST_F(AestheticDrag, ADragOfSoftenPutsTheOperatorsCurveForEachAmountIntoTheModelAndReportsTheShapeBefore)
{
    // Arrange
    ValleyScene s;
    manipulators::AestheticDragBinding binding(s.model, s.scheduler);
    std::optional<solvers::Curve3d> before;
    double finalAmount = -1.0;
    binding.setFinished([&](model::EntityId c, const solvers::Curve3d& b, double amount, const std::string& message) {
        EXPECT_EQ(c, s.curve);
        before = b;
        finalAmount = amount;
        EXPECT_TRUE(message.empty()) << message;
    });
    const solvers::Curve3d start = *s.model.find(s.curve)->local;
    aes::OperatorOptions o;
    o.at = 0;
    // Act: grab, then 10 events up to 0.2 mm.
    std::string error;
    ASSERT_TRUE(binding.grab(s.curve, aes::Operator::Soften, o, &error)) << error;
    EXPECT_EQ(s.model.dragged(), s.curve);
    for (int i = 1; i <= 10; ++i) {
        binding.moveTo(0.02 * i);
        s.scheduler.flush();
    }
    // Assert: the model's curve is the operator's for that amount (one-shot, same constraints).
    const solvers::Curve3d live = *s.model.find(s.curve)->local;
    const aes::OperatorResult oneShot = aes::applyOperator(aes::planarCurve(start), aes::Operator::Soften, 0.2, o);
    ASSERT_NEAR(oneShot.amount, 0.2, 1e-12) << oneShot.message;
    for (int k = 0; k <= 50; ++k) {
        const double u = k / 50.0;
        const Eigen::Vector2d expected = oneShot.curve.evaluate(u);
        EXPECT_LT((live.evaluate(u) - Eigen::Vector3d(expected.x(), expected.y(), 0.0)).norm(), kTolerance) << u;
    }
    // The ends stayed.
    EXPECT_LT((live.evaluate(0.0) - start.evaluate(0.0)).norm(), kTolerance);
    EXPECT_LT((live.evaluate(1.0) - start.evaluate(1.0)).norm(), kTolerance);
    binding.release();
    EXPECT_EQ(s.model.dragged(), 0u);
    ASSERT_TRUE(before.has_value());
    EXPECT_EQ(before->points(), start.points());
    EXPECT_DOUBLE_EQ(finalAmount, 0.2);
}

TEST_F(AestheticDrag, TheHandleSitsOnTheOperatedPointAlongItsDisplacementInTheWorld)
{
    // Arrange
    ValleyScene s;
    aes::OperatorOptions o;
    o.at = 1;  // the m+ at the valley's bottom
    // Act
    const manipulators::AestheticOperation op = manipulators::prepareAesthetic(s.model, s.curve, aes::Operator::Tension, o);
    // Assert: at the bottom's world point, along the principal normal (toward the centre of
    // curvature: up the plane's local y), turned into the world by the plane's frame.
    const model::PlaneFrame frame = s.model.find(s.plane)->frame;
    const auto& local = *s.model.find(s.curve)->local;
    EXPECT_LT((op.handle.point - frame.toWorld(local.evaluate(0.5))).norm(), kTolerance);
    EXPECT_LT((op.handle.direction - frame.rotation * Eigen::Vector3d::UnitY()).norm(), 1e-9);
    EXPECT_GT(op.handle.size, 0.0);
    // And the handle node shows it, its amount 0 at rest.
    manipulators::AestheticHandle handle;
    EXPECT_FALSE(handle.visible());
    handle.show(op.handle);
    EXPECT_TRUE(handle.visible());
    EXPECT_EQ(handle.amount(), 0.0);
}

TEST_F(AestheticDrag, AFixedCurveOrAnOperatorThatDoesNotApplyIsRefusedWithTheReason)
{
    ValleyScene s;
    manipulators::AestheticDragBinding binding(s.model, s.scheduler);
    std::string error;
    // A fixed curve refuses every edit.
    s.model.setFixed(s.curve, true);
    EXPECT_FALSE(binding.grab(s.curve, aes::Operator::Accelerate, {}, &error));
    EXPECT_NE(error.find("fixed"), std::string::npos) << error;
    s.model.setFixed(s.curve, false);
    aes::OperatorOptions o;
    o.at = 1;  // an m+: soften needs an M+ or m-
    EXPECT_FALSE(binding.grab(s.curve, aes::Operator::Soften, o, &error));
    EXPECT_NE(error.find("at: point 1"), std::string::npos) << error;
    EXPECT_EQ(s.model.dragged(), 0u);
}

}  // namespace
}  // namespace sculptline
