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

namespace {

// The curve moved by the rotation `angle` about `axis` through the origin, then by `shift` (a
// dragged plane moves its curves this way).
Curve3d movedRigidly(const Curve3d& c, const Vec3& axis, double angle, const Vec3& shift)
{
    const Eigen::Matrix3d R = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
    std::vector<Vec3> pts;
    for (const Vec3& p : c.points()) pts.push_back(R * p + shift);
    return Curve3d(c.degree(), c.knots(), pts, c.weights());
}

// Largest distance between two surfaces on a grid of their common domain.
double gridGap(const Surface3d& a, const Surface3d& b)
{
    double worst = 0.0;
    for (int i = 0; i <= 20; ++i)
        for (int j = 0; j <= 60; ++j) worst = std::max(worst, (a.evaluate(i / 20.0, j / 60.0) - b.evaluate(i / 20.0, j / 60.0)).norm());
    return worst;
}

}  // namespace

TEST(SweepBuilder, GivenProfileOrPathMovedRigidly_WhenUpdated_ThenSameSweepAsAFreshBuild)
{
    // Given: a helix sweep built once.
    const Curve3d path = helixPath();
    const Curve3d profile = profileAtStart(path);
    const SweepOptions options{1e-4, 513};
    SweepBuilder builder(profile, path, options);

    // When: the profile's plane turns a little about the path's start (the profile moves off the
    // normal plane), then the path's plane is dragged (the path moves rigidly).
    const Curve3d tilted = movedRigidly(profile, Vec3(1, 1, 0), 0.05, Vec3(0, 0, 0.02));
    const SweepResult afterProfile = builder.update(tilted, path);
    const Curve3d movedPath = movedRigidly(path, Vec3(0, 1, 2), 0.3, Vec3(0.5, -1, 2));
    const SweepResult afterPath = builder.update(tilted, movedPath);

    // Then: each update is within tolerance of the exact sweep, as a fresh build is, so the two
    // differ by at most twice the tolerance; the start section is the profile exactly.
    const SweepResult freshProfile = sweep(tilted, path, options);
    const SweepResult freshPath = sweep(tilted, movedPath, options);
    EXPECT_LE(afterProfile.maxDeviation, options.tolerance);
    EXPECT_LE(afterPath.maxDeviation, options.tolerance);
    EXPECT_LT(gridGap(afterProfile.surface, freshProfile.surface), 2 * options.tolerance);
    EXPECT_LT(gridGap(afterPath.surface, freshPath.surface), 2 * options.tolerance);
    EXPECT_LT(isoDeviation(afterPath.surface, true, 0.0, tilted), kExact);
}

TEST(Sweep, GivenWavyPath_WhenSwept_ThenSpansGetSectionsByTheirOwnDeviation)
{
    // Given: a path that is straight on its first half and wavy on its second.
    std::vector<Vec3> pts;
    for (int k = 0; k < 16; ++k) pts.push_back(k < 8 ? Vec3(k, 0, 0) : Vec3(k, std::sin(1.7 * k), std::cos(1.3 * k) - std::cos(1.3 * 8)));
    const Curve3d path = cubic(pts);
    const Curve3d profile = fullCircle(path.evaluate(0.0), 0.3, Vec3::UnitY(), Vec3::UnitZ());

    // When
    const SweepResult r = sweep(profile, path, SweepOptions{1e-4, 2049});

    // Then: within tolerance, with fewer sections than uniform refinement to the wavy part's
    // density would need (13 spans x the wavy spans' sections).
    EXPECT_LE(r.maxDeviation, 1e-4);
    const CurveProjector<3> onPath(path);
    for (int j = 0; j <= 200; ++j)
        for (int i = 0; i <= 16; ++i)
            EXPECT_NEAR(onPath.project(r.surface.evaluate(i / 16.0, j / 200.0)).distance, 0.3, 1e-4 + kExact);
    std::vector<double> knots = r.surface.knotsV();
    knots.erase(std::unique(knots.begin(), knots.end()), knots.end());
    double shortest = 1.0, longest = 0.0;
    for (size_t k = 0; k + 1 < knots.size(); ++k) {
        shortest = std::min(shortest, knots[k + 1] - knots[k]);
        longest = std::max(longest, knots[k + 1] - knots[k]);
    }
    EXPECT_GT(longest, 2.0 * shortest);
}

TEST(Sweep, GivenPointProfile_WhenSwept_ThenClearError)
{
    const Curve3d point = cubic({{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}});
    try {
        sweep(point, helixPath());
        FAIL() << "expected GeometryError";
    } catch (const GeometryError& e) {
        EXPECT_NE(std::string(e.what()).find("single point"), std::string::npos) << e.what();
    }
}

TEST(Sweep, GivenCurvedPathWithCorner_WhenSwept_ThenRefusedUnlessTheTearIsWithinTolerance)
{
    // Given: a profile of radius 0.3 and cubic paths with a C0 knot (triple knot at 1/2) where the
    // tangent turns by 45 degrees, and by 0.001 degree.
    const Curve3d profile = fullCircle(Vec3::Zero(), kRadius, Vec3::UnitY(), Vec3::UnitZ());
    const auto corner = [](double degrees) {
        const double a = degrees * M_PI / 180.0;
        const Vec3 d(std::cos(a), std::sin(a), 0);
        return Curve3d(3, {0, 0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1, 1},
                       {{0, 0, 0}, {0.7, 0.1, 0}, {1.4, 0, 0}, {2, 0, 0}, Vec3(2, 0, 0) + 0.6 * d,
                        Vec3(2, 0, 0) + 1.2 * d + Vec3(0, 0, 0.1), Vec3(2, 0, 0) + 2 * d});
    };
    // When / Then: 45 degrees tears the tube by about 2·0.3·sin(22.5°) = 0.23 >> 1e-4: refused,
    // naming the corner; 0.001 degree tears it by about 5e-6 < 1e-4: swept within tolerance.
    try {
        sweep(profile, corner(45.0), SweepOptions{1e-4, 513});
        FAIL() << "expected GeometryError";
    } catch (const GeometryError& e) {
        EXPECT_NE(std::string(e.what()).find("path: corner at u = 0.5"), std::string::npos) << e.what();
    }
    const SweepResult r = sweep(profile, corner(0.001), SweepOptions{1e-4, 513});
    EXPECT_LE(r.maxDeviation, 1e-4);
}

TEST(Sweep, GivenPolylinePath_WhenSwept_ThenMitredTubeExact)
{
    // Given: a circle along an open polyline turning by 60 degrees twice (once out of plane), and
    // along a closed square.
    const Curve3d profile = fullCircle(Vec3::Zero(), kRadius, Vec3::UnitY(), Vec3::UnitZ());
    const std::vector<Vec3> q{{0, 0, 0}, {2, 0, 0}, {3, std::sqrt(3.0), 0}, {3, std::sqrt(3.0) + 1, std::sqrt(3.0)}};
    const Curve3d polyline = makeClampedUniform<3>(1, q);

    // When
    const SweepResult r = sweep(profile, polyline);

    // Then: exact (no deviation), starts with the profile, and every point of segment k's part
    // lies at the radius from that segment's line (the mitres join the straight tubes exactly).
    EXPECT_EQ(r.maxDeviation, 0.0);
    EXPECT_LT(isoDeviation(r.surface, true, 0.0, profile), kExact);
    for (int k = 0; k < 3; ++k) {
        const Vec3 t = (q[k + 1] - q[k]).normalized();
        for (int j = 0; j <= 10; ++j)
            for (int i = 0; i <= 16; ++i) {
                const Vec3 x = r.surface.evaluate(i / 16.0, (k + j / 10.0) / 3.0);
                const Vec3 d = x - q[k];
                EXPECT_NEAR((d - d.dot(t) * t).norm(), kRadius, kExact) << "segment " << k;
            }
    }
    EXPECT_GT(minNeighbourNormalDot(r.surface), 0.0);

    // And: a closed square path is mitred at its seam too: the tube closes.
    const Curve3d square = makeClosedUniform<3>(1, {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}});
    const Curve3d ring = fullCircle(Vec3::Zero(), kRadius, Vec3::UnitY(), Vec3::UnitZ());
    const SweepResult closed = sweep(ring, square);
    for (int i = 0; i <= 20; ++i)
        EXPECT_LT((closed.surface.evaluate(i / 20.0, 0.0) - closed.surface.evaluate(i / 20.0, 1.0)).norm(), kExact);
}
