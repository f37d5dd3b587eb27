// Aesthetic analysis (issue 16 §4): the characteristic points alone and the full analysis (with
// characteristics, measures and log-curvature-graph slopes) of a 200-control-point cubic, the size
// of a long fitted stroke or a detailed section curve.
#include "solvers/aesthetics/curve_analysis.h"
#include "solvers/aesthetics/curve_operators.h"

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

namespace {

// One drag event of an operator (issue 16 §4): soften on a 40-control-point wavy curve, factored
// once (the constructor), then per event one product d = G b and the curve rebuilt.
void BM_OperatorDragFactor(benchmark::State& state)
{
    const Curve2d c = wavyCurve(40);
    const auto a = aesthetics::analyzeCurve(c);
    for (auto _ : state) {
        const aesthetics::OperatorSetup s = aesthetics::operatorSetup(c, a, aesthetics::Operator::Soften, {});
        benchmark::DoNotOptimize(aesthetics::OperatorDrag(s));
    }
}
BENCHMARK(BM_OperatorDragFactor)->Unit(benchmark::kMicrosecond);

void BM_OperatorDragEvent(benchmark::State& state)
{
    const Curve2d c = wavyCurve(40);
    const auto a = aesthetics::analyzeCurve(c);
    const aesthetics::OperatorDrag drag(aesthetics::operatorSetup(c, a, aesthetics::Operator::Soften, {}));
    double lambda = 0.0;
    for (auto _ : state) {
        lambda = lambda > 0.5 ? 0.0 : lambda + 0.01;
        benchmark::DoNotOptimize(drag.at(lambda));
    }
}
BENCHMARK(BM_OperatorDragEvent)->Unit(benchmark::kMicrosecond);

}  // namespace
