// The cached SVD's backends on a 1000×500 matrix (README "Regularization"), and the re-solve a new
// right-hand side costs on a kept SVD (Uᵀb and sums: TSVD's L-curve, and MTSVD's updated sweep).
#include "solvers/regularization/lcurve_corner.h"
#include "solvers/regularization/mtsvd.h"
#include "solvers/regularization/test_problems.h"

#include <benchmark/benchmark.h>

namespace {

namespace reg = sculptline::solvers::regularization;

Eigen::MatrixXd benchMatrix(int m, int n)
{
    std::srand(42);
    return Eigen::MatrixXd::Random(m, n);
}

void svdBench(benchmark::State& state, reg::SvdBackend backend)
{
    if (backend == reg::SvdBackend::Lapack && !reg::lapackAvailable()) {
        state.SkipWithError("no LAPACKE in this build");
        return;
    }
    const Eigen::MatrixXd a = benchMatrix(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
    for (auto _ : state) {
        const reg::CachedSvd svd(a, backend);
        benchmark::DoNotOptimize(svd.singularValues().data());
    }
}

void BM_RegularizationSvdEigen(benchmark::State& state) { svdBench(state, reg::SvdBackend::Eigen); }
void BM_RegularizationSvdLapack(benchmark::State& state) { svdBench(state, reg::SvdBackend::Lapack); }
BENCHMARK(BM_RegularizationSvdEigen)->Args({1000, 500})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RegularizationSvdLapack)->Args({1000, 500})->Unit(benchmark::kMillisecond);

// A new b on a kept SVD: Uᵀb, the whole TSVD L-curve, its corner and the solution there.
void BM_RegularizationTsvdResolve(benchmark::State& state)
{
    const Eigen::MatrixXd a = benchMatrix(1000, 500);
    const reg::CachedSvd svd(a);
    const Eigen::MatrixXd b = benchMatrix(1000, 3);
    for (auto _ : state) {
        const reg::ProjectedRhs rhs = reg::projectRhs(svd, b);
        const reg::LCurve lc = reg::tsvdLCurve(svd, rhs);
        const int k = reg::lcurveCorner(lc, reg::defaultCornerMethod(false)).k;
        benchmark::DoNotOptimize(reg::tsvdSolution(svd, rhs, k).data());
    }
}
BENCHMARK(BM_RegularizationTsvdResolve)->Unit(benchmark::kMillisecond);

// MTSVD's L-curve (the QR of L V_{k+1} updated across k) on shaw(n), second differences.
void BM_RegularizationMtsvdLCurve(benchmark::State& state)
{
    const int n = static_cast<int>(state.range(0));
    const reg::TestProblem p = reg::shaw(n);
    const reg::CachedSvd svd(p.a);
    const reg::MtsvdSolver m(svd, reg::secondDifferences(n));
    const reg::ProjectedRhs rhs = reg::projectRhs(svd, reg::withNoise(p.b, 1e-3, 1));
    for (auto _ : state) benchmark::DoNotOptimize(m.lcurve(rhs).rho.data());
    state.counters["rank"] = svd.rank();
}
BENCHMARK(BM_RegularizationMtsvdLCurve)->Arg(64)->Arg(256)->Unit(benchmark::kMillisecond);

}  // namespace
