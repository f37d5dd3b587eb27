// Surfaces as model entities (issue 6 §2): a surface built from curves by a recipe is rebuilt when
// one of its curves changes (a plane drag, a new shape), only the affected surfaces are rebuilt,
// once per update, a build that fails mid-drag keeps the last good surface, and documents save
// the construction so reopening rebuilds the same surface. Headless (Coin nodes, no window).
#include "model/model.h"
#include "model/model_document.h"
#include "scene/model_view.h"
#include "model/document.h"
#include "solvers/bspline/projection.h"
#include "tests/common/surface_test_support.h"

#include "scene/eigen_coin.h"
#include "solvers/bspline/tessellation.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoPath.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoNormal.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace sculptline::scene {
namespace {

/// Round-off of the transforms and builds involved, far below any visible distance (mm).
constexpr double kTolerance = 1e-9;

solvers::Curve3d cubic(std::initializer_list<Eigen::Vector3d> points)
{
    return solvers::Curve3d(3, {0, 0, 0, 0, 1, 1, 1, 1}, std::vector<Eigen::Vector3d>(points));
}

/// A vertical plane (local x = world X, local y = world Z) through `origin`.
model::PlaneFrame verticalFrame(const Eigen::Vector3d& origin)
{
    return model::PlaneFrame::fromNormal(origin, -Eigen::Vector3d::UnitY(), 200.0, Eigen::Vector3d::UnitX());
}

struct Scene {
    model::Model model;
    model::EntityId plane = 0, profile = 0, axis = 0, outlineA = 0, outlineB = 0, revolved = 0, rotated = 0;

    Scene()
    {
        plane = model.addPlane(verticalFrame(Eigen::Vector3d(0, 0, 50)));
        profile = model.addCurve(plane, cubic({{20, -40, 0}, {35, -10, 0}, {10, 10, 0}, {12, 40, 0}}));
        axis = model.addCurve(plane, cubic({{0, -45, 0}, {0, -15, 0}, {0, 15, 0}, {0, 45, 0}}));
        const model::EntityId other = model.addPlane(verticalFrame(Eigen::Vector3d(0, 80, 50)));
        outlineA = model.addCurve(other, cubic({{-40, 0, 0}, {-20, 25, 0}, {20, 25, 0}, {40, 0, 0}}));
        outlineB = model.addCurve(other, cubic({{-40, -3, 0}, {-20, -25, 0}, {20, -25, 0}, {40, -3, 0}}));
        model::SurfaceRecipe revolve;
        revolve.mode = model::Construction::Revolve;
        revolved = model.addSurface({profile, axis}, revolve);
        model::SurfaceRecipe rotation;
        rotation.mode = model::Construction::BoundaryRotation;
        rotated = model.addSurface({outlineA, outlineB}, rotation);
    }
};

using guitest::curveToSurface;

TEST(SurfaceEntity, ARevolvedSurfaceFollowsItsPlaneAndOnlyItIsRebuilt)
{
    // Given a revolve surface on plane 1's curves and a boundary rotation on plane 2's
    Scene s;
    const int rotatedBuilds = s.model.find(s.rotated)->shapeVersion;
    // When plane 1 moves and turns
    model::PlaneFrame moved = verticalFrame(Eigen::Vector3d(30, -20, 70));
    moved.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ())) * moved.rotation;
    s.model.setPlaneFrame(s.plane, moved);
    s.model.update();
    // Then the revolved surface was rebuilt once and still contains its (moved) profile
    const model::Entity* revolved = s.model.find(s.revolved);
    EXPECT_EQ(revolved->recomputations, 1);
    EXPECT_TRUE(revolved->buildError.empty());
    EXPECT_LT(curveToSurface(*s.model.find(s.profile)->world, *revolved->surface), kTolerance);
    // And its axis is the moved axis line: the surface's points keep their distance from it
    const solvers::Curve3d& axis = *s.model.find(s.axis)->world;
    const Eigen::Vector3d a0 = axis.evaluate(0.0), dir = (axis.evaluate(1.0) - a0).normalized();
    const auto distanceFromAxis = [&](const Eigen::Vector3d& x) { return (x - a0 - (x - a0).dot(dir) * dir).norm(); };
    const solvers::Curve3d& profile = *s.model.find(s.profile)->world;
    for (double v : {0.1, 0.37, 0.8}) {
        EXPECT_NEAR(distanceFromAxis(revolved->surface->evaluate(0.5, v)), distanceFromAxis(profile.evaluate(0.5)), kTolerance);
    }
    // And the surface on the other plane was not touched
    EXPECT_EQ(s.model.find(s.rotated)->recomputations, 0);
    EXPECT_EQ(s.model.find(s.rotated)->shapeVersion, rotatedBuilds);
}

TEST(SurfaceEntity, TheViewRedrawsALiveRebuildOnItsLastGridAndAdaptsItWhenAsked)
{
    // Given the two surfaces drawn by the Coin view
    SoDB::init();
    Scene s;
    ModelView view(s.model);
    const int builds = view.nodeBuilds();
    // When plane 1 moves (a drag event): only the revolve is redrawn, on its last adaptive grid,
    // in place (its knots did not change: no node is built)
    s.model.setPlaneFrame(s.plane, verticalFrame(Eigen::Vector3d(5, 0, 60)));
    s.model.update();
    EXPECT_EQ(view.nodeBuilds(), builds);
    EXPECT_EQ(view.gridReuses(), 1);
    EXPECT_EQ(view.inPlaceUpdates(), 1);
    // Then, when the drag ends, that one surface is tessellated adaptively again, and only once
    EXPECT_EQ(view.refineSurfaces(), 1);
    EXPECT_EQ(view.refineSurfaces(), 0);
    EXPECT_EQ(view.gridReuses(), 1);
}

/// The vertices and normals of the surface node of `id`.
std::pair<std::vector<SbVec3f>, std::vector<SbVec3f>> drawnMesh(const ModelView& view, model::EntityId id)
{
    SoSearchAction search;
    search.setType(SoCoordinate3::getClassTypeId());
    search.apply(view.nodeOf(id));
    const auto* coords = static_cast<SoCoordinate3*>(search.getPath()->getTail());
    search.reset();
    search.setType(SoNormal::getClassTypeId());
    search.apply(view.nodeOf(id));
    const auto* normals = static_cast<SoNormal*>(search.getPath()->getTail());
    return {std::vector<SbVec3f>(coords->point.getValues(0), coords->point.getValues(0) + coords->point.getNum()),
            std::vector<SbVec3f>(normals->vector.getValues(0), normals->vector.getValues(0) + normals->vector.getNum())};
}

std::pair<std::vector<SbVec3f>, std::vector<SbVec3f>> asDrawn(const solvers::GridMesh& mesh)
{
    std::pair<std::vector<SbVec3f>, std::vector<SbVec3f>> out;
    for (const Eigen::Vector3d& p : mesh.vertices) out.first.push_back(toSb(p));
    for (const Eigen::Vector3d& n : mesh.normals) out.second.push_back(toSb(n));
    return out;
}

TEST(SurfaceEntity, AnInPlaceRedrawIsTheMeshOnTheKeptGridAndTheRestingMeshIsAFreshOne)
{
    // Given the revolve drawn on its adaptive grid
    SoDB::init();
    Scene s;
    ModelView view(s.model);
    const solvers::GridMesh before = solvers::tessellate(*s.model.find(s.revolved)->surface);
    SoSeparator* node = view.nodeOf(s.revolved);
    EXPECT_EQ(drawnMesh(view, s.revolved), asDrawn(before));
    // When plane 1 moves twice (two drag events)
    for (double x : {5.0, 12.0}) {
        s.model.setPlaneFrame(s.plane, verticalFrame(Eigen::Vector3d(x, 0, 60)));
        s.model.update();
        // Then the same node shows exactly the moved surface's mesh on the kept grid
        EXPECT_EQ(view.nodeOf(s.revolved), node);
        const solvers::GridMesh kept = solvers::meshOnGrid(*s.model.find(s.revolved)->surface, before.u, before.v);
        EXPECT_EQ(drawnMesh(view, s.revolved), asDrawn(kept));
        // and its bounding box (the live face set's own) is the one of a plain node of that mesh
        SoSeparator* plain = makeSurfaceNode(*s.model.find(s.revolved)->surface, kept);
        plain->ref();
        SoGetBoundingBoxAction live(SbViewportRegion(100, 100)), reference(SbViewportRegion(100, 100));
        live.apply(node);
        reference.apply(plain);
        EXPECT_EQ(live.getBoundingBox().getMin(), reference.getBoundingBox().getMin());
        EXPECT_EQ(live.getBoundingBox().getMax(), reference.getBoundingBox().getMax());
        plain->unref();
    }
    EXPECT_EQ(view.inPlaceUpdates(), 2);
    // And once adapted again (the drag's end) the mesh is the one a fresh build draws
    EXPECT_EQ(view.refineSurfaces(), 1);
    EXPECT_EQ(drawnMesh(view, s.revolved), asDrawn(solvers::tessellate(*s.model.find(s.revolved)->surface)));
    ModelView fresh(s.model);
    EXPECT_EQ(drawnMesh(view, s.revolved), drawnMesh(fresh, s.revolved));
}

TEST(SurfaceEntity, ANewCurveShapeRebuildsItsSurfacesOnce)
{
    // Given the two surfaces
    Scene s;
    // When one outline is redrawn
    s.model.setCurveShape(s.outlineA, cubic({{-40, 0, 0}, {-20, 35, 0}, {20, 35, 0}, {40, 0, 0}}));
    const int recomputed = s.model.update();
    // Then the curve and its one surface were recomputed, once each, and the surface meets the
    // new outline within the deviation it reports
    EXPECT_EQ(recomputed, 2);
    const model::Entity* rotated = s.model.find(s.rotated);
    EXPECT_EQ(rotated->recomputations, 1);
    ASSERT_GE(rotated->maxDeviation, 0.0);
    EXPECT_LT(curveToSurface(*s.model.find(s.outlineA)->world, *rotated->surface), rotated->maxDeviation + kTolerance);
    EXPECT_EQ(s.model.find(s.revolved)->recomputations, 0);
}

TEST(SurfaceEntity, AFailedRebuildKeepsTheLastSurfaceAndSaysWhy)
{
    // Given a revolve about an axis line
    Scene s;
    const solvers::Surface3d before = *s.model.find(s.revolved)->surface;
    // When the axis collapses to a point (no direction), then comes back
    s.model.setCurveShape(s.axis, cubic({{0, 5, 0}, {0, 5, 0}, {0, 5, 0}, {0, 5, 0}}));
    s.model.update();
    // Then the surface is the last good one, with the reason
    const model::Entity* revolved = s.model.find(s.revolved);
    EXPECT_FALSE(revolved->buildError.empty());
    EXPECT_EQ(revolved->surface->points(), before.points());
    s.model.setCurveShape(s.axis, cubic({{0, -45, 0}, {0, -15, 0}, {0, 15, 0}, {0, 45, 0}}));
    s.model.update();
    EXPECT_TRUE(s.model.find(s.revolved)->buildError.empty());
}

TEST(SurfaceEntity, ImpossibleInputIsRefusedWithAMessageAndAddsNothing)
{
    Scene s;
    const size_t count = s.model.entities().size();
    model::SurfaceRecipe fill;
    fill.mode = model::Construction::Fill;
    // Two curves whose ends are far apart do not bound a surface
    EXPECT_THROW(s.model.addSurface({s.profile, s.outlineA}, fill), std::invalid_argument);
    // A plane is not a curve, and revolve takes exactly a profile and an axis
    model::SurfaceRecipe revolve;
    revolve.mode = model::Construction::Revolve;
    EXPECT_THROW(s.model.addSurface({s.profile, s.plane}, revolve), std::invalid_argument);
    EXPECT_THROW(s.model.addSurface({s.profile}, revolve), std::invalid_argument);
    // An unknown mode name has no construction (documents refuse it, naming the field)
    EXPECT_FALSE(model::constructionFromName("teleport"));
    EXPECT_EQ(s.model.entities().size(), count);
}

TEST(SurfaceEntity, RemovingACurveTakesItsSurfacesAlong)
{
    Scene s;
    const std::vector<model::Entity> removed = s.model.remove(s.axis).entities;
    ASSERT_EQ(removed.size(), 2u);
    EXPECT_EQ(removed[1].id, s.revolved);
    EXPECT_EQ(s.model.find(s.revolved), nullptr);
    EXPECT_NE(s.model.find(s.rotated), nullptr);
}

TEST(SurfaceEntity, SavedConstructionsReopenToTheSameSurfaces)
{
    // Given the model with an extrusion too, saved
    Scene s;
    model::SurfaceRecipe extrude;
    extrude.mode = model::Construction::Extrude;
    extrude.direction = Eigen::Vector3d(0, 0, 25);  // along plane 1's normal
    const model::EntityId extruded = s.model.addSurface({s.profile}, extrude);
    const nlohmann::json saved = model::modelToJson(s.model, model::GridSpec{});
    // When it is read back into a new model
    model::Model reopened;
    model::populateModel(model::documentFromJson(saved), reopened);
    // Then every surface has its construction and the very same control points
    for (model::EntityId id : {s.revolved, s.rotated, extruded}) {
        const model::Entity* a = s.model.find(id);
        const model::Entity* b = reopened.find(id);
        ASSERT_NE(b, nullptr) << id;
        ASSERT_TRUE(b->recipe) << id;
        EXPECT_EQ(b->recipe->mode, a->recipe->mode);
        EXPECT_EQ(b->inputs, a->inputs);
        EXPECT_EQ(b->surface->points(), a->surface->points()) << id;
    }
    // And the extrusion is along the plane's normal, 25 mm
    const model::Entity* e = reopened.find(extruded);
    const Eigen::Vector3d normal = reopened.find(s.plane)->frame.normal();
    const solvers::Curve3d& profile = *reopened.find(s.profile)->world;
    // (S(u, v) = profile(u) + v·direction, solvers/surfaces/extrude.h)
    EXPECT_LT((e->surface->evaluate(0.3, 1.0) - (profile.evaluate(0.3) + 25.0 * normal)).norm(), kTolerance);
}

/// The one pin of `model` (a position or tangent constraint), or null.
const model::Constraint* onlyPin(const model::Model& model)
{
    const model::Constraint* pin = nullptr;
    for (const auto& [id, c] : model.constraints()) {
        if (c.type == model::ConstraintType::Position || c.type == model::ConstraintType::Tangent) pin = &c;
    }
    return pin;
}

TEST(ConstraintEntity, APinFollowsItsCurveAndIsSavedWithTheFixedPoints)
{
    // Given a pin on the profile and two fixed control points
    Scene s;
    const model::ConstraintId pin = s.model.addConstraint(s.profile, model::ConstraintType::Position, 0.25);
    s.model.setFixedPoints(s.profile, {3, 0, 3});
    EXPECT_EQ(s.model.fixedPoints(s.profile), (std::vector<int>{0, 3}));
    // When the plane moves
    s.model.setPlaneFrame(s.plane, verticalFrame(Eigen::Vector3d(10, 0, 90)));
    s.model.update();
    // Then the pin's value is the moved curve's point at its parameter
    const model::Constraint* p = s.model.findConstraint(pin);
    ASSERT_NE(p, nullptr);
    EXPECT_LT((p->value - s.model.find(s.profile)->world->evaluate(0.25)).norm(), kTolerance);
    // And a saved and reopened model has the pin and the fixed points
    model::Model reopened;
    model::populateModel(model::documentFromJson(model::modelToJson(s.model, model::GridSpec{})), reopened);
    const model::Constraint* again = onlyPin(reopened);
    ASSERT_NE(again, nullptr);
    EXPECT_EQ(again->type, model::ConstraintType::Position);
    EXPECT_EQ(again->targets, std::vector<model::EntityId>{s.profile});
    EXPECT_EQ(again->parameters, std::vector<double>{0.25});
    EXPECT_EQ(reopened.fixedPoints(s.profile), (std::vector<int>{0, 3}));
    // And removing the curve removes its pin and fixed points (and its surface), and gives them
    // back for an undo
    const model::Removed removed = s.model.remove(s.profile);
    EXPECT_EQ(s.model.findConstraint(pin), nullptr);
    EXPECT_EQ(removed.constraints.size(), 2u);
    s.model.restore(removed);
    ASSERT_NE(s.model.findConstraint(pin), nullptr);
    EXPECT_EQ(s.model.fixedPoints(s.profile), (std::vector<int>{0, 3}));
}

TEST(ConstraintEntity, BadConstraintsAreRefused)
{
    Scene s;
    EXPECT_THROW(s.model.addConstraint(s.plane, model::ConstraintType::Position, 0.5), std::invalid_argument);
    EXPECT_THROW(s.model.addConstraint(s.profile, model::ConstraintType::Normal, 0.5), std::invalid_argument);
    EXPECT_THROW(s.model.addConstraint(s.profile, model::ConstraintType::Position, std::nan("")), std::invalid_argument);
    EXPECT_THROW(s.model.setFixedPoints(s.profile, {4}), std::invalid_argument);
    const nlohmann::json doc = nlohmann::json::parse(R"({"constraints": [{"curve": 7, "type": "position", "u": 0.5}]})");
    EXPECT_THROW(model::documentFromJson(doc), std::exception);
}

/// Largest angle (degrees) between the normals of `a` and `b` (either orientation) at 21 points of
/// `curve`, which lies on both.
double normalAngleAlong(const solvers::Curve3d& curve, const solvers::Surface3d& a, const solvers::Surface3d& b)
{
    const solvers::SurfaceProjector pa(a), pb(b);
    double worst = 0.0;
    for (int k = 0; k <= 20; ++k) {
        const Eigen::Vector3d x = curve.evaluate(curve.domainStart() + (curve.domainEnd() - curve.domainStart()) * k / 20.0);
        const auto fa = pa.project(x), fb = pb.project(x);
        const double c = std::abs(a.normal(fa.u, fa.v).dot(b.normal(fb.u, fb.v)));
        worst = std::max(worst, std::acos(std::min(1.0, c)) * 180.0 / 3.14159265358979);
    }
    return worst;
}

TEST(SurfaceEntity, AFillTangentToALoftFollowsItAndIsSaved)
{
    // Given a cylinder-like loft through two quarter arcs (x = 0 and x = 10), and three more curves
    // that close a loop with the second arc, leaving its ends in the loft's tangent planes
    model::Model model;
    const auto arc = [](double x) { return cubic({{x, 20, 0}, {x, 20, 11}, {x, 11, 20}, {x, 0, 20}}); };
    const model::EntityId a = model.addCurve(0, arc(0)), b = model.addCurve(0, arc(10));
    model::SurfaceRecipe loft;
    loft.mode = model::Construction::Loft;
    const model::EntityId hull = model.addSurface({a, b}, loft);
    const model::EntityId c = model.addCurve(0, cubic({{10, 20, 0}, {17, 20, 0}, {23, 20, 0}, {30, 20, 0}}));
    const model::EntityId d = model.addCurve(0, cubic({{30, 20, 0}, {30, 13, 7}, {30, 7, 13}, {30, 0, 20}}));
    const model::EntityId e = model.addCurve(0, cubic({{30, 0, 20}, {23, 0, 20}, {17, 0, 20}, {10, 0, 20}}));
    // When one fill is G1 to the loft along the arc and another is not
    model::SurfaceRecipe plain;
    plain.mode = model::Construction::Fill;
    model::SurfaceRecipe g1 = plain;
    g1.tangents = {{0, hull}};
    const model::EntityId creased = model.addSurface({b, c, d, e}, plain);
    const model::EntityId smooth = model.addSurface({b, c, d, e}, g1);
    // Then only the G1 fill continues the loft's tangent plane (0.1 degree, coons_fill.h's default)
    const solvers::Curve3d& arcB = *model.find(b)->world;
    EXPECT_GT(normalAngleAlong(arcB, *model.find(hull)->surface, *model.find(creased)->surface), 1.0);
    EXPECT_LT(normalAngleAlong(arcB, *model.find(hull)->surface, *model.find(smooth)->surface), 0.15);
    EXPECT_LT(curveToSurface(arcB, *model.find(smooth)->surface), kTolerance);
    // And it depends on the loft: moving the first arc rebuilds the loft and then the fill, once
    EXPECT_EQ(model.find(smooth)->inputs.back(), hull);
    model.setCurveShape(a, arc(-10));
    model.update();
    EXPECT_EQ(model.find(smooth)->recomputations, 1);
    EXPECT_TRUE(model.find(smooth)->buildError.empty()) << model.find(smooth)->buildError;
    EXPECT_LT(normalAngleAlong(arcB, *model.find(hull)->surface, *model.find(smooth)->surface), 0.15);
    // And when the loft turns so that no G1 fill can exist (the other boundaries leave the arc's
    // ends outside its new tangent planes), the fill keeps its last surface and says why
    model.setCurveShape(a, cubic({{0, 30, 0}, {0, 30, 16}, {0, 16, 30}, {0, 0, 30}}));
    model.update();
    EXPECT_FALSE(model.find(smooth)->buildError.empty());
    // And a saved and reopened model rebuilds the same G1 fill
    model::Model reopened;
    model::populateModel(model::documentFromJson(model::modelToJson(model, model::GridSpec{})), reopened);
    ASSERT_NE(reopened.find(smooth), nullptr);
    ASSERT_EQ(reopened.find(smooth)->recipe->tangents.size(), 1u);
    EXPECT_EQ(reopened.find(smooth)->curveInputs(), (std::vector<model::EntityId>{b, c, d, e}));
    EXPECT_EQ(reopened.find(smooth)->surface->points(), model.find(smooth)->surface->points());
}

TEST(MeshEntity, ANetworkLoopIsMeshedFollowsItsPlaneAndIsSaved)
{
    // Given a closed loop of three curves on a plane (seed 004 §4's curve network)
    model::Model model;
    const model::EntityId plane = model.addPlane(verticalFrame(Eigen::Vector3d(0, 0, 50)));
    const model::EntityId c1 = model.addCurve(plane, cubic({{-30, -20, 0}, {-10, -25, 0}, {10, -25, 0}, {30, -20, 0}}));
    const model::EntityId c2 = model.addCurve(plane, cubic({{30, -20, 0}, {35, 0, 0}, {20, 20, 0}, {0, 30, 0}}));
    const model::EntityId c3 = model.addCurve(plane, cubic({{0, 30, 0}, {-20, 20, 0}, {-35, 0, 0}, {-30, -20, 0}}));
    // When it is meshed
    const model::EntityId mesh = model.addMesh({c1, c2, c3});
    const model::Entity* m = model.find(mesh);
    ASSERT_TRUE(m->mesh);
    EXPECT_GT(m->mesh->triangles.size(), 10u);
    // Then its boundary vertices lie on the curves, and it moves with the plane
    const auto onCurves = [&](const model::Model& md, model::EntityId id) {
        const model::Entity* e = md.find(id);
        double worst = 0.0;
        for (int i = 0; i < e->mesh->boundaryVertexCount; ++i) {
            double best = 1e300;
            for (model::EntityId c : e->inputs) best = std::min(best, solvers::projectToCurve(*md.find(c)->world, e->mesh->vertices[i]).distance);
            worst = std::max(worst, best);
        }
        return worst;
    };
    EXPECT_LT(onCurves(model, mesh), kTolerance);
    model.setPlaneFrame(plane, verticalFrame(Eigen::Vector3d(40, 10, 20)));
    model.update();
    EXPECT_EQ(model.find(mesh)->recomputations, 1);
    EXPECT_LT(onCurves(model, mesh), kTolerance);
    // And a saved and reopened model rebuilds the same mesh
    model::Model reopened;
    model::populateModel(model::documentFromJson(model::modelToJson(model, model::GridSpec{})), reopened);
    ASSERT_NE(reopened.find(mesh), nullptr);
    EXPECT_EQ(reopened.find(mesh)->mesh->vertices, model.find(mesh)->mesh->vertices);
    // And curves that make no loop are refused, adding nothing
    const size_t count = model.entities().size();
    EXPECT_THROW(model.addMesh({c1, c2}), std::invalid_argument);
    EXPECT_THROW(model.addMesh({plane}), std::invalid_argument);
    EXPECT_EQ(model.entities().size(), count);
}

TEST(SurfaceEntity, AGordonSurfaceInterpolatesBothFamiliesAndIsSaved)
{
    // Given two u-curves and two v-curves that cross (a grid-like network on a saddle)
    model::Model model;
    const model::EntityId u0 = model.addCurve(0, cubic({{0, 0, 0}, {10, 0, 5}, {20, 0, 5}, {30, 0, 0}}));
    const model::EntityId u1 = model.addCurve(0, cubic({{0, 30, 0}, {10, 30, 5}, {20, 30, 5}, {30, 30, 0}}));
    const model::EntityId v0 = model.addCurve(0, cubic({{0, 0, 0}, {0, 10, -5}, {0, 20, -5}, {0, 30, 0}}));
    const model::EntityId v1 = model.addCurve(0, cubic({{30, 0, 0}, {30, 10, -5}, {30, 20, -5}, {30, 30, 0}}));
    model::SurfaceRecipe recipe;
    recipe.mode = model::Construction::Gordon;
    recipe.uCurves = 2;
    // When the Gordon surface is built
    const model::EntityId g = model.addSurface({u0, u1, v0, v1}, recipe);
    // Then it meets all four curves (to the reported gap), and reopens the same
    const model::Entity* e = model.find(g);
    for (model::EntityId c : {u0, u1, v0, v1}) EXPECT_LT(curveToSurface(*model.find(c)->world, *e->surface), e->maxDeviation + kTolerance) << c;
    model::Model reopened;
    model::populateModel(model::documentFromJson(model::modelToJson(model, model::GridSpec{})), reopened);
    EXPECT_EQ(reopened.find(g)->recipe->uCurves, 2);
    EXPECT_EQ(reopened.find(g)->surface->points(), e->surface->points());
    // And one family of one curve is refused
    recipe.uCurves = 1;
    EXPECT_THROW(model.addSurface({u0, u1, v0, v1}, recipe), std::invalid_argument);
}

TEST(SurfaceDocument, AConstructionNamingAMissingCurveIsRefused)
{
    const nlohmann::json doc = nlohmann::json::parse(R"({"surfaces": [{"id": 5, "construction": {"mode": "loft", "curves": [1, 2]}}]})");
    try {
        model::documentFromJson(doc);
        FAIL() << "accepted";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("surfaces[0].construction.curves[0]"), std::string::npos) << e.what();
    }
}

TEST(SurfaceDocument, AnUnknownModeIsRefused)
{
    const nlohmann::json doc = nlohmann::json::parse(R"({"surfaces": [{"construction": {"mode": "melt", "curves": []}}]})");
    EXPECT_THROW(model::documentFromJson(doc), std::exception);
}

}  // namespace
}  // namespace sculptline::scene

namespace sculptline::scene {
namespace {

TEST(SurfaceEntity, ADragDrawsALargeSurfaceOnAThinnedGridThatKeepsItsKnotLinesAndRestsOnAFreshOne)
{
    // Given the 18 x 135 strip's sculpt (4), drawn at rest on its adaptive grid (61 x 529 points)
    SoDB::init();
    model::Model model;
    model::populateModel(model::loadDocument(SCULPTLINE_DATA_DIR "/models/sculpt_18x135.json"), model);
    ModelView view(model);
    const model::EntityId sculpt = 4, plane = 1;
    const solvers::GridMesh resting = solvers::tessellate(*model.find(sculpt)->surface);
    ASSERT_GT(resting.u.size() * resting.v.size(), 12000u);
    // When the target's plane is dragged (two events)
    model.beginDrag(plane);
    model::PlaneFrame frame = model.find(plane)->frame;
    for (int event = 0; event < 2; ++event) {
        frame.origin.x() += 5.0;
        model.setPlaneFrame(plane, frame);
        model.update();
    }
    // Then it is drawn on a grid of at most 12,000 points: the resting grid's knot lines and every
    // other line between them, the mesh of that grid exactly, redrawn in place at the second event
    const solvers::Surface3d& s = *model.find(sculpt)->surface;
    auto thin = [](const std::vector<double>& lines, const solvers::KnotVector& knots) {
        std::vector<double> out;
        int since = 0;
        for (size_t k = 0; k < lines.size(); ++k) {
            const bool knot = k == 0 || k + 1 == lines.size() || std::binary_search(knots.begin(), knots.end(), lines[k]);
            if (knot || ++since % 2 == 0) out.push_back(lines[k]);
            if (knot) since = 0;
        }
        return out;
    };
    const std::vector<double> u = thin(resting.u, s.knotsU()), v = thin(resting.v, s.knotsV());
    EXPECT_LE(u.size() * v.size(), 12000u);
    for (double knot : s.knotsU()) EXPECT_TRUE(std::binary_search(u.begin(), u.end(), knot)) << knot;
    for (double knot : s.knotsV()) EXPECT_TRUE(std::binary_search(v.begin(), v.end(), knot)) << knot;
    EXPECT_EQ(drawnMesh(view, sculpt), asDrawn(solvers::meshOnGrid(s, u, v)));
    EXPECT_EQ(view.inPlaceUpdates(), 1);
    // And at the release it rests on the adaptive grid a fresh view draws
    model.endDrag();
    model.update();
    view.refineSurfaces();
    ModelView fresh(model);
    EXPECT_EQ(drawnMesh(view, sculpt), drawnMesh(fresh, sculpt));
}

}  // namespace
}  // namespace sculptline::scene
