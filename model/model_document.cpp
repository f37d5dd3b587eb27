#include "model/model_document.h"

#include "model/atomic_file.h"
#include "model/document_solids.h"
#include "solvers/io/geometry_json.h"

#include <map>
#include <nlohmann/json.hpp>

namespace sculptline::model {
namespace io = solvers::io;
using nlohmann::json;

PlaneFrame planeFrame(const PlaneSpec& plane)
{
    PlaneFrame frame = PlaneFrame::fromNormal(plane.origin, plane.normal, plane.size, plane.xAxis);
    if (plane.rotation) frame.rotation = *plane.rotation;
    return frame;
}

void populateModel(const SceneDocument& doc, Model& model)
{
    model.clear();
    // Entities with ids are created in id order (inputs before dependents, as when they were made:
    // the reader checks a curve's id exceeds its plane's); those without follow with fresh ids.
    enum class Kind { Plane, Curve, Surface, Constructed, Mesh, Point, Solid };
    std::map<int, std::pair<Kind, size_t>> byId;
    std::vector<std::pair<Kind, size_t>> unnumbered;
    for (size_t i = 0; i < doc.planes.size(); ++i) byId[doc.planes[i].id] = {Kind::Plane, i};
    for (size_t i = 0; i < doc.curves.size(); ++i) {
        const int id = i < doc.curveIds.size() ? doc.curveIds[i] : 0;
        if (id != 0) byId[id] = {Kind::Curve, i};
        else unnumbered.push_back({Kind::Curve, i});
    }
    for (size_t i = 0; i < doc.surfaces.size(); ++i) {
        const int id = i < doc.surfaceIds.size() ? doc.surfaceIds[i] : 0;
        if (id != 0) byId[id] = {Kind::Surface, i};
        else unnumbered.push_back({Kind::Surface, i});
    }
    for (size_t i = 0; i < doc.meshes.size(); ++i) {
        if (doc.meshes[i].id != 0) byId[doc.meshes[i].id] = {Kind::Mesh, i};
        else unnumbered.push_back({Kind::Mesh, i});
    }
    for (size_t i = 0; i < doc.points.size(); ++i) byId[doc.points[i].id] = {Kind::Point, i};
    for (size_t i = 0; i < doc.solids.size(); ++i) byId[doc.solids[i].id] = {Kind::Solid, i};
    for (size_t i = 0; i < doc.constructed.size(); ++i) {
        if (doc.constructed[i].id != 0) byId[doc.constructed[i].id] = {Kind::Constructed, i};
        else unnumbered.push_back({Kind::Constructed, i});
    }
    auto flag = [](const std::vector<bool>& states, size_t i) { return i < states.size() && states[i]; };
    auto create = [&](Kind kind, size_t i, EntityId id) {
        EntityId made = 0;
        bool fixed = false;
        switch (kind) {
        case Kind::Plane:
            made = model.addPlane(planeFrame(doc.planes[i]), id);
            fixed = doc.planes[i].fixed;
            break;
        case Kind::Curve: {
            const int plane = i < doc.curvePlanes.size() ? doc.curvePlanes[i] : 0;
            made = model.addCurve(static_cast<EntityId>(plane), doc.curves[i], id);
            if (i < doc.curveFixed.size() && !doc.curveFixed[i].empty()) model.setFixedPoints(made, doc.curveFixed[i]);
            fixed = flag(doc.curveStates, i);
            break;
        }
        case Kind::Surface:
            made = model.addSurface(doc.surfaces[i], id);
            fixed = flag(doc.surfaceStates, i);
            if (i < doc.surfaceIncidenceK.size()) model.setIncidenceK(made, doc.surfaceIncidenceK[i]);
            if (i < doc.surfacePriors.size() && doc.surfacePriors[i]) model.setIncidencePrior(made, doc.surfacePriors[i]);
            break;
        case Kind::Point:
            made = model.addPoint(doc.points[i].position, id, doc.points[i].rotation);
            fixed = doc.points[i].fixed;
            break;
        case Kind::Mesh: {
            const std::vector<EntityId> curves(doc.meshes[i].curves.begin(), doc.meshes[i].curves.end());
            made = model.addMesh(curves, id, true);
            fixed = doc.meshes[i].fixed;
            break;
        }
        case Kind::Solid: {
            const SceneDocument::SolidSpec& s = doc.solids[i];
            made = model.addSolid(std::vector<EntityId>(s.surfaces.begin(), s.surfaces.end()), s.recipe, id, s.result);
            fixed = s.fixed;
            break;
        }
        case Kind::Constructed: {
            // Rebuilt from its curves (the build is deterministic, so this is the saved surface);
            // should it fail, the saved surface (or none) stands, marked failed with the reason:
            // the document opens with everything else intact.
            const SceneDocument::ConstructedSurface& c = doc.constructed[i];
            const std::vector<EntityId> curves(c.curves.begin(), c.curves.end());
            made = model.restoreSurface(curves, c.recipe, id, c.saved);
            fixed = c.fixed;
            break;
        }
        }
        if (fixed) model.setFixed(made, true);
    };
    for (const auto& [id, entry] : byId) create(entry.first, entry.second, static_cast<EntityId>(id));
    for (const auto& [kind, i] : unnumbered) create(kind, i, 0);
    // The designer's constraints last: they name entities of any kind (the reader checked them).
    for (Constraint c : doc.constraints) {
        if (c.type == ConstraintType::FixedPoints) {
            std::vector<int> fixed = model.fixedPoints(c.targets.front());
            fixed.insert(fixed.end(), c.indices.begin(), c.indices.end());
            model.setFixedPoints(c.targets.front(), fixed);
            continue;
        }
        model.addConstraint(std::move(c));
    }
    model.update();
}

namespace {

/// The sculpt's handles, bound, blocked points, distances and curve tangents, as the reader takes them.
void sculptToJson(const Model&, const SurfaceRecipe& r, json& c)
{
    auto uv = [](const Eigen::Vector2d& p) { return json::array({p.x(), p.y()}); };
    if (!r.handles.empty()) {
        json handles = json::array();
        for (const SurfaceRecipe::Handle& h : r.handles) handles.push_back({{"point", h.point}, {"uv", uv(h.uv)}, {"normal", h.holdNormal}});
        c["points"] = std::move(handles);
    }
    if (!r.bound.empty()) {
        json bound = json::array();
        for (const Eigen::Vector2d& p : r.bound) bound.push_back(uv(p));
        c["bound"] = std::move(bound);
    }
    if (!r.blocked.empty()) c["blocked"] = r.blocked;
    if (!r.distances.empty()) {
        json distances = json::array();
        for (const SurfaceRecipe::Distance& d : r.distances) distances.push_back({{"uv", uv(d.uv)}, {"uv2", uv(d.uv2)}, {"value", d.distance}});
        c["distances"] = std::move(distances);
    }
    if (!r.curveTangents.empty()) {
        json tangents = json::array();
        for (const SurfaceRecipe::CurveTangent& t : r.curveTangents) tangents.push_back({{"curve", t.curve}, {"direction", io::toJson(t.direction)}});
        c["curve_tangents"] = std::move(tangents);
    }
}

}  // namespace

json modelToJson(const Model& model, const GridSpec& grid)
{
    json planes = json::array(), curves = json::array(), surfaces = json::array(), constraints = json::array(),
         meshes = json::array(), points = json::array(), solids = json::array();
    for (const auto& [id, e] : model.entities()) {
        json entry;
        switch (e.kind) {
        case EntityKind::Plane:
            entry = {{"id", id},
                     {"origin", io::toJson(e.frame.origin)},
                     {"normal", io::toJson(e.frame.normal())},
                     {"xAxis", io::toJson(e.frame.xAxis())},
                     {"rotation", {e.frame.rotation.x(), e.frame.rotation.y(), e.frame.rotation.z(), e.frame.rotation.w()}},
                     {"size", e.frame.size}};
            break;
        case EntityKind::Curve: {
            entry = io::toJson(*e.local);
            entry["id"] = id;
            if (e.plane() != 0) {
                entry["plane"] = e.plane();
                // Plane-local points are 2D: [x, y].
                for (json& p : entry["points"]) p.erase(2);
            }
            // Fixed control points as documents have always held them, on the curve.
            if (const std::vector<int> fixed = model.fixedPoints(id); !fixed.empty()) entry["fixed"] = fixed;
            break;
        }
        case EntityKind::Mesh: entry = {{"id", id}, {"curves", e.inputs}}; break;
        case EntityKind::Solid: entry = solidToJson(e); break;
        case EntityKind::Point:
            entry = {{"id", id}, {"position", io::toJson(e.position)}};
            if (!e.rotation.isApprox(Eigen::Quaterniond::Identity(), 0.0))
                entry["rotation"] = {e.rotation.x(), e.rotation.y(), e.rotation.z(), e.rotation.w()};
            break;
        case EntityKind::Surface: {
            // A construction that never built has no geometry: the construction alone is saved.
            entry = e.surface ? io::toJson(*e.surface) : json::object();
            entry["id"] = id;
            if (!e.recipe && e.incidenceK > 0) entry["incidence_k"] = e.incidenceK;
            if (!e.recipe && e.prior) entry["incidence_prior"] = io::toJson(*e.prior);
            if (e.recipe) {
                const ConstructionInfo& info = describe(e.recipe->mode);
                std::vector<EntityId> inputs = e.curveInputs();
                json c{{"mode", info.name}};
                if (info.baseSurface) {
                    c["base"] = inputs.front();
                    inputs.erase(inputs.begin());
                    sculptToJson(model, *e.recipe, c);
                    // The points are named by the handles; "curves" keeps the target curves.
                    inputs.erase(std::remove_if(inputs.begin(), inputs.end(),
                                                [&](EntityId in) { return model.find(in)->kind == EntityKind::Point; }),
                                 inputs.end());
                }
                c["curves"] = inputs;
                if (!e.recipe->tangents.empty()) {
                    json tangents = json::array();
                    for (const SurfaceRecipe::Tangent& t : e.recipe->tangents) tangents.push_back({{"curve", t.boundary}, {"surface", t.surface}});
                    c["tangents"] = std::move(tangents);
                }
                if (info.options & kAngleOption) c["angle"] = e.recipe->angleDegrees;
                if (info.options & kDirectionOption) c["direction"] = io::toJson(e.recipe->direction);
                if (e.recipe->tolerance > 0.0) c["tolerance"] = e.recipe->tolerance;
                if (info.options & kUCurvesOption) c["u_curves"] = e.recipe->uCurves;
                if (info.options & kStiffnessOption) {
                    c["stiffness"] = e.recipe->stiffness;
                    c["objective"] = e.recipe->displacementObjective ? "displacement" : "force";
                }
                entry["construction"] = std::move(c);
            }
            break;
        }
        }
        if (e.fixed) entry["state"] = "fixed";
        switch (e.kind) {
        case EntityKind::Plane: planes.push_back(std::move(entry)); break;
        case EntityKind::Curve: curves.push_back(std::move(entry)); break;
        case EntityKind::Mesh: meshes.push_back(std::move(entry)); break;
        case EntityKind::Surface: surfaces.push_back(std::move(entry)); break;
        case EntityKind::Point: points.push_back(std::move(entry)); break;
        case EntityKind::Solid: solids.push_back(std::move(entry)); break;
        }
    }
    for (const auto& [id, c] : model.constraints()) {
        if (derivedConstraint(c.type) || c.type == ConstraintType::FixedPoints) continue;  // with their entities
        if (c.type == ConstraintType::Position || c.type == ConstraintType::Tangent) {
            constraints.push_back({{"curve", c.targets.front()}, {"type", constraintTypeName(c.type)}, {"u", c.parameters.front()}});
            continue;
        }
        json k{{"type", constraintTypeName(c.type)}, {"targets", c.targets}};
        if (!c.sources.empty()) k["sources"] = c.sources;
        if (c.parameters.size() == 1) k["u"] = c.parameters.front();
        if (c.parameters.size() == 2) k["uv"] = c.parameters;
        if (!c.indices.empty()) k["indices"] = c.indices;
        if (!c.value.isZero()) k["value"] = io::toJson(c.value);
        if (c.weight != 1.0) k["weight"] = c.weight;
        if (c.preimage) k["preimage"] = io::toJson(*c.preimage);
        constraints.push_back(std::move(k));
    }
    json doc{{"format", kDocumentFormat},
                {"version", kDocumentVersion},
                {"units", "mm"},
                {"grid", {{"size", grid.size}, {"spacing", grid.spacing}}},
                {"planes", planes},
                {"curves", curves},
                {"surfaces", surfaces},
                {"constraints", constraints},
                {"meshes", meshes},
                {"points", points}};
    if (!solids.empty()) doc["solids"] = std::move(solids);  // documents without solids stay as they were
    return doc;
}

void saveModel(const Model& model, const GridSpec& grid, const std::string& path)
{
    writeFileAtomically(path, modelToJson(model, grid).dump(2) + "\n", true);
}

}  // namespace sculptline::model
