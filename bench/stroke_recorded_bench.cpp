// Fitting and recognition of strokes people drew (issue 15 §3: the benchmark set gets real
// recorded strokes): the $1 unistroke logs' development subjects (tests/data/unistrokes, s02-s06),
// the first repetition of every gesture at every speed, 240 strokes of 30-209 samples (81 on
// average), in pixels and milliseconds as the pen gave them. Fitted with the logs' pixel as the
// input's resolution (FitOptions::resolution = 1), as the window passes its pointer's pixel: the
// tolerance is then max(0.005 x extent, 1 px), about 1 px on these strokes. (The default
// 0.005 x extent alone is below the pixel, and the fit follows the pixel staircase: 26 control
// points on average against 17.) Arg 0: fitStroke, as `sculptline-cli fit` does; arg 1:
// recognizeStroke (fit, recognize, and the refits the loop rules ask for), as the window does when
// the pen lifts. Warm: each iteration fits all 240 in turn.
//
//   build/sculptline-bench --benchmark_filter=BM_StrokeRecorded
#include "unistroke_eval.h"

#include "solvers/stroke/shape_recognizer.h"
#include "solvers/stroke/stroke_fitter.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <vector>

namespace {

using namespace sculptline::solvers::stroke;

const std::vector<Stroke>& recordedStrokes()
{
    static const std::vector<Stroke> strokes = [] {
        std::vector<Stroke> out;
        for (const auto& r :
             sculptline::stroketest::loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, sculptline::stroketest::devSubjects()))
            if (r.number == 1) out.push_back(r.stroke);
        return out;
    }();
    return strokes;
}

// Counters: per stroke, the mean, median and 99th percentile time over every stroke fitted in the
// timed loop (microseconds), and the mean control-point count and sample count.
void BM_StrokeRecorded(benchmark::State& state)
{
    const std::vector<Stroke>& strokes = recordedStrokes();
    const bool recognize = state.range(0) == 1;
    FitOptions options;
    options.resolution = 1.0;
    std::vector<double> micros;
    double points = 0.0, samples = 0.0;
    for (auto _ : state) {
        for (const Stroke& s : strokes) {
            const auto t0 = std::chrono::steady_clock::now();
            if (recognize) {
                const StrokeRecognition r = recognizeStroke(s, options);
                benchmark::DoNotOptimize(r.recognition.candidates.data());
                points += r.fit.curve.pointCount() - (r.fit.curve.isClosed() ? 3 : 0);
            } else {
                const FitResult r = fitStroke(s, options);
                benchmark::DoNotOptimize(r.curve.points().data());
                points += r.curve.pointCount() - (r.curve.isClosed() ? 3 : 0);
            }
            micros.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
            samples += static_cast<double>(s.points.size());
        }
    }
    std::sort(micros.begin(), micros.end());
    const auto at = [&](double q) {
        return micros[std::min(micros.size() - 1, static_cast<size_t>(q * static_cast<double>(micros.size())))];
    };
    const double n = static_cast<double>(micros.size());
    double total = 0.0;
    for (double m : micros) total += m;
    state.counters["strokes"] = static_cast<double>(strokes.size());
    state.counters["mean_us"] = total / n;
    state.counters["p50_us"] = at(0.5);
    state.counters["p99_us"] = at(0.99);
    state.counters["ctrl_points"] = points / n;
    state.counters["samples"] = samples / n;
    state.SetLabel(recognize ? "recognizeStroke" : "fitStroke");
}
BENCHMARK(BM_StrokeRecorded)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
