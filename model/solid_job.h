#pragma once
// A solid's conversion, taken out of the model so that it can run on another thread: solidJob()
// copies what the conversion reads (the input surfaces as they are now, the recipe, the version
// they have), runSolidJob() converts (seconds at fine voxel sizes; cancellable through its
// progress callback), and Model::setSolidResult() stores the result only if the inputs have not
// changed meanwhile. The model itself never converts in update(): a drag would wait on it.
#include "model/model.h"
#include "solvers/volume/solidify.h"

#include <vector>

namespace sculptline::model {

struct SolidJob {
    EntityId solid = 0;
    int version = 0;  ///< the solid's sourceVersion when the job was taken
    std::vector<solvers::Surface3d> surfaces;
    SolidRecipe recipe;
};

/// The job of converting `solid` as the model is now.
/// @throws std::invalid_argument when `solid` is not a solid, or an input surface has no geometry
///         (a construction that never built).
SolidJob solidJob(const Model& model, EntityId solid);
/// The same for surfaces not (yet) in a solid entity: what "Make solid" converts before it adds one.
SolidJob solidJob(const Model& model, const std::vector<EntityId>& surfaces, const SolidRecipe& recipe);

/// Converts the job (solidify with the recipe's thickness and voxel size).
/// @throws solvers::GeometryError (the input cannot become a solid: the message names the field)
///         and solvers::volume::Cancelled (progress answered false).
solvers::volume::Solid runSolidJob(const SolidJob& job, const solvers::volume::Progress& progress = {});

/// Converts every stale solid of `model` on this thread and stores the results or errors; returns
/// how many it converted. For headless use (the CLI's documents, tests); the ui converts in the
/// background instead.
int convertStaleSolids(Model& model);

}  // namespace sculptline::model
