// The projection plane manipulator (manipulators/projection_plane_manipulator.h) without a window:
// the dragger's fields are its API, so setting them stands in for a mouse drag.
#include "manipulators/projection_plane_manipulator.h"

#include "scene/eigen_coin.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoInteraction.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoHandleEventAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/draggers/SoJackDragger.h>
#include <Inventor/events/SoLocation2Event.h>
#include <Inventor/events/SoMouseButtonEvent.h>
#include <Inventor/nodes/SoOrthographicCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoTransform.h>
#include <Inventor/sensors/SoSensorManager.h>
#include "tests/gui/coin_mouse.h"

#include <gtest/gtest.h>

namespace sculptline::manipulators {
namespace {

/// Coin computes in float: micrometres at 100 mm.
constexpr double kTolerance = 1e-3;

class ProjectionPlane : public testing::Test {
protected:
    void SetUp() override
    {
        SoInteraction::init();  // draggers need the node kit classes; idempotent
        spec_.origin = Eigen::Vector3d(0, 95, 60);
        spec_.normal = Eigen::Vector3d(0, -1, 0);
        spec_.size = 120;
        manipulator_ = std::make_unique<ProjectionPlaneManipulator>(spec_);
    }

    /// World bounds of the plane geometry alone (not the dragger).
    SbBox3f planeBounds() const
    {
        SoSearchAction search;
        search.setName("PlaneGeometry");
        search.apply(manipulator_->root());
        SoGetBoundingBoxAction bbox(SbViewportRegion(800, 600));
        bbox.apply(search.getPath());
        return bbox.getBoundingBox();
    }

    model::PlaneSpec spec_;
    std::unique_ptr<ProjectionPlaneManipulator> manipulator_;
};

/// The scale between dragger units and model units for spec_.size = 120.
constexpr double kUnit = kDraggerScale * 120.0;

TEST_F(ProjectionPlane, StartsWhereTheDocumentPutsIt)
{
    const SbBox3f box = planeBounds();
    EXPECT_NEAR(box.getCenter()[0], 0.0, kTolerance);
    EXPECT_NEAR(box.getCenter()[1], 95.0, kTolerance);
    EXPECT_NEAR(box.getCenter()[2], 60.0, kTolerance);
    EXPECT_NEAR(box.getMax()[0] - box.getMin()[0], 120.0, kTolerance);
    EXPECT_NEAR(box.getMax()[1] - box.getMin()[1], 0.0, kTolerance);
    const model::PlaneSpec now = manipulator_->plane();
    EXPECT_LT((now.origin - spec_.origin).norm(), kTolerance);
    EXPECT_LT((now.normal - spec_.normal).norm(), kTolerance);
    EXPECT_NEAR(now.size, 120.0, kTolerance);
}

TEST_F(ProjectionPlane, DraggerTranslationMovesThePlane)
{
    // Given a listener / When the dragger's translation changes (in its local frame, where +Z is
    // the plane normal and the placement maps local (x, y, z) to world (x, -z, y))
    int moves = 0;
    manipulator_->setMovedCallback([&moves]() { ++moves; });
    manipulator_->dragger()->translation.setValue(1.0f, 2.0f, 0.5f);
    SoDB::getSensorManager()->processDelayQueue(FALSE);

    // Then the motion transform follows, the plane moves by s * (1, -0.5, 2), the listener hears it
    EXPECT_EQ(manipulator_->motion()->translation.getValue(), SbVec3f(1.0f, 2.0f, 0.5f));
    const Eigen::Vector3d expected = spec_.origin + kUnit * Eigen::Vector3d(1.0, -0.5, 2.0);
    const SbBox3f box = planeBounds();
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(box.getCenter()[k], expected[k], kTolerance) << "axis " << k;
    EXPECT_LT((manipulator_->plane().origin - expected).norm(), kTolerance);
    EXPECT_LT((manipulator_->plane().normal - spec_.normal).norm(), kTolerance);
    EXPECT_GE(moves, 1);
}

TEST_F(ProjectionPlane, DraggerRotationTurnsThePlane)
{
    // When the dragger turns a quarter about its local X axis: local +Z -> local -Y -> world -Z
    manipulator_->dragger()->rotation.setValue(SbRotation(SbVec3f(1, 0, 0), static_cast<float>(M_PI / 2)));

    // Then the plane lies flat (normal down), still centred on its origin
    const model::PlaneSpec now = manipulator_->plane();
    EXPECT_LT((now.normal - Eigen::Vector3d(0, 0, -1)).norm(), kTolerance);
    EXPECT_LT((now.origin - spec_.origin).norm(), kTolerance);
    const SbBox3f box = planeBounds();
    EXPECT_NEAR(box.getMax()[2] - box.getMin()[2], 0.0, kTolerance);
    EXPECT_NEAR(box.getMax()[1] - box.getMin()[1], 120.0, kTolerance);
}

TEST_F(ProjectionPlane, RootStaysAliveWhileTheSceneHoldsIt)
{
    // Given a scene that holds the manipulator's root
    auto* scene = new SoSeparator;
    scene->ref();
    scene->addChild(manipulator_->root());
    EXPECT_EQ(manipulator_->root()->getRefCount(), 2);
    // When the manipulator goes / Then the scene's reference keeps the graph valid
    SoNode* root = manipulator_->root();
    manipulator_.reset();
    EXPECT_EQ(root->getRefCount(), 1);
    scene->unref();
}

}  // namespace
}  // namespace sculptline::manipulators

namespace sculptline::manipulators {
namespace {

/// A drag with simulated Coin events (SoHandleEventAction): the path a mouse takes in the viewer,
/// without a window.
class DraggedWithTheMouse : public ProjectionPlane {
protected:
    /// Rounding of the projected centre to whole pixels, on both ends of the drag.
    static constexpr int kPixelTolerance = 1;

    // Look straight down: the jack's centre box lies in the dragger's local XZ plane, which the
    // placement turns into the world's horizontal plane, so from above it is seen face-on.
    void SetUp() override
    {
        ProjectionPlane::SetUp();
        mouse_ = std::make_unique<guitest::CoinMouse>(std::initializer_list<SoNode*>{manipulator_->root()});
    }
    void TearDown() override { mouse_.reset(); }

    SbVec2s pixelOf(const Eigen::Vector3d& p) const { return mouse_->pixelOf(p); }
    void press(const SbVec2s& pixel) { mouse_->press(pixel); }
    void move(const SbVec2s& pixel) { mouse_->move(pixel); }
    void release(const SbVec2s& pixel) { mouse_->release(pixel); }

    std::unique_ptr<guitest::CoinMouse> mouse_;
};

TEST_F(DraggedWithTheMouse, PressMoveReleaseMovesThePlane)
{
    // Given a press on the jack's centre (its translator box, seen face-on from above)
    int starts = 0, finishes = 0;
    const auto count = [](void* counter, SoDragger*) { ++*static_cast<int*>(counter); };
    manipulator_->dragger()->addStartCallback(count, &starts);
    manipulator_->dragger()->addFinishCallback(count, &finishes);
    // Off the axes: at the centre itself the jack's vertical line translator, seen end-on, wins
    const SbVec2s centre = pixelOf(spec_.origin);
    const SbVec2s start(centre[0] + 7, centre[1] + 7);
    press(start);
    ASSERT_EQ(starts, 1) << "the press at " << start[0] << "," << start[1] << " grabbed no part of the jack";

    // When the mouse moves 40 pixels right and up (in four steps), then releases
    int moves = 0;
    manipulator_->setMovedCallback([&moves]() { ++moves; });
    const SbVec2s end(start[0] + 40, start[1] + 40);
    for (int step = 1; step <= 4; ++step) move(SbVec2s(start[0] + 10 * step, start[1] + 10 * step));
    release(end);
    SoDB::getSensorManager()->processDelayQueue(FALSE);

    // Then the plane followed the mouse: its centre is now 40 pixels right and up of where it was
    // (the box translator moves in the horizontal plane, seen face-on), it has not turned, its
    // geometry agrees with plane(), and listeners heard of it
    const model::PlaneSpec now = manipulator_->plane();
    const SbVec2s landed = pixelOf(now.origin);
    EXPECT_NEAR(landed[0] - centre[0], 40, kPixelTolerance);
    EXPECT_NEAR(landed[1] - centre[1], 40, kPixelTolerance);
    EXPECT_NEAR(now.origin.z(), spec_.origin.z(), kTolerance);
    EXPECT_LT((now.normal - spec_.normal).norm(), kTolerance);
    EXPECT_EQ(finishes, 1);
    const SbBox3f box = planeBounds();
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(box.getCenter()[k], now.origin[k], kTolerance) << "axis " << k;
    EXPECT_GE(moves, 1);
}

}  // namespace
}  // namespace sculptline::manipulators
