// The shared entry point of the CLI and the GUI: mode names round-trip, every mode builds through
// buildSurface and meets its first curve, impossible input is refused naming the input, and the
// incremental SurfaceBuilder follows moved curves like a fresh build.
#include "solvers/bspline/geometry_error.h"
#include "solvers/surfaces/surface_modes.h"
#include "surface_checks.h"

#include <gtest/gtest.h>

#include <string>

using namespace sculptline::solvers;
using namespace sculptline::solvers::surfaces;
using namespace sculptline::surfaces_test;

namespace {

// Curves for each mode, in its order.
std::vector<Curve3d> curvesFor(SurfaceMode mode)
{
    const Curve3d profile = cubic({{1, 0, 0}, {1.5, 0, 1}, {0.8, 0, 2}, {1, 0, 3}});
    switch (mode) {
    case SurfaceMode::Fill:
        return {cubic({{0, 0, 0}, {1, 0, 0.5}, {2, 0, 0}, {3, 0, 0}}), cubic({{3, 0, 0}, {3, 1, 0.2}, {3, 2, 0}, {3, 3, 0}}),
                cubic({{3, 3, 0}, {2, 3, -0.3}, {1, 3, 0}, {0, 3, 0}}), cubic({{0, 3, 0}, {0, 2, 0.4}, {0, 1, 0}, {0, 0, 0}})};
    case SurfaceMode::Revolve:
    case SurfaceMode::Extrude: return {profile};
    case SurfaceMode::Sweep:
        return {fullCircle(Vec3::Zero(), 0.2, Vec3::UnitY(), Vec3::UnitZ()),
                cubic({{0, 0, 0}, {1, 0, 0}, {2, 1, 0.5}, {3, 1, 1}})};
    case SurfaceMode::Loft: return {profile, cubic({{2, 1, 0}, {2.5, 1, 1}, {1.8, 1, 2}, {2, 1, 3}})};
    case SurfaceMode::BoundaryRotation: return {profile, cubic({{-1, 0, 0}, {-1.2, 0, 1}, {-0.9, 0, 2}, {-1, 0, 3}})};
    case SurfaceMode::RailRotation:
        return {fullCircle(Vec3::Zero(), 1.0, Vec3::UnitX(), Vec3::UnitY()),
                fullCircle(Vec3(0, 0, 3), 1.0, Vec3::UnitX(), Vec3::UnitY()), profile};
    }
    return {};
}

SurfaceOptions optionsFor(SurfaceMode mode)
{
    SurfaceOptions o;
    if (mode == SurfaceMode::Extrude) o.direction = Vec3(0, 2, 0);
    if (mode == SurfaceMode::Sweep || mode == SurfaceMode::BoundaryRotation || mode == SurfaceMode::RailRotation)
        o.tolerance = 1e-4;
    return o;
}

std::string messageOf(SurfaceMode mode, const std::vector<Curve3d>& curves, const SurfaceOptions& o = {})
{
    try {
        buildSurface(mode, curves, o);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST(SurfaceModes, GivenEveryMode_WhenNamedAndParsed_ThenRoundTripsAndUnknownNamesAreRefused)
{
    for (SurfaceMode m : kModes) EXPECT_EQ(parseSurfaceMode(surfaceModeName(m)), m);
    EXPECT_EQ(std::string(surfaceModeName(SurfaceMode::BoundaryRotation)), "boundary-rotation");
    EXPECT_THROW(parseSurfaceMode("spin"), std::invalid_argument);
}

TEST(SurfaceModes, GivenEveryMode_WhenBuilt_ThenTheFirstCurveIsMetAndNormalsAreConsistent)
{
    for (SurfaceMode m : kModes) {
        // Given
        const std::vector<Curve3d> c = curvesFor(m);
        const SurfaceOptions o = optionsFor(m);
        // When
        const SurfaceBuild b = buildSurface(m, c, o);
        // Then: exact modes meet their first curve to round-off (fill: side v = 0; rail rotation:
        // its profile is the first section), approximating ones report a deviation within tolerance.
        const Curve3d& first = m == SurfaceMode::RailRotation ? c[2] : c[0];
        const bool approximating = b.maxDeviation >= 0.0;
        EXPECT_EQ(approximating, m == SurfaceMode::Sweep || m == SurfaceMode::BoundaryRotation || m == SurfaceMode::RailRotation)
            << surfaceModeName(m);
        if (approximating) {
            EXPECT_LE(b.maxDeviation, b.tolerance) << surfaceModeName(m);
        }
        EXPECT_LT(isoDeviation(b.surface, true, b.surface.domainStart(Direction::V), first), kExact) << surfaceModeName(m);
        EXPECT_GT(minNeighbourNormalDot(b.surface), 0.0) << surfaceModeName(m);
    }
}

TEST(SurfaceModes, GivenImpossibleInput_WhenBuilt_ThenRefusedNamingTheInput)
{
    const Curve3d line = cubic({{1, 0, 0}, {1, 0, 1}, {1, 0, 2}, {1, 0, 3}});
    EXPECT_EQ(messageOf(SurfaceMode::Revolve, {}).rfind("curves: mode needs one profile curve, got 0", 0), 0u);
    EXPECT_EQ(messageOf(SurfaceMode::Loft, {line}).rfind("curves: a loft needs at least two sections", 0), 0u);
    EXPECT_EQ(messageOf(SurfaceMode::Fill, {line, cubic({{5, 0, 0}, {6, 0, 0}, {7, 0, 0}, {8, 0, 0}})}).rfind("curves:", 0), 0u);
    const Curve3d cusp = cubic({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 0, 0}});
    EXPECT_EQ(messageOf(SurfaceMode::Sweep, {line, cusp}).rfind("curves[1] (path): cusp", 0), 0u) << messageOf(SurfaceMode::Sweep, {line, cusp});
    SurfaceOptions noAxis;
    noAxis.axisDirection = Vec3::Zero();
    EXPECT_EQ(messageOf(SurfaceMode::Revolve, {line}, noAxis).rfind("axis:", 0), 0u);
    EXPECT_EQ(messageOf(SurfaceMode::Extrude, {line}).rfind("direction:", 0), 0u);  // default direction: none
}

TEST(SurfaceBuilder, GivenEveryMode_WhenACurveMovesAndTheDragEnds_ThenUpdateFollowsAndResetEqualsBuildSurface)
{
    for (SurfaceMode m : kModes) {
        // Given
        std::vector<Curve3d> c = curvesFor(m);
        const SurfaceOptions o = optionsFor(m);
        SurfaceBuilder builder(m, c, o);

        // When: the last curve moves by 0.05 in z (a plane drag moves its curves rigidly); for
        // fill and rail rotation, whose curves must keep meeting, every curve moves with it.
        const Vec3 shift(0, 0, 0.05);
        const auto moved = [&](const Curve3d& x) {
            std::vector<Vec3> p = x.points();
            for (Vec3& q : p) q += shift;
            return Curve3d(x.degree(), x.knots(), p, x.weights(), x.isClosed());
        };
        if (m == SurfaceMode::Fill || m == SurfaceMode::RailRotation)
            for (Curve3d& x : c) x = moved(x);
        else
            c.back() = moved(c.back());
        const SurfaceBuild& updated = builder.update(c);

        // Then: the moved curves are met (as a fresh build meets them), and reset gives exactly
        // the fresh build.
        const SurfaceBuild fresh = buildSurface(m, c, o);
        const Curve3d& first = m == SurfaceMode::RailRotation ? c[2] : c[0];
        EXPECT_LT(isoDeviation(updated.surface, true, updated.surface.domainStart(Direction::V), first), kExact)
            << surfaceModeName(m);
        if (updated.maxDeviation >= 0.0) {
            EXPECT_LE(updated.maxDeviation, updated.tolerance) << surfaceModeName(m);
        }
        const SurfaceBuild& after = builder.reset(c);
        double gap = 0.0;
        for (double u : {0.0, 0.3, 0.7, 1.0})
            for (double v : {0.0, 0.4, 1.0}) {
                const auto at = [&](const Surface3d& s) {
                    return s.evaluate(s.domainStart(Direction::U) + u * (s.domainEnd(Direction::U) - s.domainStart(Direction::U)),
                                      s.domainStart(Direction::V) + v * (s.domainEnd(Direction::V) - s.domainStart(Direction::V)));
                };
                gap = std::max(gap, (at(after.surface) - at(fresh.surface)).norm());
            }
        EXPECT_LT(gap, kExact) << surfaceModeName(m);
    }
}

TEST(SurfaceBuilder, GivenAnUpdateThatCannotBeBuilt_WhenUpdated_ThenThrowsAndKeepsTheLastGoodSurface)
{
    // Given: a fill, a sweep and a revolution built from good curves.
    for (SurfaceMode m : {SurfaceMode::Fill, SurfaceMode::Sweep, SurfaceMode::Revolve}) {
        std::vector<Curve3d> c = curvesFor(m);
        SurfaceBuilder builder(m, c, optionsFor(m));
        const Vec3 before = builder.build().surface.evaluate(0.5, 0.5);
        // When: a boundary pulled away (fill), a path with a cusp (sweep), a point profile (revolve).
        if (m == SurfaceMode::Fill) c[1] = cubic({{5, 0, 0}, {5, 1, 0}, {5, 2, 0}, {5, 3, 0}});
        if (m == SurfaceMode::Sweep) c[1] = cubic({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 0, 0}});
        if (m == SurfaceMode::Revolve) c[0] = cubic({{1, 0, 1}, {1, 0, 1}, {1, 0, 1}, {1, 0, 1}});
        // Then
        EXPECT_THROW(builder.update(c), std::invalid_argument) << surfaceModeName(m);
        EXPECT_EQ(builder.build().surface.evaluate(0.5, 0.5), before) << surfaceModeName(m);
    }
}
