// The curve-pull binding the program uses (manipulators::CurvePullBinding): grab, pointer events and
// release drive the model's pull, whose solver is factored once; the release reports the shape before
// for undo; a curve that cannot be pulled is refused with the model's reason.
#include "manipulators/curve_pull.h"
#include "model/model.h"
#include "scene/update_scheduler.h"

#include <Inventor/SoDB.h>
#include <gtest/gtest.h>

namespace sculptline {
namespace {

/// Round-off at the 100 mm scale.
constexpr double kTolerance = 1e-9;

struct PullScene {
    model::Model model;
    scene::UpdateScheduler scheduler{model};
    model::EntityId plane = 0, curve = 0;
    PullScene()
    {
        plane = model.addPlane(model::PlaneFrame::fromNormal(Eigen::Vector3d(0, 0, 10), Eigen::Vector3d::UnitZ(), 200));
        curve = model.addCurve(plane, solvers::Curve3d(3, {0, 0, 0, 0, 1, 2, 2, 2, 2},
                                                       {{-40, 0, 0}, {-20, 10, 0}, {0, -10, 0}, {20, 10, 0}, {40, 0, 0}}));
    }
    manipulators::StrokeHit hitAt(double u) const
    {
        manipulators::StrokeHit hit;
        hit.curve = curve;
        hit.point = model.find(curve)->world->evaluate(u);
        return hit;
    }
};

TEST(CurvePullBinding, APullDrivesTheModelAndReportsTheShapeBefore)
{
    SoDB::init();
    PullScene s;
    manipulators::CurvePullBinding binding(s.model, s.scheduler);
    model::EntityId finishedCurve = 0;
    std::optional<solvers::Curve3d> reportedBefore;
    binding.setFinishedCallback([&](model::EntityId c, const solvers::Curve3d& before, const std::string& message) {
        finishedCurve = c;
        reportedBefore = before;
        EXPECT_TRUE(message.empty()) << message;
    });
    const solvers::Curve3d start = *s.model.find(s.curve)->local;
    const int setUps = s.model.factorizations();
    // When the curve is grabbed at u = 1 and pulled 12 mm up its plane in 12 events
    const std::optional<model::PlaneFrame> frame = binding.grab(s.hitAt(1.0));
    ASSERT_TRUE(frame.has_value());
    EXPECT_EQ(s.model.dragged(), s.curve);
    Eigen::Vector3d target = start.evaluate(1.0);
    for (int i = 0; i < 12; ++i) {
        target.y() += 1.0;
        binding.moveTo(target);
        s.scheduler.flush();
    }
    // Then the grabbed point followed the pointer, with one set-up for the whole pull
    EXPECT_LT((s.model.find(s.curve)->local->evaluate(1.0) - target).norm(), kTolerance);
    EXPECT_EQ(s.model.factorizations(), setUps + 1);
    // And the release ends the drag and reports the curve and its shape at the grab
    binding.release();
    EXPECT_EQ(s.model.dragged(), 0u);
    EXPECT_EQ(finishedCurve, s.curve);
    ASSERT_TRUE(reportedBefore.has_value());
    EXPECT_EQ(reportedBefore->points(), start.points());
}

TEST(CurvePullBinding, AFixedCurveIsRefusedWithTheModelsReason)
{
    SoDB::init();
    PullScene s;
    s.model.setFixed(s.curve, true);
    manipulators::CurvePullBinding binding(s.model, s.scheduler);
    std::string error;
    EXPECT_FALSE(binding.grab(s.hitAt(1.0), &error).has_value());
    EXPECT_NE(error.find("fixed"), std::string::npos) << error;
    EXPECT_EQ(s.model.dragged(), 0u);
    // A release without a grab reports nothing
    bool reported = false;
    binding.setFinishedCallback([&](model::EntityId, const solvers::Curve3d&, const std::string&) { reported = true; });
    binding.release();
    EXPECT_FALSE(reported);
}

}  // namespace
}  // namespace sculptline
