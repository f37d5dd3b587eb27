// Solid benchmarks (solvers/volume): sculptline-bench --benchmark_filter=Solid
// The revolved sphere of radius 10 at the default voxel size (diagonal / 200 = 0.173): tessellation,
// level set, meshing and measures; the shell of a 20 × 20 patch 1 mm thick at its default voxel
// (t / 4); and the level set step alone at finer voxels, to show the cost per narrow-band voxel.
#include "solvers/surfaces/revolve.h"
#include "solvers/volume/level_set.h"
#include "solvers/volume/solidify.h"

#include <benchmark/benchmark.h>

#include <cmath>

using namespace sculptline::solvers;
namespace vol = sculptline::solvers::volume;

namespace {

// The exact rational sphere: a half circle of two 90° arcs revolved about z (The NURBS Book §8.5).
Surface3d sphere(double r)
{
    const double w = std::sqrt(0.5);
    const Curve3d half(2, {0, 0, 0, 0.5, 0.5, 1, 1, 1}, {{0, 0, -r}, {r, 0, -r}, {r, 0, 0}, {r, 0, r}, {0, 0, r}}, {1, w, 1, w, 1});
    return surfaces::revolve(half, surfaces::Axis{}, 360.0);
}

void BM_SolidSphereDefaultVoxel(benchmark::State& state)
{
    const std::vector<Surface3d> input{sphere(10.0)};
    vol::Solid solid;
    for (auto _ : state) {
        solid = vol::solidify(input);
        benchmark::DoNotOptimize(solid.volume);
    }
    state.counters["voxels"] = static_cast<double>(solid.activeVoxels);
    state.counters["triangles"] = static_cast<double>(solid.mesh.triangles.size());
    state.counters["volume_error_pct"] = 100.0 * (solid.volume / (4.0 / 3.0 * M_PI * 1000.0) - 1.0);
}
BENCHMARK(BM_SolidSphereDefaultVoxel)->Unit(benchmark::kMillisecond);

void BM_SolidPatchShell(benchmark::State& state)
{
    const Surface3d patch(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2, {{0, 0, 0}, {0, 20, 0}, {20, 0, 0}, {20, 20, 0}});
    vol::SolidOptions options;
    options.thickness = 1.0;
    vol::Solid solid;
    for (auto _ : state) {
        solid = vol::solidify({patch}, options);
        benchmark::DoNotOptimize(solid.volume);
    }
    state.counters["voxels"] = static_cast<double>(solid.activeVoxels);
}
BENCHMARK(BM_SolidPatchShell)->Unit(benchmark::kMillisecond);

// The level set step alone (no tessellation): the sphere's mesh converted at voxel 10 / arg.
void BM_SolidSphereLevelSet(benchmark::State& state)
{
    const double voxel = 10.0 / static_cast<double>(state.range(0));
    const vol::TriangleMesh mesh = vol::surfaceMesh(sphere(10.0), vol::kChordToleranceVoxels * voxel, 1e-9);
    vol::LevelSetSolid solid;
    for (auto _ : state) {
        solid = vol::solidFromMeshes({mesh}, voxel, Eigen::Vector3d::Zero());
        benchmark::DoNotOptimize(solid.volume);
    }
    state.counters["voxels"] = static_cast<double>(solid.activeVoxels);
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * solid.activeVoxels));
}
BENCHMARK(BM_SolidSphereLevelSet)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMillisecond);

}  // namespace
