// Curve editing benchmarks (issue 4): sculptline-bench --benchmark_filter=Editing
#include "solvers/editing/curve_manipulation.h"
#include "solvers/editing/lift.h"
#include "solvers/editing/oversketch.h"

#include "tests/editing/editing_fixtures.h"

#include <benchmark/benchmark.h>

#include <cmath>

using namespace sculptline::solvers;
using namespace sculptline::solvers::editing;

namespace {

using sculptline::editing_fixtures::bump;
using sculptline::editing_fixtures::wave;

// One over-sketch of a 30-control-point curve with a 300-sample stroke (issue 4 §4).
void oversketchOnce(benchmark::State& state, OversketchMethod m)
{
    const Curve2d curve = wave(30);
    const auto stroke = bump(curve, 0.4, 0.6, 2.0, 300);
    OversketchOptions o;
    o.method = m;
    for (auto _ : state) benchmark::DoNotOptimize(oversketch(curve, stroke, o));
}
void BM_EditingOversketchLocalC2(benchmark::State& s)
{
    oversketchOnce(s, OversketchMethod::LocalC2);
}
void BM_EditingOversketchBlend(benchmark::State& s)
{
    oversketchOnce(s, OversketchMethod::Blend);
}
BENCHMARK(BM_EditingOversketchLocalC2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EditingOversketchBlend)->Unit(benchmark::kMillisecond);

// The same stroke over the closed ellipse loop's seam (closed curves, tests/editing: strokeAcrossSeam).
void BM_EditingOversketchClosedLocalC2(benchmark::State& state)
{
    const Curve2d curve = sculptline::editing_fixtures::ellipseLoop();
    const auto stroke = sculptline::editing_fixtures::strokeAcrossSeam();
    for (auto _ : state) benchmark::DoNotOptimize(oversketch(curve, stroke));
}
BENCHMARK(BM_EditingOversketchClosedLocalC2)->Unit(benchmark::kMillisecond);

// A drag with 3 constraints on a 50-control-point curve (thesis Fig. 6-3: a moving point, a kept
// tangent, a kept distance); tests/editing/curve_manipulation_test.cpp checks this very drag.
using sculptline::editing_fixtures::dragConstraints;
using sculptline::editing_fixtures::helix;

void BM_EditingDragPreprocess(benchmark::State& state)
{
    const Curve3d curve = helix(50);
    const auto cs = dragConstraints(curve);
    for (auto _ : state) benchmark::DoNotOptimize(CurveManipulationSolver<3>(curve, cs, {0, 49}));
}
BENCHMARK(BM_EditingDragPreprocess)->Unit(benchmark::kMicrosecond);

// Per event, the bare stage of thesis §6.1: d = C b.
void BM_EditingDragPerEventDisplacements(benchmark::State& state)
{
    const Curve3d curve = helix(50);
    const auto cs = dragConstraints(curve);
    const CurveManipulationSolver<3> solver(curve, cs, {0, 49});
    std::vector<Eigen::Vector3d> targets = {cs[0].value, cs[1].value, cs[2].value};
    CurveManipulationSolver<3>::Displacements d;
    double t = 0.0;
    for (auto _ : state) {
        t += 1e-3;
        targets[0] = cs[0].value + Eigen::Vector3d(t, 0.5 * t, 0.0);
        solver.displacements(targets, d);
        benchmark::DoNotOptimize(d.data());
    }
}
BENCHMARK(BM_EditingDragPerEventDisplacements)->Unit(benchmark::kMicrosecond);

// Per event including building the new curve value (what a viewer update needs).
void BM_EditingDragPerEventCurve(benchmark::State& state)
{
    const Curve3d curve = helix(50);
    const auto cs = dragConstraints(curve);
    const CurveManipulationSolver<3> solver(curve, cs, {0, 49});
    std::vector<Eigen::Vector3d> targets = {cs[0].value, cs[1].value, cs[2].value};
    double t = 0.0;
    for (auto _ : state) {
        t += 1e-3;
        targets[0] = cs[0].value + Eigen::Vector3d(t, 0.5 * t, 0.0);
        benchmark::DoNotOptimize(solver.solve(targets));
    }
}
BENCHMARK(BM_EditingDragPerEventCurve)->Unit(benchmark::kMicrosecond);

void BM_EditingLift300(benchmark::State& state)
{
    const auto stroke = sculptline::editing_fixtures::liftStroke300();
    for (auto _ : state) benchmark::DoNotOptimize(liftStroke(stroke, 0.0, 5.0));
}
BENCHMARK(BM_EditingLift300)->Unit(benchmark::kMillisecond);

}  // namespace
