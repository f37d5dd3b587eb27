// Stroke fitting benchmarks (issue 3): fitting time for 200 / 1,000 / 10,000-sample strokes with
// the control-point count and the achieved error beside the time, and the thesis Fig. 4-3
// comparison of speed-only sampling with dynamic-threshold sampling (thesis §4.1.1).
//
//   build-stroke/sculptline-bench --benchmark_filter=Stroke
#include "solvers/stroke/shape_recognizer.h"
#include "solvers/stroke/stroke_fitter.h"
#include "solvers/stroke/stroke_synthesis.h"

#include <benchmark/benchmark.h>

namespace {

using namespace sculptline::solvers::stroke;

// Noise of a tablet at the drawing's scale (the shapes are ~300 units across).
constexpr double kNoise = 0.25;

Stroke benchStroke(int samples, unsigned seed = 1)
{
    DrawOptions d;
    d.noise = kNoise;
    d.seed = seed;
    return drawWithSamples(flourishShape(300), samples, d);
}

void report(benchmark::State& state, const Stroke& s, const FitResult& r)
{
    state.counters["raw_samples"] = static_cast<double>(s.points.size());
    state.counters["ls_samples"] = static_cast<double>(r.samples.size());
    state.counters["ctrl_points"] = r.curve.pointCount() - (r.curve.isClosed() ? 3 : 0);
    state.counters["corners"] = static_cast<double>(r.corners.size());
    state.counters["max_error"] = r.maxError;
    state.counters["tolerance"] = r.tolerance;
}

void BM_StrokeFit(benchmark::State& state)
{
    const Stroke s = benchStroke(static_cast<int>(state.range(0)));
    FitResult r = fitStroke(s);
    for (auto _ : state) {
        r = fitStroke(s);
        benchmark::DoNotOptimize(r.curve.points().data());  // not the double itself: benchmark 1.7.1 with GCC corrupts a non-const double passed to DoNotOptimize ("+m,r")
    }
    report(state, s, r);
}
BENCHMARK(BM_StrokeFit)->Arg(200)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

// The same with every knot tried for removal after the fit (KnotRemoval::AllKnots).
void BM_StrokeFitFewest(benchmark::State& state)
{
    const Stroke s = benchStroke(static_cast<int>(state.range(0)));
    FitOptions o;
    o.spline.removal = KnotRemoval::AllKnots;
    FitResult r = fitStroke(s, o);
    for (auto _ : state) {
        r = fitStroke(s, o);
        benchmark::DoNotOptimize(r.curve.points().data());
    }
    report(state, s, r);
}
BENCHMARK(BM_StrokeFitFewest)->Arg(200)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

// A polygon with corners (pen slows at each vertex): the piecewise fit joined with triple knots.
void BM_StrokeFitPolygon(benchmark::State& state)
{
    DrawOptions d;
    d.noise = kNoise;
    const Stroke s = drawWithSamples(
        polygonShape({{0, 0, 0}, {150, 0, 0}, {190, 110, 0}, {60, 160, 0}, {-30, 80, 0}}, true), static_cast<int>(state.range(0)), d);
    FitResult r = fitStroke(s);
    for (auto _ : state) {
        r = fitStroke(s);
        benchmark::DoNotOptimize(r.curve.points().data());  // not the double itself: benchmark 1.7.1 with GCC corrupts a non-const double passed to DoNotOptimize ("+m,r")
    }
    report(state, s, r);
}
BENCHMARK(BM_StrokeFitPolygon)->Arg(1000)->Unit(benchmark::kMicrosecond);

// Thesis Fig. 4-3: (a) every conditioned sample in the least squares ("speed-only": the density
// follows 1/speed and crowds the slow turns) against (b) the dynamic-threshold samples, at the same
// tolerance, on the Fig. 4-3-like stroke (hairpinShape: bowed sweeps, tight turns where the pen slows
// to 5 % of its peak speed, 600 samples). Arg 0: sampling (0 speed-only, 1 dynamic); arg 1: knots
// (0 averaged over the samples as in the thesis's de Boor approximation, 1 our error-driven
// insertion, the default). The counters compare the control points each needs (thesis: > 46 vs 18).
void BM_StrokeFig43(benchmark::State& state)
{
    const bool dynamic = state.range(0) != 0, errorDriven = state.range(1) != 0;
    DrawOptions d;
    d.noise = kNoise;
    d.cornerSlowdown = 0.05;
    const Stroke s = drawWithSamples(hairpinShape(200, 3, 25), 600, d);
    FitOptions o;
    o.dynamicSampling = dynamic;
    o.spline.knotPlacement = errorDriven ? KnotPlacement::ErrorDriven : KnotPlacement::Averaged;
    FitResult r = fitStroke(s, o);
    for (auto _ : state) {
        r = fitStroke(s, o);
        benchmark::DoNotOptimize(r.curve.points().data());
    }
    state.SetLabel(std::string(dynamic ? "dynamic threshold" : "speed-only") + (errorDriven ? ", error-driven knots" : ", averaged knots"));
    report(state, s, r);
}
BENCHMARK(BM_StrokeFig43)->Args({0, 1})->Args({1, 1})->Args({0, 0})->Args({1, 0})->Unit(benchmark::kMicrosecond);

// Recognition of one fitted stroke (primitive fits, candidates, regularization); the fit itself is
// outside the timed loop. Arg: 0 circle, 1 square, 2 freeform flourish.
void BM_StrokeRecognize(benchmark::State& state)
{
    DrawOptions d;
    d.noise = kNoise;
    const Shape shapes[] = {circleShape({0, 0, 0}, 80), polygonShape({{0, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}}, true),
                            flourishShape(300)};
    const FitResult fit = fitStroke(draw(shapes[state.range(0)], d));
    Recognition r = recognizeShape(fit);
    for (auto _ : state) {
        r = recognizeShape(fit);
        benchmark::DoNotOptimize(r.candidates.data());
    }
    state.SetLabel(shapeName(r.kind));
    state.counters["samples"] = fit.conditioned.size();
    state.counters["top_score"] = r.candidates.front().score;
}
BENCHMARK(BM_StrokeRecognize)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

}  // namespace
