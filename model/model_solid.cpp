// The model's solid entities (model.h): their inputs, results and errors. Conversions run outside
// (model/solid_job.h), so update() only marks a solid due (the "solid" step, solver_registry.cpp).
#include "model/model.h"
#include "model/solid_job.h"

#include "solvers/bspline/geometry_error.h"

#include <stdexcept>

namespace sculptline::model {

EntityId Model::addSolid(const std::vector<EntityId>& surfaces, const SolidRecipe& recipe, EntityId id,
                         const std::optional<solvers::volume::Solid>& result)
{
    if (surfaces.empty()) throw std::invalid_argument("a solid needs at least one surface");
    for (EntityId s : surfaces) {
        const Entity* e = find(s);
        if (!e || e->kind != EntityKind::Surface) throw std::invalid_argument("entity " + std::to_string(s) + " is not a surface");
    }
    if (const std::string error = validate(recipe); !error.empty()) throw std::invalid_argument(error);
    Entity e;
    e.kind = EntityKind::Solid;
    e.inputs = surfaces;
    e.solidRecipe = recipe;
    if (result) {
        e.solid = result;
        e.solidVersion = e.sourceVersion;
        e.shapeVersion = 1;
    }
    return insert(std::move(e), id, true);
}

bool Model::setSolidResult(EntityId id, int version, solvers::volume::Solid result)
{
    auto it = entities_.find(id);
    if (it == entities_.end() || it->second.kind != EntityKind::Solid || it->second.sourceVersion != version) return false;
    Entity& e = it->second;
    e.solid = std::move(result);
    e.solidVersion = version;
    e.buildError.clear();
    ++e.shapeVersion;
    for (ModelObserver* o : observers_) o->entityUpdated(e);
    return true;
}

bool Model::setSolidError(EntityId id, int version, const std::string& error)
{
    auto it = entities_.find(id);
    if (it == entities_.end() || it->second.kind != EntityKind::Solid || it->second.sourceVersion != version) return false;
    it->second.buildError = error;
    for (ModelObserver* o : observers_) o->entityUpdated(it->second);
    return true;
}

SolidJob solidJob(const Model& model, const std::vector<EntityId>& surfaces, const SolidRecipe& recipe)
{
    if (const std::string error = validate(recipe); !error.empty()) throw std::invalid_argument(error);
    if (surfaces.empty()) throw std::invalid_argument("a solid needs at least one surface");
    SolidJob job;
    job.recipe = recipe;
    for (EntityId s : surfaces) {
        const Entity* e = model.find(s);
        if (!e || e->kind != EntityKind::Surface) throw std::invalid_argument("entity " + std::to_string(s) + " is not a surface");
        if (!e->surface) throw std::invalid_argument("surface " + std::to_string(s) + " has no geometry (its construction never built)");
        job.surfaces.push_back(*e->surface);
    }
    return job;
}

SolidJob solidJob(const Model& model, EntityId solid)
{
    const Entity* e = model.find(solid);
    if (!e || e->kind != EntityKind::Solid) throw std::invalid_argument("entity " + std::to_string(solid) + " is not a solid");
    SolidJob job = solidJob(model, e->inputs, *e->solidRecipe);
    job.solid = solid;
    job.version = e->sourceVersion;
    return job;
}

solvers::volume::Solid runSolidJob(const SolidJob& job, const solvers::volume::Progress& progress)
{
    solvers::volume::SolidOptions options;
    options.thickness = job.recipe.mode == SolidMode::Shell ? job.recipe.thickness : 0.0;
    options.voxelSize = job.recipe.voxelSize;
    options.progress = progress;
    return solvers::volume::solidify(job.surfaces, options);
}

int convertStaleSolids(Model& model)
{
    std::vector<EntityId> stale;
    for (const auto& [id, e] : model.entities())
        if (e.solidStale()) stale.push_back(id);
    for (EntityId id : stale) {
        int version = model.find(id)->sourceVersion;
        try {
            const SolidJob job = solidJob(model, id);
            version = job.version;
            model.setSolidResult(id, version, runSolidJob(job));
        } catch (const std::exception& error) {
            model.setSolidError(id, version, error.what());
        }
    }
    return static_cast<int>(stale.size());
}

}  // namespace sculptline::model
