#include "model/model_document.h"

#include "model/atomic_file.h"
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
    enum class Kind { Plane, Curve, Surface, Constructed, Constraint, Mesh };
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
    for (size_t i = 0; i < doc.constraints.size(); ++i) {
        if (doc.constraints[i].id != 0) byId[doc.constraints[i].id] = {Kind::Constraint, i};
        else unnumbered.push_back({Kind::Constraint, i});
    }
    for (size_t i = 0; i < doc.constructed.size(); ++i) {
        if (doc.constructed[i].id != 0) byId[doc.constructed[i].id] = {Kind::Constructed, i};
        else unnumbered.push_back({Kind::Constructed, i});
    }
    auto create = [&](Kind kind, size_t i, EntityId id) {
        switch (kind) {
        case Kind::Plane: model.addPlane(planeFrame(doc.planes[i]), id); break;
        case Kind::Curve: {
            const int plane = i < doc.curvePlanes.size() ? doc.curvePlanes[i] : 0;
            const EntityId curve = model.addCurve(static_cast<EntityId>(plane), doc.curves[i], id);
            if (i < doc.curveFixed.size() && !doc.curveFixed[i].empty()) model.setFixedPoints(curve, doc.curveFixed[i]);
            break;
        }
        case Kind::Surface: model.addSurface(doc.surfaces[i], id); break;
        case Kind::Mesh: {
            const std::vector<EntityId> curves(doc.meshes[i].curves.begin(), doc.meshes[i].curves.end());
            model.addMesh(curves, id, true);
            break;
        }
        case Kind::Constraint: {
            const SceneDocument::ConstraintSpec& c = doc.constraints[i];
            model.addConstraint(static_cast<EntityId>(c.curve), c.type, c.u, id);
            break;
        }
        case Kind::Constructed: {
            // Rebuilt from its curves (the build is deterministic, so this is the saved surface);
            // should it fail, the saved surface (or none) stands, marked failed with the reason:
            // the document opens with everything else intact.
            const SceneDocument::ConstructedSurface& c = doc.constructed[i];
            const std::vector<EntityId> curves(c.curves.begin(), c.curves.end());
            model.restoreSurface(curves, c.recipe, id, c.saved);
            break;
        }
        }
    };
    for (const auto& [id, entry] : byId) create(entry.first, entry.second, static_cast<EntityId>(id));
    for (const auto& [kind, i] : unnumbered) create(kind, i, 0);
    model.update();
}

json modelToJson(const Model& model, const GridSpec& grid)
{
    json planes = json::array(), curves = json::array(), surfaces = json::array(), constraints = json::array(),
         meshes = json::array();
    for (const auto& [id, e] : model.entities()) {
        switch (e.kind) {
        case EntityKind::Plane:
            planes.push_back({{"id", id},
                              {"origin", io::toJson(e.frame.origin)},
                              {"normal", io::toJson(e.frame.normal())},
                              {"xAxis", io::toJson(e.frame.xAxis())},
                              {"rotation", {e.frame.rotation.x(), e.frame.rotation.y(), e.frame.rotation.z(), e.frame.rotation.w()}},
                              {"size", e.frame.size}});
            break;
        case EntityKind::Curve: {
            json c = io::toJson(*e.local);
            c["id"] = id;
            if (e.plane() != 0) {
                c["plane"] = e.plane();
                // Plane-local points are 2D: [x, y].
                for (json& p : c["points"]) p.erase(2);
            }
            if (!e.fixedPoints.empty()) c["fixed"] = e.fixedPoints;
            curves.push_back(std::move(c));
            break;
        }
        case EntityKind::Mesh: meshes.push_back({{"id", id}, {"curves", e.inputs}}); break;
        case EntityKind::Constraint:
            constraints.push_back({{"id", id}, {"curve", e.inputs.front()}, {"type", e.constraintType}, {"u", e.parameter}});
            break;
        case EntityKind::Surface: {
            // A construction that never built has no geometry: the construction alone is saved.
            json s = e.surface ? io::toJson(*e.surface) : json::object();
            s["id"] = id;
            if (e.recipe) {
                json c{{"mode", e.recipe->mode}, {"curves", e.curveInputs()}};
                if (!e.recipe->tangents.empty()) {
                    json tangents = json::array();
                    for (const SurfaceRecipe::Tangent& t : e.recipe->tangents) tangents.push_back({{"curve", t.boundary}, {"surface", t.surface}});
                    c["tangents"] = std::move(tangents);
                }
                if (e.recipe->mode == "revolve") c["angle"] = e.recipe->angleDegrees;
                if (e.recipe->mode == "extrude") c["direction"] = io::toJson(e.recipe->direction);
                if (e.recipe->tolerance > 0.0) c["tolerance"] = e.recipe->tolerance;
                if (e.recipe->mode == "gordon") c["u_curves"] = e.recipe->uCurves;
                s["construction"] = std::move(c);
            }
            surfaces.push_back(std::move(s));
            break;
        }
        }
    }
    return json{{"format", kDocumentFormat},
                {"version", kDocumentVersion},
                {"units", "mm"},
                {"grid", {{"size", grid.size}, {"spacing", grid.spacing}}},
                {"planes", planes},
                {"curves", curves},
                {"surfaces", surfaces},
                {"constraints", constraints},
                {"meshes", meshes}};
}

void saveModel(const Model& model, const GridSpec& grid, const std::string& path)
{
    writeFileAtomically(path, modelToJson(model, grid).dump(2) + "\n", true);
}

}  // namespace sculptline::model
