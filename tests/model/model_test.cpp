// The model's incremental updates (model/model.h) without a window: curves stored on their
// plane move rigidly with it, and only the dependents of what changed are recomputed, once each.
#include "model/model.h"
#include "model/model_document.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace sculptline::scene {
namespace {

constexpr double kTolerance = 1e-12;

solvers::Curve3d localCurve(double shift)
{
    return solvers::Curve3d(3, {0, 0, 0, 0, 1, 1, 1, 1},
                            {Eigen::Vector3d(-40 + shift, 0, 0), Eigen::Vector3d(-10, 30, 0), Eigen::Vector3d(10, -30, 0),
                             Eigen::Vector3d(40, shift, 0)});
}

model::PlaneFrame turnedFrame()
{
    model::PlaneFrame f;
    f.origin = Eigen::Vector3d(10, 20, 30);
    f.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
    f.size = 120;
    return f;
}

struct Counting : model::ModelObserver {
    std::vector<model::EntityId> updated;
    void entityAdded(const model::Entity&) override {}
    void entityRemoved(const model::Entity&) override {}
    void entityUpdated(const model::Entity& e) override { updated.push_back(e.id); }
};

TEST(Model, CurveMovesRigidlyWithItsPlane)
{
    // Given a curve on a plane
    model::Model model;
    const model::EntityId plane = model.addPlane(model::PlaneFrame{});
    const model::EntityId curve = model.addCurve(plane, localCurve(0));
    // When the plane moves and turns
    const model::PlaneFrame moved = turnedFrame();
    model.setPlaneFrame(plane, moved);
    model.update();
    // Then the world curve is the local curve carried by the new frame, point for point
    const model::Entity* c = model.find(curve);
    ASSERT_TRUE(c->world);
    for (double u : {0.0, 0.25, 0.5, 1.0}) {
        const Eigen::Vector3d expected = moved.toWorld(c->local->evaluate(u));
        EXPECT_LT((c->world->evaluate(u) - expected).norm(), kTolerance) << u;
    }
    // And the local curve (the fitted shape) is untouched
    EXPECT_EQ(c->local->points(), localCurve(0).points());
}

TEST(Model, OnlyDependentsAreRecomputedOncePerUpdate)
{
    // Given two planes with 3 and 2 curves and a world curve
    model::Model model;
    Counting counter;
    model.addObserver(&counter);
    const model::EntityId a = model.addPlane(model::PlaneFrame{});
    const model::EntityId b = model.addPlane(turnedFrame());
    std::vector<model::EntityId> onA, onB;
    for (int i = 0; i < 3; ++i) onA.push_back(model.addCurve(a, localCurve(i)));
    for (int i = 0; i < 2; ++i) onB.push_back(model.addCurve(b, localCurve(i)));
    const model::EntityId free = model.addCurve(0, localCurve(5));
    int dirtyCalls = 0;
    model.setDirtyCallback([&dirtyCalls]() { ++dirtyCalls; });

    // When plane A moves three times (a flood of dragger events) before one update
    for (int step = 1; step <= 3; ++step) {
        model::PlaneFrame f;
        f.origin = Eigen::Vector3d(0, 0, step);
        model.setPlaneFrame(a, f);
    }
    const int recomputed = model.update();

    // Then the scheduler was asked once, and A and its three curves were recomputed once each,
    // plane first; B, its curves and the world curve were not touched
    EXPECT_EQ(dirtyCalls, 1);
    EXPECT_EQ(recomputed, 4);
    EXPECT_EQ(counter.updated, (std::vector<model::EntityId>{a, onA[0], onA[1], onA[2]}));
    for (model::EntityId id : onA) EXPECT_EQ(model.find(id)->recomputations, 1);
    for (model::EntityId id : onB) EXPECT_EQ(model.find(id)->recomputations, 0);
    EXPECT_EQ(model.find(b)->recomputations, 0);
    EXPECT_EQ(model.find(free)->recomputations, 0);
    EXPECT_EQ(model.update(), 0);  // nothing left to do
}

TEST(Model, RemovingAPlaneRemovesItsCurvesAndUndoRestoresThemUnderTheirIds)
{
    model::Model model;
    const model::EntityId plane = model.addPlane(turnedFrame());
    const model::EntityId curve = model.addCurve(plane, localCurve(1));
    // When the plane is removed
    const std::vector<model::Entity> removed = model.remove(plane).entities;
    // Then its curve went with it, plane first in the returned list (the order to restore them)
    ASSERT_EQ(removed.size(), 2u);
    EXPECT_EQ(removed[0].id, plane);
    EXPECT_EQ(removed[1].id, curve);
    EXPECT_TRUE(model.entities().empty());
    // And restoring them under their ids gives the same world curve
    model.addPlane(removed[0].frame, removed[0].id);
    model.addCurve(plane, *removed[1].local, removed[1].id);
    EXPECT_LT((model.find(curve)->world->evaluate(0.5) - removed[1].world->evaluate(0.5)).norm(), kTolerance);
    EXPECT_THROW(model.addCurve(curve, localCurve(0)), std::invalid_argument);  // a curve is no plane
}

TEST(ModelDocument, SaveAndReopenRestoresTheModelExactly)
{
    // Given a model with a turned plane, a curve on it and a world curve
    model::Model model;
    const model::EntityId plane = model.addPlane(turnedFrame());
    model.addCurve(plane, localCurve(0.123456789));
    model.addCurve(0, solvers::Curve3d(2, {0, 0, 0, 1, 1, 1}, {Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, 5, 6.5), Eigen::Vector3d(7, 8, 9)}));
    model.update();
    // When it is written and read back
    const std::string text = model::modelToJson(model, model::GridSpec{}).dump();
    model::Model reopened;
    model::populateModel(model::documentFromJson(nlohmann::json::parse(text)), reopened);
    // Then the same entities come back with the same ids, frames and control points
    ASSERT_EQ(reopened.entities().size(), model.entities().size());
    for (const auto& [id, e] : model.entities()) {
        const model::Entity* r = reopened.find(id);
        ASSERT_NE(r, nullptr) << id;
        EXPECT_EQ(r->kind, e.kind);
        EXPECT_EQ(r->plane(), e.plane());
        if (e.kind == model::EntityKind::Plane) {
            EXPECT_LT((r->frame.origin - e.frame.origin).norm(), kTolerance);
            EXPECT_LT(r->frame.rotation.angularDistance(e.frame.rotation), 1e-9);
        } else {
            EXPECT_EQ(r->local->points(), e.local->points());
            EXPECT_EQ(r->local->knots(), e.local->knots());
            for (size_t k = 0; k < e.world->points().size(); ++k) EXPECT_LT((r->world->points()[k] - e.world->points()[k]).norm(), 1e-9);
        }
    }
}

TEST(ModelDocument, ACurveNamingAMissingPlaneIsRefused)
{
    const auto doc = nlohmann::json::parse(R"({"planes": [{"origin": [0,0,0], "normal": [0,0,1], "size": 10}],
        "curves": [{"degree": 1, "knots": [0,0,1,1], "points": [[0,0],[1,1]], "plane": 7}]})");
    try {
        model::documentFromJson(doc);
        FAIL() << "accepted";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("curves[0].plane: no plane has id 7"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace sculptline::scene
