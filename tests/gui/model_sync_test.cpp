// Dragger -> sensors -> model -> Coin view, without a window: simulated dragger field changes are
// coalesced into one model update per delay-queue pass (one per displayed frame), the curves follow
// their plane through one transform write, and nothing is re-tessellated.
#include "manipulators/projection_plane_manipulator.h"
#include "scene/eigen_coin.h"
#include "model/model.h"
#include "scene/model_view.h"
#include "scene/update_scheduler.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoInteraction.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/draggers/SoJackDragger.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/sensors/SoSensorManager.h>
#include <gtest/gtest.h>

namespace sculptline {
namespace {

/// Coin computes in float: micrometres at 100 mm.
constexpr double kTolerance = 1e-3;

TEST(ModelSync, DraggerEventsAreCoalescedAndCurvesFollowTheirPlane)
{
    SoInteraction::init();
    // Given a plane with two curves, its manipulator reporting to the model, a view and a scheduler
    model::Model model;
    scene::ModelView view(model);
    scene::UpdateScheduler scheduler(model);
    model::PlaneFrame start = model::PlaneFrame::fromNormal(Eigen::Vector3d(0, 95, 60), Eigen::Vector3d(0, -1, 0), 120);
    const model::EntityId plane = model.addPlane(start);
    const solvers::Curve3d local(1, {0, 0, 1, 1}, {Eigen::Vector3d(-30, 0, 0), Eigen::Vector3d(30, 10, 0)});
    const model::EntityId c1 = model.addCurve(plane, local);
    model.addCurve(plane, local);
    manipulators::ProjectionPlaneManipulator manipulator(start);
    manipulator.setMovedCallback([&]() { model.setPlaneFrame(plane, manipulator.frame()); });
    const int builds = view.nodeBuilds();

    // When the dragger's fields change five times (a burst of mouse events) before Coin's delay
    // queue runs
    for (int k = 1; k <= 5; ++k) manipulator.dragger()->translation.setValue(0.5f * k, 0.0f, 0.0f);
    EXPECT_EQ(scheduler.updates(), 0);  // nothing solved per event
    SoDB::getSensorManager()->processDelayQueue(FALSE);

    // Then the model was solved once, the curves were recomputed once, the view wrote one transform
    // and built no node; the curve's world points moved by the dragger's last offset
    EXPECT_EQ(scheduler.updates(), 1);
    EXPECT_EQ(model.find(c1)->recomputations, 1);
    EXPECT_EQ(view.transformWrites(), 1);
    EXPECT_EQ(view.nodeBuilds(), builds);
    const double unit = manipulators::kDraggerScale * 120.0;
    const Eigen::Vector3d offset = start.rotation * Eigen::Vector3d(2.5 * unit, 0, 0);
    EXPECT_LT((model.find(c1)->world->points()[0] - (start.toWorld(local.points()[0]) + offset)).norm(), kTolerance);

    // And the Coin node of the curve is drawn where the model says (bounds of the view's graph)
    SoSearchAction search;
    search.setName("Curve2");
    search.apply(view.root());
    ASSERT_NE(search.getPath(), nullptr);
    SoGetBoundingBoxAction bbox(SbViewportRegion(800, 600));
    bbox.apply(search.getPath());
    const SbVec3f center = bbox.getBoundingBox().getCenter();
    const Eigen::Vector3d expected = 0.5 * (model.find(c1)->world->points()[0] + model.find(c1)->world->points()[1]);
    EXPECT_LT((scene::toEigen(center) - expected).norm(), kTolerance);
}

TEST(ModelSync, SetFrameMovesTheManipulatorWithoutReportingAMove)
{
    SoInteraction::init();
    const model::PlaneFrame start = model::PlaneFrame::fromNormal(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 100);
    manipulators::ProjectionPlaneManipulator manipulator(start);
    int moves = 0;
    manipulator.setMovedCallback([&moves]() { ++moves; });
    manipulator.dragger()->translation.setValue(1, 2, 0);
    const int afterDrag = moves;
    model::PlaneFrame target = start;
    target.origin = Eigen::Vector3d(5, 6, 7);
    target.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitX()));
    // When the model puts it somewhere (undo)
    manipulator.setFrame(target);
    // Then it is there, and no move was reported back (no feedback loop)
    EXPECT_EQ(moves, afterDrag);
    EXPECT_LT((manipulator.frame().origin - target.origin).norm(), kTolerance);
    EXPECT_LT(manipulator.frame().rotation.angularDistance(target.rotation), 1e-5);
}

}  // namespace
}  // namespace sculptline
