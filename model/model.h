#pragma once
// The model: projection planes, curves and surfaces with ids, each knowing what it depends on (a
// curve on its plane). Plain C++ on the kernel's types (no Coin, no Qt), so incremental updates are
// testable on their own; scene/model_view.h shows it with Coin nodes.
//
// Updates are explicit and lazy: an edit (a plane moved) marks the entity dirty and calls the dirty
// callback once (the scheduler, scene/update_scheduler.h, turns that into one update per
// displayed frame); update() then recomputes the dirty entities and everything downstream of them,
// each exactly once, in dependency order. Ids grow with creation and an entity's inputs always exist
// before it, so ascending id order is a topological order (restored entities keep their ids).
#include "model/plane_frame.h"
#include "model/surface_recipe.h"
#include "solvers/bspline/bspline_surface.h"
#include "solvers/surfaces/network_mesh.h"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace sculptline::model {

using EntityId = std::uint32_t;  ///< 0 is "none"

/// Constraint: a condition kept on a curve at a parameter while the curve is pulled (thesis §6.1).
/// Mesh: a closed loop of curves filled by a triangle mesh (seed 004 §4, curve networks).
enum class EntityKind { Plane, Curve, Surface, Constraint, Mesh };
const char* kindName(EntityKind kind);

struct Entity {
    EntityId id = 0;
    EntityKind kind = EntityKind::Plane;
    std::vector<EntityId> inputs;  ///< what it depends on (a curve: its plane, if any)

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
    /// Surface: its curve inputs (the inputs that follow are the surfaces a G1 fill is tangent to).
    std::vector<std::uint32_t> curveInputs() const
    {
        return std::vector<std::uint32_t>(inputs.begin(), inputs.end() - static_cast<long>(tangentSurfaceCount()));
    }
    /// Surface: how many of its inputs are surfaces it is tangent to (at the end of `inputs`).
    size_t tangentSurfaceCount() const;

    /// Curve: control points held fixed when the curve is pulled (the "blocked" points of
    /// thesis §6.1), ascending indices (unique points of a closed curve).
    std::vector<int> fixedPoints;
    /// Constraint (inputs = {curve}): "position" keeps C(u), "tangent" keeps C'(u) while the curve
    /// is pulled; `anchor` is C(u) in world coordinates, recomputed with the curve.
    std::string constraintType;
    double parameter = 0.0;
    Eigen::Vector3d anchor = Eigen::Vector3d::Zero();

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
    /// Recomputed by update() (a Plane: its frame changed; a Curve: its world form).
    virtual void entityUpdated(const Entity& entity) = 0;
};

class Model {
public:
    /// Adds a plane; `id` restores a removed entity under its old id (undo), 0 = a fresh one.
    EntityId addPlane(const PlaneFrame& frame, EntityId id = 0);
    /// Adds a curve on `plane` (its points in the plane's local frame, z = 0), or a world-space
    /// curve when plane = 0. @throws std::invalid_argument when `plane` is not a plane.
    EntityId addCurve(EntityId plane, const solvers::Curve3d& local, EntityId id = 0);
    EntityId addSurface(const solvers::Surface3d& surface, EntityId id = 0);
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
    /// The mesh entity addMesh(curves) would add (built, id 0), without adding it.
    /// @throws std::invalid_argument as addMesh does.
    Entity makeMesh(const std::vector<EntityId>& curves) const;
    /// Replaces a built surface's recipe (an extrusion following the pointer): marks it dirty.
    void setSurfaceRecipe(EntityId surface, const SurfaceRecipe& recipe);

    /// Adds a constraint on `curve` at parameter `u` ("position" or "tangent").
    /// @throws std::invalid_argument for a non-curve, an unknown type or a non-finite parameter.
    EntityId addConstraint(EntityId curve, const std::string& type, double u, EntityId id = 0);
    /// Sets which control points of `curve` stay fixed when it is pulled (indices are checked).
    /// @throws std::invalid_argument for an index out of range.
    void setFixedPoints(EntityId curve, std::vector<int> fixed);

    /// Moves a plane: only marks it dirty (the curves follow in the next update()).
    void setPlaneFrame(EntityId plane, const PlaneFrame& frame);

    /// Replaces a curve's shape (in its plane's frame; z is set to 0 on a plane): marks it dirty,
    /// its world form and dependents follow in the next update().
    void setCurveShape(EntityId curve, const solvers::Curve3d& local);

    /// Removes `id` and everything that depends on it, dependents first; returns the removed
    /// entities in creation order (what undo needs to restore them).
    std::vector<Entity> remove(EntityId id);

    /// Recomputes every dirty entity and its dependents once, in dependency order; returns how
    /// many entities were recomputed.
    int update();
    bool updatePending() const { return !dirty_.empty(); }

    void clear();

    const Entity* find(EntityId id) const;
    /// All entities in creation (= dependency) order.
    const std::map<EntityId, Entity>& entities() const { return entities_; }
    /// Direct dependents of `id`.
    std::vector<EntityId> dependents(EntityId id) const;

    void addObserver(ModelObserver* observer) { observers_.push_back(observer); }
    void removeObserver(ModelObserver* observer);
    /// Called when the first entity becomes dirty after an update (schedule an update then).
    void setDirtyCallback(std::function<void()> callback) { dirtyCallback_ = std::move(callback); }

private:
    /// `built`: the entity's derived data is already computed (a surface built by addSurface).
    EntityId insert(Entity entity, EntityId id, bool built = false);
    void recompute(Entity& entity);
    /// @throws std::invalid_argument when `curves` do not fit `recipe` (count, kinds).
    void checkSurfaceInputs(const std::vector<EntityId>& curves, const SurfaceRecipe& recipe) const;
    /// A surface entity over `curves` with `recipe`, checked but not built yet.
    Entity unbuiltSurface(const std::vector<EntityId>& curves, const SurfaceRecipe& recipe) const;
    /// Builds a mesh entity's mesh from its curves. @throws on failure.
    void buildMesh(Entity& entity) const;
    /// Builds a surface entity's surface from its recipe and inputs. @throws on failure.
    void buildSurface(Entity& entity) const;
    void markDirty(EntityId id);

    std::map<EntityId, Entity> entities_;
    std::map<EntityId, std::set<EntityId>> dependents_;
    std::set<EntityId> dirty_;
    EntityId nextId_ = 1;
    std::vector<ModelObserver*> observers_;
    std::function<void()> dirtyCallback_;
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

/// True when every coordinate the entity would hand to a view (plane frame, curve control points and
/// weights, surface, mesh, constraint anchor) is finite. Views check it before drawing: a NaN or an
/// infinity never reaches Coin, whose bounding boxes and OpenGL would turn it into garbage.
bool hasFiniteGeometry(const Entity& entity);

/// The curve with every control point mapped by the frame (rational weights unchanged: an affine
/// map of the control points maps the curve, The NURBS Book §4.4 "affine invariance").
solvers::Curve3d transformCurve(const solvers::Curve3d& curve, const PlaneFrame& frame);

}  // namespace sculptline::model
