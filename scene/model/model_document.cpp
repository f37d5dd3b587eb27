#include "scene/model/model_document.h"

#include "solvers/io/geometry_json.h"

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

namespace sculptline::scene {
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
    // Entity ids: planes keep their document ids; everything else is numbered after them, so ids
    // still grow in dependency order.
    std::map<int, EntityId> planeIds;
    for (const PlaneSpec& p : doc.planes) planeIds[p.id] = model.addPlane(planeFrame(p), static_cast<EntityId>(p.id));
    for (size_t i = 0; i < doc.curves.size(); ++i) {
        const int plane = i < doc.curvePlanes.size() ? doc.curvePlanes[i] : 0;
        model.addCurve(plane != 0 ? planeIds.at(plane) : 0, doc.curves[i]);
    }
    for (const solvers::Surface3d& s : doc.surfaces) model.addSurface(s);
    model.update();
}

json modelToJson(const Model& model, const GridSpec& grid)
{
    json planes = json::array(), curves = json::array(), surfaces = json::array();
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
            if (e.plane() != 0) {
                c["plane"] = e.plane();
                // Plane-local points are 2D: [x, y].
                for (json& p : c["points"]) p.erase(2);
            }
            curves.push_back(std::move(c));
            break;
        }
        case EntityKind::Surface: surfaces.push_back(io::toJson(*e.surface)); break;
        }
    }
    return json{{"units", "mm"},
                {"grid", {{"size", grid.size}, {"spacing", grid.spacing}}},
                {"planes", planes},
                {"curves", curves},
                {"surfaces", surfaces}};
}

void saveModel(const Model& model, const GridSpec& grid, const std::string& path)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (out) out << modelToJson(model, grid).dump(2) << "\n";
    if (!out) throw io::InputError(path + ": cannot write file");
}

}  // namespace sculptline::scene
