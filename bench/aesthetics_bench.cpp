// Aesthetic analysis (issue 16 §4): the characteristic points alone and the full analysis (with
// characteristics, measures and log-curvature-graph slopes) of a 200-control-point cubic, the size
// of a long fitted stroke or a detailed section curve.
#include "solvers/aesthetics/curve_analysis.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

using namespace sculptline::solvers;

Curve2d wavyCurve(int count)
{
    std::vector<Eigen::Vector2d> pts;
    for (int i = 0; i < count; ++i) {
        const double t = double(i) / (count - 1);
        pts.emplace_back(100.0 * t, 8.0 * std::sin(20.0 * t) + 2.0 * std::sin(57.0 * t));
    }
    return makeClampedUniform<2>(3, pts);
}

void BM_CharacteristicPoints200(benchmark::State& state)
{
    const Curve2d c = wavyCurve(200);
    for (auto _ : state) benchmark::DoNotOptimize(aesthetics::characteristicPoints(c));
}
BENCHMARK(BM_CharacteristicPoints200)->Unit(benchmark::kMicrosecond);

void BM_AnalyzeCurve200(benchmark::State& state)
{
    const Curve2d c = wavyCurve(200);
    for (auto _ : state) benchmark::DoNotOptimize(aesthetics::analyzeCurve(c));
}
BENCHMARK(BM_AnalyzeCurve200)->Unit(benchmark::kMicrosecond);

}  // namespace
