#include "model/model.h"

#include "solvers/surfaces/surface_modes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>

namespace sculptline::model {

const char* kindName(EntityKind kind)
{
    switch (kind) {
    case EntityKind::Plane: return "plane";
    case EntityKind::Curve: return "curve";
    case EntityKind::Surface: return "surface";
    case EntityKind::Constraint: return "constraint";
    case EntityKind::Mesh: return "mesh";
    }
    return "?";
}

size_t Entity::tangentSurfaceCount() const
{
    if (!recipe) return 0;
    std::set<std::uint32_t> surfaces;
    for (const SurfaceRecipe::Tangent& t : recipe->tangents) surfaces.insert(t.surface);
    return surfaces.size();
}

solvers::Curve3d transformCurve(const solvers::Curve3d& curve, const PlaneFrame& frame)
{
    std::vector<Eigen::Vector3d> points;
    points.reserve(curve.points().size());
    for (const Eigen::Vector3d& p : curve.points()) points.push_back(frame.toWorld(p));
    return solvers::Curve3d(curve.degree(), curve.knots(), points, curve.weights(), curve.isClosed());
}

namespace {

template <typename Points>
bool allFinite(const Points& points)
{
    return std::all_of(points.begin(), points.end(), [](const auto& p) { return p.allFinite(); });
}

template <typename Geometry>
bool finiteSpline(const Geometry& g)
{
    return allFinite(g.points()) && std::all_of(g.weights().begin(), g.weights().end(), [](double w) { return std::isfinite(w); });
}

}  // namespace

double curveExtent(const solvers::Curve3d& curve)
{
    Eigen::Vector3d lo = curve.points().front(), hi = lo;
    for (const Eigen::Vector3d& p : curve.points()) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    return (hi - lo).norm();
}

void requireCurveExtent(const solvers::Curve3d& curve, double minimum)
{
    const double extent = curveExtent(curve);
    if (!(extent >= minimum)) {
        char text[160];
        std::snprintf(text, sizeof text, "the curve would span %.3g mm, less than the %.3g mm it must span", extent, minimum);
        throw std::invalid_argument(text);
    }
}

bool hasFiniteGeometry(const Entity& e)
{
    switch (e.kind) {
    case EntityKind::Plane:
        return e.frame.origin.allFinite() && e.frame.rotation.coeffs().allFinite() && std::isfinite(e.frame.size);
    case EntityKind::Curve: return (!e.local || finiteSpline(*e.local)) && (!e.world || finiteSpline(*e.world));
    case EntityKind::Surface: return !e.surface || finiteSpline(*e.surface);
    case EntityKind::Mesh: return !e.mesh || (allFinite(e.mesh->vertices) && allFinite(e.mesh->normals));
    case EntityKind::Constraint: return e.anchor.allFinite();
    }
    return false;
}

namespace {

/// On a plane a curve is planar by construction; z is exactly 0 so the document's 2D points
/// restore it bit for bit.
solvers::Curve3d flatten(const solvers::Curve3d& local)
{
    std::vector<Eigen::Vector3d> flat = local.points();
    for (Eigen::Vector3d& p : flat) p.z() = 0.0;
    return solvers::Curve3d(local.degree(), local.knots(), flat, local.weights(), local.isClosed());
}

}  // namespace

void Model::setCurveShape(EntityId curve, const solvers::Curve3d& local)
{
    auto it = entities_.find(curve);
    if (it == entities_.end() || it->second.kind != EntityKind::Curve) return;
    it->second.local = it->second.plane() != 0 ? flatten(local) : local;
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
    for (ModelObserver* o : observers_) o->entityAdded(stored);
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
    e.local = plane != 0 ? flatten(local) : local;
    return insert(std::move(e), id);
}

EntityId Model::addSurface(const solvers::Surface3d& surface, EntityId id)
{
    Entity e;
    e.kind = EntityKind::Surface;
    e.surface = surface;
    return insert(std::move(e), id);
}

void Model::checkSurfaceInputs(const std::vector<EntityId>& curves, const SurfaceRecipe& recipe) const
{
    const InputCount count = surfaceInputCount(recipe.mode);
    const int n = static_cast<int>(curves.size());
    if (n < count.min || n > count.max) {
        throw std::invalid_argument(recipe.mode + " needs " +
                                    (count.min == count.max ? std::to_string(count.min)
                                                            : std::to_string(count.min) + " to " + std::to_string(count.max)) +
                                    " curves, got " + std::to_string(n));
    }
    for (EntityId c : curves) {
        const Entity* e = find(c);
        if (!e || e->kind != EntityKind::Curve) throw std::invalid_argument("entity " + std::to_string(c) + " is not a curve");
    }
    for (const SurfaceRecipe::Tangent& t : recipe.tangents) {
        const Entity* s = find(t.surface);
        if (recipe.mode != "fill") throw std::invalid_argument("only a fill can be tangent to other surfaces");
        if (t.boundary < 0 || t.boundary >= n) throw std::invalid_argument("tangent boundary " + std::to_string(t.boundary) + " is not a boundary");
        if (!s || s->kind != EntityKind::Surface) throw std::invalid_argument("entity " + std::to_string(t.surface) + " is not a surface");
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
        buildSurface(e);
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
        buildSurface(e);
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
        buildSurface(e);
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
        buildMesh(e);
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

void Model::buildMesh(Entity& e) const
{
    std::vector<solvers::Curve3d> curves;
    std::vector<int> loop;
    for (EntityId input : e.inputs) {
        loop.push_back(static_cast<int>(curves.size()));
        curves.push_back(*entities_.at(input).world);
    }
    e.mesh = solvers::surfaces::meshNetwork(curves, {loop});
    e.buildError.clear();
    ++e.shapeVersion;
}

EntityId Model::addConstraint(EntityId curve, const std::string& type, double u, EntityId id)
{
    const Entity* c = find(curve);
    if (!c || c->kind != EntityKind::Curve) throw std::invalid_argument("entity " + std::to_string(curve) + " is not a curve");
    if (type != "position" && type != "tangent") throw std::invalid_argument("constraint type must be \"position\" or \"tangent\"");
    if (!std::isfinite(u)) throw std::invalid_argument("constraint parameter must be finite");
    Entity e;
    e.kind = EntityKind::Constraint;
    e.inputs = {curve};
    e.constraintType = type;
    // Kept inside the curve's domain, where the solver reads it (closed curves wrap there too).
    e.parameter = std::clamp(u, c->local->domainStart(), c->local->domainEnd());
    return insert(std::move(e), id);
}

void Model::setFixedPoints(EntityId curve, std::vector<int> fixed)
{
    auto it = entities_.find(curve);
    if (it == entities_.end() || it->second.kind != EntityKind::Curve) return;
    std::sort(fixed.begin(), fixed.end());
    fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());
    const int count = it->second.local->isClosed() ? it->second.local->pointCount() - it->second.local->degree()
                                                   : it->second.local->pointCount();
    for (int i : fixed) {
        if (i < 0 || i >= count) throw std::invalid_argument("fixed point " + std::to_string(i) + " is not a control point of curve " + std::to_string(curve));
    }
    it->second.fixedPoints = std::move(fixed);
    for (ModelObserver* o : observers_) o->entityUpdated(it->second);
}

void Model::setSurfaceRecipe(EntityId surface, const SurfaceRecipe& recipe)
{
    auto it = entities_.find(surface);
    if (it == entities_.end() || !it->second.recipe) return;
    it->second.recipe = recipe;
    markDirty(surface);
}

void Model::buildSurface(Entity& e) const
{
    namespace surf = solvers::surfaces;
    const SurfaceRecipe& r = *e.recipe;
    std::vector<solvers::Curve3d> curves;
    for (EntityId input : e.inputs) {
        const Entity& in = entities_.at(input);
        if (in.kind == EntityKind::Curve) curves.push_back(*in.world);
    }
    const surf::SurfaceBuild build = [&]() -> surf::SurfaceBuild {
        if (r.mode == "gordon") {
            // A grid-like network (seed 004 §4, The NURBS Book §10.5): the first `uCurves` inputs are
            // one family, the rest the other; every curve of one meets every curve of the other. The
            // reported deviation is the largest gap between crossing curves.
            const auto split = curves.begin() + std::clamp(r.uCurves, 0, static_cast<int>(curves.size()));
            const surf::GordonResult g = surf::buildGordon({curves.begin(), split}, {split, curves.end()}, {r.tolerance});
            return {g.surface, g.maxGap};
        }
        surf::SurfaceOptions options;
        options.tolerance = r.tolerance;
        for (const SurfaceRecipe::Tangent& t : r.tangents) {
            const Entity& adjacent = entities_.at(t.surface);
            if (!adjacent.surface) throw std::invalid_argument("surface " + std::to_string(t.surface) + ", which it is tangent to, has not been built");
            options.fillTangents.push_back({t.boundary, *adjacent.surface});
        }
        if (r.mode == "network") throw std::invalid_argument("\"network\" makes a mesh entity from a loop of curves, not a surface");
        const surf::SurfaceMode mode = surf::parseSurfaceMode(r.mode);
        if (mode == surf::SurfaceMode::Revolve) {
            // The axis is the line the designer drew: the last input's ends, start to end.
            const solvers::Curve3d axis = curves.back();
            curves.pop_back();
            if (axis.isClosed())
                throw std::invalid_argument("axis: the axis curve is closed, its ends coincide and give no direction");
            options.axisPoint = axis.evaluate(axis.domainStart());
            options.axisDirection = axis.evaluate(axis.domainEnd()) - options.axisPoint;
            options.angleDegrees = r.angleDegrees;
        }
        if (mode == surf::SurfaceMode::Extrude) {
            const Entity& profile = entities_.at(e.inputs.front());
            options.direction = profile.plane() != 0 ? Eigen::Vector3d(entities_.at(profile.plane()).frame.rotation * r.direction)
                                                     : r.direction;
        }
        return surf::buildSurface(mode, curves, options);
    }();
    e.surface = build.surface;
    e.maxDeviation = build.maxDeviation;
    e.maxTangentAngle = build.maxTangentAngleDegrees;
    e.buildError.clear();
    ++e.shapeVersion;
}

void Model::setPlaneFrame(EntityId plane, const PlaneFrame& frame)
{
    auto it = entities_.find(plane);
    if (it == entities_.end() || it->second.kind != EntityKind::Plane) return;
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

int Model::update()
{
    if (dirty_.empty()) return 0;
    // The closure of the dirty set under "depends on", in a std::set: ascending ids are a
    // topological order (see model.h), and a set visits each entity once however many paths lead
    // to it.
    std::set<EntityId> affected;
    std::vector<EntityId> stack(dirty_.begin(), dirty_.end());
    dirty_.clear();
    while (!stack.empty()) {
        const EntityId id = stack.back();
        stack.pop_back();
        if (!entities_.count(id) || !affected.insert(id).second) continue;
        if (auto d = dependents_.find(id); d != dependents_.end()) stack.insert(stack.end(), d->second.begin(), d->second.end());
    }
    for (EntityId id : affected) {
        Entity& e = entities_.at(id);
        recompute(e);
        ++e.recomputations;
        for (ModelObserver* o : observers_) o->entityUpdated(e);
    }
    return static_cast<int>(affected.size());
}

void Model::recompute(Entity& e)
{
    if (e.kind == EntityKind::Surface) {
        if (!e.recipe) return;  // a static surface, as read
        try {
            buildSurface(e);
        } catch (const std::exception& error) {
            // Mid-drag the curves may pass through a configuration the mode cannot build (a fill
            // whose boundaries no longer meet): keep the last good surface and say why.
            e.buildError = error.what();
        }
        return;
    }
    if (e.kind == EntityKind::Mesh) {
        try {
            buildMesh(e);
        } catch (const std::exception& error) {
            e.buildError = error.what();  // the curves pulled apart mid-drag: keep the last mesh
        }
        return;
    }
    if (e.kind == EntityKind::Constraint) {
        const solvers::Curve3d& curve = *entities_.at(e.inputs.front()).world;
        e.anchor = curve.evaluate(std::clamp(e.parameter, curve.domainStart(), curve.domainEnd()));
        return;
    }
    if (e.kind != EntityKind::Curve) return;  // a plane holds its frame
    const EntityId plane = e.plane();
    try {
        e.world = plane != 0 ? transformCurve(*e.local, entities_.at(plane).frame) : *e.local;
        e.buildError.clear();
    } catch (const std::exception& error) {
        e.buildError = error.what();  // coordinates beyond double range: the last world form stays
    }
}

std::vector<Entity> Model::remove(EntityId id)
{
    if (!entities_.count(id)) return {};
    std::set<EntityId> doomed;
    std::vector<EntityId> stack{id};
    while (!stack.empty()) {
        const EntityId next = stack.back();
        stack.pop_back();
        if (!doomed.insert(next).second) continue;
        if (auto d = dependents_.find(next); d != dependents_.end()) stack.insert(stack.end(), d->second.begin(), d->second.end());
    }
    std::vector<Entity> removed;
    // Dependents first (highest ids first), so observers never see a curve outlive its plane.
    for (auto it = doomed.rbegin(); it != doomed.rend(); ++it) {
        auto e = entities_.find(*it);
        for (ModelObserver* o : observers_) o->entityRemoved(e->second);
        for (EntityId input : e->second.inputs) dependents_[input].erase(*it);
        dependents_.erase(*it);
        dirty_.erase(*it);
        removed.push_back(std::move(e->second));
        entities_.erase(e);
    }
    std::reverse(removed.begin(), removed.end());
    return removed;
}

void Model::clear()
{
    while (!entities_.empty()) remove(entities_.begin()->first);
    nextId_ = 1;
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
