// Per-event cost of the model and its Coin view while a plane is dragged or a curve pulled (issue 6
// §2: p99 <= 16 ms with 4 dependent surfaces; issue 12: no slower than the model before the
// constraint graph, and the gain of the solvers factored once per drag). Every benchmark's time is
// one pointer event: the edit (a plane moved a little, a pull's target moved), then model.update().
// "WithView" variants run the same loop with a scene::ModelView observing the model, as the GUI
// does; their coin_ms counter is the time spent in the view's observer calls (re-tessellating the
// rebuilt surfaces, writing the plane's transform), so model and Coin cost read apart in one run.
// Variants without "CachedBuilders" edit and update with no drag in progress, so each event builds
// the surfaces afresh (what the model did before beginDrag); "CachedBuilders" ones wrap the loop in
// model.beginDrag(plane) ... endDrag(), the GUI's path (manipulators/plane_binding.cpp), where fill,
// loft and sweep keep their builders' set-up across the events.
#include "model/model.h"
#include "model/model_document.h"
#include "scene/model_view.h"
#include "model/document.h"
#include "solvers/bspline/tessellation.h"
#include "solvers/editing/curve_manipulation.h"
#include "solvers/math_constants.h"

#include <Inventor/SoDB.h>
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <vector>

namespace {

using namespace sculptline;
using Vec3 = Eigen::Vector3d;

/// Forwards the model's notifications to a ModelView and adds up the time they take: the Coin part
/// of an update, measured inside the same events as the model part.
class TimedView : public model::ModelObserver {
public:
    explicit TimedView(model::Model& model) : model_(model), view_(model)
    {
        model_.removeObserver(&view_);
        model_.addObserver(this);
    }
    ~TimedView() override { model_.removeObserver(this); }
    TimedView(const TimedView&) = delete;
    TimedView& operator=(const TimedView&) = delete;

    void entityAdded(const model::Entity& e) override { timed([&] { view_.entityAdded(e); }); }
    void entityRemoved(const model::Entity& e) override { timed([&] { view_.entityRemoved(e); }); }
    void entityUpdated(const model::Entity& e) override { timed([&] { view_.entityUpdated(e); }); }
    void constraintAdded(const model::Constraint& c) override { timed([&] { view_.constraintAdded(c); }); }
    void constraintRemoved(const model::Constraint& c) override { timed([&] { view_.constraintRemoved(c); }); }
    void constraintUpdated(const model::Constraint& c) override { timed([&] { view_.constraintUpdated(c); }); }

    /// Milliseconds spent in the view since the last reset.
    double milliseconds() const { return seconds_ * 1e3; }
    void reset() { seconds_ = 0.0; }

private:
    template <class F>
    void timed(F&& f)
    {
        const auto start = std::chrono::steady_clock::now();
        f();
        seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    model::Model& model_;
    scene::ModelView view_;
    double seconds_ = 0.0;
};

/// How a plane-drag benchmark runs its events.
struct DragSetup {
    bool withView = false;
    bool cachedBuilders = false;  ///< inside beginDrag(plane) .. endDrag()
};

/// Drags `plane` of `model` along `axis` (world), 0.5 model units per event, back and forth so the
/// scene stays where it is.
void dragPlane(benchmark::State& state, model::Model& model, model::EntityId plane, const Vec3& axis, DragSetup setup)
{
    SoDB::init();
    std::unique_ptr<TimedView> view = setup.withView ? std::make_unique<TimedView>(model) : nullptr;
    if (view) view->reset();
    model::PlaneFrame frame = model.find(plane)->frame;
    const int factored = model.factorizations();
    if (setup.cachedBuilders) model.beginDrag(plane);
    int step = 0;
    for (auto _ : state) {
        frame.origin += ((step++ % 40 < 20) ? 0.5 : -0.5) * axis;
        model.setPlaneFrame(plane, frame);
        benchmark::DoNotOptimize(model.update());
    }
    if (setup.cachedBuilders) model.endDrag();
    state.counters["factorizations"] = model.factorizations() - factored;
    if (view) state.counters["coin_ms"] = benchmark::Counter(view->milliseconds(), benchmark::Counter::kAvgIterations);
    int grid = 0, vertices = 0;
    for (const auto& [id, e] : model.entities()) {
        if (e.kind != model::EntityKind::Surface || !e.surface) continue;
        grid += e.surface->countU() * e.surface->countV();
        vertices += static_cast<int>(solvers::tessellate(*e.surface).vertices.size());
    }
    state.counters["control_points"] = grid;
    state.counters["mesh_vertices"] = vertices;
}

void loadInto(model::Model& model, const char* path) { model::populateModel(model::loadDocument(path), model); }

// The document of the live-update replay (data/models/surfaces_drag_start.json: boundary rotation,
// revolve, extrusion and sweep on plane 1's curves), plane 1 moved along z (in its plane). Only the
// sweep has a cached builder; the other three rebuild in full even in a drag.
void fourSurfaces(benchmark::State& state, DragSetup setup)
{
    model::Model model;
    loadInto(model, SCULPTLINE_DATA_DIR "/models/surfaces_drag_start.json");
    dragPlane(state, model, 1, Vec3::UnitZ(), setup);
}

void BM_ScenePlaneDragFourSurfaces(benchmark::State& state) { fourSurfaces(state, {false, false}); }
void BM_ScenePlaneDragFourSurfacesWithView(benchmark::State& state) { fourSurfaces(state, {true, false}); }
void BM_ScenePlaneDragFourSurfacesCachedBuilders(benchmark::State& state) { fourSurfaces(state, {false, true}); }
void BM_ScenePlaneDragFourSurfacesCachedBuildersWithView(benchmark::State& state) { fourSurfaces(state, {true, true}); }

// Issue 5's scene (data/bench_20_curves_5_planes.json: 20 curves on 5 planes, one static surface),
// plane 1 (4 curves) moved along its normal, as data/sessions/drag_bench.json drags it. No surface
// is rebuilt: the model places 4 curves, the view writes one transform.
void twentyCurves(benchmark::State& state, DragSetup setup)
{
    model::Model model;
    loadInto(model, SCULPTLINE_DATA_DIR "/bench_20_curves_5_planes.json");
    dragPlane(state, model, 1, model.find(1)->frame.rotation * Vec3::UnitZ(), setup);
}

void BM_ScenePlaneDrag20Curves(benchmark::State& state) { twentyCurves(state, {false, false}); }
void BM_ScenePlaneDrag20CurvesWithView(benchmark::State& state) { twentyCurves(state, {true, false}); }
void BM_ScenePlaneDrag20CurvesInDrag(benchmark::State& state) { twentyCurves(state, {false, true}); }
void BM_ScenePlaneDrag20CurvesInDragWithView(benchmark::State& state) { twentyCurves(state, {true, true}); }

}  // namespace

BENCHMARK(BM_ScenePlaneDragFourSurfaces)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ScenePlaneDragFourSurfacesWithView)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ScenePlaneDragFourSurfacesCachedBuilders)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ScenePlaneDragFourSurfacesCachedBuildersWithView)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ScenePlaneDrag20Curves)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ScenePlaneDrag20CurvesWithView)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ScenePlaneDrag20CurvesInDrag)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ScenePlaneDrag20CurvesInDragWithView)->Unit(benchmark::kMicrosecond);

namespace {

/// A cubic through `points` (local coordinates of its plane, z = 0), clamped uniform knots.
solvers::Curve3d cubicThrough(const std::vector<Vec3>& points)
{
    return solvers::makeClampedUniform<3>(3, points);
}

/// A wavy cubic of `n` control points from a to b (plane-local, z = 0), bulging by `lift` across.
solvers::Curve3d wavy(int n, const Vec3& a, const Vec3& b, double phase, double lift)
{
    const Vec3 across = Vec3(-(b - a).y(), (b - a).x(), 0.0).normalized();
    std::vector<Vec3> points;
    for (int i = 0; i < n; ++i) {
        const double t = static_cast<double>(i) / (n - 1);
        const double bump = (i == 0 || i == n - 1) ? 0.0 : lift * std::sin(3.0 * t + phase);
        points.push_back(a + t * (b - a) + bump * across);
    }
    return cubicThrough(points);
}

/// A vertical plane (local x = world X, local y = world Z) through `origin`.
model::PlaneFrame verticalFrame(const Vec3& origin)
{
    return model::PlaneFrame::fromNormal(origin, -Vec3::UnitY(), 200.0, Vec3::UnitX());
}

/// The scene where the cached builders matter: vertical plane 1 carries the middle section of a
/// loft (its other two sections on parallel planes 20 units before and behind), the four
/// boundaries of a fill, and the path of a sweep whose closed profile lies on a horizontal plane at
/// the path's start. Curves of 8 control points. Dragging plane 1 rebuilds the three surfaces.
struct BuilderScene {
    model::Model model;
    model::EntityId plane = 0;
    std::vector<model::EntityId> boundaries;  ///< the fill's, on plane 1

    BuilderScene()
    {
        constexpr int n = 8;
        plane = model.addPlane(verticalFrame(Vec3(0, 0, 60)));
        const model::EntityId front = model.addPlane(verticalFrame(Vec3(0, -20, 60)));
        const model::EntityId back = model.addPlane(verticalFrame(Vec3(0, 20, 60)));
        // Loft: three sections, one per plane, across x in [-90, -30].
        std::vector<model::EntityId> sections;
        for (model::EntityId p : {front, plane, back}) {
            const double phase = 0.7 * static_cast<double>(sections.size());
            sections.push_back(model.addCurve(p, wavy(n, Vec3(-90, -20, 0), Vec3(-30, -20, 0), phase, 6.0)));
        }
        // Fill: four boundaries on plane 1 meeting at the corners of [-20, 20] x [-60, -20].
        const Vec3 c0(-20, -60, 0), c1(20, -60, 0), c2(20, -20, 0), c3(-20, -20, 0);
        boundaries = {model.addCurve(plane, wavy(n, c0, c1, 0.0, 4.0)),
                                                      model.addCurve(plane, wavy(n, c1, c2, 1.0, 4.0)),
                                                      model.addCurve(plane, wavy(n, c2, c3, 2.0, 4.0)),
                                                      model.addCurve(plane, wavy(n, c3, c0, 3.0, 4.0))};
        // Sweep: the path on plane 1 rising from (60, z = 40); the profile a closed loop of radius 5
        // on a horizontal plane through the path's start.
        const model::EntityId path = model.addCurve(plane, wavy(n, Vec3(60, -20, 0), Vec3(70, 40, 0), 0.5, 5.0));
        const model::EntityId level =
            model.addPlane(model::PlaneFrame::fromNormal(Vec3(60, 0, 40), Vec3::UnitZ(), 40.0, Vec3::UnitX()));
        std::vector<Vec3> loop;
        for (int k = 0; k <= 8; ++k) {
            const double a = 2.0 * solvers::kPi * k / 8.0;
            loop.push_back(Vec3(5.0 * std::cos(a), 5.0 * std::sin(a), 0.0));
        }
        loop.back() = loop.front();  // closed: its ends coincide
        const model::EntityId profile = model.addCurve(level, cubicThrough(loop));

        model::SurfaceRecipe loft;
        loft.mode = model::Construction::Loft;
        model.addSurface(sections, loft);
        model::SurfaceRecipe fill;
        fill.mode = model::Construction::Fill;
        model.addSurface(boundaries, fill);
        model::SurfaceRecipe sweep;
        sweep.mode = model::Construction::Sweep;
        model.addSurface({profile, path}, sweep);
    }
};

// Plane 1 of BuilderScene moved along z (in its plane; the loft's middle section rises and falls),
// per event: with no drag each event builds the loft, fill and sweep afresh; with beginDrag the
// three re-solve with their cached builders. The ratio of the two is the cached builders' gain.
void builderScene(benchmark::State& state, DragSetup setup)
{
    BuilderScene s;
    dragPlane(state, s.model, s.plane, Vec3::UnitZ(), setup);
}

void BM_ScenePlaneDragLoftFillSweep(benchmark::State& state) { builderScene(state, {false, false}); }
void BM_ScenePlaneDragLoftFillSweepCachedBuilders(benchmark::State& state) { builderScene(state, {false, true}); }
void BM_ScenePlaneDragLoftFillSweepWithView(benchmark::State& state) { builderScene(state, {true, false}); }
void BM_ScenePlaneDragLoftFillSweepCachedBuildersWithView(benchmark::State& state) { builderScene(state, {true, true}); }

}  // namespace

BENCHMARK(BM_ScenePlaneDragLoftFillSweep)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ScenePlaneDragLoftFillSweepCachedBuilders)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ScenePlaneDragLoftFillSweepWithView)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ScenePlaneDragLoftFillSweepCachedBuildersWithView)->Unit(benchmark::kMillisecond);

namespace {

/// A pull of the fill's first boundary in BuilderScene (the fill and only it depends on the curve)
/// at u = 0.5, the curve's ends pinned (position pins at both ends, so the fill's corners hold).
struct PullScene {
    BuilderScene s;
    model::EntityId curve = 0;
    static constexpr double u = 0.5;
    solvers::Curve3d start;
    Vec3 grip;

    PullScene() : curve(s.boundaries.front()), start(*s.model.find(curve)->local), grip(start.evaluate(u))
    {
        s.model.addConstraint(curve, model::ConstraintType::Position, start.domainStart());
        s.model.addConstraint(curve, model::ConstraintType::Position, start.domainEnd());
        s.model.update();
    }

    /// The pull's target for event `step`: back and forth across the curve, up to 5 units.
    Vec3 target(int step) const
    {
        const int k = step % 40;
        return grip + Vec3(0, 0.25 * (k < 20 ? k : 40 - k), 0);
    }
};

// A pull as the GUI does it (ui/sketch_document_input.cpp): beginPull once (the least-change
// solver factored, the fill's builder set up), then per event pullTo + update().
void BM_ScenePullFactoredOnce(benchmark::State& state)
{
    PullScene p;
    const int factored = p.s.model.factorizations();
    p.s.model.beginPull(p.curve, PullScene::u);
    int step = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(p.s.model.pullTo(p.target(step++)));
        benchmark::DoNotOptimize(p.s.model.update());
    }
    p.s.model.endDrag();
    state.counters["factorizations"] = p.s.model.factorizations() - factored;
}

/// One event of a pull with nothing kept: the least-change solver (grip and the two end pins)
/// made and factored from the drag's start curve, solved, the shape set and the model updated.
void pullUnfactored(PullScene& p, int step)
{
    namespace ed = solvers::editing;
    std::vector<ed::CurveConstraint<3>> constraints(3);
    constraints[0].u = PullScene::u;
    constraints[1].u = p.start.domainStart();
    constraints[2].u = p.start.domainEnd();
    const ed::CurveManipulationSolver<3> solver(p.start, constraints);
    const std::vector<Vec3> targets{p.target(step), p.start.evaluate(constraints[1].u), p.start.evaluate(constraints[2].u)};
    p.s.model.setCurveShape(p.curve, solver.solve(targets));
    benchmark::DoNotOptimize(p.s.model.update());
}

// The same pull with the solver made per event and no drag in progress: the fill is built afresh
// too. Against BM_ScenePullFactoredOnce: the whole gain of factoring once per drag.
void BM_ScenePullRefactoredPerEvent(benchmark::State& state)
{
    PullScene p;
    int step = 0;
    for (auto _ : state) pullUnfactored(p, step++);
}

// The solver made per event inside beginDrag(curve), so the fill keeps its builder: against
// BM_ScenePullFactoredOnce, the gain of the least-change solver's factorization alone.
void BM_ScenePullRefactoredPerEventCachedBuilders(benchmark::State& state)
{
    PullScene p;
    p.s.model.beginDrag(p.curve);
    int step = 0;
    for (auto _ : state) pullUnfactored(p, step++);
    p.s.model.endDrag();
}

}  // namespace

BENCHMARK(BM_ScenePullFactoredOnce)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ScenePullRefactoredPerEvent)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ScenePullRefactoredPerEventCachedBuilders)->Unit(benchmark::kMicrosecond);

namespace {

/// The kernel's adaptive tessellation of the four surfaces alone (what a rebuild re-tessellates).
void BM_SceneTessellateFourSurfaces(benchmark::State& state)
{
    model::Model model;
    loadInto(model, SCULPTLINE_DATA_DIR "/models/surfaces_drag_start.json");
    for (auto _ : state) {
        for (const auto& [id, e] : model.entities()) {
            if (e.kind == model::EntityKind::Surface) benchmark::DoNotOptimize(solvers::tessellate(*e.surface));
        }
    }
}

}  // namespace

BENCHMARK(BM_SceneTessellateFourSurfaces)->Unit(benchmark::kMillisecond);
