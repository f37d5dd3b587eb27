#include "model/solver_registry.h"

#include "model/model.h"
#include "solvers/deformation/surface_deformation.h"
#include "solvers/incidence/incidence_solve.h"
#include "solvers/editing/curve_manipulation.h"
#include "solvers/surfaces/surface_modes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace sculptline::model {

namespace surf = solvers::surfaces;

Entity& StepSolver::entity(Model& model, EntityId id) { return model.entity(id); }

namespace {

/// The world curves a construction reads, in input order (the tangent surfaces are not curves).
std::vector<solvers::Curve3d> worldCurves(const Model& model, const Entity& e)
{
    std::vector<solvers::Curve3d> curves;
    for (EntityId input : e.inputs) {
        const Entity* in = model.find(input);
        if (in && in->kind == EntityKind::Curve) curves.push_back(*in->world);
    }
    return curves;
}

/// The solver options of a surface's recipe with the model's present geometry (the revolve axis
/// from its curve, the extrusion direction in its profile plane's frame, the adjacent surfaces of a
/// G1 fill); `curves` loses the revolve axis.
surf::SurfaceOptions surfaceOptions(const Model& model, const Entity& e, std::vector<solvers::Curve3d>& curves)
{
    const SurfaceRecipe& r = *e.recipe;
    surf::SurfaceOptions options;
    options.tolerance = r.tolerance;
    for (const SurfaceRecipe::Tangent& t : r.tangents) {
        const Entity* adjacent = model.find(t.surface);
        if (!adjacent || !adjacent->surface)
            throw std::invalid_argument("surface " + std::to_string(t.surface) + ", which it is tangent to, has not been built");
        options.fillTangents.push_back({t.boundary, *adjacent->surface});
    }
    if (r.mode == Construction::Revolve) {
        // The axis is the line the designer drew: the last input's ends, start to end.
        const solvers::Curve3d axis = curves.back();
        curves.pop_back();
        if (axis.isClosed()) throw std::invalid_argument("axis: the axis curve is closed, its ends coincide and give no direction");
        options.axisPoint = axis.evaluate(axis.domainStart());
        options.axisDirection = axis.evaluate(axis.domainEnd()) - options.axisPoint;
        options.angleDegrees = r.angleDegrees;
    }
    if (r.mode == Construction::Extrude) {
        const Entity& profile = *model.find(e.inputs.front());
        options.direction = profile.plane() != 0 ? Eigen::Vector3d(model.find(profile.plane())->frame.rotation * r.direction) : r.direction;
    }
    return options;
}

void store(Entity& e, const surf::SurfaceBuild& build)
{
    e.surface = build.surface;
    e.maxDeviation = build.maxDeviation;
    e.maxTangentAngle = build.maxTangentAngleDegrees;
    e.buildError.clear();
    ++e.shapeVersion;
}

/// placement: world = frame(local); no set-up.
class PlacementSolver : public StepSolver {
public:
    void factor(const Model&, const PlanStep&) override {}
    void solve(Model& model, const PlanStep& step) override
    {
        for (EntityId id : step.solve) place(model, id);
    }

    static void place(Model& model, EntityId id)
    {
        Entity& e = entity(model, id);
        if (e.kind != EntityKind::Curve || !e.local) return;
        const EntityId plane = e.plane();
        try {
            e.world = plane != 0 ? transformCurve(*e.local, model.find(plane)->frame) : *e.local;
            e.buildError.clear();
        } catch (const std::exception& error) {
            e.buildError = error.what();  // coordinates beyond double range: the last world form stays
        }
    }
};

/// least-change: a curve pulled with its pins held and its fixed points blocked. factor() makes the
/// solver (one QR of the constraint matrix, curve_manipulation.h) at the grip's parameter, which
/// the model passes as the step's first constraint parameter through setGripParameter().
class LeastChangeSolver : public StepSolver {
public:
    explicit LeastChangeSolver(double gripU = std::numeric_limits<double>::quiet_NaN()) : gripU_(gripU) {}

    void factor(const Model& model, const PlanStep& step) override
    {
        curve_ = step.solve.front();
        solver_.reset();
        held_.clear();
        if (!std::isfinite(gripU_)) return;  // no pull: nothing moves the shape
        const Entity& c = *model.find(curve_);
        namespace ed = solvers::editing;
        ed::CurveConstraint<3> grip;
        grip.u = gripU_;
        std::vector<ed::CurveConstraint<3>> constraints{grip};
        std::vector<int> blocked;
        for (ConstraintId id : model.constraintsOn(curve_)) {
            const Constraint& k = *model.findConstraint(id);
            if (k.type == ConstraintType::FixedPoints) blocked = k.indices;
            if (k.type != ConstraintType::Position && k.type != ConstraintType::Tangent) continue;
            ed::CurveConstraint<3> kept;
            kept.type = k.type == ConstraintType::Tangent ? ed::ConstraintType::Tangent : ed::ConstraintType::Position;
            kept.u = k.parameters.front();
            constraints.push_back(kept);
            held_.push_back(c.local->derivatives(kept.u, 1)[k.type == ConstraintType::Tangent ? 1 : 0]);
        }
        try {
            solver_ = std::make_unique<ed::CurveManipulationSolver<3>>(*c.local, constraints, blocked);
        } catch (const std::exception& error) {
            throw std::invalid_argument(error.what());
        }
        if (solver_->freeIndices().empty())
            throw std::invalid_argument("every control point of curve " + std::to_string(curve_) + " is fixed: nothing can move");
        grip_ = solver_->currentValues().front();
    }

    void setGrip(const Eigen::Vector3d& target) override { grip_ = target; }

    void solve(Model& model, const PlanStep& step) override
    {
        message_.clear();
        if (solver_) {
            std::vector<Eigen::Vector3d> targets{grip_};
            targets.insert(targets.end(), held_.begin(), held_.end());
            solvers::editing::ManipulationReport report;
            solvers::Curve3d pulled = solver_->solve(targets, &report);
            message_ = report.message;
            if (curveExtent(pulled) >= kMinCurveExtent) {
                Entity& e = entity(model, curve_);
                e.local = e.plane() != 0 ? flattenToPlane(pulled) : pulled;
                ++e.shapeVersion;
            } else {
                try {
                    requireCurveExtent(pulled);
                } catch (const std::exception& error) {
                    message_ = error.what();  // the curve keeps its last shape
                }
            }
        }
        for (EntityId id : step.solve) PlacementSolver::place(model, id);
    }

    std::string message() const override { return message_; }
    void reset() override
    {
        solver_.reset();
        held_.clear();
    }

private:
    double gripU_;
    EntityId curve_ = 0;
    std::unique_ptr<solvers::editing::CurveManipulationSolver<3>> solver_;
    std::vector<Eigen::Vector3d> held_;
    Eigen::Vector3d grip_ = Eigen::Vector3d::Zero();
    std::string message_;
};

/// surface-builder: SurfaceBuilder made at factor() from the present curves; solve() updates it with
/// the moved curves (fill, loft and sweep keep their parameterization and refinement). Options that
/// follow the geometry (an extrusion's direction with its plane, a revolve's axis, a G1 fill's
/// adjacent surfaces) are re-read each solve; when they changed the builder is made again.
class SurfaceBuilderSolver : public StepSolver {
public:
    void factor(const Model& model, const PlanStep& step) override
    {
        surface_ = step.solve.front();
        builder_.reset();
        const Entity& e = *model.find(surface_);
        if (!e.recipe || !describe(e.recipe->mode).solverMode) return;  // static, or gordon
        std::vector<solvers::Curve3d> curves = worldCurves(model, e);
        try {
            options_ = surfaceOptions(model, e, curves);
            builder_ = std::make_unique<surf::SurfaceBuilder>(*describe(e.recipe->mode).solverMode, curves, options_);
            builtFrom_ = std::move(curves);
        } catch (const std::exception&) {
            builder_.reset();  // it cannot be built as it is: each solve then tries afresh
        }
    }

    void solve(Model& model, const PlanStep& step) override
    {
        for (EntityId id : step.solve) {
            Entity& e = entity(model, id);
            if (!e.recipe) continue;  // a static surface, as read
            try {
                if (builder_ && id == surface_) {
                    std::vector<solvers::Curve3d> curves = worldCurves(model, e);
                    const surf::SurfaceOptions options = surfaceOptions(model, e, curves);
                    if (!sameOptions(options, options_)) {
                        options_ = options;
                        builder_ = std::make_unique<surf::SurfaceBuilder>(builder_->mode(), curves, options_);
                        store(e, builder_->build());
                    } else if (sameCurves(curves, builtFrom_)) {
                        // The builder's last build is of these very curves (a step factored and
                        // solved at once, outside a drag): it is the result, no second build.
                        store(e, builder_->build());
                    } else {
                        store(e, builder_->update(curves));
                    }
                    builtFrom_ = std::move(curves);
                } else {
                    buildSurfaceEntity(model, e);
                }
            } catch (const std::exception& error) {
                // Mid-drag the curves may pass through a configuration the mode cannot build (a
                // fill whose boundaries no longer meet): keep the last good surface and say why.
                e.buildError = error.what();
            }
        }
    }

    void reset() override
    {
        builder_.reset();
        builtFrom_.clear();
    }

private:
    static bool sameOptions(const surf::SurfaceOptions& a, const surf::SurfaceOptions& b)
    {
        if (a.fillTangents.size() != b.fillTangents.size()) return false;
        for (size_t k = 0; k < a.fillTangents.size(); ++k) {
            if (a.fillTangents[k].curve != b.fillTangents[k].curve || a.fillTangents[k].reference.points() != b.fillTangents[k].reference.points()) return false;
        }
        return a.direction == b.direction && a.axisPoint == b.axisPoint && a.axisDirection == b.axisDirection &&
               a.angleDegrees == b.angleDegrees && a.tolerance == b.tolerance;
    }

    static bool sameCurves(const std::vector<solvers::Curve3d>& a, const std::vector<solvers::Curve3d>& b)
    {
        return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const solvers::Curve3d& x, const solvers::Curve3d& y) {
            return x.degree() == y.degree() && x.knots() == y.knots() && x.points() == y.points() && x.weights() == y.weights();
        });
    }

    EntityId surface_ = 0;
    std::unique_ptr<surf::SurfaceBuilder> builder_;
    /// The curves of the builder's last build (what build() is the surface of).
    std::vector<solvers::Curve3d> builtFrom_;
    surf::SurfaceOptions options_;
};

/// The deformation of a sculpt (thesis ch. 6): one Curve constraint per target curve (key points by
/// eq. 6-24, their feet by global projection), a Position (and with its normal held, Tangents)
/// constraint per handle point, the recipe's distances and curve tangents, at the recipe's
/// stiffness, objective, bound and blocked points.
struct SculptProblem {
    const solvers::Surface3d* base = nullptr;
    std::vector<solvers::deformation::SurfaceConstraint> constraints;
    solvers::deformation::DeformationOptions options;
};

/// The domain curve G along which a curve tangent acts: the feet of the target curve on the base
/// (global projection), joined as a polyline in the domain.
solvers::BSplineCurve<2> footCurve(const solvers::Surface3d& base, const solvers::Curve3d& target)
{
    // Enough feet to follow a target across a few dozen spans; the key points along it are found
    // on this polyline (eq. 6-24 counts spans crossed, at most a few per span).
    constexpr int kFeet = 33;
    const solvers::SurfaceProjector projector(base);
    std::vector<Eigen::Vector2d> feet;
    for (int k = 0; k < kFeet; ++k) {
        const double t = target.domainStart() + (target.domainEnd() - target.domainStart()) * k / (kFeet - 1);
        const solvers::SurfaceProjection f = projector.project(target.evaluate(t));
        feet.emplace_back(f.u, f.v);
    }
    std::vector<double> knots{0.0, 0.0};
    for (int k = 1; k < kFeet - 1; ++k) knots.push_back(static_cast<double>(k) / (kFeet - 1));
    knots.insert(knots.end(), {1.0, 1.0});
    return solvers::BSplineCurve<2>(1, knots, feet);
}

/// `withDomains`: compute the curve tangents' domain curves (a set-up: factor() and one-shot
/// builds); a drag's events read values only and skip it.
SculptProblem sculptProblem(const Model& model, const Entity& e, bool withDomains = true)
{
    namespace dfm = solvers::deformation;
    SculptProblem p;
    const Entity* base = model.find(e.inputs.front());
    if (!base || !base->surface) throw std::invalid_argument("base: surface " + std::to_string(e.inputs.front()) + " has no geometry");
    p.base = &*base->surface;
    const SurfaceRecipe& r = *e.recipe;
    std::map<EntityId, solvers::Curve3d> targets;
    for (size_t k = 1; k < e.inputs.size(); ++k) {
        const Entity* in = model.find(e.inputs[k]);
        if (!in || in->kind != EntityKind::Curve) continue;
        dfm::SurfaceConstraint c;
        c.type = dfm::SurfaceConstraintType::Curve;
        c.target = *in->world;
        if (withDomains && !r.curveTangents.empty()) targets.emplace(in->id, *in->world);  // their domains' feet
        p.constraints.push_back(std::move(c));
    }
    for (const SurfaceRecipe::Handle& h : r.handles) {
        const Entity& point = *model.find(h.point);
        dfm::SurfaceConstraint c;
        c.type = dfm::SurfaceConstraintType::Position;
        c.uv = h.uv;
        c.value = point.position;
        p.constraints.push_back(c);
        if (!h.holdNormal) continue;
        // The tangent plane turned with the handle: S_u, S_v of the base rotated by the point's
        // rotation (linear rows whose values alone change when it turns: one factorization a drag).
        const auto der = p.base->derivatives(std::clamp(h.uv.x(), p.base->domainStart(solvers::Direction::U), p.base->domainEnd(solvers::Direction::U)),
                                             std::clamp(h.uv.y(), p.base->domainStart(solvers::Direction::V), p.base->domainEnd(solvers::Direction::V)), 1);
        c.type = dfm::SurfaceConstraintType::Tangents;
        c.value = point.rotation * der[1][0];
        c.value2 = point.rotation * der[0][1];
        p.constraints.push_back(c);
    }
    for (const SurfaceRecipe::Distance& d : r.distances) {
        dfm::SurfaceConstraint c;
        c.type = dfm::SurfaceConstraintType::Distance;
        c.uv = d.uv;
        c.uv2 = d.uv2;
        c.distance = d.distance;
        p.constraints.push_back(c);
    }
    for (const SurfaceRecipe::CurveTangent& t : r.curveTangents) {
        dfm::SurfaceConstraint c;
        c.type = dfm::SurfaceConstraintType::CurveTangent;
        c.value = t.direction;
        const auto it = targets.find(t.curve);
        if (withDomains && it != targets.end()) c.domain = footCurve(*p.base, it->second);
        p.constraints.push_back(std::move(c));
    }
    p.options.stiffness = r.stiffness;
    p.options.objective = r.displacementObjective ? dfm::Objective::Displacement : dfm::Objective::Force;
    p.options.bound = r.bound;
    p.options.blocked = r.blocked;
    return p;
}

void storeSculpt(Entity& e, solvers::Surface3d surface, const solvers::deformation::DeformationReport& report)
{
    // The largest residual is the deviation from the construction (the inspector shows it): a
    // compromise (conflicting targets, too few free points) keeps the least-squares surface, and
    // says so in solveMessage.
    store(e, surf::SurfaceBuild{std::move(surface), report.maxResidual});
    e.solveMessage = report.message;
}

/// deformation: a sculpt's solver factored once per drag (F and the objective's factorization for
/// the key points found at the press); each event moves only the targets: one back-substitution.
class DeformationStepSolver : public StepSolver {
public:
    void factor(const Model& model, const PlanStep& step) override
    {
        surface_ = step.solve.front();
        solver_.reset();
        const Entity& e = *model.find(surface_);
        try {
            const SculptProblem p = sculptProblem(model, e);
            auto solver = std::make_unique<solvers::deformation::SurfaceDeformationSolver>();
            solver->factor(*p.base, p.constraints, p.options);
            solver_ = std::move(solver);
            baseVersion_ = model.find(e.inputs.front())->shapeVersion;
        } catch (const std::exception&) {
            solver_.reset();  // it cannot be solved as it is: each solve then tries afresh
        }
    }
    void solve(Model& model, const PlanStep& step) override
    {
        for (EntityId id : step.solve) {
            Entity& e = entity(model, id);
            try {
                solvers::deformation::DeformationReport report;
                // The factorization holds while the base stays (its shape version, bumped by each
                // rebuild); a rebuilt base is solved afresh.
                if (solver_ && id == surface_ && model.find(e.inputs.front())->shapeVersion == baseVersion_) {
                    const SculptProblem values = sculptProblem(model, e, false);
                    storeSculpt(e, solver_->solve(values.constraints, &report), report);
                } else {
                    const SculptProblem p = sculptProblem(model, e);
                    storeSculpt(e, solvers::deformation::deformSurface(*p.base, p.constraints, p.options, &report), report);
                }
            } catch (const std::exception& error) {
                e.buildError = error.what();  // the last good surface stays
            }
        }
    }
    void reset() override { solver_.reset(); }

private:
    EntityId surface_ = 0;
    std::unique_ptr<solvers::deformation::SurfaceDeformationSolver> solver_;
    int baseVersion_ = -1;
};

/// incidence: a surface entity without a recipe and the curves lying on it (curve-on-surface, seed
/// 000): the curves keep their placement, and the surface is solved to pass through them
/// (solvers/incidence: fixed curves exactly, the others by TSVD at the L-curve's corner corrected by
/// MTSVD), always from the surface's prior (Entity::prior: its shape before the first curve), so
/// the result depends on the curves and k, not on the order of edits. factor() (a drag's start)
/// keeps the solver: the SVD, k and MTSVD's correction; each event is then the curves' new
/// right-hand side and two products. Outside a drag, or when a curve changed its layout (an
/// over-sketch adds knots), the surface is solved afresh from the prior.
class IncidenceStepSolver : public StepSolver {
public:
    void factor(const Model& model, const PlanStep& step) override
    {
        solver_.reset();
        for (EntityId id : step.solve) {
            const Entity* e = model.find(id);
            if (!e || e->kind != EntityKind::Surface || !e->surface) continue;
            try {
                auto solver = std::make_unique<solvers::incidence::IncidenceSolver>();
                solver->factor(e->prior ? *e->prior : *e->surface, curvesOn(model, step, id), options(*e));
                solver_ = std::move(solver);
                surface_ = id;
            } catch (const std::exception&) {
                solver_.reset();  // each solve tries afresh (and says why)
            }
        }
    }
    void solve(Model& model, const PlanStep& step) override
    {
        for (EntityId id : step.solve) PlacementSolver::place(model, id);
        for (EntityId id : step.solve) {
            Entity& s = entity(model, id);
            if (s.kind != EntityKind::Surface || !s.surface) continue;
            const std::vector<solvers::incidence::IncidenceCurve> curves = curvesOn(model, step, id);
            if (curves.empty()) continue;
            try {
                std::string note;
                const solvers::incidence::IncidenceResult r = [&] {
                    if (solver_ && surface_ == id && solver_->fits(curves)) return solver_->solve(curves);
                    try {
                        return solvers::incidence::solveIncidence(s.prior ? *s.prior : *s.surface, curves, options(s));
                    } catch (const std::invalid_argument&) {
                        // The designer's k exceeds what the curves now give (one was deleted): the corner.
                        if (s.incidenceK == 0) throw;
                        solvers::incidence::IncidenceResult atCorner = solvers::incidence::solveIncidence(s.prior ? *s.prior : *s.surface, curves);
                        note = "; k = " + std::to_string(s.incidenceK) + " is beyond the " + std::to_string(atCorner.lcurve.rho.size()) +
                               " singular values the curves give: the corner is used";
                        return atCorner;
                    }
                }();

                store(s, surf::SurfaceBuild{r.surface, std::max(r.residual, r.fixedResidual)});
                Entity::IncidenceReport report;
                report.rho.assign(r.lcurve.rho.data(), r.lcurve.rho.data() + r.lcurve.rho.size());
                report.eta.assign(r.lcurve.eta.data(), r.lcurve.eta.data() + r.lcurve.eta.size());
                report.k = r.k;
                report.corner = r.corner;
                report.rows = r.rows;
                report.cols = r.cols;
                report.hardRows = r.hardRows;
                report.curves = static_cast<int>(curves.size());
                report.residual = r.residual;
                report.fixedResidual = r.fixedResidual;
                s.incidence = std::move(report);
                const bool soft = std::any_of(curves.begin(), curves.end(), [](const auto& c) { return !c.fixed && c.target; });
                if (r.k == 0 && soft)
                    note += "; the fixed curves leave the surface no freedom where the others are (more control points would give some)";
                s.solveMessage = "through " + std::to_string(curves.size()) + (curves.size() == 1 ? " curve" : " curves") +
                                 ": k = " + std::to_string(r.k) + " of " + std::to_string(r.lcurve.rho.size()) + " (the L-curve's corner " +
                                 std::to_string(r.corner) + ")" + note;
            } catch (const std::exception& error) {
                s.buildError = error.what();  // the last surface stays
            }
        }
    }
    void reset() override { solver_.reset(); }

private:
    /// The curves on `surface` among the step's constraints: their world forms as targets, their
    /// pre-images (when the constraint has one) as domains, fixed when the curve is.
    static std::vector<solvers::incidence::IncidenceCurve> curvesOn(const Model& model, const PlanStep& step, EntityId surface)
    {
        std::vector<solvers::incidence::IncidenceCurve> curves;
        for (ConstraintId k : step.constraints) {
            const Constraint* c = model.findConstraint(k);
            if (!c || c->type != ConstraintType::CurveOnSurface || c->targets.size() != 2 || c->targets[1] != surface) continue;
            const Entity* curve = model.find(c->targets[0]);
            if (!curve || !curve->world) continue;
            solvers::incidence::IncidenceCurve in;
            in.target = *curve->world;
            in.fixed = curve->fixed;
            if (c->preimage) in.domain = preimageDomain(*c->preimage);
            curves.push_back(std::move(in));
        }
        return curves;
    }

    /// The designer's truncation (0 = the corner).
    static solvers::incidence::IncidenceOptions options(const Entity& surface)
    {
        solvers::incidence::IncidenceOptions o;
        o.k = surface.incidenceK;
        return o;
    }

    EntityId surface_ = 0;
    std::unique_ptr<solvers::incidence::IncidenceSolver> solver_;
};

/// network-mesh: the loop is triangulated afresh (no set-up to keep).
class MeshSolver : public StepSolver {
public:
    void factor(const Model&, const PlanStep&) override {}
    void solve(Model& model, const PlanStep& step) override
    {
        for (EntityId id : step.solve) {
            Entity& e = entity(model, id);
            try {
                buildMeshEntity(model, e);
            } catch (const std::exception& error) {
                e.buildError = error.what();  // the curves pulled apart mid-drag: keep the last mesh
            }
        }
    }
};

/// solid: a solid's surfaces changed; its conversion takes seconds, so the step only marks it due
/// (a new sourceVersion) and the conversion runs outside update() (model/solid_job.h): a drag's
/// events cost nothing here, and the ui converts once the drag has ended.
class SolidDueSolver : public StepSolver {
public:
    void factor(const Model&, const PlanStep&) override {}
    void solve(Model& model, const PlanStep& step) override
    {
        for (EntityId id : step.solve) ++entity(model, id).sourceVersion;
    }
};

/// unsolved: a cluster of coupled free entities no registered solver handles (yet); its entities
/// keep their geometry. Curves still take their placement.
class UnsolvedCluster : public StepSolver {
public:
    void factor(const Model&, const PlanStep&) override {}
    void solve(Model& model, const PlanStep& step) override
    {
        for (EntityId id : step.solve) PlacementSolver::place(model, id);
    }
    std::string message() const override { return "no solver handles this cluster of coupled constraints yet"; }
};

}  // namespace

void buildSurfaceEntity(const Model& model, Entity& e)
{
    const SurfaceRecipe& r = *e.recipe;
    std::vector<solvers::Curve3d> curves = worldCurves(model, e);
    if (r.mode == Construction::Gordon) {
        // A grid-like network (seed 004 §4, The NURBS Book §10.5): the first `uCurves` inputs are
        // one family, the rest the other; every curve of one meets every curve of the other. The
        // reported deviation is the largest gap between crossing curves.
        const auto split = curves.begin() + std::clamp(r.uCurves, 0, static_cast<int>(curves.size()));
        const surf::GordonResult g = surf::buildGordon({curves.begin(), split}, {split, curves.end()}, {r.tolerance});
        store(e, surf::SurfaceBuild{g.surface, g.maxGap});
        return;
    }
    const ConstructionInfo& info = describe(r.mode);
    if (r.mode == Construction::Sculpt) {
        const SculptProblem p = sculptProblem(model, e);
        solvers::deformation::DeformationReport report;
        storeSculpt(e, solvers::deformation::deformSurface(*p.base, p.constraints, p.options, &report), report);
        return;
    }
    if (!info.solverMode) throw std::invalid_argument(std::string("\"") + info.name + "\" makes a mesh entity from a loop of curves, not a surface");
    const surf::SurfaceOptions options = surfaceOptions(model, e, curves);
    store(e, surf::buildSurface(*info.solverMode, curves, options));
}

void buildMeshEntity(const Model& model, Entity& e)
{
    std::vector<solvers::Curve3d> curves;
    std::vector<int> loop;
    for (EntityId input : e.inputs) {
        loop.push_back(static_cast<int>(curves.size()));
        curves.push_back(*model.find(input)->world);
    }
    e.mesh = surf::meshNetwork(curves, {loop});
    e.buildError.clear();
    ++e.shapeVersion;
}

SolverRegistry::SolverRegistry()
{
    add("placement", [] { return std::make_unique<PlacementSolver>(); });
    add("least-change", [] { return std::make_unique<LeastChangeSolver>(); });
    add("surface-builder", [] { return std::make_unique<SurfaceBuilderSolver>(); });
    add("network-mesh", [] { return std::make_unique<MeshSolver>(); });
    add("solid", [] { return std::make_unique<SolidDueSolver>(); });
    add("deformation", [] { return std::make_unique<DeformationStepSolver>(); });
    add("incidence", [] { return std::make_unique<IncidenceStepSolver>(); });
    add("unsolved", [] { return std::make_unique<UnsolvedCluster>(); });
}

void SolverRegistry::add(const std::string& key, Factory factory) { factories_[key] = std::move(factory); }

std::unique_ptr<StepSolver> SolverRegistry::make(const std::string& key) const
{
    const auto it = factories_.find(key);
    if (it == factories_.end()) throw std::invalid_argument("no solver is registered as \"" + key + "\"");
    return it->second();
}

std::string SolverRegistry::choose(const Model& model, const PlanStep& step) const
{
    // Curves lying on one surface without a recipe (and the curves' placements): incidence.
    const auto onSurface = [&] {
        int surfaces = 0, onIt = 0;
        for (EntityId id : step.solve) {
            const Entity* e = model.find(id);
            if (!e) return false;
            if (e->kind == EntityKind::Surface) {
                if (e->recipe || !e->surface) return false;
                ++surfaces;
            } else if (e->kind != EntityKind::Curve) {
                return false;
            }
        }
        for (ConstraintId id : step.constraints) {
            const Constraint* c = model.findConstraint(id);
            if (!c) continue;
            if (c->type == ConstraintType::CurveOnSurface) ++onIt;
            else if (c->type != ConstraintType::Placement) return false;
        }
        return surfaces == 1 && onIt > 0;
    };
    if (onSurface()) return "incidence";
    if (step.solve.size() != 1) return "unsolved";
    const Entity* e = model.find(step.solve.front());
    if (!e) return "unsolved";
    bool construction = false, placement = false, pins = false, other = false;
    for (ConstraintId id : step.constraints) {
        const Constraint* c = model.findConstraint(id);
        if (!c) continue;
        switch (c->type) {
        case ConstraintType::Construction: construction = true; break;
        case ConstraintType::Placement: placement = true; break;
        case ConstraintType::Position:
        case ConstraintType::Tangent:
        case ConstraintType::FixedPoints: pins = true; break;
        default: other = true;
        }
    }
    if (other) return "unsolved";
    if (e->kind == EntityKind::Surface && construction && e->recipe && e->recipe->mode == Construction::Sculpt) return "deformation";
    if (e->kind == EntityKind::Surface && construction) return "surface-builder";
    if (e->kind == EntityKind::Mesh && construction) return "network-mesh";
    if (e->kind == EntityKind::Solid && construction) return "solid";
    if (e->kind == EntityKind::Curve && pins) return "least-change";
    if (e->kind == EntityKind::Curve && placement) return "placement";
    return "unsolved";
}

bool SolverRegistry::caches(const std::string& key) const
{
    return key == "surface-builder" || key == "deformation" || key == "incidence";
}

std::unique_ptr<StepSolver> makePullSolver(double u) { return std::make_unique<LeastChangeSolver>(u); }

}  // namespace sculptline::model
