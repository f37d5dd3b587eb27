// A sculpt's bound and blocked control points in the model view (scene/model_view.h): the bound
// polygon of the base's domain drawn on the sculpted surface, the blocked points at their control
// points, both following the recipe (undo, redo) and unpickable; nothing for a sculpt without them.
#include "model/model.h"
#include "scene/eigen_coin.h"
#include "scene/model_view.h"
#include "tests/model/sculpt_scene.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

namespace sculptline::scene {
namespace {

/// The coordinates under the node named `name` below `root`, or null.
SoCoordinate3* coordinatesUnder(SoNode* root, const char* name)
{
    SoSearchAction byName;
    byName.setName(SbName(name));
    byName.apply(root);
    if (!byName.getPath()) return nullptr;
    SoSearchAction coords;
    coords.setType(SoCoordinate3::getClassTypeId());
    coords.apply(byName.getPath()->getTail());
    return coords.getPath() ? static_cast<SoCoordinate3*>(coords.getPath()->getTail()) : nullptr;
}

TEST(SculptMarks, TheBoundIsDrawnOnTheSculptAndBlockedPointsAtTheirControlPoints)
{
    SoDB::init();
    model::Model model;
    const model::EntityId base = model.addSurface(model::flatSheet());
    const model::EntityId point = model.addPoint(model::flatSheet().evaluate(2, 2));
    model::SurfaceRecipe recipe;
    recipe.mode = model::Construction::Sculpt;
    recipe.handles = {{point, Eigen::Vector2d(2, 2), true}};
    const model::EntityId sculpt = model.addSurface({base, point}, recipe);
    ModelView view(model);
    SoNode* node = view.nodeOf(sculpt);
    ASSERT_NE(node, nullptr);
    // No bound, nothing blocked: no marks
    EXPECT_EQ(coordinatesUnder(node, "SculptBound"), nullptr);
    EXPECT_EQ(coordinatesUnder(node, "SculptBlocked"), nullptr);

    // When a square bound round the middle and control point (1, 5) blocked are set, the point pulled up
    recipe.bound = {{1, 1}, {3, 1}, {3, 3}, {1, 3}};
    recipe.blocked = {{1, 5}};
    model.setSurfaceRecipe(sculpt, recipe);
    model.setPointPose(point, Eigen::Vector3d(0, 0, 12), Eigen::Quaterniond::Identity());
    model.update();
    node = view.nodeOf(sculpt);
    const solvers::Surface3d& s = *model.find(sculpt)->surface;
    // Then the bound is a closed polyline drawn twice, lifted off the surface to both sides by 0.4 % of its extent
    SoCoordinate3* bound = coordinatesUnder(node, "SculptBound");
    ASSERT_NE(bound, nullptr);
    const int n = bound->point.getNum();
    ASSERT_EQ(n, 2 * (4 * 4 + 1));
    Eigen::AlignedBox3d box;
    for (const Eigen::Vector3d& p : s.points()) box.extend(p);
    const double lift = 0.004 * box.diagonal().norm();
    const SbVec3f corner = bound->point[0];
    const Eigen::Vector3d onSurface = s.evaluate(1, 1);
    EXPECT_NEAR((toEigen(corner) - onSurface).norm(), lift, 1e-3 * lift + 1e-4);
    EXPECT_EQ(bound->point[0], bound->point[n / 2 - 1]);  // closed
    // And the blocked point sits at control point (1, 5), lifted likewise
    SoCoordinate3* blocked = coordinatesUnder(node, "SculptBlocked");
    ASSERT_NE(blocked, nullptr);
    ASSERT_EQ(blocked->point.getNum(), 2);
    EXPECT_NEAR((toEigen(blocked->point[0]) - s.point(1, 5)).norm(), lift, 1e-3 * lift + 1e-4);
    EXPECT_EQ(s.point(1, 5), model.find(base)->surface->point(1, 5));

    // When the recipe loses them again (an undo), the marks go
    recipe.bound.clear();
    recipe.blocked.clear();
    model.setSurfaceRecipe(sculpt, recipe);
    model.update();
    EXPECT_EQ(coordinatesUnder(view.nodeOf(sculpt), "SculptBound"), nullptr);
    EXPECT_EQ(coordinatesUnder(view.nodeOf(sculpt), "SculptBlocked"), nullptr);
}

}  // namespace
}  // namespace sculptline::scene
