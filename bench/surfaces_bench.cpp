// Surface interpreter benchmarks (issue 6): sculptline-bench --benchmark_filter=Surface
// Every mode at 10, 20 and 40 control points per direction; the goal is a rebuild of a 20 x 20
// surface from its curves in <= 1 ms (issue 6 §2). Builders measure the per-drag-event update.
#include "solvers/surfaces/boundary_rotation.h"
#include "solvers/surfaces/coons_fill.h"
#include "solvers/surfaces/extrude.h"
#include "solvers/surfaces/gordon.h"
#include "solvers/surfaces/interpolation.h"
#include "solvers/surfaces/network_mesh.h"
#include "solvers/surfaces/loft.h"
#include "solvers/surfaces/rail_rotation.h"
#include "solvers/surfaces/revolve.h"
#include "solvers/surfaces/sweep.h"

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <cmath>

using namespace sculptline::solvers;
using namespace sculptline::solvers::surfaces;
using Vec3 = Eigen::Vector3d;

namespace {

// A wavy cubic of n control points from a to b, offset by `lift` along z.
Curve3d wavy(int n, const Vec3& a, const Vec3& b, double phase, double lift = 0.3)
{
    std::vector<Vec3> pts;
    for (int i = 0; i < n; ++i) {
        const double t = static_cast<double>(i) / (n - 1);
        const double bump = (i == 0 || i == n - 1) ? 0.0 : lift * std::sin(3.0 * t + phase);
        pts.push_back(a + t * (b - a) + Vec3(0, 0, bump));
    }
    return makeClampedUniform<3>(3, pts);
}

std::vector<Curve3d> sections(int n)
{
    std::vector<Curve3d> s;
    for (int k = 0; k < n; ++k) s.push_back(wavy(n, Vec3(0, k, 0), Vec3(5, k, 0.2 * k), 0.3 * k));
    return s;
}

std::vector<Curve3d> boundaries(int n)
{
    return {wavy(n, Vec3(0, 0, 0), Vec3(4, 0, 0), 0.0), wavy(n, Vec3(4, 0, 0), Vec3(4, 3, 0), 1.0),
            wavy(n, Vec3(4, 3, 0), Vec3(0, 3, 0), 2.0), wavy(n, Vec3(0, 3, 0), Vec3(0, 0, 0), 3.0)};
}

Curve3d moved(const Curve3d& c, double dz)
{
    std::vector<Vec3> pts = c.points();
    pts[pts.size() / 2].z() += dz;
    return Curve3d(c.degree(), c.knots(), pts);
}

void BM_SurfaceLoft(benchmark::State& state)
{
    const std::vector<Curve3d> s = sections(static_cast<int>(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(loft(s));
}

void BM_SurfaceLoftBuilderUpdate(benchmark::State& state)
{
    const std::vector<Curve3d> s = sections(static_cast<int>(state.range(0)));
    LoftBuilder builder(s);
    const Curve3d a = moved(s[s.size() / 2], 0.5);
    const Curve3d b = moved(s[s.size() / 2], -0.5);
    int k = 0;
    for (auto _ : state) benchmark::DoNotOptimize(&builder.update(static_cast<int>(s.size() / 2), (++k % 2) ? a : b));
}

void BM_SurfaceFill(benchmark::State& state)
{
    const std::vector<Curve3d> b = boundaries(static_cast<int>(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(fill(b));
}

void BM_SurfaceFillBuilderUpdate(benchmark::State& state)
{
    std::vector<Curve3d> b = boundaries(static_cast<int>(state.range(0)));
    FillBuilder builder(b);
    std::vector<Curve3d> other = b;
    other[2] = moved(b[2], 0.5);
    int k = 0;
    for (auto _ : state) benchmark::DoNotOptimize(&builder.update((++k % 2) ? other : b));
}

// The fill boundaries with a reference surface along the first: the ruled surface b0(u) + w·D(u),
// D running linearly from the direction in which the last boundary arrives at b0's start to the
// one in which the second leaves b0's end, so G1 along b0 is consistent at both corners.
Surface3d referenceAlongFirst(const std::vector<Curve3d>& b)
{
    const Curve3d& b0 = b[0];
    const Vec3 d0 = -(b[3].derivatives(b[3].domainEnd(), 1)[1]).normalized();
    const Vec3 d1 = b[1].derivatives(b[1].domainStart(), 1)[1].normalized();
    const std::vector<double> g = grevilleAbscissae(b0.degree(), b0.knots());
    std::vector<Vec3> pts;
    for (int i = 0; i < b0.pointCount(); ++i) {
        // A linear function's B-spline coefficients are its values at the Greville abscissae.
        pts.push_back(b0.points()[i]);
        pts.push_back(b0.points()[i] + (1.0 - g[i]) * d0 + g[i] * d1);
    }
    return Surface3d(b0.degree(), 1, b0.knots(), {0.0, 0.0, 1.0, 1.0}, b0.pointCount(), 2, pts);
}

void BM_SurfaceFillG1(benchmark::State& state)
{
    const std::vector<Curve3d> b = boundaries(static_cast<int>(state.range(0)));
    FillOptions options;
    options.tangents.push_back({0, referenceAlongFirst(b)});
    FillBuilder built(b, options);
    for (auto _ : state) benchmark::DoNotOptimize(fill(b, options));
    state.counters["countU"] = built.surface().countU();
    state.counters["max_angle_deg"] = built.maxTangentAngleDegrees();
}

void BM_SurfaceFillG1BuilderUpdate(benchmark::State& state)
{
    const std::vector<Curve3d> b = boundaries(static_cast<int>(state.range(0)));
    FillOptions options;
    options.tangents.push_back({0, referenceAlongFirst(b)});
    FillBuilder builder(b, options);
    std::vector<Curve3d> other = b;
    other[2] = moved(b[2], 0.5);
    int k = 0;
    for (auto _ : state) benchmark::DoNotOptimize(&builder.update((++k % 2) ? other : b));
    state.counters["max_angle_deg"] = builder.maxTangentAngleDegrees();
}

void BM_SurfaceExtrude(benchmark::State& state)
{
    const Curve3d profile = wavy(static_cast<int>(state.range(0)), Vec3(0, 0, 0), Vec3(4, 0, 0), 0.0);
    for (auto _ : state) benchmark::DoNotOptimize(extrude(profile, Vec3(0, 2, 1)));
}

void BM_SurfaceRevolve(benchmark::State& state)
{
    const Curve3d profile = wavy(static_cast<int>(state.range(0)), Vec3(1, 0, 0), Vec3(1, 0, 4), 0.0);
    const Axis axis{Vec3::Zero(), Vec3::UnitZ()};
    for (auto _ : state) benchmark::DoNotOptimize(revolve(profile, axis));
}

void BM_SurfaceExtrudePath(benchmark::State& state)
{
    const int n = static_cast<int>(state.range(0));
    const Curve3d profile = wavy(n, Vec3(0, 0, 0), Vec3(4, 0, 0), 0.0);
    const Curve3d path = wavy(n, Vec3(0, 0, 0), Vec3(0, 4, 1), 1.0);
    for (auto _ : state) benchmark::DoNotOptimize(extrude(profile, path));
}

void BM_SurfaceSweep(benchmark::State& state)
{
    const int n = static_cast<int>(state.range(0));
    const Curve3d profile = wavy(n, Vec3(0, -0.5, 0), Vec3(0, 0.5, 0), 0.0, 0.2);
    const Curve3d path = wavy(n, Vec3(0, 0, 0), Vec3(6, 0, 2), 1.0, 1.0);
    SweepResult r = sweep(profile, path);
    for (auto _ : state) benchmark::DoNotOptimize(r = sweep(profile, path));
    state.counters["sections"] = r.sections;
    state.counters["max_deviation"] = r.maxDeviation;
}

// A curve moved as its plane is when dragged: turned by `angle` about z and lifted by `dz`.
Curve3d dragged(const Curve3d& c, double angle, double dz)
{
    const Eigen::Matrix3d R = Eigen::AngleAxisd(angle, Vec3::UnitZ()).toRotationMatrix();
    std::vector<Vec3> pts;
    for (const Vec3& p : c.points()) pts.push_back(R * p + Vec3(0, 0, dz));
    return Curve3d(c.degree(), c.knots(), pts, c.weights());
}

// Per drag event while the profile's plane is dragged (the path stays).
void BM_SurfaceSweepBuilderProfileDrag(benchmark::State& state)
{
    const int n = static_cast<int>(state.range(0));
    const Curve3d profile = wavy(n, Vec3(0, -0.5, 0), Vec3(0, 0.5, 0), 0.0, 0.2);
    const Curve3d path = wavy(n, Vec3(0, 0, 0), Vec3(6, 0, 2), 1.0, 1.0);
    SweepBuilder builder(profile, path);
    const Curve3d a = dragged(profile, 0.0, 0.01), b = dragged(profile, 0.0, -0.01);
    int k = 0;
    for (auto _ : state) benchmark::DoNotOptimize(&builder.update((++k % 2) ? a : b, path));
    state.counters["sections"] = builder.result().sections;
}

// Per drag event while the path's plane is dragged (the path moves rigidly).
void BM_SurfaceSweepBuilderPathDrag(benchmark::State& state)
{
    const int n = static_cast<int>(state.range(0));
    const Curve3d profile = wavy(n, Vec3(0, -0.5, 0), Vec3(0, 0.5, 0), 0.0, 0.2);
    const Curve3d path = wavy(n, Vec3(0, 0, 0), Vec3(6, 0, 2), 1.0, 1.0);
    SweepBuilder builder(profile, path);
    const Curve3d a = dragged(path, 0.01, 0.01), b = dragged(path, -0.01, -0.01);
    int k = 0;
    for (auto _ : state) benchmark::DoNotOptimize(&builder.update(profile, (++k % 2) ? a : b));
    state.counters["sections"] = builder.result().sections;
}

void BM_SurfaceBoundaryRotation(benchmark::State& state)
{
    const int n = static_cast<int>(state.range(0));
    const Curve3d l = wavy(n, Vec3(0, 0, 0), Vec3(6, 0, 0), 0.0, 1.5);
    // Shifted along x so that D = (Cl - Cr)/2 turns and |D| is not a polynomial (E must be fitted).
    const Curve3d r = wavy(n, Vec3(0.4, 0, 0), Vec3(5.6, 0, 0), 3.5, 1.0);
    ApproximatedSurface s = boundaryRotation(l, r);
    for (auto _ : state) benchmark::DoNotOptimize(s = boundaryRotation(l, r));
    state.counters["countU"] = s.surface.countU();
    state.counters["max_deviation"] = s.maxDeviation;
}

Curve3d ellipse(double a, double b, double z)
{
    const double w = std::sqrt(0.5);
    const double cs[9][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    std::vector<Vec3> pts;
    std::vector<double> ws;
    for (int j = 0; j < 9; ++j) {
        pts.push_back(Vec3(a * cs[j][0], b * cs[j][1], z));
        ws.push_back(j % 2 ? w : 1.0);
    }
    return Curve3d(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, pts, ws);
}

void BM_SurfaceRailRotation(benchmark::State& state)
{
    const int n = static_cast<int>(state.range(0));
    const Curve3d r1 = ellipse(2.0, 1.0, 0.0);
    const Curve3d r2 = ellipse(1.2, 0.8, 3.0);
    std::vector<Vec3> pts;
    for (int i = 0; i < n; ++i) {
        const double t = static_cast<double>(i) / (n - 1);
        pts.push_back(Vec3(2.0 - 0.8 * t + 0.4 * std::sin(M_PI * t), 0, 3.0 * t));
    }
    const Curve3d profile = makeClampedUniform<3>(3, pts);
    ApproximatedSurface s = railRotation(r1, r2, profile);
    for (auto _ : state) benchmark::DoNotOptimize(s = railRotation(r1, r2, profile));
    state.counters["countV"] = s.surface.countV();
    state.counters["max_deviation"] = s.maxDeviation;
}

// A Gordon network of 4 x 4 curves with n control points each, on z = 0.3 sin(x) cos(y).
void BM_SurfaceGordon(benchmark::State& state)
{
    const int n = static_cast<int>(state.range(0));
    const auto h = [](double x, double y) { return 0.3 * std::sin(x) * std::cos(y); };
    std::vector<Curve3d> us, vs;
    for (int k = 0; k < 4; ++k) {
        std::vector<Vec3> a, b;
        for (int i = 0; i < n; ++i) {
            // Vertices at the integers (where the other family crosses), so the network intersects
            // exactly and the curves need no reparameterization.
            double t = 3.0 * i / (n - 1);
            if (std::abs(t - std::round(t)) < 1.5 / (n - 1)) t = std::round(t);
            a.push_back(Vec3(t, k, h(t, k)));
            b.push_back(Vec3(k, t, h(k, t)));
        }
        us.push_back(makeClampedUniform<3>(1, a));
        vs.push_back(makeClampedUniform<3>(1, b));
    }
    for (auto _ : state) benchmark::DoNotOptimize(gordon(us, vs));
}

// A four-sided loop with n control points per curve meshed at 16 segments per curve.
void BM_SurfaceNetworkMesh(benchmark::State& state)
{
    const std::vector<Curve3d> b = boundaries(static_cast<int>(state.range(0)));
    NetworkMesh m;
    for (auto _ : state) benchmark::DoNotOptimize(m = meshNetwork(b, {{0, 1, 2, 3}}));
    state.counters["triangles"] = static_cast<double>(m.triangles.size());
}

}  // namespace

BENCHMARK(BM_SurfaceLoft)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SurfaceLoftBuilderUpdate)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SurfaceFill)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SurfaceFillBuilderUpdate)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SurfaceFillG1)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SurfaceFillG1BuilderUpdate)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SurfaceExtrude)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SurfaceRevolve)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SurfaceExtrudePath)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SurfaceSweep)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SurfaceSweepBuilderProfileDrag)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SurfaceSweepBuilderPathDrag)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SurfaceBoundaryRotation)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SurfaceRailRotation)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SurfaceGordon)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SurfaceNetworkMesh)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
