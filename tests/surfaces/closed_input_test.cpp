// Closed profiles, sections, paths and rails: every mode gives a surface that closes along the
// seam (the two seam edges coincide to 1e-9) with normals that agree across it.
#include "solvers/bspline/projection.h"
#include "solvers/surfaces/extrude.h"
#include "solvers/surfaces/loft.h"
#include "solvers/surfaces/rail_rotation.h"
#include "solvers/surfaces/revolve.h"
#include "solvers/surfaces/rotation_minimizing_frames.h"
#include "solvers/surfaces/sweep.h"
#include "surface_checks.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace sculptline::solvers;
using namespace sculptline::solvers::surfaces;
using namespace sculptline::surfaces_test;

namespace {

// Across a seam the normals of a closed surface agree; a fold or a flipped side would make them
// opposite. The seam of a periodic profile is smooth, so they agree closely.
constexpr double kSeamNormalDot = 0.9;

// A wobbly closed loop (periodic cubic, 8 control points) around `centre` in the plane spanned by
// a and b, starting at control point `start` (so loops can have their seams in different places).
Curve3d loop(const Vec3& centre, double r, const Vec3& a, const Vec3& b, int start = 0, bool backwards = false)
{
    std::vector<Vec3> pts;
    for (int k = 0; k < 8; ++k) {
        const int j = (start + (backwards ? -k : k) + 8) % 8;
        const double t = 2 * kPi * j / 8;
        const double rr = r * (1.0 + 0.15 * std::cos(3 * t));
        pts.push_back(centre + rr * (std::cos(t) * a + std::sin(t) * b));
    }
    return makeClosedUniform<3>(3, pts);
}

// Largest gap between the seam edges u = 0 and u = 1 (vFixed = false) or v = 0 and v = 1.
double seamGap(const Surface3d& s, bool alongU)
{
    double worst = 0.0;
    for (int k = 0; k <= 100; ++k) {
        const double t = k / 100.0;
        const Direction d = alongU ? Direction::V : Direction::U;
        const double x = s.domainStart(d) + t * (s.domainEnd(d) - s.domainStart(d));
        const Vec3 p = alongU ? s.evaluate(s.domainStart(Direction::U), x) : s.evaluate(x, s.domainStart(Direction::V));
        const Vec3 q = alongU ? s.evaluate(s.domainEnd(Direction::U), x) : s.evaluate(x, s.domainEnd(Direction::V));
        worst = std::max(worst, (p - q).norm());
    }
    return worst;
}

// Smallest dot product of the unit normals on the two sides of the seam.
double seamNormalDot(const Surface3d& s, bool alongU)
{
    double worst = 1.0;
    for (int k = 1; k < 100; ++k) {
        const double t = k / 100.0;
        const Direction d = alongU ? Direction::V : Direction::U;
        const double x = s.domainStart(d) + t * (s.domainEnd(d) - s.domainStart(d));
        const Vec3 a = alongU ? limitNormal(s, s.domainStart(Direction::U), x) : limitNormal(s, x, s.domainStart(Direction::V));
        const Vec3 b = alongU ? limitNormal(s, s.domainEnd(Direction::U), x) : limitNormal(s, x, s.domainEnd(Direction::V));
        if (a.norm() > 0.5 && b.norm() > 0.5) worst = std::min(worst, a.dot(b));
    }
    return worst;
}

}  // namespace

TEST(ClosedInput, GivenClosedProfile_WhenRevolvedFullTurn_ThenClosedAlongBothSeams)
{
    // Given: a closed loop in the xz-plane beside the z axis (a torus-like ring).
    const Curve3d profile = loop(Vec3(3, 0, 0), 1.0, Vec3::UnitX(), Vec3::UnitZ());
    // When
    const Surface3d s = revolve(profile, Axis{Vec3::Zero(), Vec3::UnitZ()}, 360.0);
    // Then
    EXPECT_LT(seamGap(s, true), kExact);
    EXPECT_LT(seamGap(s, false), kExact);
    EXPECT_GT(seamNormalDot(s, true), kSeamNormalDot);
    EXPECT_GT(seamNormalDot(s, false), kSeamNormalDot);
}

TEST(ClosedInput, GivenClosedProfileOrPath_WhenExtruded_ThenClosedAlongTheSeam)
{
    const Curve3d profile = loop(Vec3::Zero(), 1.0, Vec3::UnitX(), Vec3::UnitY());
    const Surface3d straight = extrude(profile, Vec3(0.2, 0, 2));
    EXPECT_LT(seamGap(straight, true), kExact);
    EXPECT_GT(seamNormalDot(straight, true), kSeamNormalDot);

    const Curve3d open = cubic({{0, 0, 0}, {0.5, 0.3, 0.2}, {1, 0, 0.5}, {1.5, 0.2, 0.4}});
    const Surface3d alongOpen = extrude(profile, open);
    EXPECT_LT(seamGap(alongOpen, true), kExact);

    const Curve3d closedPath = loop(Vec3::Zero(), 2.0, Vec3::UnitY(), Vec3::UnitZ());
    const Surface3d alongClosed = extrude(cubic({{0, 0, 0}, {0.3, 0.2, 0}, {0.6, 0, 0}, {1, 0.1, 0}}), closedPath);
    EXPECT_LT(seamGap(alongClosed, false), kExact);
}

TEST(ClosedInput, GivenClosedProfileAlongClosedNonPlanarPath_WhenSwept_ThenTubeClosesAtBothSeams)
{
    constexpr double kTube = 0.2;
    // Given: a twisted closed path (no symmetry that would cancel its torsion), along which the rotation-minimizing frame comes back
    // turned (holonomy), and a circle in its normal plane at the start.
    std::vector<Vec3> pts;
    for (int k = 0; k < 12; ++k) {
        const double t = 2 * kPi * k / 12;
        pts.emplace_back(2 * std::cos(t), 2 * std::sin(t) + 0.3 * std::cos(2 * t), 0.6 * std::sin(2 * t) + 0.3 * std::sin(3 * t));
    }
    const Curve3d path = makeClosedUniform<3>(3, pts);
    const Vec3 t0 = unitTangent(path, path.domainStart());
    const Vec3 n0 = t0.unitOrthogonal();
    // (The tube's radius is below the path's smallest radius of curvature, so the distance from
    // the path measures it.)
    const Curve3d profile = fullCircle(path.evaluate(path.domainStart()), kTube, n0, t0.cross(n0));
    std::vector<double> params;
    for (int k = 0; k <= 1000; ++k) params.push_back(path.domainStart() + (path.domainEnd() - path.domainStart()) * k / 1000);
    const std::vector<Frame> rmf = rotationMinimizingFrames(path.clamped(), params, n0);
    const double holonomyDegrees = std::acos(std::clamp(rmf.front().normal.dot(rmf.back().normal), -1.0, 1.0)) * 180 / kPi;
    ASSERT_GT(holonomyDegrees, 1.0) << "the path must turn the plain frame, or the test proves nothing";

    // When
    const SweepResult r = sweep(profile, path, SweepOptions{1e-4, 2049});

    // Then: closed along the profile's seam and along the path's; a tube of radius kTube.
    EXPECT_LT(seamGap(r.surface, true), kExact);
    EXPECT_LT(seamGap(r.surface, false), kExact);
    EXPECT_GT(seamNormalDot(r.surface, false), kSeamNormalDot);
    EXPECT_LE(r.maxDeviation, 1e-4);
    const CurveProjector<3> onPath(path);
    for (int j = 0; j <= 120; ++j)
        for (int i = 0; i <= 16; ++i)
            EXPECT_NEAR(onPath.project(r.surface.evaluate(i / 16.0, j / 120.0)).distance, kTube, 1e-4 + kExact);
}

TEST(ClosedInput, GivenClosedSectionsWithSeamsApartAndOneReversed_WhenLofted_ThenClosedTubeWithoutTwist)
{
    // Given: three closed loops up the z axis, the second drawn backwards, the third with its seam
    // a quarter turn on.
    const std::vector<Curve3d> sections{loop(Vec3(0, 0, 0), 1.0, Vec3::UnitX(), Vec3::UnitY()),
                                        loop(Vec3(0, 0, 1), 1.4, Vec3::UnitX(), Vec3::UnitY(), 0, true),
                                        loop(Vec3(0, 0, 2), 0.8, Vec3::UnitX(), Vec3::UnitY(), 2)};
    // When
    const Surface3d s = loft(sections);
    // Then: closed along the seam; each iso-curve u = const runs up at one angle about z (no twist:
    // the sections' seams were lined up and the backwards one turned); no fold.
    EXPECT_LT(seamGap(s, true), kExact);
    EXPECT_GT(seamNormalDot(s, true), kSeamNormalDot);
    for (int i = 0; i <= 20; ++i) {
        const double u = i / 20.0;
        const double a0 = std::atan2(s.evaluate(u, 0.0).y(), s.evaluate(u, 0.0).x());
        for (double v : {0.5, 1.0}) {
            const Vec3 p = s.evaluate(u, v);
            const double turn = std::remainder(std::atan2(p.y(), p.x()) - a0, 2 * kPi);
            EXPECT_LT(std::abs(turn), kPi / 8) << "u = " << u << ", v = " << v;
        }
    }
    EXPECT_GT(minNeighbourNormalDot(s), 0.0);
    // And: dragging the middle loop (its plane lifted) keeps the seams lined up.
    LoftBuilder builder(sections);
    std::vector<Vec3> lifted = sections[1].points();
    for (Vec3& p : lifted) p.z() += 0.2;
    const Surface3d& moved = builder.update(1, Curve3d(3, sections[1].knots(), lifted, {}, true));
    EXPECT_LT(seamGap(moved, true), kExact);
}

TEST(ClosedInput, GivenPeriodicRails_WhenRailRotated_ThenClosedAroundTheAxis)
{
    // Given: two periodic (non-rational) rails around the z axis and a profile between them.
    const Curve3d r1 = loop(Vec3(0, 0, 0), 2.0, Vec3::UnitX(), Vec3::UnitY());
    const Curve3d r2 = loop(Vec3(0, 0, 3), 1.2, Vec3::UnitX(), Vec3::UnitY());
    const Vec3 p0 = r1.evaluate(r1.domainStart()), q0 = r2.evaluate(r2.domainStart());
    const Curve3d profile = cubic({p0, p0 + Vec3(0.4, 0, 1), q0 + Vec3(0.6, 0, -1), q0});
    // When
    const ApproximatedSurface r = railRotation(r1, r2, profile, {1e-4, 2049});
    // Then: the v seam closes (periodic in v) and the rails are followed within the deviation.
    EXPECT_LT(seamGap(r.surface, false), kExact);
    EXPECT_GT(seamNormalDot(r.surface, false), kSeamNormalDot);
    EXPECT_LE(r.maxDeviation, 1e-4);
    const CurveProjector<3> on1(r1), on2(r2);
    for (int j = 0; j <= 100; ++j) {
        EXPECT_LT(on1.project(r.surface.evaluate(0.0, j / 100.0)).distance, 1e-4 + kExact);
        EXPECT_LT(on2.project(r.surface.evaluate(1.0, j / 100.0)).distance, 1e-4 + kExact);
    }
}
