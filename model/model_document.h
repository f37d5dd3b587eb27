#pragma once
// Documents <-> the model. A saved document restores the model exactly: planes keep their ids and
// full frames (origin, normal and in-plane X axis), curves on a plane keep their plane-local control
// points, and numbers are written with round-trip precision (nlohmann::json prints the shortest
// decimal that reads back as the same double).
#include "model/model.h"
#include "model/document.h"

#include <nlohmann/json_fwd.hpp>
#include <string>

namespace sculptline::model {

/// The frame of a document plane (PlaneFrame::fromNormal with its xAxis).
PlaneFrame planeFrame(const PlaneSpec& plane);

/// Clears `model` and fills it from `doc`: planes first (with their document ids), then curves,
/// then surfaces; update()s so every curve has its world form.
void populateModel(const SceneDocument& doc, Model& model);

/// The document of `model` in the format documentFromJson reads (units, grid, planes with id and
/// xAxis, curves with "plane", surfaces).
nlohmann::json modelToJson(const Model& model, const GridSpec& grid);

/// Writes modelToJson to `path` atomically, the previous version kept in backupPath(path)
/// (model/atomic_file.h). @throws solvers::io::InputError("path: cannot save (reason)"); the
/// file at `path` is then unchanged.
void saveModel(const Model& model, const GridSpec& grid, const std::string& path);

}  // namespace sculptline::model
