// Per-event cost of a plane drag when surfaces depend on the plane's curves (issue 6 §2: p99
// <= 16 ms with 4 dependent surfaces): the document of the live-update replay
// (data/models/surfaces_drag_start.json: boundary rotation, revolve, extrusion and sweep on one
// plane's curves), the plane moved a little per iteration, the model updated. With the Coin view,
// the rebuilt surfaces are re-tessellated too, as in the GUI.
#include "model/model.h"
#include "model/model_document.h"
#include "scene/model_view.h"
#include "model/document.h"
#include "solvers/bspline/tessellation.h"

#include <Inventor/SoDB.h>
#include <benchmark/benchmark.h>

#include <memory>

namespace {

using namespace sculptline;

void dragPlane(benchmark::State& state, bool withView)
{
    SoDB::init();
    model::Model model;
    model::populateModel(model::loadDocument(SCULPTLINE_DATA_DIR "/models/surfaces_drag_start.json"), model);
    std::unique_ptr<scene::ModelView> view = withView ? std::make_unique<scene::ModelView>(model) : nullptr;
    model::PlaneFrame frame = model.find(1)->frame;
    int step = 0;
    for (auto _ : state) {
        // A pointer event's worth of motion, back and forth so the scene stays where it is.
        frame.origin.z() += (step++ % 40 < 20) ? 0.5 : -0.5;
        model.setPlaneFrame(1, frame);
        benchmark::DoNotOptimize(model.update());
    }
    int grid = 0, vertices = 0;
    for (const auto& [id, e] : model.entities()) {
        if (e.kind != model::EntityKind::Surface) continue;
        grid += e.surface->countU() * e.surface->countV();
        vertices += static_cast<int>(solvers::tessellate(*e.surface).vertices.size());
    }
    state.counters["control_points"] = grid;
    state.counters["mesh_vertices"] = vertices;
}

void BM_ScenePlaneDragFourSurfaces(benchmark::State& state) { dragPlane(state, false); }
void BM_ScenePlaneDragFourSurfacesWithView(benchmark::State& state) { dragPlane(state, true); }

}  // namespace

BENCHMARK(BM_ScenePlaneDragFourSurfaces)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ScenePlaneDragFourSurfacesWithView)->Unit(benchmark::kMillisecond);

namespace {

/// The kernel's adaptive tessellation of the four surfaces alone (what a rebuild re-tessellates).
void BM_SceneTessellateFourSurfaces(benchmark::State& state)
{
    model::Model model;
    model::populateModel(model::loadDocument(SCULPTLINE_DATA_DIR "/models/surfaces_drag_start.json"), model);
    for (auto _ : state) {
        for (const auto& [id, e] : model.entities()) {
            if (e.kind == model::EntityKind::Surface) benchmark::DoNotOptimize(solvers::tessellate(*e.surface));
        }
    }
}

}  // namespace

BENCHMARK(BM_SceneTessellateFourSurfaces)->Unit(benchmark::kMillisecond);
