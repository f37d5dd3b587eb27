#pragma once
// The model (seed 000 §3.2): a constraint graph of entities — projection planes, curves, surfaces,
// meshes, points — and the constraints between them (model/constraint.h), each entity fixed, free
// or changed. Plain C++ on the kernel's types (no Coin, no Qt), so a document can be loaded and
// re-solved headless; scene/model_view.h shows it with Coin nodes.
//
// Updates are explicit and lazy: an edit (a plane moved) marks the entity changed and calls the
// dirty callback once (the scheduler, scene/update_scheduler.h, turns that into one update per
// displayed frame); update() then runs the construction plan's steps (model/plan.h) that lie
// downstream of the changed entities, each exactly once, in plan order, each step by the solver
// the registry (model/solver_registry.h) gives for it. The plan is made again only when the
// distribution of freedom changes (an entity or constraint added or removed, an entity fixed or
// freed); a drag re-uses it, and the solvers of the steps it drives keep their factorizations from
// beginDrag() to endDrag(), outside the undo snapshots (Entity, Constraint), which stay plain data.
#include "model/constraint.h"
#include "model/entity_kind.h"
#include "model/plan.h"
#include "model/plane_frame.h"
#include "model/solid_recipe.h"
#include "model/surface_recipe.h"
#include "solvers/bspline/bspline_surface.h"
#include "solvers/surfaces/network_mesh.h"
#include "solvers/volume/solidify.h"

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace sculptline::model {

struct Entity {
    EntityId id = 0;
    EntityKind kind = EntityKind::Plane;
    /// What it is made from, in the order its construction reads them (a curve: its plane, if any;
    /// a surface: its curves in the mode's order, then the surfaces a G1 fill is tangent to; a
    /// mesh: its loop). The model derives the placement and construction constraints from it.
    std::vector<EntityId> inputs;
    /// Fixed by the designer (persistent; Model::state adds "changed").
    bool fixed = false;

    PlaneFrame frame;  ///< Plane: where it is
    /// Curve: the curve in its plane's local frame (z = 0), or in world coordinates when the curve
    /// lies on no plane. The source of truth: a plane drag never touches it.
    std::optional<solvers::Curve3d> local;
    /// Curve: derived world-space curve (the frame applied to the control points), kept for
    /// dependents (surfaces) and export; recomputed by update().
    std::optional<solvers::Curve3d> world;
    /// Surface: the current surface (rebuilt from the inputs by update() when it has a recipe).
    std::optional<solvers::Surface3d> surface;
    /// Surface: how it is built from its input curves (`inputs`, in the mode's order); absent = a
    /// static surface as read from a document.
    std::optional<SurfaceRecipe> recipe;
    /// Point: where it is, world coordinates.
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    /// Point: how it is turned from where it was made (a sculpt handle tilts the normal by it).
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
    /// Surface: what the solver remarked on its last build although it succeeded (a compromise
    /// between conflicting constraints, a target outside the bound); empty when nothing.
    std::string solveMessage;
    /// Surface, mesh: why the last rebuild failed (the curves no longer meet, ...), empty when it
    /// succeeded; the last good surface is kept meanwhile. A surface whose build never succeeded
    /// (a document whose construction cannot be rebuilt) has no `surface` at all.
    std::string buildError;
    bool failed() const { return !buildError.empty(); }
    /// Surface: the deviation an approximating mode reached (model units); negative for exact modes.
    double maxDeviation = -1.0;
    /// Mesh: the triangulated loop of its input curves (in loop order), rebuilt with them.
    std::optional<solvers::surfaces::NetworkMesh> mesh;
    /// Surface: a G1 fill's largest angle (degrees) between its normals and those of the surfaces
    /// it is tangent to, across those boundaries; negative otherwise.
    double maxTangentAngle = -1.0;
    /// Surface without a recipe that curves lie on (the incidence step, seed 000): the designer's
    /// truncation k (0 = the L-curve's corner, the default), saved with the surface.
    int incidenceK = 0;
    /// Surface without a recipe with curves lying on it: the shape it had before the first curve was
    /// put on it (seed 000's prior F0). Every incidence solve starts from it, so the solved shape
    /// depends on the curves and k only, not on the order of edits: removing the curves (an undo)
    /// gives it back. Saved with the surface; none while no curve lies on it.
    std::optional<solvers::Surface3d> prior;
    /// Surface: what the last incidence solve found (its L-curve, the k it used, the corner, the
    /// residuals; the L-curve dock shows it); none when no incidence solve ran. Not saved.
    struct IncidenceReport {
        std::vector<double> rho, eta;  ///< ρ_k = ‖A F_k − H‖, η_k = ‖F_k − F0‖ for k = 1..r
        int k = 0, corner = 0;
        int rows = 0, cols = 0, hardRows = 0, curves = 0;
        double residual = 0.0, fixedResidual = 0.0;  ///< model units (incidence_solve.h)
    };
    std::optional<IncidenceReport> incidence;
    /// Surface: the inputs of its construction in the mode's order (curves; a sculpt's base surface
    /// first); the inputs that follow are the surfaces a G1 fill is tangent to.
    std::vector<std::uint32_t> curveInputs() const
    {
        return std::vector<std::uint32_t>(inputs.begin(), inputs.end() - static_cast<long>(tangentSurfaceCount()));
    }
    /// Surface: how many of its inputs are surfaces it is tangent to (at the end of `inputs`).
    size_t tangentSurfaceCount() const;

    /// Solid: how it is made from its input surfaces (`inputs`).
    std::optional<SolidRecipe> solidRecipe;
    /// Solid: its last finished conversion (mesh, volume, area, voxel size); none before the first.
    /// Conversions take seconds, so update() does not run them: it bumps sourceVersion, and a
    /// caller (the ui's background builder, or runSolidJob headless) converts and hands the result
    /// to setSolidResult() (model/solid_job.h).
    std::optional<solvers::volume::Solid> solid;
    int sourceVersion = 0;   ///< Solid: bumped whenever an input surface changed
    int solidVersion = -1;   ///< Solid: the sourceVersion `solid` was converted from
    bool solidStale() const { return kind == EntityKind::Solid && solidVersion != sourceVersion; }

    int recomputations = 0;  ///< times update() recomputed this entity (tests count them)
    /// Curve: bumped whenever `local` is replaced (an over-sketch), so views know to re-tessellate;
    /// a plane drag leaves it alone. Surface: bumped on every rebuild.
    int shapeVersion = 0;

    EntityId plane() const { return kind == EntityKind::Curve && !inputs.empty() ? inputs.front() : 0; }
};

/// Told about every change, after it happened (the Coin view, the ui's manipulators and lists).
class ModelObserver {
public:
    virtual ~ModelObserver() = default;
    virtual void entityAdded(const Entity& entity) = 0;
    virtual void entityRemoved(const Entity& entity) = 0;  ///< still readable during the call
    /// Recomputed by update() (a Plane: its frame changed; a Curve: its world form), or its state
    /// or fixed points changed.
    virtual void entityUpdated(const Entity& entity) = 0;
    /// The designer's constraints (pins, fixed points, ...): added, removed (still readable), and
    /// their values recomputed with the geometry they hold.
    virtual void constraintAdded(const Constraint&) {}
    virtual void constraintRemoved(const Constraint&) {}
    virtual void constraintUpdated(const Constraint&) {}
};

/// What Model::remove took out (dependents and the constraints on them), in creation order: what
/// undo needs to put it back with Model::restore.
struct Removed {
    std::vector<Entity> entities;
    std::vector<Constraint> constraints;  ///< the designer's only; derived ones come back with their entity
};

/// Degrees of freedom of one entity (seed 000 §3.2, Fig. 3): how many its geometry has and how many
/// its constraints consume; what is left is what a sketch interpreted onto it may still change.
struct Dof {
    int total = 0;
    int consumed = 0;
    int free() const { return consumed >= total ? 0 : total - consumed; }
};

class StepSolver;
class SolverRegistry;

class Model {
public:
    Model();
    ~Model();
    Model(const Model&) = delete;
    Model& operator=(const Model&) = delete;
    /// Moves the graph; observers, callbacks and solver caches stay with the source.
    Model(Model&& other) noexcept;
    Model& operator=(Model&& other) noexcept;

    /// Adds a plane; `id` restores a removed entity under its old id (undo), 0 = a fresh one.
    EntityId addPlane(const PlaneFrame& frame, EntityId id = 0);
    /// Adds a curve on `plane` (its points in the plane's local frame, z = 0), or a world-space
    /// curve when plane = 0. @throws std::invalid_argument when `plane` is not a plane.
    EntityId addCurve(EntityId plane, const solvers::Curve3d& local, EntityId id = 0);
    EntityId addSurface(const solvers::Surface3d& surface, EntityId id = 0);
    /// Adds a point (world coordinates), turned by `rotation` (normalized).
    /// @throws std::invalid_argument when it is not finite or the rotation is zero.
    EntityId addPoint(const Eigen::Vector3d& position, EntityId id = 0,
                      const Eigen::Quaterniond& rotation = Eigen::Quaterniond::Identity());
    /// Moves and turns a point: marks it changed (a sculpt handle's dragger). A fixed point, or a
    /// non-finite or zero pose, is refused (the point stays).
    void setPointPose(EntityId point, const Eigen::Vector3d& position, const Eigen::Quaterniond& rotation);
    /// Adds a surface built from `curves` (world forms) by `recipe`, rebuilt whenever one of them
    /// changes. When the first build fails, `saved` (the surface as it was saved or before an undo)
    /// stands in with buildError set; without it nothing is added.
    /// @throws std::invalid_argument when an input is not a curve, the count does not fit the mode,
    ///         or the build fails and there is no `saved` surface (the message says why).
    EntityId addSurface(const std::vector<EntityId>& curves, const SurfaceRecipe& recipe, EntityId id = 0,
                        const solvers::Surface3d* saved = nullptr);
    /// Restores a surface built from `curves` by `recipe` (a document being opened, an undo) that
    /// may not build any more: a failed build keeps the entity, with `saved` as its last surface
    /// (or no surface at all) and buildError saying why, so nothing else is lost and it rebuilds
    /// once its curves allow.
    /// @throws std::invalid_argument only when `recipe` does not fit `curves` (count, kinds).
    EntityId restoreSurface(const std::vector<EntityId>& curves, const SurfaceRecipe& recipe, EntityId id,
                            const std::optional<solvers::Surface3d>& saved);
    /// The surface entity `addSurface(curves, recipe)` would add (built, id 0), without adding it.
    /// @throws std::invalid_argument as addSurface does.
    Entity makeSurface(const std::vector<EntityId>& curves, const SurfaceRecipe& recipe) const;
    /// Adds a mesh filling the closed loop of `curves` (chained end to end, in this order; one
    /// closed curve is a loop too), rebuilt whenever one of them changes. `keepOnFailure`: when
    /// they make no loop, add it empty with buildError set (documents, undo) instead of throwing.
    /// @throws std::invalid_argument when an input is not a curve or the curves make no loop.
    EntityId addMesh(const std::vector<EntityId>& curves, EntityId id = 0, bool keepOnFailure = false);
    /// Adds a solid made from `surfaces` by `recipe`. With `result` (an undo, a document that saved
    /// the conversion) it is current; without, it is due for conversion (Entity::solidStale()).
    /// @throws std::invalid_argument when an input is not a surface, there is none, or the recipe
    ///         is invalid (validate(SolidRecipe)).
    EntityId addSolid(const std::vector<EntityId>& surfaces, const SolidRecipe& recipe, EntityId id = 0,
                      const std::optional<solvers::volume::Solid>& result = std::nullopt);
    /// A conversion of `solid` finished (model/solid_job.h): stored when it was made from the inputs
    /// as they still are (`version` == sourceVersion), observers told; returns false (nothing
    /// changes) for a stale version or an entity that is no solid any more.
    bool setSolidResult(EntityId solid, int version, solvers::volume::Solid result);
    /// A conversion of `solid` at `version` failed or was cancelled: buildError says why, the last
    /// good mesh stays. Ignored for a stale version.
    bool setSolidError(EntityId solid, int version, const std::string& error);
    /// The mesh entity addMesh(curves) would add (built, id 0), without adding it.
    /// @throws std::invalid_argument as addMesh does.
    Entity makeMesh(const std::vector<EntityId>& curves) const;
    /// Adds an entity as it was (an undo, a redo): its kind's add with its id, its fixed state.
    /// @throws std::invalid_argument as that add does.
    EntityId restore(const Entity& entity);
    /// Puts back what remove() took out (entities, then the designer's constraints on them).
    void restore(const Removed& removed);
    /// Replaces a built surface's recipe (an extrusion following the pointer): marks it changed.
    void setSurfaceRecipe(EntityId surface, const SurfaceRecipe& recipe);
    /// A surface without a recipe takes `surface` as its shape (an undo of an incidence edit, a
    /// re-sketched parameter line); what depends on it is rebuilt at the next update, and curves
    /// lying on it are met again from there. Ignored for a fixed surface, one with a recipe (its
    /// curves make it), or a surface that is not finite.
    void setSurfaceShape(EntityId surface, const solvers::Surface3d& shape);
    /// A surface's incidence prior (Entity::prior), as a document saved it.
    void setIncidencePrior(EntityId surface, const std::optional<solvers::Surface3d>& prior);
    /// A surface's incidence truncation (Entity::incidenceK; 0 = the L-curve's corner); the surface is
    /// solved again. Ignored for a fixed surface, or a negative k.
    void setIncidenceK(EntityId surface, int k);

    /// Adds one of the designer's constraints (not placement or construction, which the model
    /// derives). `constraint.id` != 0 restores it under that id. Its targets and sources must
    /// exist and fit the type; parameters must be finite; a pin's value is computed from its curve.
    /// @throws std::invalid_argument saying what does not fit.
    ConstraintId addConstraint(Constraint constraint);
    /// A pin: C(u) ("position") or C'(u) ("tangent") of `curve` kept while it is pulled.
    /// @throws std::invalid_argument for a non-curve, another type or a non-finite parameter.
    ConstraintId addConstraint(EntityId curve, ConstraintType type, double u, ConstraintId id = 0);
    /// Removes one of the designer's constraints; returns it (empty when there is none such).
    std::optional<Constraint> removeConstraint(ConstraintId id);
    /// Sets which control points of `curve` stay fixed when it is pulled (indices are checked):
    /// one FixedPoints constraint on the curve, removed when `fixed` is empty.
    /// @throws std::invalid_argument for an index out of range.
    void setFixedPoints(EntityId curve, std::vector<int> fixed);
    /// The control points of `curve` held by its FixedPoints constraint, ascending (unique points of
    /// a closed curve); empty when none.
    std::vector<int> fixedPoints(EntityId curve) const;
    /// Fixes or frees an entity (seed 000 §3.2): a fixed one refuses edits and solves never change
    /// it. Changes the distribution of freedom: the next plan() is a new one.
    void setFixed(EntityId id, bool fixed);
    /// Fixed, free, or changed (edited, its dependents not updated yet).
    State state(EntityId id) const;

    /// Moves a plane: only marks it changed (the curves follow in the next update()). A fixed
    /// plane, or a non-finite frame, is refused (the plane stays).
    void setPlaneFrame(EntityId plane, const PlaneFrame& frame);

    /// Replaces a curve's shape (in its plane's frame; z is set to 0 on a plane): marks it changed,
    /// its world form and dependents follow in the next update(). A fixed curve stays.
    void setCurveShape(EntityId curve, const solvers::Curve3d& local);

    /// Removes `id` and everything that depends on it, dependents first, with the constraints on
    /// them; returns what was removed in creation order (what undo needs to restore them).
    Removed remove(EntityId id);

    /// Runs the plan's steps for every changed entity's dependents once, in plan order; returns how
    /// many entities were recomputed.
    int update();
    bool updatePending() const { return !dirty_.empty(); }

    void clear();

    const Entity* find(EntityId id) const;
    /// All entities in creation order.
    const std::map<EntityId, Entity>& entities() const { return entities_; }
    /// Direct dependents of `id` (entities whose placement or construction reads it).
    std::vector<EntityId> dependents(EntityId id) const;

    /// Every constraint of the graph, derived ones included, by id.
    const std::map<ConstraintId, Constraint>& constraints() const { return constraints_; }
    const Constraint* findConstraint(ConstraintId id) const;
    /// The constraints that read or consume `entity` (derived ones included), ascending ids.
    std::vector<ConstraintId> constraintsOn(EntityId entity) const;

    /// Degrees of freedom of `entity`: what its geometry has (a curve on a plane: two per unique
    /// control point; in space, and a surface's: three; a plane: six; a point: three; a mesh:
    /// none of its own), and what the constraints targeting it consume (a construction or a
    /// placement consumes all of it; a pin 2 in a plane, 3 in space; fixed points 2 or 3 each).
    Dof dof(EntityId entity) const;

    /// The construction plan (model/plan.h) for the present graph and states; made again only when
    /// the distribution of freedom changed since the last one.
    const Plan& plan() const;
    /// How many plans were made (tests check that a drag re-uses one).
    int planCount() const { return planCount_; }

    /// A drag starts on `entity` (a plane's dragger pressed, a curve grabbed): the solvers of the
    /// plan's steps downstream of it are made and factored now, once, and each update() until
    /// endDrag() re-solves with them (surface builders keep their parameterization). Ends a drag
    /// in progress first.
    void beginDrag(EntityId entity);
    /// Starts pulling `curve` at parameter `u` (thesis §6.1): a drag of the curve whose own
    /// least-change solver is factored here, with its pins held and its fixed points blocked.
    /// @throws std::invalid_argument when the curve cannot be pulled (fixed, no freedom left,
    ///         constraints it cannot keep: the message says why); no drag is then in progress.
    void beginPull(EntityId curve, double u);
    /// Moves the pulled point to `local` (the curve's plane frame, or world for a curve in space):
    /// one solve with the pull's factorization; the curve is marked changed. Returns the solver's
    /// message when it compromised (constraints that cannot all be met), empty otherwise; a result
    /// smaller than kMinCurveExtent is refused (the curve keeps its last shape, the message says so).
    std::string pullTo(const Eigen::Vector3d& local);
    /// Ends the drag: its solvers are dropped, and the surfaces it rebuilt incrementally are marked
    /// changed so the next update() rebuilds them as a fresh build would (the resting shape).
    void endDrag();
    /// The entity being dragged, or 0.
    EntityId dragged() const { return dragged_; }
    /// Solver set-ups (factor() calls) since the model was made: a drag's events add none.
    int factorizations() const { return factorizations_; }

    void addObserver(ModelObserver* observer) { observers_.push_back(observer); }
    void removeObserver(ModelObserver* observer);
    /// Called when the first entity becomes changed after an update (schedule an update then).
    void setDirtyCallback(std::function<void()> callback) { dirtyCallback_ = std::move(callback); }

private:
    friend class StepSolver;
    /// `built`: the entity's derived data is already computed (a surface built by addSurface).
    EntityId insert(Entity entity, EntityId id, bool built = false);
    ConstraintId insertConstraint(Constraint constraint);
    /// The placement or construction constraint that `entity`'s inputs imply, if any.
    void deriveConstraints(const Entity& entity);
    void recompute(Entity& entity);
    /// @throws std::invalid_argument when `curves` do not fit `recipe` (count, kinds).
    void checkSurfaceInputs(const std::vector<EntityId>& curves, const SurfaceRecipe& recipe) const;
    /// A sculpt's handles, bound, blocked points, distances and curve tangents against its inputs
    /// (one handle per point input, finite values, a bound of three points or more).
    /// @throws std::invalid_argument saying what does not fit.
    void checkSculptRecipe(const std::vector<EntityId>& inputs, const SurfaceRecipe& recipe) const;
    /// A surface entity over `curves` with `recipe`, checked but not built yet.
    Entity unbuiltSurface(const std::vector<EntityId>& curves, const SurfaceRecipe& recipe) const;
    void markDirty(EntityId id);
    void freedomChanged()
    {
        planValid_ = false;
        downstreamValid_ = false;
    }
    /// stepsAfter(plan(), ..., changed), remembered for the last `changed` while the plan lasts (a
    /// drag asks the same question every event).
    const std::vector<size_t>& downstreamSteps(const std::set<EntityId>& changed);
    /// Recomputes the values the designer's constraints on `curve` hold (a pin's point).
    void refreshConstraintValues(EntityId curve);
    /// A curve-on-surface constraint was added to or removed from `surface`: the first one keeps the
    /// surface's shape as its prior, removing the last gives that shape back; the surface is solved
    /// again at the next update.
    void curvesOnSurfaceChanged(EntityId surface);
    Entity& entity(EntityId id) { return entities_.at(id); }

    std::map<EntityId, Entity> entities_;
    std::map<EntityId, std::set<EntityId>> dependents_;
    std::map<ConstraintId, Constraint> constraints_;
    /// Entity -> the constraints that read or consume it.
    std::map<EntityId, std::set<ConstraintId>> constraintsOn_;
    std::set<EntityId> dirty_;
    EntityId nextId_ = 1;
    ConstraintId nextConstraintId_ = 1;
    std::vector<ModelObserver*> observers_;
    std::function<void()> dirtyCallback_;

    mutable Plan plan_;
    mutable bool planValid_ = false;
    mutable int planCount_ = 0;
    /// downstreamSteps()'s last question and answer; dropped whenever the plan is.
    std::set<EntityId> downstreamOf_;
    std::vector<size_t> downstream_;
    bool downstreamValid_ = false;

    std::unique_ptr<SolverRegistry> registry_;
    /// A drag's solvers, factored at beginDrag, by the index of their step in the plan.
    std::map<size_t, std::unique_ptr<StepSolver>> dragSolvers_;
    /// A solver per registry key for the steps solved outside a drag (set up afresh each time).
    std::map<std::string, std::unique_ptr<StepSolver>> scratch_;
    /// The steps a drag re-solved (their entities are rebuilt fresh at endDrag).
    std::set<EntityId> dragRebuilt_;
    EntityId dragged_ = 0;
    /// The pull in progress: its least-change solver and the grip's parameter.
    std::unique_ptr<StepSolver> pull_;
    int factorizations_ = 0;
};

/// Smallest extent (diagonal of the control points' bounding box, model units) of a curve that is
/// drawn, reshaped or lifted: a nanometre in millimetres. Documents hold coordinates up to 1e6,
/// where a double resolves 1e6 x 2.2e-16 = 2.2e-10; a curve thousands of times larger than that
/// keeps its shape through plane transforms, and the arc lengths, projections and fits that edit
/// it stay well conditioned. A smaller one (a stroke drawn with the camera almost on its plane)
/// would be a point to the designer and to the solvers alike.
constexpr double kMinCurveExtent = 1e-6;
/// The diagonal of the bounding box of the curve's control points (model units).
double curveExtent(const solvers::Curve3d& curve);
/// @throws std::invalid_argument, saying how small it is, when curveExtent(curve) < `minimum`.
void requireCurveExtent(const solvers::Curve3d& curve, double minimum = kMinCurveExtent);

/// The curve with z = 0 at every control point: on a plane a curve is planar by construction, and
/// z exactly 0 lets the document's 2D points restore it bit for bit.
solvers::Curve3d flattenToPlane(const solvers::Curve3d& local);

/// True when every coordinate the entity would hand to a view (plane frame, curve control points and
/// weights, surface, mesh, constraint anchor) is finite. Views check it before drawing: a NaN or an
/// infinity never reaches Coin, whose bounding boxes and OpenGL would turn it into garbage.
bool hasFiniteGeometry(const Entity& entity);
/// The same for a constraint's value (a pin's point).
bool hasFiniteGeometry(const Constraint& constraint);

/// The curve with every control point mapped by the frame (rational weights unchanged: an affine
/// map of the control points maps the curve, The NURBS Book §4.4 "affine invariance").
solvers::Curve3d transformCurve(const solvers::Curve3d& curve, const PlaneFrame& frame);

}  // namespace sculptline::model
