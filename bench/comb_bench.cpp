// Per-event cost of the curvature comb and of the Aesthetics dock's analysis while a curve is
// pulled: each iteration is one pointer event of a pull (the pulled point moved, model.update()),
// with or without the selected curve's comb (scene/curvature_comb.h) observing the model, and the
// analysis the dock runs once per event-loop turn (solvers/aesthetics analyzeCurve on the curve in
// its plane). The curve: a sketched wave's size, a cubic of `points` control points on a plane.
#include "model/model.h"
#include "scene/curvature_comb.h"
#include "solvers/aesthetics/curve_analysis.h"

#include <Inventor/SoDB.h>
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

namespace {

using namespace sculptline;

/// A clamped uniform cubic through a sine period, 90 mm long, 28 mm high, in the plane's frame.
solvers::Curve3d wave(int points)
{
    std::vector<Eigen::Vector3d> p;
    for (int i = 0; i < points; ++i) {
        const double t = static_cast<double>(i) / (points - 1);
        p.emplace_back(-45.0 + 90.0 * t, 14.0 * std::sin(2.0 * M_PI * t), 0.0);
    }
    std::vector<double> knots(4, 0.0);
    for (int i = 1; i < points - 3; ++i) knots.push_back(i);
    knots.insert(knots.end(), 4, static_cast<double>(points - 3));
    return solvers::Curve3d(3, knots, p);
}

void pull(benchmark::State& state, bool comb)
{
    SoDB::init();
    model::Model model;
    const model::EntityId plane = model.addPlane(model::PlaneFrame::fromNormal({0, 95, 60}, {0, -1, 0}, 120));
    const solvers::Curve3d curve = wave(static_cast<int>(state.range(0)));
    const model::EntityId id = model.addCurve(plane, curve);
    model.update();
    std::unique_ptr<scene::CurvatureComb> view;
    if (comb) {
        view = std::make_unique<scene::CurvatureComb>(model);
        view->setCurve(id);
        view->setVisible(true);
    }
    const double u = 0.75 * curve.domainEnd();
    model.beginPull(id, u);
    const Eigen::Vector3d start = curve.evaluate(u);
    int k = 0;
    for (auto _ : state) {
        model.pullTo(start + Eigen::Vector3d(0, 0.1 * (k++ % 100), 0));
        model.update();
    }
    model.endDrag();
    if (view) state.counters["teeth"] = static_cast<double>(view->teeth().size());
}

void BM_PullFrame(benchmark::State& state) { pull(state, false); }
void BM_PullFrameWithComb(benchmark::State& state) { pull(state, true); }

void BM_DockAnalysis(benchmark::State& state)
{
    const solvers::Curve2d planar = solvers::aesthetics::planarCurve(wave(static_cast<int>(state.range(0))));
    for (auto _ : state) benchmark::DoNotOptimize(solvers::aesthetics::analyzeCurve(planar));
}

}  // namespace

BENCHMARK(BM_PullFrame)->Arg(9)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PullFrameWithComb)->Arg(9)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DockAnalysis)->Arg(9)->Arg(40)->Unit(benchmark::kMicrosecond);
