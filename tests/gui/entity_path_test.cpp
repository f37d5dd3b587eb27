// scene/entity_path.h on the program's own graph, without a window: a ModelView's nodes and the
// plane draggers' roots, reached through search paths and a ray pick as the pickers see them.
#include "scene/entity_path.h"

#include "manipulators/plane_binding.h"
#include "model/model.h"
#include "scene/model_view.h"
#include "scene/update_scheduler.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoInteraction.h>
#include <Inventor/SoPath.h>
#include <Inventor/SoPickedPoint.h>
#include <Inventor/actions/SoRayPickAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/draggers/SoJackDragger.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoOrthographicCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <limits>
#include <string>

namespace sculptline::scene {
namespace {

using model::EntityKind;

/// Given a plane far off the z axis carrying a curve, a world-space curve along x through the
/// origin and a flat surface off to the side, drawn by a ModelView with the plane draggers beside it.
class EntityPath : public testing::Test {
protected:
    // Before any fixture exists: its members are Coin nodes and draggers (node kits). Idempotent.
    static void SetUpTestSuite() { SoInteraction::init(); }

    void SetUp() override
    {
        plane_ = model_.addPlane(model::PlaneFrame::fromNormal(Eigen::Vector3d(0, 200, 0), Eigen::Vector3d(0, -1, 0), 120));
        const solvers::Curve3d line(1, {0, 0, 1, 1}, {Eigen::Vector3d(-30, 0, 0), Eigen::Vector3d(30, 0, 0)});
        planeCurve_ = model_.addCurve(plane_, line);
        worldCurve_ = model_.addCurve(0, line);
        const solvers::Surface3d patch(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2,
                                       {Eigen::Vector3d(500, 0, 0), Eigen::Vector3d(500, 50, 0),
                                        Eigen::Vector3d(550, 0, 0), Eigen::Vector3d(550, 50, 0)});
        surface_ = model_.addSurface(patch);
        root_ = new SoSeparator;
        root_->ref();
        camera_ = new SoOrthographicCamera;
        camera_->position.setValue(0, 0, 100);  // looking down -z at the world curve
        camera_->height = 100;
        camera_->nearDistance = 1;
        camera_->farDistance = 1000;
        root_->addChild(camera_);
        root_->addChild(view_.root());
        root_->addChild(draggers_.root());
    }
    void TearDown() override { root_->unref(); }

    /// The first path from the scene root to a node of `type`, under the node named `under` if given.
    SoPath* find(SoType type, const char* under = nullptr)
    {
        search_.reset();
        search_.setType(type);
        search_.setInterest(SoSearchAction::ALL);
        search_.apply(root_);
        for (int i = 0; i < search_.getPaths().getLength(); ++i) {
            SoPath* path = search_.getPaths()[i];
            if (!under) return path;
            for (int k = 0; k < path->getLength(); ++k) {
                if (std::string(path->getNode(k)->getName().getString()) == under) return path;
            }
        }
        return nullptr;
    }

    model::Model model_;
    ModelView view_{model_};
    UpdateScheduler scheduler_{model_};
    manipulators::PlaneDraggers draggers_{model_, scheduler_};
    model::EntityId plane_ = 0, planeCurve_ = 0, worldCurve_ = 0, surface_ = 0;
    SoSeparator* root_ = nullptr;
    SoOrthographicCamera* camera_ = nullptr;
    SoSearchAction search_;
};

TEST(EntityNodeName, NamesAreTheKindFollowedByTheId)
{
    EXPECT_EQ(entityNodeName(EntityKind::Plane, 3), "Plane3");
    EXPECT_EQ(entityNodeName(EntityKind::Curve, 17), "Curve17");
    EXPECT_EQ(entityNodeName(EntityKind::Surface, 9), "Surface9");
    EXPECT_EQ(entityNodeName(EntityKind::Mesh, 4), "Mesh4");
    EXPECT_EQ(entityNodeName(EntityKind::Point, 5), "Point5");
    // A pin's marker is a constraint's, numbered apart from entities: it names no entity
    EXPECT_EQ(constraintNodeName(5), "Constraint5");
    EXPECT_FALSE(entityOfName(constraintNodeName(5)).has_value());
}

TEST(EntityNodeName, ParsingInvertsNaming)
{
    for (const EntityKind kind : {EntityKind::Plane, EntityKind::Curve, EntityKind::Surface, EntityKind::Mesh, EntityKind::Point,
                                  EntityKind::Solid}) {
        const model::EntityId id = std::numeric_limits<model::EntityId>::max();
        const auto ref = entityOfName(entityNodeName(kind, id));
        ASSERT_TRUE(ref.has_value()) << entityNodeName(kind, id);
        EXPECT_EQ(ref->id, id);
        EXPECT_EQ(ref->kind, kind);
    }
}

TEST(EntityNodeName, GroupsAndOtherNamesNameNoEntity)
{
    for (const char* name : {"", "Curves", "Surfaces", "PlaneCurves", "Planes", "Plane3Curves", "PlaneGeometry",
                             "ProjectionPlane", "ControlPolygon", "Curve", "Curve0", "Curve-1", "Curve+1", "Curve 1",
                             "curve1", "Curve1x", "Curve4294967296", "Curve99999999999999999999", "Model"}) {
        EXPECT_FALSE(entityOfName(name).has_value()) << '"' << name << '"';
    }
}

TEST_F(EntityPath, APathToACurveOnAPlaneIsTheCurve)
{
    // The curve's line set lies under "PlaneCurves" > "Plane1Curves" > "Curve2"
    SoPath* path = find(SoLineSet::getClassTypeId(), entityNodeName(EntityKind::Curve, planeCurve_).c_str());
    ASSERT_NE(path, nullptr);
    const auto ref = entityAt(path);
    ASSERT_TRUE(ref.has_value());
    EXPECT_EQ(ref->id, planeCurve_);
    EXPECT_EQ(ref->kind, EntityKind::Curve);
    // Asked for planes only, the curve's path leads to none (its plane's group is not the plane)
    EXPECT_FALSE(entityAt(path, {EntityKind::Plane}).has_value());
}

TEST_F(EntityPath, APathToASurfaceIsTheSurface)
{
    SoPath* path = find(SoIndexedFaceSet::getClassTypeId(), entityNodeName(EntityKind::Surface, surface_).c_str());
    ASSERT_NE(path, nullptr);
    const auto ref = entityAt(path);
    ASSERT_TRUE(ref.has_value());
    EXPECT_EQ(ref->id, surface_);
    EXPECT_EQ(ref->kind, EntityKind::Surface);
    EXPECT_FALSE(entityAt(path, {EntityKind::Curve}).has_value());
}

TEST_F(EntityPath, APathIntoAPlanesDraggerIsThePlane)
{
    SoPath* path = find(SoJackDragger::getClassTypeId());
    ASSERT_NE(path, nullptr);
    const auto ref = entityAt(path, {EntityKind::Curve, EntityKind::Plane, EntityKind::Surface});
    ASSERT_TRUE(ref.has_value());
    EXPECT_EQ(ref->id, plane_);
    EXPECT_EQ(ref->kind, EntityKind::Plane);
}

TEST_F(EntityPath, PathsToGroupsAndOtherNodesLeadToNoEntity)
{
    EXPECT_FALSE(entityAt(nullptr).has_value());
    EXPECT_FALSE(entityAt(find(SoOrthographicCamera::getClassTypeId())).has_value());
    // The plane's curve group holds its transform: a path to that names no entity
    search_.reset();
    search_.setName(SbName((entityNodeName(EntityKind::Plane, plane_) + "Curves").c_str()));
    search_.apply(root_);
    ASSERT_NE(search_.getPath(), nullptr);
    EXPECT_FALSE(entityAt(search_.getPath()).has_value());
    for (const char* group : {"Curves", "Surfaces", "Planes", "Model"}) {
        search_.reset();
        search_.setName(group);
        search_.apply(root_);
        ASSERT_NE(search_.getPath(), nullptr) << group;
        EXPECT_FALSE(entityAt(search_.getPath()).has_value()) << group;
    }
}

TEST_F(EntityPath, ARayPickOnACurveIsTheCurve)
{
    // When the view's centre is picked (the world curve runs through it along x)
    const SbViewportRegion viewport(200, 200);
    SoRayPickAction pick(viewport);
    pick.setPoint(SbVec2s(100, 100));
    pick.setRadius(4);
    pick.apply(root_);
    // Then the picked path leads to that curve
    const SoPickedPoint* point = pick.getPickedPoint();
    ASSERT_NE(point, nullptr);
    const auto ref = entityAt(point->getPath());
    ASSERT_TRUE(ref.has_value());
    EXPECT_EQ(ref->id, worldCurve_);
    EXPECT_EQ(ref->kind, EntityKind::Curve);
}

TEST_F(EntityPath, ARayPickOnEmptySpaceIsNoEntity)
{
    const SbViewportRegion viewport(200, 200);
    SoRayPickAction pick(viewport);
    pick.setPoint(SbVec2s(100, 20));  // 40 model units below the world curve: nothing there
    pick.setRadius(4);
    pick.apply(root_);
    const SoPickedPoint* point = pick.getPickedPoint();
    EXPECT_FALSE(point && entityAt(point->getPath()).has_value());
}

}  // namespace
}  // namespace sculptline::scene
