#include "model/model.h"

#include "model/solver_registry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>

namespace sculptline::model {

Model::Model() : registry_(std::make_unique<SolverRegistry>()) {}
Model::~Model() = default;

Model::Model(Model&& other) noexcept
    : entities_(std::move(other.entities_)),
      dependents_(std::move(other.dependents_)),
      constraints_(std::move(other.constraints_)),
      constraintsOn_(std::move(other.constraintsOn_)),
      dirty_(std::move(other.dirty_)),
      nextId_(other.nextId_),
      nextConstraintId_(other.nextConstraintId_),
      registry_(std::make_unique<SolverRegistry>())
{
}

Model& Model::operator=(Model&& other) noexcept
{
    entities_ = std::move(other.entities_);
    dependents_ = std::move(other.dependents_);
    constraints_ = std::move(other.constraints_);
    constraintsOn_ = std::move(other.constraintsOn_);
    dirty_ = std::move(other.dirty_);
    nextId_ = other.nextId_;
    nextConstraintId_ = other.nextConstraintId_;
    freedomChanged();
    dragSolvers_.clear();
    pull_.reset();
    dragged_ = 0;
    return *this;
}

void Model::setCurveShape(EntityId curve, const solvers::Curve3d& local)
{
    auto it = entities_.find(curve);
    if (it == entities_.end() || it->second.kind != EntityKind::Curve || it->second.fixed) return;
    it->second.local = it->second.plane() != 0 ? flattenToPlane(local) : local;
    ++it->second.shapeVersion;
    markDirty(curve);
}

EntityId Model::insert(Entity entity, EntityId id, bool built)
{
    if (id == 0) id = nextId_;
    if (entities_.count(id) != 0) throw std::invalid_argument("entity id " + std::to_string(id) + " is taken");
    nextId_ = std::max(nextId_, id + 1);
    entity.id = id;
    for (EntityId input : entity.inputs) dependents_[input].insert(id);
    if (!built) recompute(entity);
    entity.recomputations = 0;  // building is not an update
    const Entity& stored = entities_.emplace(id, std::move(entity)).first->second;
    deriveConstraints(stored);
    freedomChanged();
    for (ModelObserver* o : observers_) o->entityAdded(stored);
    return id;
}

void Model::deriveConstraints(const Entity& e)
{
    Constraint c;
    if (e.kind == EntityKind::Curve && e.plane() != 0) {
        c.type = ConstraintType::Placement;
        c.sources = {e.plane()};
    } else if ((e.kind == EntityKind::Surface && e.recipe) || e.kind == EntityKind::Mesh || e.kind == EntityKind::Solid) {
        c.type = ConstraintType::Construction;
        c.sources = e.inputs;
    } else {
        return;
    }
    c.targets = {e.id};
    insertConstraint(std::move(c));
}

ConstraintId Model::insertConstraint(Constraint c)
{
    if (c.id == 0) c.id = nextConstraintId_;
    if (constraints_.count(c.id) != 0) throw std::invalid_argument("constraint id " + std::to_string(c.id) + " is taken");
    nextConstraintId_ = std::max(nextConstraintId_, c.id + 1);
    for (EntityId e : c.sources) constraintsOn_[e].insert(c.id);
    for (EntityId e : c.targets) constraintsOn_[e].insert(c.id);
    const ConstraintId id = c.id;
    const Constraint& stored = constraints_.emplace(id, std::move(c)).first->second;
    freedomChanged();
    if (!derivedConstraint(stored.type)) {
        for (ModelObserver* o : observers_) o->constraintAdded(stored);
    }
    return id;
}

EntityId Model::addPlane(const PlaneFrame& frame, EntityId id)
{
    Entity e;
    e.kind = EntityKind::Plane;
    e.frame = frame;
    return insert(std::move(e), id);
}

EntityId Model::addCurve(EntityId plane, const solvers::Curve3d& local, EntityId id)
{
    Entity e;
    e.kind = EntityKind::Curve;
    if (plane != 0) {
        const Entity* p = find(plane);
        if (!p || p->kind != EntityKind::Plane) throw std::invalid_argument("entity " + std::to_string(plane) + " is not a plane");
        e.inputs.push_back(plane);
    }
    e.local = plane != 0 ? flattenToPlane(local) : local;
    return insert(std::move(e), id);
}

EntityId Model::addSurface(const solvers::Surface3d& surface, EntityId id)
{
    Entity e;
    e.kind = EntityKind::Surface;
    e.surface = surface;
    return insert(std::move(e), id);
}

EntityId Model::addPoint(const Eigen::Vector3d& position, EntityId id, const Eigen::Quaterniond& rotation)
{
    if (!position.allFinite()) throw std::invalid_argument("a point must have finite coordinates");
    if (!rotation.coeffs().allFinite() || rotation.norm() == 0.0) throw std::invalid_argument("a point's rotation must be a finite non-zero quaternion");
    Entity e;
    e.kind = EntityKind::Point;
    e.position = position;
    e.rotation = rotation.normalized();
    return insert(std::move(e), id);
}

void Model::setPointPose(EntityId point, const Eigen::Vector3d& position, const Eigen::Quaterniond& rotation)
{
    auto it = entities_.find(point);
    if (it == entities_.end() || it->second.kind != EntityKind::Point || it->second.fixed) return;
    if (!position.allFinite() || !rotation.coeffs().allFinite() || rotation.norm() == 0.0) return;
    const Eigen::Quaterniond r = rotation.normalized();
    if (it->second.position == position && it->second.rotation.coeffs() == r.coeffs()) return;
    it->second.position = position;
    it->second.rotation = r;
    markDirty(point);
}

void Model::checkSurfaceInputs(const std::vector<EntityId>& curves, const SurfaceRecipe& recipe) const
{
    const ConstructionInfo& info = describe(recipe.mode);
    const InputCount count = surfaceInputCount(recipe.mode);
    const int n = static_cast<int>(curves.size());
    if (n < count.min || n > count.max) {
        throw std::invalid_argument(std::string(info.name) + " needs " +
                                    (count.min == count.max ? std::to_string(count.min)
                                                            : std::to_string(count.min) + " to " + std::to_string(count.max)) +
                                    " curves, got " + std::to_string(n));
    }
    for (size_t k = 0; k < curves.size(); ++k) {
        const Entity* e = find(curves[k]);
        const EntityKind want = k == 0 && info.baseSurface ? EntityKind::Surface : EntityKind::Curve;
        // A sculpt's targets are curves and handle points.
        const bool handle = info.baseSurface && k > 0 && e && e->kind == EntityKind::Point;
        if (!e || (e->kind != want && !handle))
            throw std::invalid_argument("entity " + std::to_string(curves[k]) + " is not a " + kindName(want));
    }
    checkSculptRecipe(curves, recipe);
    if (info.options & kStiffnessOption) {
        if (!(recipe.stiffness > 0.0 && recipe.stiffness <= 1.0)) throw std::invalid_argument("stiffness: must be in (0, 1]");
    }
    for (const SurfaceRecipe::Tangent& t : recipe.tangents) {
        const Entity* s = find(t.surface);
        if (!(info.options & kTangentsOption)) throw std::invalid_argument("only a fill can be tangent to other surfaces");
        if (t.boundary < 0 || t.boundary >= n) throw std::invalid_argument("tangent boundary " + std::to_string(t.boundary) + " is not a boundary");
        if (!s || s->kind != EntityKind::Surface) throw std::invalid_argument("entity " + std::to_string(t.surface) + " is not a surface");
    }
}

void Model::checkSculptRecipe(const std::vector<EntityId>& inputs, const SurfaceRecipe& r) const
{
    const bool sculpt = describe(r.mode).baseSurface;
    if (!sculpt) {
        if (!r.handles.empty() || !r.bound.empty() || !r.blocked.empty() || !r.distances.empty() || !r.curveTangents.empty())
            throw std::invalid_argument(std::string("only a sculpt takes handles, a bound, blocked points, distances or curve tangents, not ") +
                                        constructionName(r.mode));
        return;
    }
    auto isInput = [&](EntityId id, EntityKind kind) {
        const Entity* e = find(id);
        return e && e->kind == kind && std::find(inputs.begin() + 1, inputs.end(), id) != inputs.end();
    };
    auto finiteUv = [](const Eigen::Vector2d& uv) { return uv.allFinite(); };
    std::set<EntityId> handled;
    for (size_t k = 0; k < r.handles.size(); ++k) {
        const SurfaceRecipe::Handle& h = r.handles[k];
        const std::string at = "handles[" + std::to_string(k) + "]";
        if (!isInput(h.point, EntityKind::Point)) throw std::invalid_argument(at + ": entity " + std::to_string(h.point) + " is not one of the sculpt's points");
        if (!handled.insert(h.point).second) throw std::invalid_argument(at + ": point " + std::to_string(h.point) + " has two handles");
        if (!finiteUv(h.uv)) throw std::invalid_argument(at + ".uv: not a finite number");
    }
    for (size_t k = 1; k < inputs.size(); ++k) {
        const Entity* e = find(inputs[k]);
        if (e && e->kind == EntityKind::Point && !handled.count(inputs[k]))
            throw std::invalid_argument("point " + std::to_string(inputs[k]) + " has no handle (where on the surface it pulls)");
    }
    if (!r.bound.empty() && r.bound.size() < 3) throw std::invalid_argument("bound: a closed bound needs 3 points or more, got " + std::to_string(r.bound.size()));
    if (!std::all_of(r.bound.begin(), r.bound.end(), finiteUv)) throw std::invalid_argument("bound: not a finite number");
    for (const auto& b : r.blocked) {
        if (b[0] < 0 || b[1] < 0) throw std::invalid_argument("blocked: negative control point index");
    }
    for (const SurfaceRecipe::Distance& d : r.distances) {
        if (!finiteUv(d.uv) || !finiteUv(d.uv2) || !std::isfinite(d.distance) || d.distance < 0.0)
            throw std::invalid_argument("distances: two finite (u, v) and a finite distance >= 0 are needed");
    }
    for (const SurfaceRecipe::CurveTangent& t : r.curveTangents) {
        if (!isInput(t.curve, EntityKind::Curve)) throw std::invalid_argument("curve tangent: entity " + std::to_string(t.curve) + " is not one of the sculpt's target curves");
        if (!t.direction.allFinite() || t.direction.norm() == 0.0) throw std::invalid_argument("curve tangent: the direction must be a finite non-zero vector");
    }
}

Entity Model::unbuiltSurface(const std::vector<EntityId>& curves, const SurfaceRecipe& recipe) const
{
    checkSurfaceInputs(curves, recipe);
    Entity e;
    e.kind = EntityKind::Surface;
    e.inputs = curves;
    // The surfaces a G1 fill is tangent to are inputs too: it follows them when they change.
    for (const SurfaceRecipe::Tangent& t : recipe.tangents) {
        if (std::find(e.inputs.begin() + static_cast<long>(curves.size()), e.inputs.end(), t.surface) == e.inputs.end())
            e.inputs.push_back(t.surface);
    }
    e.recipe = recipe;
    return e;
}

Entity Model::makeSurface(const std::vector<EntityId>& curves, const SurfaceRecipe& recipe) const
{
    Entity e = unbuiltSurface(curves, recipe);
    try {
        buildSurfaceEntity(*this, e);
    } catch (const std::exception& error) {
        throw std::invalid_argument(error.what());
    }
    return e;
}

EntityId Model::addSurface(const std::vector<EntityId>& curves, const SurfaceRecipe& recipe, EntityId id,
                           const solvers::Surface3d* saved)
{
    Entity e = unbuiltSurface(curves, recipe);
    try {
        buildSurfaceEntity(*this, e);
    } catch (const std::exception& error) {
        if (!saved) throw std::invalid_argument(error.what());
        e.surface = *saved;
        e.buildError = error.what();
    }
    return insert(std::move(e), id, true);
}

EntityId Model::restoreSurface(const std::vector<EntityId>& curves, const SurfaceRecipe& recipe, EntityId id,
                               const std::optional<solvers::Surface3d>& saved)
{
    Entity e = unbuiltSurface(curves, recipe);
    try {
        buildSurfaceEntity(*this, e);
    } catch (const std::exception& error) {
        e.surface = saved;
        e.buildError = error.what();
    }
    return insert(std::move(e), id, true);
}

Entity Model::makeMesh(const std::vector<EntityId>& curves) const
{
    if (curves.empty()) throw std::invalid_argument("a mesh needs a loop of curves");
    for (EntityId c : curves) {
        const Entity* e = find(c);
        if (!e || e->kind != EntityKind::Curve) throw std::invalid_argument("entity " + std::to_string(c) + " is not a curve");
    }
    Entity e;
    e.kind = EntityKind::Mesh;
    e.inputs = curves;
    try {
        buildMeshEntity(*this, e);
    } catch (const std::exception& error) {
        throw std::invalid_argument(error.what());
    }
    return e;
}

EntityId Model::addMesh(const std::vector<EntityId>& curves, EntityId id, bool keepOnFailure)
{
    Entity e;
    try {
        e = makeMesh(curves);
    } catch (const std::invalid_argument& error) {
        // A document or an undo restores a mesh whose curves may no longer close: keep it, empty,
        // with the reason, so that nothing else of the document is lost (its curves must exist).
        if (!keepOnFailure || curves.empty() || std::any_of(curves.begin(), curves.end(), [this](EntityId c) {
                const Entity* k = find(c);
                return !k || k->kind != EntityKind::Curve;
            })) {
            throw;
        }
        e.kind = EntityKind::Mesh;
        e.inputs = curves;
        e.mesh = solvers::surfaces::NetworkMesh{};
        e.buildError = error.what();
    }
    return insert(std::move(e), id, true);
}

EntityId Model::restore(const Entity& e)
{
    EntityId id = 0;
    switch (e.kind) {
    case EntityKind::Plane: id = addPlane(e.frame, e.id); break;
    case EntityKind::Curve: id = addCurve(e.plane(), *e.local, e.id); break;
    case EntityKind::Mesh: id = addMesh(e.inputs, e.id, true); break;
    case EntityKind::Point: id = addPoint(e.position, e.id, e.rotation); break;
    case EntityKind::Solid: id = addSolid(e.inputs, *e.solidRecipe, e.id, e.solidStale() ? std::nullopt : e.solid); break;
    case EntityKind::Surface:
        id = e.recipe ? restoreSurface(e.curveInputs(), *e.recipe, e.id, e.surface) : addSurface(*e.surface, e.id);
        entity(id).incidenceK = e.incidenceK;
        entity(id).prior = e.prior;
        break;
    }
    if (e.fixed) setFixed(id, true);
    return id;
}

void Model::restore(const Removed& removed)
{
    for (const Entity& e : removed.entities) restore(e);
    for (const Constraint& c : removed.constraints) addConstraint(c);
}

ConstraintId Model::addConstraint(Constraint c)
{
    const ConstraintTypeInfo& info = describe(c.type);
    if (derivedConstraint(c.type))
        throw std::invalid_argument(std::string(info.name) + " constraints are made by the model from the entity they build");
    std::vector<EntityKind> kinds;
    for (EntityId t : c.targets) {
        const Entity* e = find(t);
        if (!e) throw std::invalid_argument(std::string(info.name) + ": entity " + std::to_string(t) + " does not exist");
        kinds.push_back(e->kind);
    }
    for (EntityId s : c.sources) {
        if (!find(s)) throw std::invalid_argument(std::string(info.name) + ": entity " + std::to_string(s) + " does not exist");
    }
    for (double p : c.parameters) {
        if (!std::isfinite(p)) throw std::invalid_argument(std::string(info.name) + ": parameters must be finite");
    }
    if (!c.value.allFinite() || !std::isfinite(c.weight)) throw std::invalid_argument(std::string(info.name) + ": value and weight must be finite");
    if (const std::string error = constraintShapeError(c.type, kinds, c.parameters.size(), c.indices.size()); !error.empty())
        throw std::invalid_argument(error);
    const Entity& first = *find(c.targets.front());
    if (c.type == ConstraintType::Position || c.type == ConstraintType::Tangent) {
        // Kept inside the curve's domain, where the solver reads it (closed curves wrap there too).
        c.parameters.front() = std::clamp(c.parameters.front(), first.local->domainStart(), first.local->domainEnd());
    }
    if (c.type == ConstraintType::FixedPoints) {
        std::sort(c.indices.begin(), c.indices.end());
        c.indices.erase(std::unique(c.indices.begin(), c.indices.end()), c.indices.end());
        const int count = first.local->isClosed() ? first.local->pointCount() - first.local->degree() : first.local->pointCount();
        for (int i : c.indices) {
            if (i < 0 || i >= count)
                throw std::invalid_argument("fixed point " + std::to_string(i) + " is not a control point of curve " + std::to_string(first.id));
        }
    }
    const ConstraintId id = insertConstraint(std::move(c));
    const Constraint& added = constraints_.at(id);
    refreshConstraintValues(added.targets.front());
    // A curve put on a surface asks the surface to change (its incidence solve): the next update.
    if (added.type == ConstraintType::CurveOnSurface) curvesOnSurfaceChanged(added.targets.back());
    return id;
}

ConstraintId Model::addConstraint(EntityId curve, ConstraintType type, double u, ConstraintId id)
{
    const Entity* c = find(curve);
    if (!c || c->kind != EntityKind::Curve) throw std::invalid_argument("entity " + std::to_string(curve) + " is not a curve");
    if (type != ConstraintType::Position && type != ConstraintType::Tangent)
        throw std::invalid_argument("a pin's constraint type must be \"position\" or \"tangent\"");
    if (!std::isfinite(u)) throw std::invalid_argument("constraint parameter must be finite");
    Constraint k;
    k.id = id;
    k.type = type;
    k.targets = {curve};
    k.parameters = {u};
    return addConstraint(std::move(k));
}

std::optional<Constraint> Model::removeConstraint(ConstraintId id)
{
    const auto it = constraints_.find(id);
    if (it == constraints_.end() || derivedConstraint(it->second.type)) return std::nullopt;
    for (ModelObserver* o : observers_) o->constraintRemoved(it->second);
    for (EntityId e : it->second.sources) constraintsOn_[e].erase(id);
    for (EntityId e : it->second.targets) constraintsOn_[e].erase(id);
    Constraint removed = std::move(it->second);
    constraints_.erase(it);
    freedomChanged();
    if (removed.type == ConstraintType::CurveOnSurface && removed.targets.size() == 2) curvesOnSurfaceChanged(removed.targets.back());
    return removed;
}

void Model::setFixedPoints(EntityId curve, std::vector<int> fixed)
{
    auto it = entities_.find(curve);
    if (it == entities_.end() || it->second.kind != EntityKind::Curve) return;
    Constraint c;
    c.type = ConstraintType::FixedPoints;
    c.targets = {curve};
    c.indices = std::move(fixed);
    // Checked before the old set goes: a bad index leaves the curve as it was.
    std::sort(c.indices.begin(), c.indices.end());
    c.indices.erase(std::unique(c.indices.begin(), c.indices.end()), c.indices.end());
    const solvers::Curve3d& local = *it->second.local;
    const int count = local.isClosed() ? local.pointCount() - local.degree() : local.pointCount();
    for (int i : c.indices) {
        if (i < 0 || i >= count) throw std::invalid_argument("fixed point " + std::to_string(i) + " is not a control point of curve " + std::to_string(curve));
    }
    for (ConstraintId id : constraintsOn(curve)) {
        if (constraints_.at(id).type == ConstraintType::FixedPoints) {
            c.id = id;  // the curve's one set keeps its id
            removeConstraint(id);
        }
    }
    if (!c.indices.empty()) addConstraint(std::move(c));
    for (ModelObserver* o : observers_) o->entityUpdated(it->second);
}

std::vector<int> Model::fixedPoints(EntityId curve) const
{
    for (ConstraintId id : constraintsOn(curve)) {
        const Constraint& c = constraints_.at(id);
        if (c.type == ConstraintType::FixedPoints) return c.indices;
    }
    return {};
}

void Model::setFixed(EntityId id, bool fixed)
{
    auto it = entities_.find(id);
    if (it == entities_.end() || it->second.fixed == fixed) return;
    it->second.fixed = fixed;
    freedomChanged();
    for (ModelObserver* o : observers_) o->entityUpdated(it->second);
}

State Model::state(EntityId id) const
{
    const Entity* e = find(id);
    if (!e) return State::Free;
    if (dirty_.count(id)) return State::Changed;
    return e->fixed ? State::Fixed : State::Free;
}

void Model::setSurfaceRecipe(EntityId surface, const SurfaceRecipe& recipe)
{
    auto it = entities_.find(surface);
    if (it == entities_.end() || !it->second.recipe || it->second.fixed) return;
    it->second.recipe = recipe;
    markDirty(surface);
}

void Model::setPlaneFrame(EntityId plane, const PlaneFrame& frame)
{
    auto it = entities_.find(plane);
    if (it == entities_.end() || it->second.kind != EntityKind::Plane || it->second.fixed) return;
    if (it->second.frame == frame) return;
    // A degenerate manipulation (a dragger scaled to nothing) can hand over NaN: the plane stays.
    if (!frame.origin.allFinite() || !frame.rotation.coeffs().allFinite()) return;
    it->second.frame = frame;
    markDirty(plane);
}

void Model::markDirty(EntityId id)
{
    const bool first = dirty_.empty();
    dirty_.insert(id);
    if (first && dirtyCallback_) dirtyCallback_();
}

const Plan& Model::plan() const
{
    if (planValid_) return plan_;
    std::vector<EntityId> ids;
    std::set<EntityId> fixed;
    for (const auto& [id, e] : entities_) {
        ids.push_back(id);
        if (e.fixed) fixed.insert(id);
    }
    std::vector<const Constraint*> constraints;
    for (const auto& [id, c] : constraints_) constraints.push_back(&c);
    plan_ = makePlan(ids, fixed, constraints, [this](const PlanStep& step) { return registry_->choose(*this, step); });
    planValid_ = true;
    ++planCount_;
    return plan_;
}

const std::vector<size_t>& Model::downstreamSteps(const std::set<EntityId>& changed)
{
    const Plan& p = plan();
    if (!downstreamValid_ || downstreamOf_ != changed) {
        downstream_ = stepsAfter(p, changed);
        downstreamOf_ = changed;
        downstreamValid_ = true;
    }
    return downstream_;
}

Dof Model::dof(EntityId id) const
{
    Dof d;
    const Entity* e = find(id);
    if (!e) return d;
    const int dim = e->kind == EntityKind::Curve && e->plane() != 0 ? 2 : 3;
    auto uniquePoints = [](const auto& g) { return g.isClosed() ? g.pointCount() - g.degree() : g.pointCount(); };
    switch (e->kind) {
    case EntityKind::Plane: d.total = 6; break;  // a rigid frame: position and orientation
    case EntityKind::Curve: d.total = e->local ? dim * uniquePoints(*e->local) : 0; break;
    case EntityKind::Surface: d.total = e->surface ? 3 * e->surface->countU() * e->surface->countV() : 0; break;
    case EntityKind::Point: d.total = 3; break;
    case EntityKind::Mesh: d.total = 0; break;  // its freedom is its curves'
    case EntityKind::Solid: d.total = 0; break;  // likewise its surfaces'
    }
    for (ConstraintId cid : constraintsOn(id)) {
        const Constraint& c = constraints_.at(cid);
        if (std::find(c.targets.begin(), c.targets.end(), id) == c.targets.end()) continue;
        const int per = describe(c.type).dofPerUse;
        if (per == -1) d.consumed += d.total;
        else if (c.type == ConstraintType::FixedPoints) d.consumed += dim * static_cast<int>(c.indices.size());
        else if (c.type == ConstraintType::PointOnCurve) {
            // Incidence of a point on a curve: a point in space has `dim` coordinates; on the curve
            // at an unknown parameter it keeps one of them (seed 000 Fig. 3: P1 and P2 on A take
            // two DOF of B). With the parameter given, all `dim`.
            d.consumed += c.parameters.empty() ? dim - 1 : dim;
        } else d.consumed += per * dim;
    }
    return d;
}

std::vector<ConstraintId> Model::constraintsOn(EntityId entity) const
{
    const auto it = constraintsOn_.find(entity);
    return it == constraintsOn_.end() ? std::vector<ConstraintId>{} : std::vector<ConstraintId>(it->second.begin(), it->second.end());
}

const Constraint* Model::findConstraint(ConstraintId id) const
{
    const auto it = constraints_.find(id);
    return it == constraints_.end() ? nullptr : &it->second;
}

void Model::refreshConstraintValues(EntityId curve)
{
    const Entity* e = find(curve);
    if (!e || e->kind != EntityKind::Curve || !e->world) return;
    const auto on = constraintsOn_.find(curve);
    if (on == constraintsOn_.end()) return;
    for (ConstraintId id : on->second) {
        Constraint& c = constraints_.at(id);
        if (c.type != ConstraintType::Position && c.type != ConstraintType::Tangent) continue;
        c.value = e->world->evaluate(std::clamp(c.parameters.front(), e->world->domainStart(), e->world->domainEnd()));
        for (ModelObserver* o : observers_) o->constraintUpdated(c);
    }
}

int Model::update()
{
    if (dirty_.empty()) return 0;
    const Plan& p = plan();
    std::set<EntityId> changed;
    changed.swap(dirty_);
    std::set<EntityId> recomputed;
    // A changed entity no step solves is a source: its own derived data first (a curve in space
    // that nothing constrains: its world form is its shape), then what depends on it.
    for (EntityId id : changed) {
        auto it = entities_.find(id);
        if (it != entities_.end() && !p.stepOf.count(id)) recompute(it->second);
    }
    const std::vector<size_t> steps = downstreamSteps(changed);  // a copy: solvers run meanwhile
    for (size_t index : steps) {
        const PlanStep& step = p.steps[index];
        if (std::none_of(step.solve.begin(), step.solve.end(), [this](EntityId id) { return entities_.count(id) != 0; })) continue;
        if (const auto cached = dragSolvers_.find(index); cached != dragSolvers_.end()) {
            cached->second->solve(*this, step);
            dragRebuilt_.insert(step.solve.begin(), step.solve.end());
        } else {
            // Outside a drag a step is solved without a set-up: what a fresh build gives. One
            // solver per key serves every such step, so an event allocates none.
            std::unique_ptr<StepSolver>& solver = scratch_[step.solver];
            if (!solver) solver = registry_->make(step.solver);
            solver->reset();
            solver->solve(*this, step);
        }
        recomputed.insert(step.solve.begin(), step.solve.end());
    }
    // What changed itself is updated too (a plane's frame: its observers redraw it).
    recomputed.insert(changed.begin(), changed.end());
    int count = 0;
    for (EntityId id : recomputed) {
        auto it = entities_.find(id);
        if (it == entities_.end()) continue;
        ++it->second.recomputations;
        ++count;
        refreshConstraintValues(id);
        for (ModelObserver* o : observers_) o->entityUpdated(it->second);
    }
    return count;
}

void Model::recompute(Entity& e)
{
    // An entity being added: its derived data from its inputs, as its step's solver would.
    if (e.kind == EntityKind::Curve && e.local) {
        try {
            e.world = e.plane() != 0 ? transformCurve(*e.local, entities_.at(e.plane()).frame) : *e.local;
            e.buildError.clear();
        } catch (const std::exception& error) {
            e.buildError = error.what();
        }
    }
}

void Model::beginDrag(EntityId id)
{
    if (dragged_ != 0) endDrag();
    if (!entities_.count(id)) return;
    update();  // the drag starts from a settled model
    dragged_ = id;
    const Plan& p = plan();
    const std::vector<size_t> steps = downstreamSteps({id});
    for (size_t index : steps) {
        const PlanStep& step = p.steps[index];
        if (!registry_->caches(step.solver)) continue;
        std::unique_ptr<StepSolver> solver = registry_->make(step.solver);
        solver->factor(*this, step);
        ++factorizations_;
        dragSolvers_.emplace(index, std::move(solver));
    }
}

void Model::beginPull(EntityId curve, double u)
{
    if (dragged_ != 0) endDrag();
    const Entity* c = find(curve);
    if (!c || c->kind != EntityKind::Curve || !c->local) throw std::invalid_argument("entity " + std::to_string(curve) + " is not a curve");
    if (c->fixed) throw std::invalid_argument("curve " + std::to_string(curve) + " is fixed");
    if (!std::isfinite(u)) throw std::invalid_argument("the grip's parameter must be finite");
    update();
    PlanStep step;
    step.solve = {curve};
    step.solver = "least-change";
    std::unique_ptr<StepSolver> solver = makePullSolver(std::clamp(u, c->local->domainStart(), c->local->domainEnd()));
    solver->factor(*this, step);  // throws when it cannot be pulled: no drag then
    ++factorizations_;
    beginDrag(curve);
    pull_ = std::move(solver);
}

std::string Model::pullTo(const Eigen::Vector3d& local)
{
    if (!pull_ || !entities_.count(dragged_)) return {};
    PlanStep step;
    step.solve = {dragged_};
    step.solver = "least-change";
    pull_->setGrip(local);
    const int before = entities_.at(dragged_).shapeVersion;
    pull_->solve(*this, step);
    if (entities_.at(dragged_).shapeVersion != before) markDirty(dragged_);
    return pull_->message();
}

void Model::endDrag()
{
    // The surfaces rebuilt incrementally come to rest as a fresh build makes them.
    for (EntityId id : dragRebuilt_) {
        if (entities_.count(id)) markDirty(id);
    }
    dragRebuilt_.clear();
    dragSolvers_.clear();
    pull_.reset();
    dragged_ = 0;
}

Removed Model::remove(EntityId id)
{
    if (!entities_.count(id)) return {};
    if (dragged_ != 0) endDrag();
    std::set<EntityId> doomed;
    std::vector<EntityId> stack{id};
    while (!stack.empty()) {
        const EntityId next = stack.back();
        stack.pop_back();
        if (!doomed.insert(next).second) continue;
        if (auto d = dependents_.find(next); d != dependents_.end()) stack.insert(stack.end(), d->second.begin(), d->second.end());
    }
    Removed removed;
    // The designer's constraints on anything removed go first (they name it).
    std::set<ConstraintId> constraints;
    for (EntityId e : doomed) {
        for (ConstraintId c : constraintsOn(e)) constraints.insert(c);
    }
    for (ConstraintId c : constraints) {
        if (derivedConstraint(constraints_.at(c).type)) continue;
        if (std::optional<Constraint> k = removeConstraint(c)) removed.constraints.push_back(std::move(*k));
    }
    // Dependents first (highest ids first), so observers never see a curve outlive its plane.
    for (auto it = doomed.rbegin(); it != doomed.rend(); ++it) {
        auto e = entities_.find(*it);
        for (ModelObserver* o : observers_) o->entityRemoved(e->second);
        for (EntityId input : e->second.inputs) dependents_[input].erase(*it);
        dependents_.erase(*it);
        dirty_.erase(*it);
        for (ConstraintId c : constraintsOn(*it)) {
            // The derived constraint that makes it goes with it.
            const Constraint& k = constraints_.at(c);
            for (EntityId s : k.sources) constraintsOn_[s].erase(c);
            for (EntityId t : k.targets) constraintsOn_[t].erase(c);
            constraints_.erase(c);
        }
        constraintsOn_.erase(*it);
        removed.entities.push_back(std::move(e->second));
        entities_.erase(e);
    }
    freedomChanged();
    std::reverse(removed.entities.begin(), removed.entities.end());
    return removed;
}

void Model::clear()
{
    endDrag();
    while (!entities_.empty()) remove(entities_.begin()->first);
    dirty_.clear();
    nextId_ = 1;
    nextConstraintId_ = 1;
}

const Entity* Model::find(EntityId id) const
{
    const auto it = entities_.find(id);
    return it == entities_.end() ? nullptr : &it->second;
}

std::vector<EntityId> Model::dependents(EntityId id) const
{
    const auto it = dependents_.find(id);
    return it == dependents_.end() ? std::vector<EntityId>{} : std::vector<EntityId>(it->second.begin(), it->second.end());
}

void Model::removeObserver(ModelObserver* observer)
{
    observers_.erase(std::remove(observers_.begin(), observers_.end(), observer), observers_.end());
}

}  // namespace sculptline::model
