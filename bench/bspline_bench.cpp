// Kernel benchmarks: evaluation and projection (sculptline-bench --benchmark_filter=BSpline).
#include "solvers/bspline/bspline_surface.h"
#include "solvers/bspline/projection.h"
#include "solvers/bspline/surface_jet.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

using namespace sculptline::solvers;

namespace {

Curve3d helix(int points)
{
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < points; ++i) {
        const double t = 0.4 * i;
        pts.emplace_back(10 * std::cos(t), 10 * std::sin(t), 2.0 * t);
    }
    return makeClampedUniform<3>(3, pts);
}

Surface3d wavySurface(int n)
{
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) pts.emplace_back(i, j, std::sin(0.7 * i) * std::cos(0.5 * j));
    KnotVector k(static_cast<size_t>(n + 4));
    for (int i = 0; i < n + 4; ++i) k[i] = std::clamp(i - 3, 0, n - 3);
    return Surface3d(3, 3, k, k, n, n, pts);
}

void BSplineCurveEvaluate(benchmark::State& state)
{
    const Curve3d c = helix(static_cast<int>(state.range(0)));
    double u = 0.0;
    const double step = 0.618034 * (c.domainEnd() - c.domainStart());
    for (auto _ : state) {
        u = std::fmod(u + step, c.domainEnd());
        benchmark::DoNotOptimize(c.evaluate(u));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BSplineCurveEvaluate)->Arg(10)->Arg(100)->Arg(1000);

void BSplineCurveDerivatives2(benchmark::State& state)
{
    const Curve3d c = helix(100);
    double u = 0.0;
    for (auto _ : state) {
        u = std::fmod(u + 0.618034 * c.domainEnd(), c.domainEnd());
        benchmark::DoNotOptimize(c.derivatives(u, 2));
    }
}
BENCHMARK(BSplineCurveDerivatives2);

// Evaluates `at(u, v)` per iteration at parameters stepped by irrational fractions of the domain
// (the square nets of wavySurface: U and V share it), so that no span is favoured.
template <class At>
void sweepSurface(benchmark::State& state, const Surface3d& s, At at)
{
    const double end = s.domainEnd(Direction::U);
    double u = 0.0, v = 0.0;
    for (auto _ : state) {
        u = std::fmod(u + 0.618034 * end, end);
        v = std::fmod(v + 0.414214 * end, end);
        benchmark::DoNotOptimize(at(u, v));
    }
}

void BSplineSurfaceEvaluate(benchmark::State& state)
{
    const Surface3d s = wavySurface(static_cast<int>(state.range(0)));
    sweepSurface(state, s, [&](double u, double v) { return s.evaluate(u, v); });
}
BENCHMARK(BSplineSurfaceEvaluate)->Arg(10)->Arg(40);

void BSplineCurveProject(benchmark::State& state)
{
    const CurveProjector<3> proj(helix(static_cast<int>(state.range(0))));
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> uni(-12, 12);
    for (auto _ : state) {
        const Eigen::Vector3d x(uni(rng), uni(rng), std::abs(uni(rng)) * 2);
        benchmark::DoNotOptimize(proj.project(x));
    }
}
BENCHMARK(BSplineCurveProject)->Arg(10)->Arg(100);

void BSplineSurfaceProject(benchmark::State& state)
{
    const int n = static_cast<int>(state.range(0));
    const SurfaceProjector proj(wavySurface(n));
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> uni(0, n - 1);
    for (auto _ : state) {
        const Eigen::Vector3d x(uni(rng), uni(rng), 0.5 * std::sin(uni(rng)));
        benchmark::DoNotOptimize(proj.project(x));
    }
}
BENCHMARK(BSplineSurfaceProject)->Arg(10)->Arg(20);

// The projector's set-up on a net of n x n points: at n = 135 (132 spans a side) the grid is capped
// at kMaxGridSamples a side (2 samples per span instead of 8).
void BSplineSurfaceProjectorBuild(benchmark::State& state)
{
    const Surface3d s = wavySurface(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        const SurfaceProjector proj(s);
        benchmark::DoNotOptimize(&proj);
    }
}
BENCHMARK(BSplineSurfaceProjectorBuild)->Arg(20)->Arg(135)->Unit(benchmark::kMillisecond);

// S and its derivatives to second order, as the projector's Newton needs them: the allocating
// BSplineSurface::derivatives against SurfaceJet.
void BSplineSurfaceDerivatives2(benchmark::State& state)
{
    const Surface3d s = wavySurface(20);
    sweepSurface(state, s, [&](double u, double v) { return s.derivatives(u, v, 2); });
}
BENCHMARK(BSplineSurfaceDerivatives2);

void BSplineSurfaceJet(benchmark::State& state)
{
    const Surface3d s = wavySurface(20);
    const SurfaceJet jet(s);
    sweepSurface(state, s, [&](double u, double v) { return jet.evaluate(u, v); });
}
BENCHMARK(BSplineSurfaceJet);

void BSplineCurveInsertKnot(benchmark::State& state)
{
    const Curve3d c = helix(100);
    for (auto _ : state) benchmark::DoNotOptimize(c.insertKnot(0.5 * c.domainEnd() + 0.123));
}
BENCHMARK(BSplineCurveInsertKnot);

}  // namespace
