// Surface deformation benchmarks: sculptline-bench --benchmark_filter=Deform
// The seven rows of thesis 002_d9515b9d07f9cfd1 Table 6-2 (control net U×V, key points on the target
// curve, polygon mesh, the thesis's update time). Goals: a one-shot solve (set-up + factor + solve)
// at least 100× faster than the table, a drag event (factor kept: solve + new surface + mesh) at
// least 1000× faster. Counters: thesis_ms, goal_ms (the 1000× or 100× goal), smoothness (‖K d‖ of
// the change per unit pull, lower is smoother) and residual.
#include "solvers/bspline/tessellation.h"
#include "solvers/deformation/surface_deformation.h"

#include "tests/deformation/deformation_fixtures.h"

#include <Eigen/Geometry>
#include <benchmark/benchmark.h>

#include <cmath>

using namespace sculptline::solvers;
using namespace sculptline::solvers::deformation;

namespace {

struct TableRow {
    int nu, nv, keyPoints, meshU, meshV;
    double thesisSeconds;
};

// Thesis Table 6-2, row by row.
constexpr TableRow kTable62[] = {
    {21, 10, 12, 40, 40, 0.203}, {20, 20, 14, 40, 40, 0.219}, {26, 26, 14, 40, 40, 0.313}, {28, 10, 22, 40, 40, 0.328},
    {24, 8, 12, 15, 5, 0.094},   {35, 8, 10, 15, 15, 0.125},  {18, 135, 13, 41, 50, 3.75},
};

// The table's set-up: a target curve above the surface, across it along U at v = 0.5, pulling it up.
struct Problem {
    Surface3d surface;
    std::vector<SurfaceConstraint> constraints;
};

Problem problem(const TableRow& row, double lift)
{
    Problem p{sculptline::deformtest::wavySurface(row.nu, row.nv), {}};
    SurfaceConstraint c;
    c.type = SurfaceConstraintType::Curve;
    c.domain = BSplineCurve<2>(1, {0, 0, 1, 1}, {Eigen::Vector2d(0.15, 0.5), Eigen::Vector2d(0.85, 0.5)});
    const Eigen::Vector3d a = p.surface.evaluate(0.15, 0.5), b = p.surface.evaluate(0.85, 0.5);
    const Eigen::Vector3d mid = 0.5 * (a + b) + Eigen::Vector3d(0, 0, lift);
    c.target = BSplineCurve<3>(2, {0, 0, 0, 1, 1, 1}, {a, mid, b});
    c.keyPoints = row.keyPoints;
    p.constraints.push_back(c);
    return p;
}

std::vector<double> grid(int n)
{
    std::vector<double> t(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) t[static_cast<size_t>(k)] = static_cast<double>(k) / (n - 1);
    return t;
}


DeformationOptions withObjective(int objective)
{
    DeformationOptions o;
    o.objective = objective == 0 ? Objective::Displacement : Objective::Force;
    return o;
}

// One-shot: set-up + factor + solve (what the thesis's update time measured, without the mesh).
void BM_DeformOneShot(benchmark::State& state)
{
    const TableRow& row = kTable62[state.range(0)];
    const Problem p = problem(row, 1.0);
    const DeformationOptions options = withObjective(static_cast<int>(state.range(1)));
    DeformationReport report;
    for (auto _ : state) {
        Surface3d out = deformSurface(p.surface, p.constraints, options, &report);
        benchmark::DoNotOptimize(out);
    }
    const Surface3d out = deformSurface(p.surface, p.constraints, options, &report);
    state.counters["thesis_ms"] = row.thesisSeconds * 1e3;
    state.counters["goal_ms"] = row.thesisSeconds * 1e3 / 100.0;
    state.counters["residual"] = report.maxResidual;
    state.counters["smoothness"] = forceChange(p.surface, out);
    state.SetLabel(std::to_string(row.nu) + "x" + std::to_string(row.nv) + " key " + std::to_string(row.keyPoints) +
                   (state.range(1) == 0 ? " displacement" : " force"));
}
BENCHMARK(BM_DeformOneShot)
    ->ArgsProduct({{0, 1, 2, 3, 4, 5, 6}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

// The same with a normal constraint added at the middle of the curve's span: the rows then couple
// x, y and z, and the general path (three times the columns) runs instead of the per-coordinate one.
void BM_DeformOneShotWithNormal(benchmark::State& state)
{
    const TableRow& row = kTable62[state.range(0)];
    Problem p = problem(row, 1.0);
    SurfaceConstraint n;
    n.type = SurfaceConstraintType::Normal;
    n.uv = {0.5, 0.25};
    n.value = p.surface.normal(0.5, 0.25) + Eigen::Vector3d(0.2, 0.0, 0.0);
    p.constraints.push_back(n);
    const DeformationOptions options = withObjective(static_cast<int>(state.range(1)));
    DeformationReport report;
    for (auto _ : state) {
        Surface3d out = deformSurface(p.surface, p.constraints, options, &report);
        benchmark::DoNotOptimize(out);
    }
    state.counters["thesis_ms"] = row.thesisSeconds * 1e3;
    state.counters["goal_ms"] = row.thesisSeconds * 1e3 / 100.0;
    state.counters["residual"] = report.maxResidual;
    state.SetLabel(std::to_string(row.nu) + "x" + std::to_string(row.nv) + " key " + std::to_string(row.keyPoints) +
                   " + normal" + (state.range(1) == 0 ? " displacement" : " force"));
}
BENCHMARK(BM_DeformOneShotWithNormal)->ArgsProduct({{0, 6}, {0, 1}})->Unit(benchmark::kMillisecond);

// Drag event: the factorization kept; the target curve moves; solve + new surface + the table's mesh.
void BM_DeformDragEvent(benchmark::State& state)
{
    const TableRow& row = kTable62[state.range(0)];
    Problem p = problem(row, 0.0);
    const DeformationOptions options = withObjective(static_cast<int>(state.range(1)));
    SurfaceDeformationSolver solver;
    solver.factor(p.surface, p.constraints, options);
    const std::vector<double> us = grid(row.meshU), vs = grid(row.meshV);
    const Eigen::Vector3d a = p.surface.evaluate(0.15, 0.5), b = p.surface.evaluate(0.85, 0.5);
    int event = 0;
    for (auto _ : state) {
        const double lift = 0.01 * (++event % 100);
        p.constraints[0].target =
            BSplineCurve<3>(2, {0, 0, 0, 1, 1, 1}, {a, 0.5 * (a + b) + Eigen::Vector3d(0, 0, lift), b});
        Surface3d out = solver.solve(p.constraints);
        GridMesh mesh = meshOnGrid(out, us, vs);
        benchmark::DoNotOptimize(mesh);
    }
    state.counters["thesis_ms"] = row.thesisSeconds * 1e3;
    state.counters["goal_ms"] = row.thesisSeconds * 1e3 / 1000.0;
    state.SetLabel(std::to_string(row.nu) + "x" + std::to_string(row.nv) + " key " + std::to_string(row.keyPoints) +
                   " mesh " + std::to_string(row.meshU) + "x" + std::to_string(row.meshV) +
                   (state.range(1) == 0 ? " displacement" : " force"));
}
BENCHMARK(BM_DeformDragEvent)
    ->ArgsProduct({{0, 1, 2, 3, 4, 5, 6}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

// A handle's drag event (Fig. 6-5 c–d; the GUI's point dragger): position and the tangent plane
// turned with the handle (9 rows), beside the table's target curve; the factorization of the press
// kept while the handle moves and turns: solve + new surface + the table's mesh.
void BM_DeformHandleDragEvent(benchmark::State& state)
{
    const TableRow& row = kTable62[state.range(0)];
    Problem p = problem(row, 0.0);
    const Eigen::Vector2d uv(0.5, 0.25);
    const auto der = p.surface.derivatives(uv.x(), uv.y(), 1);
    const Eigen::Vector3d at = p.surface.evaluate(uv.x(), uv.y());
    SurfaceConstraint point;
    point.type = SurfaceConstraintType::Position;
    point.uv = uv;
    point.value = at;
    SurfaceConstraint tangents = point;
    tangents.type = SurfaceConstraintType::Tangents;
    tangents.value = der[1][0];
    tangents.value2 = der[0][1];
    p.constraints.push_back(point);
    p.constraints.push_back(tangents);
    SurfaceDeformationSolver solver;
    solver.factor(p.surface, p.constraints, withObjective(1));
    const std::vector<double> us = grid(row.meshU), vs = grid(row.meshV);
    int event = 0;
    for (auto _ : state) {
        const double t = 0.01 * (++event % 100);
        const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.5 * t, Eigen::Vector3d::UnitX()).toRotationMatrix();
        p.constraints[1].value = at + Eigen::Vector3d(0, 0, t);
        p.constraints[2].value = turn * der[1][0];
        p.constraints[2].value2 = turn * der[0][1];
        Surface3d out = solver.solve(p.constraints);
        GridMesh mesh = meshOnGrid(out, us, vs);
        benchmark::DoNotOptimize(mesh);
    }
    state.counters["thesis_ms"] = row.thesisSeconds * 1e3;
    state.counters["goal_ms"] = row.thesisSeconds * 1e3 / 1000.0;
    state.SetLabel(std::to_string(row.nu) + "x" + std::to_string(row.nv) + " key " + std::to_string(row.keyPoints) +
                   " + handle, force");
}
BENCHMARK(BM_DeformHandleDragEvent)->DenseRange(0, 6)->Unit(benchmark::kMillisecond);

// The GUI's per-event mesh of the 18x135 net during a drag: the surface's control points move, its
// knots stay, and it is redrawn on the grid of its last adaptive tessellation (61 x 529 here).
// Arg 0: meshOnGrid (basis of every grid line, vertices, normals, triangles made anew; the path of
// a rebuilt node); arg 1: GridBasis::evaluate with the basis kept (vertices and normals only, the
// path of the view's in-place update). Both give the same vertices and normals.
void BM_DeformKeptGridMesh18x135(benchmark::State& state)
{
    const TableRow& row = kTable62[6];
    Surface3d surface = sculptline::deformtest::wavySurface(row.nu, row.nv);
    const GridMesh adaptive = tessellate(surface);
    const GridBasis basis(surface, adaptive.u, adaptive.v);
    std::vector<Eigen::Vector3d> vertices, normals;
    std::vector<Eigen::Vector3d> points = surface.points();
    int event = 0;
    for (auto _ : state) {
        // One drag event's new net: every control point moved a little (as a sculpt's solve does).
        const double lift = 0.01 * (++event % 100);
        for (size_t k = 0; k < points.size(); ++k) points[k].z() = surface.points()[k].z() + lift * std::sin(0.1 * k);
        const Surface3d moved(surface.degreeU(), surface.degreeV(), surface.knotsU(), surface.knotsV(), surface.countU(),
                              surface.countV(), points);
        if (state.range(0) == 0) {
            GridMesh mesh = meshOnGrid(moved, adaptive.u, adaptive.v);
            benchmark::DoNotOptimize(mesh);
        } else {
            basis.evaluate(moved, vertices, normals);
            benchmark::DoNotOptimize(vertices.data());
            benchmark::DoNotOptimize(normals.data());
        }
    }
    state.counters["vertices"] = static_cast<double>(adaptive.u.size() * adaptive.v.size());
    state.SetLabel(std::to_string(adaptive.u.size()) + "x" + std::to_string(adaptive.v.size()) +
                   (state.range(0) == 0 ? " meshOnGrid" : " kept basis"));
}
BENCHMARK(BM_DeformKeptGridMesh18x135)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
