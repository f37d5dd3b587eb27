#pragma once
// Export of the model as an Open Inventor 2.1 ASCII file made of standard nodes only (no draggers,
// no Coin extensions such as SoPolygonOffset), so that it loads in Coin and in SGI's reference
// reader (ivcat, ivview) alike.
#include "model/model.h"
#include "model/document.h"

#include <string>

class SoSeparator;

namespace sculptline::scene {

/// A graph of plain nodes: SoSeparator "SculptlineExport" { "GroundGrid", "Surfaces", "Curves"
/// (world-space line sets), "Planes" (placed quads with their grid) }. Reference count 0.
SoSeparator* makeExportGraph(const model::Model& model, const model::GridSpec& grid);

/// Writes makeExportGraph to `path` with SoWriteAction.
/// @throws solvers::io::InputError("path: cannot write file").
void exportIv(const model::Model& model, const model::GridSpec& grid, const std::string& path);

}  // namespace sculptline::scene
