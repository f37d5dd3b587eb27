// SketchDocument's CAD and mesh export (solvers/exchange): the model's world geometry as it is
// now — every curve's world form, every surface's current patch, every network mesh.
#include "ui/sketch_document.h"

namespace sculptline::ui {

std::uintmax_t SketchDocument::exportGeometry(const QString& path, solvers::exchange::Format format)
{
    scheduler_->flush();
    namespace ex = solvers::exchange;
    ex::ExchangeContent content;
    for (const auto& [id, e] : model_.entities()) {
        if (e.kind == model::EntityKind::Curve && e.world) content.curves.push_back(*e.world);
        if (e.kind == model::EntityKind::Surface && e.surface) content.surfaces.push_back(*e.surface);
        // STEP and IGES carry B-splines only; a network mesh goes into the mesh formats.
        if (e.kind == model::EntityKind::Mesh && e.mesh && (format == ex::Format::Stl || format == ex::Format::Obj)) {
            content.meshes.push_back({e.mesh->vertices, e.mesh->triangles});
        }
    }
    return ex::writeFile(content, format, path.toStdString());
}

}  // namespace sculptline::ui
