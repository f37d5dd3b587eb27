// Sweep along rotation-minimizing frames: the profile starts the surface exactly, the result is a
// tube within the reported deviation, no twist on a planar path, cusps refused.
#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/projection.h"
#include "solvers/surfaces/rotation_minimizing_frames.h"
#include "solvers/surfaces/sweep.h"
#include "surface_checks.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::surfaces;
using namespace sculptline::surfaces_test;

namespace {

constexpr double kExact = 1e-9;
constexpr double kRadius = 0.3;

Curve3d planarPath() { return cubic({{0, 0, 0}, {2, 0, 0}, {3, 2, 0}, {5, 3, 0}, {7, 3, 0}, {8, 1, 0}}); }

Curve3d helixPath()
{
    std::vector<Vec3> pts;
    for (int k = 0; k < 12; ++k) pts.push_back(Vec3(2 * std::cos(0.6 * k), 2 * std::sin(0.6 * k), 0.4 * k));
    return cubic(pts);
}

// A circle of kRadius around the path's start, in its normal plane.
Curve3d profileAtStart(const Curve3d& path)
{
    const Vec3 t = unitTangent(path, 0.0);
    const Vec3 a = t.unitOrthogonal();
    return fullCircle(path.evaluate(0.0), kRadius, a, t.cross(a));
}

}  // namespace

TEST(Sweep, GivenCircleAlongPlanarPath_WhenSwept_ThenTubeWithoutTwist)
{
    const Curve3d path = planarPath();
    // The circle in the yz plane (path starts along +x): u = 1/4 is the point +z·r.
    const Curve3d profile = fullCircle(Vec3::Zero(), kRadius, Vec3::UnitY(), Vec3::UnitZ());
    const SweepResult r = sweep(profile, path);
    EXPECT_LE(r.maxDeviation, r.tolerance);
    EXPECT_LT(isoDeviation(r.surface, true, 0.0, profile), kExact);
    const CurveProjector<3> onPath(path);
    for (int j = 0; j <= 60; ++j) {
        const double v = j / 60.0;
        // A planar path's RMF keeps the plane's normal: the +z point of the profile stays at z = r.
        EXPECT_NEAR(r.surface.evaluate(0.25, v).z(), kRadius, r.maxDeviation + kExact) << v;
        for (int i = 0; i <= 16; ++i) {
            const Vec3 p = r.surface.evaluate(i / 16.0, v);
            EXPECT_NEAR(onPath.project(p).distance, kRadius, r.maxDeviation + kExact);
        }
    }
    EXPECT_GT(minNeighbourNormalDot(r.surface), 0.0);
}

TEST(Sweep, GivenHelixPath_WhenSwept_ThenTubeWithinReportedDeviationAndNoFlip)
{
    const Curve3d path = helixPath();
    const SweepResult r = sweep(profileAtStart(path), path, SweepOptions{1e-4, 513});
    EXPECT_LE(r.maxDeviation, 1e-4);
    const CurveProjector<3> onPath(path);
    for (int j = 0; j <= 80; ++j)
        for (int i = 0; i <= 16; ++i)
            EXPECT_NEAR(onPath.project(r.surface.evaluate(i / 16.0, j / 80.0)).distance, kRadius, 1e-4 + kExact);
    EXPECT_GT(minNeighbourNormalDot(r.surface, 60), 0.0);
}

TEST(Sweep, GivenLooseTolerance_WhenSwept_ThenFewerSectionsAndLargerReportedDeviation)
{
    const Curve3d path = helixPath();
    const SweepResult fine = sweep(profileAtStart(path), path, SweepOptions{1e-5, 2049});
    const SweepResult coarse = sweep(profileAtStart(path), path, SweepOptions{1e-2, 2049});
    EXPECT_LT(coarse.sections, fine.sections);
    EXPECT_LE(coarse.maxDeviation, 1e-2);
    EXPECT_LE(fine.maxDeviation, 1e-5);
}

TEST(Sweep, GivenPathWithCusp_WhenSwept_ThenClearError)
{
    const Curve3d profile = fullCircle(Vec3::Zero(), kRadius, Vec3::UnitY(), Vec3::UnitZ());
    const Curve3d backAndForth = cubic({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 0, 0}});  // C'(1/2) = 0
    const Curve3d reversal(1, {0, 0, 0.5, 1, 1}, {{0, 0, 0}, {1, 0, 0}, {0, 0.01, 0}});
    for (const Curve3d& path : {backAndForth, reversal}) {
        try {
            sweep(profile, path);
            FAIL() << "expected GeometryError";
        } catch (const GeometryError& e) {
            EXPECT_NE(std::string(e.what()).find("cusp"), std::string::npos) << e.what();
        }
    }
    EXPECT_THROW(sweep(profile, cubic({{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}})), GeometryError);
}

TEST(RotationMinimizingFrames, GivenHelix_WhenPropagated_ThenOrthonormalAndAngularVelocityHasNoTangentPart)
{
    const Curve3d path = helixPath();
    std::vector<double> params;
    for (int k = 0; k <= 2000; ++k) params.push_back(k / 2000.0);
    const std::vector<Frame> f = rotationMinimizingFrames(path, params, Vec3::UnitZ());
    for (size_t k = 0; k + 1 < f.size(); ++k) {
        EXPECT_NEAR(f[k].normal.dot(f[k].tangent), 0.0, 1e-12);
        EXPECT_NEAR(f[k].binormal.norm(), 1.0, 1e-12);
        // Rotation minimizing: dr/ds has no component along s (Bishop 1975); finite difference.
        const double twist = (f[k + 1].normal - f[k].normal).dot(f[k].binormal);
        EXPECT_LT(std::abs(twist), 1e-5) << k;
    }
}
