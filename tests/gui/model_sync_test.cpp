// Dragger -> the plane binding (manipulators/plane_binding.h) -> model -> Coin view, without a
// window, wired as the program wires it: simulated dragger field changes are coalesced into one
// model update per delay-queue pass (one per displayed frame), the curves follow their plane
// through one transform write, nothing is re-tessellated, a mouse drag reports its frames before
// and after, and a frame set from outside (undo) moves the dragger.
#include "manipulators/plane_binding.h"
#include "manipulators/projection_plane_manipulator.h"
#include "model/model.h"
#include "scene/eigen_coin.h"
#include "scene/entity_path.h"
#include "scene/model_view.h"
#include "scene/update_scheduler.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoInteraction.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoHandleEventAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/draggers/SoJackDragger.h>
#include <Inventor/events/SoLocation2Event.h>
#include <Inventor/events/SoMouseButtonEvent.h>
#include <Inventor/nodes/SoOrthographicCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/sensors/SoSensorManager.h>
#include "tests/gui/coin_mouse.h"

#include <gtest/gtest.h>

#include <vector>

namespace sculptline {
namespace {

/// Coin computes in float: micrometres at 100 mm.
constexpr double kTolerance = 1e-3;
/// Rounding of projected points to whole pixels, on both ends of a drag.
constexpr int kPixelTolerance = 1;

/// What the binding's drag callbacks reported.
struct Finished {
    model::EntityId plane = 0;
    model::PlaneFrame before, after;
};

/// Given a plane with two curves (left of its dragger, so a press on the jack grabs the jack), the
/// model's view, its scheduler and the plane draggers, as SketchDocument builds them.
class ModelSync : public testing::Test {
protected:
    // Before any fixture exists: its members are Coin nodes and draggers (node kits). Idempotent.
    static void SetUpTestSuite() { SoInteraction::init(); }

    void SetUp() override
    {
        draggers_.setDragCallbacks([this](model::EntityId plane) { started_.push_back(plane); },
                                   [this](model::EntityId plane, const model::PlaneFrame& before, const model::PlaneFrame& after) {
                                       finished_.push_back({plane, before, after});
                                   });
        plane_ = model_.addPlane(start_);
        c1_ = model_.addCurve(plane_, local_);
        c2_ = model_.addCurve(plane_, local_);
        manipulator_ = draggers_.manipulator(plane_);
    }

    model::Model model_;
    scene::ModelView view_{model_};
    scene::UpdateScheduler scheduler_{model_};
    manipulators::PlaneDraggers draggers_{model_, scheduler_};
    const model::PlaneFrame start_ = model::PlaneFrame::fromNormal(Eigen::Vector3d(0, 95, 60), Eigen::Vector3d(0, -1, 0), 120);
    const solvers::Curve3d local_{1, {0, 0, 1, 1}, {Eigen::Vector3d(-55, 0, 0), Eigen::Vector3d(-35, 10, 0)}};
    model::EntityId plane_ = 0, c1_ = 0, c2_ = 0;
    manipulators::ProjectionPlaneManipulator* manipulator_ = nullptr;
    std::vector<model::EntityId> started_;
    std::vector<Finished> finished_;
};

TEST_F(ModelSync, EveryPlaneHasANamedManipulatorUnderTheBindingsRoot)
{
    ASSERT_NE(manipulator_, nullptr);
    EXPECT_EQ(draggers_.size(), 1u);
    EXPECT_EQ(draggers_.root()->findChild(manipulator_->root()), 0);
    EXPECT_EQ(std::string(manipulator_->root()->getName().getString()), scene::entityNodeName(model::EntityKind::Plane, plane_));
    EXPECT_EQ(draggers_.manipulator(c1_), nullptr);  // curves have no dragger
    EXPECT_LT((manipulator_->frame().origin - start_.origin).norm(), kTolerance);
}

TEST_F(ModelSync, DraggerEventsAreCoalescedAndCurvesFollowTheirPlane)
{
    const int builds = view_.nodeBuilds();
    const int updates = scheduler_.updates();

    // When the dragger's fields change five times (a burst of mouse events) before Coin's delay
    // queue runs
    for (int k = 1; k <= 5; ++k) manipulator_->dragger()->translation.setValue(0.5f * k, 0.0f, 0.0f);
    EXPECT_EQ(scheduler_.updates(), updates);  // nothing solved per event
    EXPECT_TRUE(model_.updatePending());  // the binding wrote the frame into the model
    SoDB::getSensorManager()->processDelayQueue(FALSE);

    // Then the model was solved once, the curves were recomputed once, the view wrote one transform
    // and built no node; the curve's world points moved by the dragger's last offset
    EXPECT_EQ(scheduler_.updates(), updates + 1);
    EXPECT_EQ(model_.find(c1_)->recomputations, 1);
    EXPECT_EQ(model_.find(c2_)->recomputations, 1);
    EXPECT_EQ(view_.transformWrites(), 1);
    EXPECT_EQ(view_.nodeBuilds(), builds);
    const double unit = manipulators::kDraggerScale * 120.0;
    const Eigen::Vector3d offset = start_.rotation * Eigen::Vector3d(2.5 * unit, 0, 0);
    EXPECT_LT((model_.find(c1_)->world->points()[0] - (start_.toWorld(local_.points()[0]) + offset)).norm(), kTolerance);

    // And the Coin node of the curve is drawn where the model says (bounds of the view's graph)
    SoSearchAction search;
    search.setName(scene::entityNodeName(model::EntityKind::Curve, c1_).c_str());
    search.apply(view_.root());
    ASSERT_NE(search.getPath(), nullptr);
    SoGetBoundingBoxAction bbox(SbViewportRegion(800, 600));
    bbox.apply(search.getPath());
    const SbVec3f center = bbox.getBoundingBox().getCenter();
    const Eigen::Vector3d expected = 0.5 * (model_.find(c1_)->world->points()[0] + model_.find(c1_)->world->points()[1]);
    EXPECT_LT((scene::toEigen(center) - expected).norm(), kTolerance);
}

TEST_F(ModelSync, SetPlaneFrameFromOutsideMovesTheManipulatorWithoutReportingAMove)
{
    // Given no drag under way
    ASSERT_EQ(draggers_.dragging(), 0u);
    model::PlaneFrame target = start_;
    target.origin = Eigen::Vector3d(5, 6, 7);
    target.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitX()));

    // When the model's frame is set from outside (an undo) and the update runs
    model_.setPlaneFrame(plane_, target);
    scheduler_.flush();

    // Then the manipulator is there, and moving it did not write the frame back into the model
    // (no feedback loop: nothing is pending and the model keeps the frame it was given)
    EXPECT_LT((manipulator_->frame().origin - target.origin).norm(), kTolerance);
    EXPECT_LT(manipulator_->frame().rotation.angularDistance(target.rotation), 1e-5);
    EXPECT_FALSE(model_.updatePending());
    EXPECT_EQ(model_.find(plane_)->frame, target);
    EXPECT_TRUE(started_.empty());
    EXPECT_TRUE(finished_.empty());
}

TEST_F(ModelSync, RemovingThePlaneRemovesItsManipulator)
{
    model_.remove(plane_);
    EXPECT_EQ(draggers_.manipulator(plane_), nullptr);
    EXPECT_EQ(draggers_.size(), 0u);
    EXPECT_EQ(draggers_.root()->getNumChildren(), 0);
    // And an undo brings it back
    model_.addPlane(start_, plane_);
    ASSERT_NE(draggers_.manipulator(plane_), nullptr);
    EXPECT_EQ(draggers_.root()->getNumChildren(), 1);
}

/// A drag with simulated Coin events (SoHandleEventAction) on the program's graph: the view and
/// the draggers under one camera looking straight down, so the jack's centre box is seen face-on.
class ModelSyncMouse : public ModelSync {
protected:
    void SetUp() override
    {
        ModelSync::SetUp();
        mouse_ = std::make_unique<guitest::CoinMouse>(std::initializer_list<SoNode*>{view_.root(), draggers_.root()});
    }
    void TearDown() override { mouse_.reset(); }

    SbVec2s pixelOf(const Eigen::Vector3d& p) const { return mouse_->pixelOf(p); }

    std::unique_ptr<guitest::CoinMouse> mouse_;
};

TEST_F(ModelSyncMouse, ADragReportsItsFramesBeforeAndAfter)
{
    // Given a press on the jack's centre box (off the axes: at the centre itself the jack's
    // vertical line translator, seen end-on, wins)
    const int builds = view_.nodeBuilds();
    const SbVec2s centre = pixelOf(start_.origin);
    const SbVec2s press(centre[0] + 7, centre[1] + 7);
    mouse_->press(press);
    ASSERT_EQ(started_, std::vector<model::EntityId>{plane_}) << "the press grabbed no part of the jack";
    EXPECT_EQ(draggers_.dragging(), plane_);

    // When the mouse moves 40 pixels right and up in four steps, one frame passing after each, and
    // an update runs mid-drag
    const int updates = scheduler_.updates();
    for (int step = 1; step <= 4; ++step) {
        mouse_->move(SbVec2s(press[0] + 10 * step, press[1] + 10 * step));
        SoDB::getSensorManager()->processDelayQueue(FALSE);
    }
    EXPECT_EQ(scheduler_.updates(), updates + 4);  // one per frame
    // (the manipulator being dragged is not put back by the model's own updates)
    EXPECT_LT((manipulator_->frame().origin - model_.find(plane_)->frame.origin).norm(), kTolerance);
    mouse_->release(SbVec2s(press[0] + 40, press[1] + 40));

    // Then the finished callback reports the frame at the press and the model's frame at the
    // release, which lies 40 pixels right and up of the start; the drag is over, the curves
    // followed and nothing was re-tessellated
    ASSERT_EQ(finished_.size(), 1u);
    EXPECT_EQ(draggers_.dragging(), 0u);
    const Finished& f = finished_.front();
    EXPECT_EQ(f.plane, plane_);
    EXPECT_EQ(f.before, start_);
    EXPECT_EQ(f.after, model_.find(plane_)->frame);
    EXPECT_FALSE(model_.updatePending());
    const SbVec2s landed = pixelOf(f.after.origin);
    EXPECT_NEAR(landed[0] - centre[0], 40, kPixelTolerance);
    EXPECT_NEAR(landed[1] - centre[1], 40, kPixelTolerance);
    EXPECT_NEAR(f.after.origin.z(), start_.origin.z(), kTolerance);
    EXPECT_LT((model_.find(c1_)->world->points()[1] - f.after.toWorld(local_.points()[1])).norm(), kTolerance);
    EXPECT_EQ(view_.nodeBuilds(), builds);
}

TEST_F(ModelSyncMouse, APressAndReleaseWithoutMotionReportsNoMove)
{
    const SbVec2s centre = pixelOf(start_.origin);
    const SbVec2s press(centre[0] + 7, centre[1] + 7);
    mouse_->press(press);
    ASSERT_EQ(started_.size(), 1u);
    mouse_->release(press);
    ASSERT_EQ(finished_.size(), 1u);
    EXPECT_EQ(finished_.front().before, finished_.front().after);  // the ui pushes no undo step
}

}  // namespace
}  // namespace sculptline
