// Sculpt handles' jacks (manipulators/point_handles.h) driven by simulated mouse events through
// Coin's event path: one jack per Point entity, a press-drag-release on the jack moves the point in
// the model with one factorization for the whole drag, the sculpt follows, and the finished callback
// reports the poses for the undo step; a pose set by the model (undo) puts the jack there.
#include "manipulators/point_handles.h"

#include "model/model.h"
#include "scene/update_scheduler.h"
#include "tests/gui/coin_mouse.h"
#include "tests/model/sculpt_scene.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoInteraction.h>

#include <gtest/gtest.h>

namespace sculptline::manipulators {
namespace {

TEST(PointHandles, DraggingAJackMovesThePointAndTheSculptWithOneFactorization)
{
    SoDB::init();
    SoInteraction::init();
    model::Model model;
    const model::EntityId base = model.addSurface(model::flatSheet());
    const Eigen::Vector3d centre = model::flatSheet().evaluate(2, 2);
    const model::EntityId point = model.addPoint(centre);
    model::SurfaceRecipe recipe;
    recipe.mode = model::Construction::Sculpt;
    recipe.handles = {{point, Eigen::Vector2d(2, 2), true}};
    const model::EntityId sculpt = model.addSurface({base, point}, recipe);
    model.update();
    scene::UpdateScheduler scheduler(model);
    PointHandles handles(model, scheduler);
    ASSERT_EQ(handles.size(), 1u);
    ASSERT_NE(handles.handle(point), nullptr);
    // Small beside the sheet (0.04 of its diagonal per jack unit, the jack spans 3 units)
    EXPECT_LT(handles.handle(point)->size(), 0.05 * 120.0 * std::sqrt(2.0));
    model::EntityId started = 0;
    PointPose before, after;
    int finished = 0;
    handles.setDragCallbacks([&](model::EntityId id) { started = id; },
                             [&](model::EntityId, const PointPose& b, const PointPose& a) {
                                 before = b;
                                 after = a;
                                 ++finished;
                             });

    // When the jack's centre is pressed, dragged across the view and released (the view looks down -z)
    guitest::CoinMouse mouse({handles.root()});
    const int factorizations = model.factorizations();
    const SbVec2s at = mouse.pixelOf(centre);
    mouse.press(at);
    EXPECT_EQ(started, point);
    EXPECT_EQ(handles.dragging(), point);
    for (int k = 1; k <= 10; ++k) {
        mouse.move(SbVec2s(static_cast<short>(at[0] + 4 * k), static_cast<short>(at[1] + 2 * k)));
        scheduler.flush();
        // Then the sculpt follows at every event, through the point
        const model::Entity& p = *model.find(point);
        EXPECT_LT((model.find(sculpt)->surface->evaluate(2, 2) - p.position).norm(), 1e-9) << k;
    }
    mouse.release(SbVec2s(static_cast<short>(at[0] + 40), static_cast<short>(at[1] + 20)));
    // And the drag factored its sculpt once (at the press)
    EXPECT_EQ(model.factorizations(), factorizations + 1);
    EXPECT_EQ(handles.dragging(), 0u);
    ASSERT_EQ(finished, 1);
    EXPECT_EQ(before.position, centre);
    EXPECT_GT((after.position - centre).norm(), 1.0);
    EXPECT_EQ(after.position, model.find(point)->position);
    EXPECT_LT((model.find(sculpt)->surface->evaluate(2, 2) - after.position).norm(), 1e-9);

    // When the model puts the point back (an undo), the jack goes there without writing the model
    model.setPointPose(point, before.position, before.rotation);
    scheduler.flush();
    EXPECT_LT((handles.handle(point)->pose().position - centre).norm(), 1e-4);  // the jack's fields are floats
    EXPECT_EQ(model.find(point)->position, centre);
    EXPECT_LT((model.find(sculpt)->surface->evaluate(2, 2) - centre).norm(), 1e-9);

    // A removed point takes its jack with it
    model.remove(sculpt);
    model.remove(point);
    EXPECT_EQ(handles.size(), 0u);
}

}  // namespace
}  // namespace sculptline::manipulators
