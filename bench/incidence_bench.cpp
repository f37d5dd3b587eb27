// Curve-surface incidence benchmarks: sculptline-bench --benchmark_filter=Incidence
// Building A (H = A F, seed 000 §2.1) for a system of about 1000 rows: four cubic domain curves (one
// iso-parametric, one fixed) on a 25x20 bicubic surface, composed exactly; the same with the requests brought into the curves' spaces and
// the crossings' rows (the whole stacked system); the discretized alternative with as many rows;
// and the smoothing Gram matrix with its factor (seed 000 §4.4). Counter rows: the system's rows.
#include "solvers/incidence/incidence_solve.h"
#include "solvers/incidence/incidence_system.h"
#include "solvers/incidence/point_incidence.h"
#include "solvers/incidence/smoothing_functionals.h"

#include "tests/incidence/incidence_fixtures.h"

#include <benchmark/benchmark.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::incidence;
using namespace sculptline::incidence_test;

namespace {

// A cubic domain curve through the given points (clamped uniform knots).
Curve2d through(std::vector<Curve2d::Point> points) { return makeClampedUniform<2>(3, points); }

struct Scene {
    Surface3d surface = wavySurface(25, 20);
    std::vector<CurveRequest> curves;
    Scene()
    {
        const std::vector<Curve2d> domains{
            through({{0.2, 0.2}, {0.35, 0.3}, {0.5, 0.45}, {0.6, 0.65}}),
            through({{0.3, 0.2}, {0.45, 0.3}, {0.55, 0.3}, {0.7, 0.2}}),
            through({{0.2, 0.8}, {0.4, 0.75}, {0.5, 0.75}, {0.7, 0.8}}),
            through({{0.5, 0.32}, {0.5, 0.45}, {0.5, 0.55}, {0.5, 0.68}}),  // iso-parametric
        };
        const SurfaceStructure s = SurfaceStructure::of(surface);
        for (const Curve2d& g : domains) {
            // A cubic request: the surface curve sampled at the domain curve's control points, lifted.
            std::vector<Curve3d::Point> points;
            for (const auto& uv : g.points()) points.push_back(surface.evaluate(uv.x(), uv.y()) + Curve3d::Point(0, 0, 2.0));
            curves.push_back({g, Curve3d(3, g.knots(), points), false});
        }
        curves[3].fixed = true;
    }
};

const Scene& scene()
{
    static const Scene s;
    return s;
}

void BM_IncidenceCompose1000Rows(benchmark::State& state)
{
    const SurfaceStructure s = SurfaceStructure::of(scene().surface);
    Eigen::Index rows = 0;
    for (auto _ : state) {
        rows = 0;
        for (const CurveRequest& c : scene().curves) {
            const Composition a = compose(s, c.domain);
            rows += a.matrix.rows();
            benchmark::DoNotOptimize(a.matrix.valuePtr());
        }
    }
    state.counters["rows"] = static_cast<double>(rows);
}
BENCHMARK(BM_IncidenceCompose1000Rows)->Unit(benchmark::kMillisecond);

void BM_IncidenceStackedSystem1000Rows(benchmark::State& state)
{
    const SurfaceStructure s = SurfaceStructure::of(scene().surface);
    StackOptions options;
    options.reduceMultiplicities = state.range(0) == 1;
    Eigen::Index rows = 0, nonZeros = 0;
    for (auto _ : state) {
        const IncidenceSystem system = stackIncidences(s, scene().curves, options);
        rows = system.matrix.rows();
        nonZeros = system.matrix.nonZeros();
        benchmark::DoNotOptimize(system.rhs.data());
    }
    state.counters["rows"] = static_cast<double>(rows);
    state.counters["nonzeros"] = static_cast<double>(nonZeros);
    state.SetLabel(options.reduceMultiplicities ? "reduced multiplicities" : "Bezier form");
}
BENCHMARK(BM_IncidenceStackedSystem1000Rows)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_IncidenceDiscretized1000Rows(benchmark::State& state)
{
    const SurfaceStructure s = SurfaceStructure::of(scene().surface);
    std::vector<int> counts;
    for (const CurveRequest& c : scene().curves) counts.push_back(static_cast<int>(compose(s, c.domain).matrix.rows()));
    Eigen::Index rows = 0;
    for (auto _ : state) {
        rows = 0;
        for (size_t k = 0; k < counts.size(); ++k) {
            const SparseRows a = discretizedIncidence(s, scene().curves[k].domain, uniformParameters(scene().curves[k].domain, counts[k]));
            rows += a.rows();
            benchmark::DoNotOptimize(a.valuePtr());
        }
    }
    state.counters["rows"] = static_cast<double>(rows);
}
BENCHMARK(BM_IncidenceDiscretized1000Rows)->Unit(benchmark::kMillisecond);

void BM_IncidenceSmoothingGram25x20(benchmark::State& state)
{
    const SurfaceStructure s = SurfaceStructure::of(scene().surface);
    for (auto _ : state) {
        const Eigen::SparseMatrix<double> g = smoothingGram(s, 0.2, 0.5, 0.3);
        benchmark::DoNotOptimize(g.valuePtr());
    }
}
BENCHMARK(BM_IncidenceSmoothingGram25x20)->Unit(benchmark::kMillisecond);

void BM_IncidenceGramFactor25x20(benchmark::State& state)
{
    const SurfaceStructure s = SurfaceStructure::of(scene().surface);
    const Eigen::MatrixXd g(smoothingGram(s, 0.2, 0.5, 0.3));
    const auto method = state.range(0) == 0 ? FactorMethod::SquareRoot : FactorMethod::CholeskyRidge;
    for (auto _ : state) {
        const Eigen::MatrixXd l = gramFactor(g, method);
        benchmark::DoNotOptimize(l.data());
    }
    state.SetLabel(state.range(0) == 0 ? "square root" : "Cholesky + ridge");
}
BENCHMARK(BM_IncidenceGramFactor25x20)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace

namespace {

// The incidence solve of the scene above (about 1000 rows over 500 control points; one fixed
// curve): arg 0, the whole solve (stacking, SVDs, the corner, MTSVD's correction); arg 1, a drag
// event on the kept solver: the first curve's request moved, its right-hand side, Uᵀ b and two
// products (issue 14 §4: ≤ 1 ms for this size).
void BM_IncidenceSolve1000Rows(benchmark::State& state)
{
    const Scene& s = scene();
    std::vector<IncidenceCurve> curves;
    for (const CurveRequest& r : s.curves) curves.push_back({r.domain, r.request, r.fixed});
    if (state.range(0) != 1) {
        // arg 0: MTSVD at TSVD's corner (the default); arg 2: TSVD alone, so that the difference is
        // what MTSVD's one correction costs.
        IncidenceOptions options;
        if (state.range(0) == 2) options.method = IncidenceMethod::Tsvd;
        int k = 0;
        for (auto _ : state) {
            const IncidenceResult r = solveIncidence(s.surface, curves, options);
            k = r.k;
            benchmark::DoNotOptimize(r.surface.points().data());
        }
        state.counters["k"] = k;
        state.SetLabel(state.range(0) == 0 ? "whole solve, MTSVD at TSVD's k" : "whole solve, TSVD");
        return;
    }
    IncidenceSolver solver;
    solver.factor(s.surface, curves);
    const Curve3d start = *curves[0].target;
    int event = 0;
    for (auto _ : state) {
        std::vector<Curve3d::Point> points = start.points();
        for (auto& p : points) p.z() += 0.01 * (++event % 100);
        curves[0].target = Curve3d(start.degree(), start.knots(), points);
        benchmark::DoNotOptimize(solver.solve(curves));
    }
}
BENCHMARK(BM_IncidenceSolve1000Rows)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace

#include "solvers/regularization/cached_svd.h"
#include "solvers/regularization/lcurve_corner.h"
#include "solvers/regularization/mtsvd.h"

#include <cstdio>
#include <cstdlib>

namespace {

// The SVD of the scene's whole stacked system (958 rows over the 25x20 surface's 500 control points,
// dense): arg 0 Eigen's BDCSVD, arg 1 LAPACK's dgesdd through LAPACKE (issue 14 §4: within 1.2x of
// the machine's fastest gesdd on the same matrix). With SCULPTLINE_BENCH_MATRIX=<file> set, the
// matrix is written there once (rows, cols as two int32, then column-major float64) so that
// scripts/compare_regularization.py --timing-matrix <file> times numpy's gesdd on the same matrix.
void BM_IncidenceSvd1000Rows(benchmark::State& state)
{
    namespace reg = sculptline::solvers::regularization;
    const auto backend = state.range(0) == 0 ? reg::SvdBackend::Eigen : reg::SvdBackend::Lapack;
    if (backend == reg::SvdBackend::Lapack && !reg::lapackAvailable()) {
        state.SkipWithError("no LAPACKE in this build");
        return;
    }
    const Eigen::MatrixXd a(stackIncidences(SurfaceStructure::of(scene().surface), scene().curves).matrix);
    if (const char* path = std::getenv("SCULPTLINE_BENCH_MATRIX"); path && state.range(0) == 0) {
        if (std::FILE* f = std::fopen(path, "wb")) {
            const int dims[2] = {static_cast<int>(a.rows()), static_cast<int>(a.cols())};
            std::fwrite(dims, sizeof(int), 2, f);
            std::fwrite(a.data(), sizeof(double), static_cast<size_t>(a.size()), f);
            std::fclose(f);
        }
    }
    int rank = 0;
    for (auto _ : state) {
        const reg::CachedSvd svd(a, backend);
        rank = svd.rank();
        benchmark::DoNotOptimize(svd.singularValues().data());
    }
    state.counters["rows"] = static_cast<double>(a.rows());
    state.counters["cols"] = static_cast<double>(a.cols());
    state.counters["rank"] = rank;
    state.SetLabel(backend == reg::SvdBackend::Eigen ? "Eigen BDCSVD" : "LAPACKE dgesdd");
}
BENCHMARK(BM_IncidenceSvd1000Rows)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// MTSVD on the same stacked system (all rows soft, L the thin-plate Gram factor, 500 x 500), on its
// kept SVD: arg 0, the L-curve over every k with the QR of L V_{k+1} updated across k (Hansen, Sekii
// & Shibahashi; what seed 000 §4.4 describes and then advises against); arg 1, one solution at a
// given k (a fresh complete orthogonal decomposition: what the incidence solve does once).
void BM_IncidenceMtsvd1000Rows(benchmark::State& state)
{
    namespace reg = sculptline::solvers::regularization;
    const SurfaceStructure s = SurfaceStructure::of(scene().surface);
    const IncidenceSystem system = stackIncidences(s, scene().curves);
    const reg::CachedSvd svd{Eigen::MatrixXd(system.matrix)};
    const Eigen::MatrixXd l = gramFactor(Eigen::MatrixXd(smoothingGram(s, 0.0, 1.0, 0.0)));
    const reg::MtsvdSolver mtsvd(svd, l);
    Eigen::MatrixXd prior(svd.cols(), 3);
    for (Eigen::Index i = 0; i < prior.rows(); ++i) prior.row(i) = scene().surface.points()[static_cast<size_t>(i)].transpose();
    const reg::ProjectedRhs rhs = reg::projectRhs(svd, Eigen::MatrixXd(system.rhs), prior);
    const int k = reg::lcurveCorner(reg::tsvdLCurve(svd, rhs), reg::defaultCornerMethod(false)).k;
    for (auto _ : state) {
        if (state.range(0) == 0) {
            benchmark::DoNotOptimize(mtsvd.lcurve(rhs).rho.data());
        } else {
            benchmark::DoNotOptimize(mtsvd.solution(rhs, k).data());
        }
    }
    state.counters["rank"] = svd.rank();
    state.counters["k"] = k;
    state.SetLabel(state.range(0) == 0 ? "L-curve, QR updated across k" : "one solution at TSVD's k");
}
BENCHMARK(BM_IncidenceMtsvd1000Rows)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
