// SketchDocument's CAD and mesh export (solvers/exchange): the model's world geometry as it is
// now — every curve's world form, every surface's current patch, every network mesh; in the mesh
// formats a solid's watertight mesh stands for the surfaces it was made from (a 3D printer wants
// the closed solid, not the open patches inside it).
#include "ui/sketch_document.h"

#include <set>

namespace sculptline::ui {

std::uintmax_t SketchDocument::exportGeometry(const QString& path, solvers::exchange::Format format)
{
    scheduler_->flush();
    namespace ex = solvers::exchange;
    ex::ExchangeContent content;
    const bool meshFormat = format == ex::Format::Stl || format == ex::Format::Obj;
    std::set<model::EntityId> inSolids;
    for (const auto& [id, e] : model_.entities()) {
        if (e.kind == model::EntityKind::Solid && e.solid && meshFormat) inSolids.insert(e.inputs.begin(), e.inputs.end());
    }
    for (const auto& [id, e] : model_.entities()) {
        if (e.kind == model::EntityKind::Curve && e.world) content.curves.push_back(*e.world);
        if (e.kind == model::EntityKind::Surface && e.surface && !inSolids.count(id)) content.surfaces.push_back(*e.surface);
        if (e.kind == model::EntityKind::Solid && e.solid && meshFormat) content.meshes.push_back({e.solid->mesh.vertices, e.solid->mesh.triangles});
        // STEP and IGES carry B-splines only; a network mesh goes into the mesh formats.
        if (e.kind == model::EntityKind::Mesh && e.mesh && (format == ex::Format::Stl || format == ex::Format::Obj)) {
            content.meshes.push_back({e.mesh->vertices, e.mesh->triangles});
        }
    }
    return ex::writeFile(content, format, path.toStdString());
}

}  // namespace sculptline::ui
