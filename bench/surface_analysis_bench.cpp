// Per-event cost of the surface analysis display during a drag (scene/surface_analysis_display.h):
// the revolved bottle (data/models/bottle_surfaces.json: two revolves and a sweep on plane 2's
// curves) with every surface Shaded, Zebra, Gaussian or Mean, plane 2 dragged within a drag
// (beginDrag .. endDrag, as the GUI does). The time is one pointer event: the model's update plus
// the view's in-place rewrite and, in the analysis modes, the recolouring; the analysis share is
// the difference to the Shaded run.
#include "model/document.h"
#include "model/model.h"
#include "model/model_document.h"
#include "scene/model_view.h"
#include "solvers/bspline/surface_curvature.h"
#include "solvers/bspline/tessellation.h"

#include <Inventor/SoDB.h>
#include <benchmark/benchmark.h>

namespace {

using namespace sculptline;

void dragBottle(benchmark::State& state, scene::SurfaceDisplay mode)
{
    SoDB::init();
    model::Model model;
    model::populateModel(model::loadDocument(SCULPTLINE_DATA_DIR "/models/bottle_surfaces.json"), model);
    scene::ModelView view(model);
    view.setSurfaceDisplay(0, mode);
    constexpr model::EntityId kPlane = 2;
    model::PlaneFrame frame = model.find(kPlane)->frame;
    const Eigen::Vector3d axis = frame.rotation * Eigen::Vector3d::UnitX();
    model.beginDrag(kPlane);
    const int recoloursBefore = view.surfaceAnalysis().recolours();
    int step = 0;
    for (auto _ : state) {
        frame.origin += ((step++ % 40 < 20) ? 0.2 : -0.2) * axis;
        model.setPlaneFrame(kPlane, frame);
        benchmark::DoNotOptimize(model.update());
    }
    model.endDrag();
    state.counters["recolours"] =
        benchmark::Counter(view.surfaceAnalysis().recolours() - recoloursBefore, benchmark::Counter::kAvgIterations);
    state.counters["in_place"] = benchmark::Counter(view.inPlaceUpdates(), benchmark::Counter::kAvgIterations);
    size_t vertices = 0;
    for (const auto& [id, e] : model.entities()) {
        const std::vector<double>* u = view.surfaceAnalysis().gridU(id);
        if (u) vertices += u->size() * view.surfaceAnalysis().gridV(id)->size();
    }
    state.counters["analysed_vertices"] = static_cast<double>(vertices);
}

void BM_SurfaceAnalysisDragBottleShaded(benchmark::State& state) { dragBottle(state, scene::SurfaceDisplay::Shaded); }
void BM_SurfaceAnalysisDragBottleZebra(benchmark::State& state) { dragBottle(state, scene::SurfaceDisplay::Zebra); }
void BM_SurfaceAnalysisDragBottleGaussian(benchmark::State& state) { dragBottle(state, scene::SurfaceDisplay::Gaussian); }
void BM_SurfaceAnalysisDragBottleMean(benchmark::State& state) { dragBottle(state, scene::SurfaceDisplay::Mean); }

/// K and H on a drag-sized grid (the model view's kDragVertexBudget, 12,000 vertices) of the
/// bottle's rational bicubic x biquadratic revolve: the curvature part of one recolouring.
void BM_CurvatureGridBottle12k(benchmark::State& state)
{
    const model::SceneDocument doc = model::loadDocument(SCULPTLINE_DATA_DIR "/models/bottle_surfaces.json");
    model::Model model;
    model::populateModel(doc, model);
    const solvers::Surface3d& s = *model.find(8)->surface;
    std::vector<double> u(100), v(120);
    for (size_t i = 0; i < u.size(); ++i) u[i] = static_cast<double>(i) / (u.size() - 1);
    for (size_t i = 0; i < v.size(); ++i) v[i] = static_cast<double>(i) / (v.size() - 1);
    const solvers::CurvatureGrid grid(s, u, v);
    std::vector<solvers::SurfaceCurvature> out;
    for (auto _ : state) {
        grid.evaluate(s, out);
        benchmark::DoNotOptimize(out.data());
    }
    state.counters["vertices"] = static_cast<double>(out.size());
}

}  // namespace

BENCHMARK(BM_SurfaceAnalysisDragBottleShaded)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SurfaceAnalysisDragBottleZebra)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SurfaceAnalysisDragBottleGaussian)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SurfaceAnalysisDragBottleMean)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CurvatureGridBottle12k)->Unit(benchmark::kMillisecond);
