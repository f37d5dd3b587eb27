// A sculpt's constraints beside its target curves (issue 13 §1, thesis ch. 6): point handles that
// move and turn (position, and the tangent plane turned with the handle), a bound curve (§6.3's
// over-, under- and well-constrained targets), blocked control points, distances and curve
// tangents; their drags factored once, their documents re-solved on opening.
#include "model/document.h"
#include "model/model.h"
#include "model/model_document.h"
#include "solvers/deformation/deformation_region.h"
#include "solvers/incidence/spanning_sheet.h"
#include "solvers/bspline/projection.h"
#include "solvers/io/geometry_json.h"
#include "tests/common/surface_test_support.h"
#include "tests/model/sculpt_scene.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <Eigen/Geometry>
#include <cmath>
#include <optional>

namespace sculptline::model {
namespace {

/// Round-off of the solves at the 100 mm scale of the sheet (met constraints sit near 1e-13).
constexpr double kTolerance = 1e-9;
/// The bound on a held normal's angle.
constexpr double kAngleTolerance = 1e-6;

double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    return std::atan2(a.cross(b).norm(), a.dot(b));
}

/// The sheet's centre (0, 0, 0) is (u, v) = (2, 2) of its [0, 4]² domain.
const Eigen::Vector2d kCentre(2.0, 2.0);

struct HandleScene {
    Model model;
    EntityId base = 0, point = 0, sculpt = 0;
    SurfaceRecipe recipe;
    explicit HandleScene(bool holdNormal = true, Eigen::Vector2d uv = kCentre)
    {
        base = model.addSurface(flatSheet());
        point = model.addPoint(flatSheet().evaluate(uv.x(), uv.y()));
        recipe.mode = Construction::Sculpt;
        recipe.handles = {{point, uv, holdNormal}};
        sculpt = model.addSurface({base, point}, recipe);
    }
    const solvers::Surface3d& surface() const { return *model.find(sculpt)->surface; }
};

double largestChange(const solvers::Surface3d& a, const solvers::Surface3d& b)
{
    double worst = 0.0;
    for (size_t k = 0; k < a.points().size(); ++k) worst = std::max(worst, (a.points()[k] - b.points()[k]).norm());
    return worst;
}

TEST(SculptHandle, ThePointPullsTheSurfaceAndItsRotationTiltsTheNormal)
{
    HandleScene s;
    ASSERT_FALSE(s.model.find(s.sculpt)->failed()) << s.model.find(s.sculpt)->buildError;
    // A handle dropped where the surface is, unturned, changes nothing
    EXPECT_LT(largestChange(s.surface(), flatSheet()), 1e-12);
    // When it is lifted 10 mm and turned 20° about x
    const Eigen::Quaterniond turn(Eigen::AngleAxisd(20.0 * M_PI / 180.0, Eigen::Vector3d::UnitX()));
    s.model.setPointPose(s.point, Eigen::Vector3d(0, 0, 10), turn);
    s.model.update();
    // Then the surface passes through it, with its normal turned the same way
    EXPECT_LT((s.surface().evaluate(2, 2) - Eigen::Vector3d(0, 0, 10)).norm(), kTolerance);
    EXPECT_LT(angleBetween(s.surface().normal(2, 2), turn * Eigen::Vector3d::UnitZ()), kAngleTolerance);
    EXPECT_LT(s.model.find(s.sculpt)->maxDeviation, kAngleTolerance);
    // And saved and reopened, the point keeps its pose and the sculpt re-solves to the same surface
    Model reopened;
    populateModel(documentFromJson(modelToJson(s.model, GridSpec{})), reopened);
    ASSERT_NE(reopened.find(s.point), nullptr);
    EXPECT_EQ(reopened.find(s.point)->position, Eigen::Vector3d(0, 0, 10));
    EXPECT_LT(reopened.find(s.point)->rotation.angularDistance(turn), 1e-15);
    EXPECT_EQ(reopened.find(s.sculpt)->surface->points(), s.surface().points());
}

TEST(SculptHandle, WithoutItsNormalOnlyThePointIsHeldAndTheTangentPlaneIsFree)
{
    HandleScene held(true), free(false);
    const Eigen::Quaterniond turn(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()));
    for (HandleScene* s : {&held, &free}) {
        s->model.setPointPose(s->point, Eigen::Vector3d(0, 0, 10), turn);
        s->model.update();
        EXPECT_LT((s->surface().evaluate(2, 2) - Eigen::Vector3d(0, 0, 10)).norm(), kTolerance);
    }
    // The free one's normal stays vertical at the top of its symmetric bump; the held one tilts 0.3 rad
    EXPECT_LT(angleBetween(free.surface().normal(2, 2), Eigen::Vector3d::UnitZ()), kAngleTolerance);
    EXPECT_NEAR(angleBetween(held.surface().normal(2, 2), Eigen::Vector3d::UnitZ()), 0.3, kAngleTolerance);
}

TEST(SculptHandle, ADragIsFactoredOnceAndEveryEventEqualsAFreshSolve)
{
    HandleScene s;
    const int before = s.model.factorizations();
    s.model.beginDrag(s.point);
    EXPECT_EQ(s.model.factorizations(), before + 1);
    for (int i = 1; i <= 8; ++i) {
        const Eigen::Quaterniond turn(Eigen::AngleAxisd(0.05 * i, Eigen::Vector3d(1, 1, 0).normalized()));
        const Eigen::Vector3d at(1.5 * i, -i, 2.0 * i);
        s.model.setPointPose(s.point, at, turn);
        s.model.update();
        // Each event meets the handle and equals what a fresh solve of the same sculpt gives
        EXPECT_LT((s.surface().evaluate(2, 2) - at).norm(), kTolerance) << i;
        EXPECT_LT(largestChange(s.surface(), *s.model.makeSurface({s.base, s.point}, s.recipe).surface), kTolerance) << i;
    }
    EXPECT_EQ(s.model.factorizations(), before + 1);  // a turn changes values, not the factorization
    s.model.endDrag();
    s.model.update();
    EXPECT_EQ(s.surface().points(), s.model.makeSurface({s.base, s.point}, s.recipe).surface->points());
}

TEST(SculptHandle, AFixedPointRefusesToMove)
{
    HandleScene s;
    const Eigen::Vector3d start = s.model.find(s.point)->position;
    s.model.setFixed(s.point, true);
    s.model.setPointPose(s.point, Eigen::Vector3d(0, 0, 10), Eigen::Quaterniond::Identity());
    EXPECT_EQ(s.model.find(s.point)->position, start);
    // Nor does a non-finite pose move a free one
    s.model.setFixed(s.point, false);
    s.model.setPointPose(s.point, Eigen::Vector3d(NAN, 0, 0), Eigen::Quaterniond::Identity());
    s.model.setPointPose(s.point, Eigen::Vector3d(0, 0, 1), Eigen::Quaterniond(0, 0, 0, 0));
    EXPECT_EQ(s.model.find(s.point)->position, start);
}

/// A 13 x 13 sheet (domain [0, 10]²; enough free columns under a bound for the arch's key points).
constexpr int kFineNet = 13;

/// The sculpt of SculptScene (a target arch across the sheet at v = 5, over the middle two thirds
/// in u) within a square bound [lo, hi]² of the domain.
Entity boundedSculpt(SculptScene& s, double lo, double hi)
{
    SurfaceRecipe recipe;
    recipe.mode = Construction::Sculpt;
    recipe.bound = {{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}};
    return s.model.makeSurface({s.base, s.target}, recipe);
}

TEST(SculptBound, OnlyTheInsideMovesAndATargetPartlyInsideActsThere)
{
    // Given a bound around the middle of the sheet, the target arch crossing it (under-constrained)
    SculptScene s(1.0, kFineNet);
    const solvers::Surface3d sheet = flatSheet(kFineNet);
    const Entity e = boundedSculpt(s, 2.5, 7.5);
    ASSERT_FALSE(e.failed()) << e.buildError;
    const std::vector<bool> inside = solvers::deformation::insideBound(sheet, e.recipe->bound);
    int moved = 0;
    for (size_t k = 0; k < inside.size(); ++k) {
        // Then the control points outside it stay bit for bit, and some inside move
        if (!inside[k]) {
            EXPECT_EQ(e.surface->points()[k], sheet.points()[k]) << k;
        }
        if (inside[k] && e.surface->points()[k] != sheet.points()[k]) ++moved;
    }
    EXPECT_GT(moved, 0);
    // And the inside span of the arch (12 mm high) is met
    EXPECT_NEAR(e.surface->evaluate(5, 5).z(), 12.0, 0.5);
    EXPECT_LT(e.maxDeviation, 1e-6);
    EXPECT_TRUE(e.solveMessage.empty()) << e.solveMessage;
}

TEST(SculptBound, ATargetWhollyOutsideLeavesTheSurfaceAloneAndSaysSo)
{
    // Given a bound in a corner of the domain, away from the target (over-constrained, §6.3)
    SculptScene s(1.0, kFineNet);
    const Entity e = boundedSculpt(s, 0.5, 3.0);
    // Then the surface is the base, and the designer is told why
    ASSERT_TRUE(e.surface);
    EXPECT_EQ(e.surface->points(), flatSheet(kFineNet).points());
    EXPECT_NE(e.solveMessage.find("outside the bound"), std::string::npos) << e.solveMessage;
    EXPECT_FALSE(e.failed());
}

TEST(SculptBound, ATargetWellInsideHasAllItsKeyPointsMet)
{
    SculptScene s(1.0, kFineNet);
    const Entity e = boundedSculpt(s, 0.5, 9.5);
    ASSERT_FALSE(e.failed()) << e.buildError;
    EXPECT_LT(e.maxDeviation, 1e-6);  // every key point met, as without a bound
    EXPECT_TRUE(e.solveMessage.empty()) << e.solveMessage;
}

TEST(SculptBlocked, BlockedControlPointsStayExactly)
{
    SculptScene s;
    SurfaceRecipe recipe;
    recipe.mode = Construction::Sculpt;
    recipe.blocked = {{3, 3}, {2, 3}};  // under the arch's middle
    const Entity e = s.model.makeSurface({s.base, s.target}, recipe);
    EXPECT_EQ(e.surface->point(3, 3), flatSheet().point(3, 3));
    EXPECT_EQ(e.surface->point(2, 3), flatSheet().point(2, 3));
    EXPECT_NE(e.surface->point(4, 3), flatSheet().point(4, 3));
    // An index beyond the net is a failed build that says which
    recipe.blocked = {{7, 0}};
    EXPECT_THROW(s.model.makeSurface({s.base, s.target}, recipe), std::invalid_argument);
}

TEST(SculptDistance, TwoSurfacePointsAreHeldThatFarApart)
{
    // Given two points 40 mm apart across the middle (u = 4/3 and 8/3 at v = 2), held 30 apart
    HandleScene s;
    SurfaceRecipe recipe = s.recipe;
    recipe.distances = {{{4.0 / 3.0, 2.0}, {8.0 / 3.0, 2.0}, 30.0}};
    s.model.setPointPose(s.point, Eigen::Vector3d(0, 0, 5), Eigen::Quaterniond::Identity());
    s.model.update();
    const Entity e = s.model.makeSurface({s.base, s.point}, recipe);
    ASSERT_FALSE(e.failed()) << e.buildError;
    EXPECT_NEAR((e.surface->evaluate(8.0 / 3.0, 2) - e.surface->evaluate(4.0 / 3.0, 2)).norm(), 30.0, kTolerance);
    EXPECT_LT((e.surface->evaluate(2, 2) - Eigen::Vector3d(0, 0, 5)).norm(), kTolerance);
}

TEST(SculptCurveTangent, AlongTheTargetTheCrossTangentPointsAlongTheDirection)
{
    // Given the arch, with the surface's tangent across it asked to point along (0, 1, 1)
    SculptScene s;
    SurfaceRecipe recipe;
    recipe.mode = Construction::Sculpt;
    const Eigen::Vector3d direction = Eigen::Vector3d(0, 1, 1).normalized();
    recipe.curveTangents = {{s.target, direction}};
    const Entity e = s.model.makeSurface({s.base, s.target}, recipe);
    ASSERT_FALSE(e.failed()) << e.buildError;
    // Then every constraint's residual (key points in mm, the cross tangent's angle in rad) is met
    EXPECT_LT(e.maxDeviation, kAngleTolerance);
    EXPECT_TRUE(e.solveMessage.empty()) << e.solveMessage;
    // And under the arch's middle the tangent across (S_v, the arch runs along u) leans that way
    const Eigen::Vector3d across = e.surface->derivatives(2, 2, 1)[0][1];
    EXPECT_LT(angleBetween(across, direction), 0.1);
    EXPECT_NEAR(angleBetween(flatSheet().derivatives(2, 2, 1)[0][1], direction), M_PI / 4, 1e-12);
}

TEST(SculptDocument, EveryConstraintIsSavedAndReSolvedOnOpening)
{
    SculptScene s;
    const EntityId point = s.model.addPoint(Eigen::Vector3d(-20, 30, 4), 0,
                                            Eigen::Quaterniond(Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY())));
    SurfaceRecipe recipe;
    recipe.mode = Construction::Sculpt;
    recipe.stiffness = 0.8;
    recipe.handles = {{point, {4.0 / 3.0, 3.5}, true}};
    recipe.bound = {{0.2, 0.2}, {3.8, 0.2}, {3.8, 3.8}, {0.2, 3.8}};
    recipe.blocked = {{0, 0}};
    recipe.distances = {{{1.0, 1.0}, {3.0, 1.0}, 41.0}};
    recipe.curveTangents = {{s.target, Eigen::Vector3d(0, 1, 0.5)}};
    const EntityId sculpt = s.model.addSurface({s.base, s.target, point}, recipe);
    ASSERT_FALSE(s.model.find(sculpt)->failed()) << s.model.find(sculpt)->buildError;
    Model reopened;
    populateModel(documentFromJson(modelToJson(s.model, GridSpec{})), reopened);
    const Entity& again = *reopened.find(sculpt);
    ASSERT_TRUE(again.recipe);
    const SurfaceRecipe& r = *again.recipe;
    EXPECT_EQ(again.inputs, s.model.find(sculpt)->inputs);
    ASSERT_EQ(r.handles.size(), 1u);
    EXPECT_EQ(r.handles[0].point, point);
    EXPECT_EQ(r.handles[0].uv, recipe.handles[0].uv);
    EXPECT_EQ(r.bound, recipe.bound);
    EXPECT_EQ(r.blocked, recipe.blocked);
    ASSERT_EQ(r.distances.size(), 1u);
    EXPECT_EQ(r.distances[0].distance, 41.0);
    ASSERT_EQ(r.curveTangents.size(), 1u);
    EXPECT_EQ(r.curveTangents[0].direction, recipe.curveTangents[0].direction);
    EXPECT_EQ(r.stiffness, 0.8);
    EXPECT_EQ(again.surface->points(), s.model.find(sculpt)->surface->points());
}

TEST(SculptDocument, BadSculptFieldsAreRefusedNamingTheField)
{
    SculptScene s;
    const EntityId point = s.model.addPoint(Eigen::Vector3d(0, 0, 0));
    SurfaceRecipe recipe;
    recipe.mode = Construction::Sculpt;
    recipe.handles = {{point, kCentre, true}};
    s.model.addSurface({s.base, s.target, point}, recipe);
    const nlohmann::json good = modelToJson(s.model, GridSpec{});
    auto refused = [&](const std::function<void(nlohmann::json&)>& spoil, const std::string& field) {
        nlohmann::json j = good;
        spoil(j);
        try {
            documentFromJson(j);
            ADD_FAILURE() << "accepted; expected an error naming " << field;
        } catch (const solvers::io::InputError& e) {
            EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
        }
    };
    auto construction = [](nlohmann::json& j) -> nlohmann::json& { return j["surfaces"].back()["construction"]; };
    refused([&](nlohmann::json& j) { construction(j)["points"][0]["point"] = 999; }, "construction.points[0].point");
    refused([&](nlohmann::json& j) { construction(j)["points"][0]["uv"] = {1}; }, "construction.points[0].uv");
    refused([&](nlohmann::json& j) { construction(j)["points"][0]["normal"] = "yes"; }, "construction.points[0].normal");
    refused([&](nlohmann::json& j) { construction(j)["bound"] = {{0, 0}, {1, 1}}; }, "construction.bound");
    refused([&](nlohmann::json& j) { construction(j)["blocked"] = {{0}}; }, "construction.blocked[0]");
    refused([&](nlohmann::json& j) { construction(j)["distances"] = {{{"uv", {1, 1}}, {"uv2", {2, 2}}, {"value", -1}}}; },
            "construction.distances[0].value");
    refused([&](nlohmann::json& j) { construction(j)["curve_tangents"] = {{{"curve", 1}, {"direction", {0, 0, 1}}}}; },
            "construction.curve_tangents[0].curve");
    refused([&](nlohmann::json& j) { j["points"][0]["rotation"] = {0, 0, 0, 0}; }, "points[0].rotation");
    refused([&](nlohmann::json& j) { j["points"][0]["position"] = {0, 0, 1e300}; }, "points[0].position");
    refused([&](nlohmann::json& j) { j["points"][0].erase("id"); }, "points[0].id");
}

TEST(SculptRecipe, RecipesThatDoNotFitTheirInputsAreRefused)
{
    SculptScene s;
    const EntityId point = s.model.addPoint(Eigen::Vector3d(0, 0, 0));
    SurfaceRecipe recipe;
    recipe.mode = Construction::Sculpt;
    // A point among the inputs without a handle saying where it pulls
    EXPECT_THROW(s.model.addSurface({s.base, point}, recipe), std::invalid_argument);
    // A handle on a point that is not an input
    recipe.handles = {{point, kCentre, true}};
    EXPECT_THROW(s.model.addSurface({s.base, s.target}, recipe), std::invalid_argument);
    // A curve tangent along a curve that is not a target
    recipe.handles.clear();
    recipe.curveTangents = {{s.plane, Eigen::Vector3d::UnitZ()}};
    EXPECT_THROW(s.model.addSurface({s.base, s.target}, recipe), std::invalid_argument);
    // A bound of two points, and a handle on a fill
    recipe.curveTangents.clear();
    recipe.bound = {{0, 0}, {1, 1}};
    EXPECT_THROW(s.model.addSurface({s.base, s.target}, recipe), std::invalid_argument);
    SurfaceRecipe fill;
    fill.handles = {{point, kCentre, true}};
    EXPECT_THROW(s.model.makeSurface({s.target}, fill), std::invalid_argument);
    // A handle off the base's domain is a failed build that says so, not a crash
    recipe.bound.clear();
    recipe.handles = {{point, {9, 9}, true}};
    EXPECT_THROW(s.model.addSurface({s.base, point}, recipe), std::invalid_argument);
}

}  // namespace
}  // namespace sculptline::model

namespace sculptline::model {
namespace {

TEST(IncidenceStep, CurvesOnAStaticSurfaceAreMetAndFollowTheirPlanesDrag)
{
    // Given a flat sheet (no recipe), and an arch 8 mm high on the vertical plane y = 0 across it,
    // asked to lie on the sheet (curve-on-surface, seed 000)
    Model model;
    const EntityId sheet = model.addSurface(flatSheet(9));
    const EntityId plane = model.addPlane(PlaneFrame::fromNormal(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY(), 150));
    const PlaneFrame& f = model.find(plane)->frame;
    std::vector<Eigen::Vector3d> local;
    for (int i = 0; i < 5; ++i) {
        Eigen::Vector3d p = f.toLocal(Eigen::Vector3d(-40 + 20 * i, 0, i == 0 || i == 4 ? 0.0 : 8.0));
        p.z() = 0;
        local.push_back(p);
    }
    const EntityId arch = model.addCurve(plane, solvers::Curve3d(3, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}, local));
    Constraint on;
    on.type = ConstraintType::CurveOnSurface;
    on.targets = {arch, sheet};
    model.addConstraint(on);
    const std::vector<Eigen::Vector3d> drawn = model.find(arch)->world->points();
    model.update();
    // Then the plan solves the sheet by incidence, and the sheet passes through the arch
    const Plan& plan = model.plan();
    EXPECT_EQ(plan.steps[plan.stepOf.at(sheet)].solver, "incidence");
    const Entity& s = *model.find(sheet);
    EXPECT_FALSE(s.failed()) << s.buildError;
    // (within half a millimetre of the 8 mm arch: the L-curve's corner, k = 7 here, trades a little
    // residual for a net that does not ripple; measured 0.13 mm from the curve, 0.31 at worst)
    EXPECT_LT(guitest::curveToSurface(*model.find(arch)->world, *s.surface), 0.5) << s.solveMessage;
    EXPECT_LT(s.maxDeviation, 0.5);
    EXPECT_NEAR(s.surface->evaluate(3.0, 3.0).z(), 8.0, 0.5);
    EXPECT_EQ(model.find(arch)->world->points(), drawn);  // the curve is not changed: the surface moves to it
    // When the arch's plane is dragged 6 mm across the sheet
    const int before = model.factorizations();
    model.beginDrag(plane);
    EXPECT_EQ(model.factorizations(), before + 1);
    for (int event = 1; event <= 3; ++event) {
        PlaneFrame moved = model.find(plane)->frame;
        moved.origin.y() += 2.0;
        model.setPlaneFrame(plane, moved);
        model.update();
        // Then at every event the sheet passes through the moved arch
        EXPECT_LT(guitest::curveToSurface(*model.find(arch)->world, *model.find(sheet)->surface), 0.5) << event;
    }
    model.endDrag();
    EXPECT_NEAR(model.find(arch)->world->evaluate(0.5).y(), 6.0, 1e-9);
    // The arch's middle now rises over y = 6: the sheet's crest moved with it
    const solvers::Surface3d& moved = *model.find(sheet)->surface;
    const solvers::SurfaceProjection foot = solvers::SurfaceProjector(moved).project(model.find(arch)->world->evaluate(0.5));
    EXPECT_LT(foot.distance, 0.5);
}


// Seed 000's dome through the model (§3.2, Figs. 2-3, 8): a rim A drawn on the flat sheet's plane and
// fixed, an arch B across it on a vertical plane, then C across both; each a curve-on-surface
// constraint on a static sheet, solved by the plan's incidence step (the solver-level dome with its
// tolerances: tests/incidence/incidence_dome_test.cpp).
namespace dome {
constexpr double kHeight = 20.0;  // mm, the arches' height at the rim's centre
constexpr double kRim = 40.0;     // mm, the rim's radius on the 120 mm sheet
constexpr double kSheet = 120.0;  // mm
// The fixed rim is a hard constraint: round-off only (1e-9 of the sheet, as the solver-level test).
constexpr double kRimTolerance = 1e-9 * kSheet;
// The arches: the exact rim pins the control points next to it, so the surface lags the cos² rise
// there (solver-level test: 3.1 mm of 20 in that band); here the arches' requests are their control
// polygons' smoothing of the bump and the corner keeps k = 4 of 5 usable directions: measured 4.7 mm
// (B), and 6.0 mm (B and C, k = 2 of 7: every solve starts from the flat prior, not from the sheet
// as A and B left it). Asserted at 35 % of the height. A rim that bounds the sheet instead (the
// window's Interpolation, IncidenceStep.GivenASheetBoundedByAFixedRim...) does far better.
constexpr double kArchTolerance = 0.35 * kHeight;
// The sheet's centre rises at least this much of the arches' 20 mm (measured 17.9 and 18.5 mm).
constexpr double kCentreRiseAtLeast = 0.85 * kHeight;

/// A cubic arch over the vertical plane through the origin along `direction`: 15 control points from
/// -55 to 55 mm, at height kHeight cos²(π s / 2 kRim) inside the rim, 0 outside.
solvers::Curve3d arch(const PlaneFrame& f, const Eigen::Vector3d& direction)
{
    std::vector<Eigen::Vector3d> local;
    for (int i = 0; i < 15; ++i) {
        const double s = -55.0 + 110.0 * i / 14.0;
        const double c = std::abs(s) < kRim ? std::cos(M_PI * s / (2.0 * kRim)) : 0.0;
        Eigen::Vector3d p = f.toLocal(s * direction + Eigen::Vector3d(0, 0, kHeight * c * c));
        p.z() = 0;
        local.push_back(p);
    }
    return solvers::makeClampedUniform<3>(3, local);
}
/// The rim A on `ground`: a closed uniform cubic of 16 control points whose curve has radius kRim (a
/// uniform closed cubic sits at (2 + cos(2π/n))/3 of its polygon's radius).
EntityId addRim(Model& model, EntityId ground)
{
    std::vector<Eigen::Vector3d> circle;
    for (int i = 0; i < 16; ++i) {
        const double a = 2.0 * M_PI * i / 16;
        const double r = kRim * 3.0 / (2.0 + std::cos(2.0 * M_PI / 16));
        Eigen::Vector3d p = model.find(ground)->frame.toLocal(Eigen::Vector3d(r * std::cos(a), r * std::sin(a), 0));
        p.z() = 0;
        circle.push_back(p);
    }
    return model.addCurve(ground, solvers::makeClosedUniform<3>(3, circle));
}

/// `curve` on `sheet` (a curve-on-surface constraint; `preimage` empty: found by projection).
void putOn(Model& model, EntityId curve, EntityId sheet, std::optional<solvers::Curve3d> preimage = std::nullopt)
{
    Constraint on;
    on.type = ConstraintType::CurveOnSurface;
    on.targets = {curve, sheet};
    on.preimage = std::move(preimage);
    model.addConstraint(on);
}

/// An arch across the rim on a vertical plane through the origin along `direction` (in z = 0).
EntityId addArch(Model& model, const Eigen::Vector3d& direction)
{
    const Eigen::Vector3d along = direction.normalized();
    const EntityId plane = model.addPlane(PlaneFrame::fromNormal(Eigen::Vector3d::Zero(), Eigen::Vector3d(-along.y(), along.x(), 0), 150));
    return model.addCurve(plane, arch(model.find(plane)->frame, along));
}
}  // namespace dome

TEST(IncidenceStep, GivenAFixedRimAndArchesAcrossIt_WhenTheSheetIsSolved_ThenTheRimHoldsAndTheSheetBulges)
{
    // Given a flat 20 x 20 sheet (120 mm square at z = 0), the rim A on the sheet's own plane, fixed
    Model model;
    const EntityId sheet = model.addSurface(flatSheet(20));
    const EntityId ground = model.addPlane(PlaneFrame::fromNormal(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 150));
    const EntityId rim = dome::addRim(model, ground);
    dome::putOn(model, rim, sheet);
    model.setFixed(rim, true);
    // ... and B, an arch 20 mm high across it on a vertical plane along (2, 1)
    const EntityId b = dome::addArch(model, Eigen::Vector3d(2, 1, 0));
    dome::putOn(model, b, sheet);

    // When the model is updated
    model.update();
    const Entity& s = *model.find(sheet);
    ASSERT_FALSE(s.failed()) << s.buildError;
    ASSERT_TRUE(s.incidence.has_value());
    const double centreAB = s.surface->evaluate(8.5, 8.5).z();
    std::cout << "Model dome A+B: " << s.solveMessage << "; A " << s.incidence->fixedResidual << " mm, B "
              << s.incidence->residual << " mm, centre " << centreAB << " mm; B to the sheet "
              << guitest::curveToSurface(*model.find(b)->world, *s.surface) << " mm\n";
    // Then the plan solves the sheet by incidence, A exactly, B close, and the sheet bulges
    EXPECT_EQ(model.plan().steps[model.plan().stepOf.at(sheet)].solver, "incidence");
    EXPECT_GT(s.incidence->hardRows, 0);
    EXPECT_LE(s.incidence->fixedResidual, dome::kRimTolerance);
    EXPECT_LE(guitest::curveToSurface(*model.find(rim)->world, *s.surface), dome::kRimTolerance);
    EXPECT_LE(s.incidence->residual, dome::kArchTolerance);
    EXPECT_GE(centreAB, dome::kCentreRiseAtLeast);

    // When C is added across both, along (-1, 2)
    const EntityId c = dome::addArch(model, Eigen::Vector3d(-1, 2, 0));
    dome::putOn(model, c, sheet);
    model.update();
    const Entity& s2 = *model.find(sheet);
    ASSERT_FALSE(s2.failed()) << s2.buildError;
    std::cout << "Model dome A+B+C: " << s2.solveMessage << "; A " << s2.incidence->fixedResidual << " mm, B and C "
              << s2.incidence->residual << " mm, centre " << s2.surface->evaluate(8.5, 8.5).z() << " mm; A to the sheet "
              << guitest::curveToSurface(*model.find(rim)->world, *s2.surface) << " mm\n";
    // Then A still holds to round-off, B and C are close, the centre stays up
    EXPECT_LE(s2.incidence->fixedResidual, dome::kRimTolerance);
    EXPECT_LE(guitest::curveToSurface(*model.find(rim)->world, *s2.surface), dome::kRimTolerance);
    EXPECT_LE(s2.incidence->residual, dome::kArchTolerance);
    EXPECT_LE(guitest::curveToSurface(*model.find(b)->world, *s2.surface), dome::kArchTolerance);
    EXPECT_GE(s2.surface->evaluate(8.5, 8.5).z(), dome::kCentreRiseAtLeast);
    EXPECT_TRUE(model.find(rim)->fixed);
}


/// Arches across a sheet the rim bounds, inside the rim: measured 0.43 mm (B) and 0.27 mm (B and C)
/// from the surface, against 4.7 and 6.0 mm with the rim drawn inside a square sheet (the test
/// above); asserted at 5 % of the arches' 20 mm.
constexpr double kBoundedArchTolerance = 0.05 * dome::kHeight;

/// The largest distance to `surface` of `curve`'s points inside the rim (the arches run on 15 mm
/// beyond it, at z = 0, where a sheet the rim bounds does not reach).
double insideRimToSurface(const solvers::Curve3d& curve, const solvers::Surface3d& surface)
{
    const solvers::SurfaceProjector projector(surface);
    double worst = 0.0;
    for (int k = 0; k <= 400; ++k) {
        const Eigen::Vector3d p = curve.evaluate(curve.domainStart() + (curve.domainEnd() - curve.domainStart()) * k / 400.0);
        if (p.head<2>().norm() < dome::kRim) worst = std::max(worst, projector.project(p).distance);
    }
    return worst;
}

TEST(IncidenceStep, GivenASheetBoundedByAFixedRim_WhenArchesCrossIt_ThenTheRimHoldsAndTheDomeMeetsThem)
{
    // Given the window's Interpolation through a closed rim (ui/sketch_document_incidence.cpp): the
    // sheet bounded by the rim (solvers/incidence/spanning_sheet.h), the rim fixed with the domain's
    // boundary as its pre-image, and arch B across it
    Model model;
    const EntityId ground = model.addPlane(PlaneFrame::fromNormal(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 150));
    const EntityId rim = dome::addRim(model, ground);
    const solvers::incidence::BoundedSheet bounded = solvers::incidence::sheetBoundedBy(*model.find(rim)->world);
    const EntityId sheet = model.addSurface(bounded.surface);
    dome::putOn(model, rim, sheet, preimageCurve(bounded.rimDomain));
    model.setFixed(rim, true);
    const EntityId b = dome::addArch(model, Eigen::Vector3d(2, 1, 0));
    dome::putOn(model, b, sheet);
    // When the model is updated
    model.update();
    const Entity& s = *model.find(sheet);
    ASSERT_FALSE(s.failed()) << s.buildError;
    ASSERT_TRUE(s.incidence.has_value());
    const Eigen::Vector3d top = s.surface->evaluate(0.5 * (s.surface->domainStart(solvers::Direction::U) + s.surface->domainEnd(solvers::Direction::U)),
                                                    0.5 * (s.surface->domainStart(solvers::Direction::V) + s.surface->domainEnd(solvers::Direction::V)));
    const double bInside = insideRimToSurface(*model.find(b)->world, *s.surface);
    std::cout << "Bounded dome A+B: " << s.solveMessage << "; A " << s.incidence->fixedResidual << " mm, B inside the rim "
              << bInside << " mm, middle of the domain at z = " << top.z() << " mm\n";
    // Then the rim holds to round-off, the arch inside it is met within the tolerance, the sheet bulges
    EXPECT_LE(s.incidence->fixedResidual, dome::kRimTolerance);
    EXPECT_LE(guitest::curveToSurface(*model.find(rim)->world, *s.surface), dome::kRimTolerance);
    EXPECT_LE(bInside, kBoundedArchTolerance);
    EXPECT_GE(top.z(), dome::kCentreRiseAtLeast);
    // When C is added across B, then taken away again
    const std::vector<Eigen::Vector3d> withB = s.surface->points();
    const EntityId c = dome::addArch(model, Eigen::Vector3d(-1, 2, 0));
    dome::putOn(model, c, sheet);
    model.update();
    const Entity& s2 = *model.find(sheet);
    ASSERT_FALSE(s2.failed()) << s2.buildError;
    const double bcInside = std::max(insideRimToSurface(*model.find(b)->world, *s2.surface),
                                     insideRimToSurface(*model.find(c)->world, *s2.surface));
    std::cout << "Bounded dome A+B+C: " << s2.solveMessage << "; A " << s2.incidence->fixedResidual << " mm, B and C inside the rim "
              << bcInside << " mm\n";
    // Then A holds, B and C are met within the tolerance
    EXPECT_LE(s2.incidence->fixedResidual, dome::kRimTolerance);
    EXPECT_LE(bcInside, kBoundedArchTolerance);
    // and removing C gives back the surface A and B made, bit for bit (every solve starts from the prior)
    model.remove(c);
    model.update();
    EXPECT_EQ(model.find(sheet)->surface->points(), withB);
}

}  // namespace
}  // namespace sculptline::model
