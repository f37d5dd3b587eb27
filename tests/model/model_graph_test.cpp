// The model as a constraint graph (issue 12): states, constraints as records, degrees of freedom,
// the plan made again only when freedom is redistributed, and drags whose solvers are factored once.
#include "model/document.h"
#include "model/model.h"
#include "model/model_document.h"
#include "solvers/bspline/projection.h"
#include "tests/common/surface_test_support.h"
#include "tests/model/sculpt_scene.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace sculptline::model {
namespace {

/// Round-off of the kernel's evaluations at the 100 mm scale of these scenes.
constexpr double kTolerance = 1e-9;

solvers::Curve3d cubic(std::vector<Eigen::Vector3d> points)
{
    return solvers::Curve3d(3, {0, 0, 0, 0, 1, 1, 1, 1}, std::move(points));
}

/// An open uniform cubic through 6 control points in a plane's frame (z = 0), shifted by `y`.
solvers::Curve3d wave(double y)
{
    std::vector<Eigen::Vector3d> p;
    for (int i = 0; i < 6; ++i) p.emplace_back(-50 + 20 * i, y + 8 * std::sin(i), 0);
    return solvers::Curve3d(3, {0, 0, 0, 0, 1, 2, 3, 3, 3, 3}, p);
}

/// A plane carrying two waves, a loft through them; a second plane with a curve of its own.
struct LoftScene {
    Model model;
    EntityId plane = 0, a = 0, b = 0, loft = 0, other = 0, alone = 0;
    LoftScene()
    {
        plane = model.addPlane(PlaneFrame::fromNormal(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 200));
        a = model.addCurve(plane, wave(-20));
        // The second section in space, so the loft is not flat: the plane's drag bends it.
        b = model.addCurve(0, transformCurve(wave(20), PlaneFrame::fromNormal(Eigen::Vector3d(0, 0, 40), Eigen::Vector3d::UnitZ(), 200)));
        SurfaceRecipe recipe;
        recipe.mode = Construction::Loft;
        loft = model.addSurface({a, b}, recipe);
        other = model.addPlane(PlaneFrame::fromNormal(Eigen::Vector3d(0, 300, 0), Eigen::Vector3d::UnitY(), 100));
        alone = model.addCurve(other, wave(0));
    }
    void movePlane(double dz)
    {
        PlaneFrame f = model.find(plane)->frame;
        f.origin.z() += dz;
        model.setPlaneFrame(plane, f);
        model.update();
    }
};

TEST(ModelGraph, TheDescriptorTablesAreInEnumOrderAndAgreeWithTheSolvers)
{
    for (size_t k = 0; k < constructions().size(); ++k) {
        const ConstructionInfo& info = constructions()[k];
        EXPECT_EQ(static_cast<size_t>(info.mode), k) << info.name;
        EXPECT_EQ(constructionFromName(info.name), info.mode) << info.name;
        // A mode the solvers build is spelled as they spell it
        if (info.solverMode) {
            EXPECT_STREQ(solvers::surfaces::surfaceModeName(*info.solverMode), info.name);
        }
        EXPECT_LE(info.minInputs, info.maxInputs) << info.name;
    }
    for (size_t k = 0; k < constraintTypes().size(); ++k) {
        EXPECT_EQ(static_cast<size_t>(constraintTypes()[k].type), k);
        EXPECT_EQ(constraintTypeFromName(constraintTypes()[k].name), constraintTypes()[k].type);
    }
    for (size_t k = 0; k < entityKinds().size(); ++k) EXPECT_EQ(static_cast<size_t>(entityKinds()[k].kind), k);
    EXPECT_FALSE(constructionFromName("teleport"));
    EXPECT_FALSE(constraintTypeFromName("twist"));
}

TEST(ModelGraph, RecipesAndPlacementsAreConstraintsTheModelDerives)
{
    LoftScene s;
    // The curve on a plane has a placement from its plane, the loft a construction from its curves
    int placements = 0, constructions = 0;
    for (const auto& [id, c] : s.model.constraints()) {
        if (c.type == ConstraintType::Placement) {
            ++placements;
            EXPECT_EQ(c.sources.size(), 1u);
            EXPECT_EQ(s.model.find(c.sources.front())->kind, EntityKind::Plane);
        }
        if (c.type == ConstraintType::Construction) {
            ++constructions;
            EXPECT_EQ(c.targets, std::vector<EntityId>{s.loft});
            EXPECT_EQ(c.sources, (std::vector<EntityId>{s.a, s.b}));
        }
    }
    EXPECT_EQ(placements, 2);
    EXPECT_EQ(constructions, 1);
    // And removing the loft removes its construction
    s.model.remove(s.loft);
    for (const auto& [id, c] : s.model.constraints()) EXPECT_NE(c.type, ConstraintType::Construction);
}

TEST(ModelGraph, StatesAreFixedFreeOrChangedAndAFixedEntityRefusesEdits)
{
    LoftScene s;
    EXPECT_EQ(s.model.state(s.plane), State::Free);
    PlaneFrame moved = s.model.find(s.plane)->frame;
    moved.origin.z() += 5;
    s.model.setPlaneFrame(s.plane, moved);
    EXPECT_EQ(s.model.state(s.plane), State::Changed);
    s.model.update();
    EXPECT_EQ(s.model.state(s.plane), State::Free);
    // When fixed, a frame or a shape handed to it is refused
    s.model.setFixed(s.plane, true);
    EXPECT_EQ(s.model.state(s.plane), State::Fixed);
    moved.origin.z() += 5;
    s.model.setPlaneFrame(s.plane, moved);
    EXPECT_FALSE(s.model.updatePending());
    s.model.setFixed(s.a, true);
    const solvers::Curve3d before = *s.model.find(s.a)->local;
    s.model.setCurveShape(s.a, wave(-25));
    EXPECT_EQ(s.model.find(s.a)->local->points(), before.points());
    EXPECT_THROW(s.model.beginPull(s.a, 1.5), std::invalid_argument);
    // And the state is saved and read back
    Model reopened;
    populateModel(documentFromJson(modelToJson(s.model, GridSpec{})), reopened);
    EXPECT_EQ(reopened.state(s.plane), State::Fixed);
    EXPECT_EQ(reopened.state(s.a), State::Fixed);
    EXPECT_EQ(reopened.state(s.b), State::Free);
}

TEST(ModelGraph, AFixedCurveStillFollowsItsPlane)
{
    // A placement maps the curve's own shape: fixing the curve keeps that shape, not its place
    LoftScene s;
    s.model.setFixed(s.a, true);
    s.movePlane(10);
    const Entity& a = *s.model.find(s.a);
    EXPECT_LT((a.world->points().front() - transformCurve(*a.local, s.model.find(s.plane)->frame).points().front()).norm(), kTolerance);
}

TEST(ModelGraph, DegreesOfFreedomAreCountedPerEntityAndConsumedByConstraints)
{
    LoftScene s;
    // A curve on a plane: 2 per control point; the loft: all of its freedom made by its construction
    EXPECT_EQ(s.model.dof(s.a).total, 12);
    EXPECT_EQ(s.model.dof(s.a).consumed, 0);
    EXPECT_EQ(s.model.dof(s.b).total, 18);  // in space: 3 per control point
    const Dof loft = s.model.dof(s.loft);
    EXPECT_GT(loft.total, 0);
    EXPECT_EQ(loft.consumed, loft.total);
    EXPECT_EQ(s.model.dof(s.plane).total, 6);
    // A pin takes 2 of a plane curve's, two fixed control points 4 more
    s.model.addConstraint(s.a, ConstraintType::Position, 1.5);
    s.model.setFixedPoints(s.a, {0, 5});
    EXPECT_EQ(s.model.dof(s.a).consumed, 6);
    EXPECT_EQ(s.model.dof(s.a).free(), 6);
}

TEST(ModelGraph, SeedFigureThreeCrossingPointsConsumeTwoDegreesOfFreedomOfCurveB)
{
    // Seed 000 §3.2, Fig. 2-3: curve A fixed, curve B drawn across it in the same sketch plane;
    // P1 and P2 where they cross lie on both. The points on A take, on B, one DOF each (a point on
    // a plane curve at a free parameter): two of B's.
    Model m;
    const EntityId plane = m.addPlane(PlaneFrame::fromNormal(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 200));
    const EntityId a = m.addCurve(plane, cubic({{-40, 0, 0}, {-10, 30, 0}, {10, 30, 0}, {40, 0, 0}}));
    const EntityId b = m.addCurve(plane, cubic({{-30, -10, 0}, {-20, 40, 0}, {20, 40, 0}, {30, -10, 0}}));
    m.setFixed(a, true);
    const EntityId p1 = m.addPoint(Eigen::Vector3d(-25, 14, 0));
    const EntityId p2 = m.addPoint(Eigen::Vector3d(25, 14, 0));
    for (EntityId p : {p1, p2}) {
        Constraint onA;
        onA.type = ConstraintType::PointOnCurve;
        onA.targets = {p, a};
        m.addConstraint(onA);
        Constraint onB = onA;
        onB.targets = {p, b};
        m.addConstraint(onB);
    }
    EXPECT_EQ(m.dof(b).consumed, 2);
    EXPECT_EQ(m.dof(b).free(), m.dof(b).total - 2);
    // And the plan: A is a source (fixed); the points and B are coupled through their incidences
    // (one cluster, for a solver of a later issue), after A's placement
    const Plan& plan = m.plan();
    ASSERT_TRUE(plan.stepOf.count(b));
    const PlanStep& cluster = plan.steps[plan.stepOf.at(b)];
    EXPECT_EQ(cluster.solve, (std::vector<EntityId>{b, p1, p2}));
    EXPECT_EQ(cluster.solver, "unsolved");
    EXPECT_LT(plan.stepOf.at(a), plan.stepOf.at(b));
}

TEST(ModelGraph, ThePlanIsMadeAgainOnlyWhenFreedomIsRedistributed)
{
    LoftScene s;
    s.model.plan();
    const int plans = s.model.planCount();
    // A drag re-uses it
    s.model.beginDrag(s.plane);
    for (int i = 0; i < 10; ++i) s.movePlane(1.0);
    s.model.endDrag();
    s.model.update();
    EXPECT_EQ(s.model.planCount(), plans);
    // Fixing, adding a constraint, adding and removing entities each make a new one
    s.model.setFixed(s.b, true);
    s.model.plan();
    EXPECT_EQ(s.model.planCount(), plans + 1);
    s.model.addConstraint(s.a, ConstraintType::Tangent, 0.5);
    s.model.plan();
    EXPECT_EQ(s.model.planCount(), plans + 2);
    const EntityId c = s.model.addCurve(s.other, wave(30));
    s.model.plan();
    EXPECT_EQ(s.model.planCount(), plans + 3);
    s.model.remove(c);
    s.model.plan();
    EXPECT_EQ(s.model.planCount(), plans + 4);
}

TEST(ModelGraph, APlaneDragFactorsTheSurfaceBuilderOnceAndComesToRestAsAFreshBuild)
{
    LoftScene s;
    const int before = s.model.factorizations();
    // When the plane is dragged through 20 events
    s.model.beginDrag(s.plane);
    EXPECT_EQ(s.model.factorizations(), before + 1);  // the loft's builder
    for (int i = 0; i < 20; ++i) s.movePlane(0.5);
    // Then no event set anything up again, and the loft follows its curves all along
    EXPECT_EQ(s.model.factorizations(), before + 1);
    EXPECT_LT(guitest::curveToSurface(*s.model.find(s.a)->world, *s.model.find(s.loft)->surface), 1e-6);
    EXPECT_LT(guitest::curveToSurface(*s.model.find(s.b)->world, *s.model.find(s.loft)->surface), 1e-6);
    // And the other plane's curve was never recomputed
    EXPECT_EQ(s.model.find(s.alone)->recomputations, 0);
    // When the drag ends, the loft is rebuilt as a fresh build of its curves would be
    s.model.endDrag();
    s.model.update();
    SurfaceRecipe recipe;
    recipe.mode = Construction::Loft;
    const Entity fresh = s.model.makeSurface({s.a, s.b}, recipe);
    EXPECT_EQ(s.model.find(s.loft)->surface->points(), fresh.surface->points());
    EXPECT_EQ(s.model.dragged(), 0u);
}

TEST(ModelGraph, APullKeepsItsPinsAndFixedPointsAndFactorsOnce)
{
    LoftScene s;
    const ConstraintId pin = s.model.addConstraint(s.a, ConstraintType::Position, 2.5);
    s.model.setFixedPoints(s.a, {0});
    const Eigen::Vector3d pinned = s.model.findConstraint(pin)->value;
    const solvers::Curve3d start = *s.model.find(s.a)->local;
    const int before = s.model.factorizations();
    // When the curve is grabbed at u = 1 and pulled through 15 events
    s.model.beginPull(s.a, 1.0);
    Eigen::Vector3d target = start.evaluate(1.0);
    std::string message;
    for (int i = 0; i < 15; ++i) {
        target += Eigen::Vector3d(0, 1.0, 0);
        message = s.model.pullTo(target);
        s.model.update();
    }
    // Then the solver and the loft's builder were set up once, at the grab
    EXPECT_EQ(s.model.factorizations(), before + 2);
    EXPECT_TRUE(message.empty()) << message;
    // And the grabbed point is where the pointer is, the pin and the fixed point did not move
    const Entity& a = *s.model.find(s.a);
    EXPECT_LT((a.local->evaluate(1.0) - target).norm(), kTolerance);
    EXPECT_LT((s.model.findConstraint(pin)->value - pinned).norm(), kTolerance);
    EXPECT_EQ(a.local->points().front(), start.points().front());
    // And the loft followed, the curve on the other plane did not change
    EXPECT_LT(guitest::curveToSurface(*a.world, *s.model.find(s.loft)->surface), 1e-6);
    EXPECT_EQ(s.model.find(s.alone)->recomputations, 0);
    s.model.endDrag();
    EXPECT_EQ(s.model.dragged(), 0u);
}

TEST(ModelGraph, ACurveWithNoFreedomLeftCannotBePulledAndSaysWhy)
{
    LoftScene s;
    // Every control point fixed: the grip has nothing to move
    s.model.setFixedPoints(s.a, {0, 1, 2, 3, 4, 5});
    EXPECT_THROW(s.model.beginPull(s.a, 1.0), std::invalid_argument);
    EXPECT_EQ(s.model.dragged(), 0u);
}

TEST(ModelGraph, ConstraintsThatDoNotFitAreRefusedAndNothingIsAdded)
{
    LoftScene s;
    const size_t count = s.model.constraints().size();
    Constraint c;
    c.type = ConstraintType::CurveOnSurface;
    c.targets = {s.loft, s.a};  // the order is curve, surface
    EXPECT_THROW(s.model.addConstraint(c), std::invalid_argument);
    c.targets = {s.a, 999};
    EXPECT_THROW(s.model.addConstraint(c), std::invalid_argument);
    c.type = ConstraintType::Construction;  // the model's own
    c.targets = {s.loft};
    EXPECT_THROW(s.model.addConstraint(c), std::invalid_argument);
    c.type = ConstraintType::Normal;
    c.parameters = {0.5, std::nan("")};
    EXPECT_THROW(s.model.addConstraint(c), std::invalid_argument);
    EXPECT_EQ(s.model.constraints().size(), count);
    // A fitting one is added, and a curve-on-surface between free entities makes one cluster
    c.type = ConstraintType::CurveOnSurface;
    c.parameters.clear();
    c.targets = {s.alone, s.loft};
    s.model.addConstraint(c);
    const Plan& plan = s.model.plan();
    const std::vector<EntityId> both{std::min(s.loft, s.alone), std::max(s.loft, s.alone)};
    EXPECT_EQ(plan.steps[plan.stepOf.at(s.loft)].solve, both);
    EXPECT_EQ(plan.steps[plan.stepOf.at(s.loft)].solver, "unsolved");
}

TEST(ModelGraph, APreimageIsStoredAsAFlatCurveAndReadBackExactly)
{
    // Given domain curves as the incidence solver makes them: an open cubic and a closed degree-1 rim
    const solvers::Curve2d open(3, {0, 0, 0, 0, 0.5, 1, 1, 1, 1},
                                {{0.1, 0.2}, {0.3, 0.25}, {0.5, 0.6}, {0.7, 0.4}, {0.9, 0.8}});
    const solvers::Curve2d rim(1, {-1, 0, 1, 2, 3, 4, 5}, {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}}, {}, true);
    for (const solvers::Curve2d& domain : {open, rim}) {
        // When stored as a constraint's pre-image and read back
        const solvers::Curve3d stored = preimageCurve(domain);
        const solvers::Curve2d back = preimageDomain(stored);
        // Then the stored points are [u, v, 0], and degree, knots, points and closure come back exactly
        for (size_t i = 0; i < domain.points().size(); ++i) {
            EXPECT_EQ(stored.points()[i], Eigen::Vector3d(domain.points()[i].x(), domain.points()[i].y(), 0.0));
        }
        EXPECT_EQ(stored.isClosed(), domain.isClosed());
        EXPECT_EQ(back.degree(), domain.degree());
        EXPECT_EQ(back.knots(), domain.knots());
        EXPECT_EQ(back.points(), domain.points());
        EXPECT_EQ(back.isClosed(), domain.isClosed());
    }
}

TEST(ModelGraph, DocumentsWithEveryConstraintTypeRoundTrip)
{
    // An older document: a pin numbered among the entities, fixed points on the curve
    const nlohmann::json old = nlohmann::json::parse(R"({
      "planes": [{"id": 1, "origin": [0, 0, 0], "normal": [0, 0, 1], "size": 200}],
      "curves": [{"id": 2, "plane": 1, "degree": 3, "knots": [0, 0, 0, 0, 1, 1, 1, 1],
                  "points": [[0, 0], [10, 5], [20, 5], [30, 0]], "fixed": [0]}],
      "constraints": [{"id": 3, "curve": 2, "type": "position", "u": 0.5},
                      {"type": "smoothing", "targets": [2], "weight": 0.25}]
    })");
    Model m;
    populateModel(documentFromJson(old), m);
    EXPECT_EQ(m.fixedPoints(2), std::vector<int>{0});
    int pins = 0, smoothing = 0;
    for (const auto& [id, c] : m.constraints()) {
        pins += c.type == ConstraintType::Position ? 1 : 0;
        if (c.type == ConstraintType::Smoothing) {
            ++smoothing;
            EXPECT_EQ(c.weight, 0.25);
        }
    }
    EXPECT_EQ(pins, 1);
    EXPECT_EQ(smoothing, 1);
    // Saved and reopened, the document is the same
    const nlohmann::json saved = modelToJson(m, GridSpec{});
    Model again;
    populateModel(documentFromJson(saved), again);
    EXPECT_EQ(modelToJson(again, GridSpec{}), saved);
    // And a constraint naming what does not fit is refused by the reader, naming the field
    nlohmann::json bad = old;
    bad["constraints"][1] = {{"type", "curve-on-surface"}, {"targets", {2, 1}}};
    try {
        documentFromJson(bad);
        FAIL() << "accepted a curve-on-surface on a plane";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("constraints[1]"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace sculptline::model

namespace sculptline::model {
namespace {

TEST(Sculpt, TheBaseSurfaceMovesOntoTheTargetCurveAndTheDocumentReSolvesIt)
{
    SculptScene s;
    const Entity& sculpt = *s.model.find(s.sculpt);
    ASSERT_TRUE(sculpt.surface.has_value()) << sculpt.buildError;
    EXPECT_TRUE(sculpt.buildError.empty()) << sculpt.buildError;
    // The target curve lies on the sculpted surface at its key points (and near it between them)
    const solvers::Curve3d& target = *s.model.find(s.target)->world;
    EXPECT_LT(sculpt.maxDeviation, 1e-6);
    EXPECT_LT(guitest::curveToSurface(target, *sculpt.surface), 0.5);
    EXPECT_GT(guitest::curveToSurface(target, *s.model.find(s.base)->surface), 5.0);
    // The base is unchanged; the plan builds the sculpt by its deformation solver
    EXPECT_EQ(s.model.find(s.base)->surface->points(), flatSheet().points());
    EXPECT_EQ(s.model.plan().steps[s.model.plan().stepOf.at(s.sculpt)].solver, "deformation");
    // Saved and reopened, the sculpt is solved again to the same surface
    Model reopened;
    populateModel(documentFromJson(modelToJson(s.model, GridSpec{})), reopened);
    ASSERT_NE(reopened.find(s.sculpt), nullptr);
    ASSERT_TRUE(reopened.find(s.sculpt)->recipe);
    EXPECT_EQ(reopened.find(s.sculpt)->recipe->mode, Construction::Sculpt);
    EXPECT_EQ(reopened.find(s.sculpt)->surface->points(), sculpt.surface->points());
}

TEST(Sculpt, DraggingTheTargetsPlaneReSolvesWithOneFactorization)
{
    SculptScene s;
    const int before = s.model.factorizations();
    s.model.beginDrag(s.plane);
    EXPECT_EQ(s.model.factorizations(), before + 1);
    for (int i = 0; i < 10; ++i) {
        PlaneFrame f = s.model.find(s.plane)->frame;
        f.origin.y() += 1.0;  // across the sheet
        s.model.setPlaneFrame(s.plane, f);
        s.model.update();
        // The surface follows the moved target at each event
        EXPECT_LT(guitest::curveToSurface(*s.model.find(s.target)->world, *s.model.find(s.sculpt)->surface), 0.5) << i;
    }
    EXPECT_EQ(s.model.factorizations(), before + 1);
    s.model.endDrag();
    s.model.update();
    // At rest it is what a fresh solve gives
    SurfaceRecipe recipe;
    recipe.mode = Construction::Sculpt;
    EXPECT_EQ(s.model.find(s.sculpt)->surface->points(), s.model.makeSurface({s.base, s.target}, recipe).surface->points());
}

TEST(Sculpt, StiffnessMovesTheSurfaceThatShareOfTheWay)
{
    SculptScene full(1.0), half(0.5);
    const solvers::Surface3d& base = *full.model.find(full.base)->surface;
    const auto& a = full.model.find(full.sculpt)->surface->points();
    const auto& b = half.model.find(half.sculpt)->surface->points();
    for (size_t k = 0; k < a.size(); ++k) {
        EXPECT_LT(((b[k] - base.points()[k]) - 0.5 * (a[k] - base.points()[k])).norm(), 1e-9) << k;
    }
    // And the bad ones are refused
    SurfaceRecipe recipe;
    recipe.mode = Construction::Sculpt;
    recipe.stiffness = 0.0;
    EXPECT_THROW(full.model.addSurface({full.base, full.target}, recipe), std::invalid_argument);
    recipe.stiffness = 1.0;
    EXPECT_THROW(full.model.addSurface({full.target, full.target}, recipe), std::invalid_argument);  // no base
}

TEST(Sculpt, AChangedBaseIsSculptedAnewAndStillMeetsTheTarget)
{
    // Given a sculpt whose base is a loft of two curves (the LoftScene), onto a target on the other plane
    LoftScene s;
    const EntityId plane = s.model.addPlane(PlaneFrame::fromNormal(Eigen::Vector3d(0, 0, 30), Eigen::Vector3d::UnitY(), 150));
    const PlaneFrame& f = s.model.find(plane)->frame;
    std::vector<Eigen::Vector3d> local;
    for (int i = 0; i < 4; ++i) {
        Eigen::Vector3d p = f.toLocal(Eigen::Vector3d(-30 + 20 * i, 0, 30 + 6 * std::sin(i)));
        p.z() = 0;
        local.push_back(p);
    }
    const EntityId target = s.model.addCurve(plane, cubic(local));
    SurfaceRecipe recipe;
    recipe.mode = Construction::Sculpt;
    const EntityId sculpt = s.model.addSurface({s.loft, target}, recipe);
    ASSERT_FALSE(s.model.find(sculpt)->failed()) << s.model.find(sculpt)->buildError;
    const std::vector<Eigen::Vector3d> first = s.model.find(sculpt)->surface->points();
    // When the base's first curve is redrawn (its loft rebuilt)
    s.model.setCurveShape(s.a, wave(-30));
    s.model.update();
    // Then the sculpt is solved again on the new base, and still passes through its target's key points
    const Entity& again = *s.model.find(sculpt);
    EXPECT_FALSE(again.failed()) << again.buildError;
    EXPECT_NE(again.surface->points(), first);
    EXPECT_LT(again.maxDeviation, 1e-6);
    EXPECT_EQ(again.recomputations, 1);
}

TEST(ModelGraph, AFreeFormSurfacesNewShapeMarksItChangedAndItsSculptFollows)
{
    // Given a sculpt over a static sheet (seed 001 §5.2 re-sketches such a free-form surface)
    SculptScene s;
    const solvers::Surface3d before = *s.model.find(s.sculpt)->surface;
    std::vector<Eigen::Vector3d> raised = s.model.find(s.base)->surface->points();
    for (auto& p : raised) p.z() += 5.0;
    const solvers::Surface3d& b = *s.model.find(s.base)->surface;
    const solvers::Surface3d shape(3, 3, b.knotsU(), b.knotsV(), b.countU(), b.countV(), raised);
    // When the sheet's net is replaced
    s.model.setSurfaceShape(s.base, shape);
    // Then the sheet is changed until the update, then has the new net, and the sculpt was rebuilt
    EXPECT_EQ(s.model.state(s.base), State::Changed);
    s.model.update();
    EXPECT_EQ(s.model.find(s.base)->surface->points(), raised);
    EXPECT_NE(s.model.find(s.sculpt)->surface->points(), before.points());
}

TEST(ModelGraph, ASurfaceBuiltFromCurvesKeepsItsShape)
{
    // Given a loft (its curves make it: a new net would be lost at its next rebuild)
    LoftScene s;
    const solvers::Surface3d loft = *s.model.find(s.loft)->surface;
    std::vector<Eigen::Vector3d> moved = loft.points();
    for (auto& p : moved) p.z() += 5.0;
    const solvers::Surface3d shape(loft.degreeU(), loft.degreeV(), loft.knotsU(), loft.knotsV(), loft.countU(), loft.countV(), moved);
    // When it is given a new net, or a curve is
    s.model.setSurfaceShape(s.loft, shape);
    s.model.setSurfaceShape(s.a, shape);
    // Then nothing changed
    EXPECT_EQ(s.model.find(s.loft)->surface->points(), loft.points());
    EXPECT_FALSE(s.model.updatePending());
}

}  // namespace
}  // namespace sculptline::model
