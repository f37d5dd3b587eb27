// Degenerate input through the shared entry point (surface_modes.h), which the CLI and the GUI's
// model both use: every mode refuses it with a std::invalid_argument whose message names the input
// and says why, or (tolerances below double precision) clamps it and reports what it used; it
// never crashes, hangs or returns a surface with a non-finite number.
#include "solvers/bspline/geometry_error.h"
#include "solvers/surfaces/approximation_tolerance.h"
#include "solvers/surfaces/surface_modes.h"
#include "surface_checks.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>

using namespace sculptline::solvers;
using namespace sculptline::solvers::surfaces;
using namespace sculptline::surfaces_test;

namespace {

const Curve3d& profile()
{
    static const Curve3d c = cubic({{1, 0, 0}, {1.5, 0, 1}, {0.8, 0, 2}, {1, 0, 3}});
    return c;
}

// All control points at one place: a curve that is a point.
Curve3d collapsed() { return cubic({{2, 3, 4}, {2, 3, 4}, {2, 3, 4}, {2, 3, 4}}); }

// Valid curves for each mode, in its order (as surface_modes_test.cpp).
std::vector<Curve3d> curvesFor(SurfaceMode mode)
{
    switch (mode) {
    case SurfaceMode::Fill:
        return {cubic({{0, 0, 0}, {1, 0, 0.5}, {2, 0, 0}, {3, 0, 0}}), cubic({{3, 0, 0}, {3, 1, 0.2}, {3, 2, 0}, {3, 3, 0}}),
                cubic({{3, 3, 0}, {2, 3, -0.3}, {1, 3, 0}, {0, 3, 0}}), cubic({{0, 3, 0}, {0, 2, 0.4}, {0, 1, 0}, {0, 0, 0}})};
    case SurfaceMode::Revolve:
    case SurfaceMode::Extrude: return {profile()};
    case SurfaceMode::Sweep:
        return {fullCircle(Vec3::Zero(), 0.2, Vec3::UnitY(), Vec3::UnitZ()),
                cubic({{0, 0, 0}, {1, 0, 0}, {2, 1, 0.5}, {3, 1, 1}})};
    case SurfaceMode::Loft: return {profile(), cubic({{2, 1, 0}, {2.5, 1, 1}, {1.8, 1, 2}, {2, 1, 3}})};
    case SurfaceMode::BoundaryRotation: return {profile(), cubic({{-1, 0, 0}, {-1.2, 0, 1}, {-0.9, 0, 2}, {-1, 0, 3}})};
    case SurfaceMode::RailRotation:
        return {fullCircle(Vec3::Zero(), 1.0, Vec3::UnitX(), Vec3::UnitY()),
                fullCircle(Vec3(0, 0, 3), 1.0, Vec3::UnitX(), Vec3::UnitY()), profile()};
    }
    return {};
}

SurfaceOptions optionsFor(SurfaceMode mode)
{
    SurfaceOptions o;
    if (mode == SurfaceMode::Extrude) o.direction = Vec3(0, 2, 0);
    return o;
}

// The message of the std::invalid_argument that building throws ("" if it does not throw).
std::string refusal(SurfaceMode mode, const std::vector<Curve3d>& curves, const SurfaceOptions& options)
{
    try {
        buildSurface(mode, curves, options);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

}  // namespace

TEST(DegenerateInput, GivenACollapsedCurveInEachPositionOfEveryMode_WhenBuilt_ThenRefusedNamingThatCurve)
{
    for (SurfaceMode mode : kModes) {
        const std::vector<Curve3d> good = curvesFor(mode);
        for (size_t k = 0; k < good.size(); ++k) {
            // Arrange: one curve replaced by a point.
            std::vector<Curve3d> curves = good;
            curves[k] = collapsed();

            // Act
            const std::string message = refusal(mode, curves, optionsFor(mode));

            // Assert
            const std::string expected = "curves[" + std::to_string(k) + "]: degenerate, all control points coincide";
            EXPECT_EQ(message, expected) << surfaceModeName(mode);
        }
    }
}

TEST(DegenerateInput, GivenAProfileCollapsedToRoundOff_WhenExtruded_ThenRefusedAsDegenerate)
{
    // Control points 1e-14 apart at magnitude 1e3: a point to double precision (17 ulps).
    const Curve3d dust = cubic({{1e3, 1e3, 0}, {1e3 + 1e-11, 1e3, 0}, {1e3, 1e3 + 1e-11, 0}, {1e3, 1e3, 1e-11}});
    SurfaceOptions o;
    o.direction = Vec3(0, 0, 1);
    EXPECT_EQ(refusal(SurfaceMode::Extrude, {dust}, o), "curves[0]: degenerate, all control points coincide");
}

TEST(DegenerateInput, GivenTheSameCurveFourTimes_WhenFilled_ThenRefusedAsRepeatedBoundary)
{
    const Curve3d c = cubic({{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0}});
    const std::string message = refusal(SurfaceMode::Fill, {c, c, c, c}, {});
    EXPECT_TRUE(startsWith(message, "curves[1]: the same curve as curves[0]")) << message;
}

TEST(DegenerateInput, GivenACurveAndItsReverse_WhenFilled_ThenRefusedAsRepeatedBoundary)
{
    const Curve3d c = cubic({{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0}});
    const Curve3d reversed = cubic({{3, 0, 0}, {2, 1, 0}, {1, 1, 0}, {0, 0, 0}});
    const std::string message = refusal(SurfaceMode::Fill, {c, reversed}, {});
    EXPECT_TRUE(startsWith(message, "curves[1]: the same curve as curves[0]")) << message;
}

TEST(DegenerateInput, GivenBoundariesThatDoNotMeet_WhenFilled_ThenRefusedNamingTheCurves)
{
    const std::vector<Curve3d> apart{cubic({{0, 0, 0}, {0.3, 0, 0}, {0.6, 0, 0}, {1, 0, 0}}),
                                     cubic({{5, 0, 0}, {5, 0.3, 0}, {5, 0.6, 0}, {5, 1, 0}}),
                                     cubic({{0, 7, 0}, {0.3, 7, 0}, {0.6, 7, 0}, {1, 9, 0}})};
    const std::string message = refusal(SurfaceMode::Fill, apart, {});
    EXPECT_TRUE(startsWith(message, "curves")) << message;
    EXPECT_NE(message.find("do not meet"), std::string::npos) << message;
}

TEST(DegenerateInput, GivenAnAxisFromAClosedCurve_WhenRevolved_ThenRefusedNamingTheAxis)
{
    // The GUI's revolve axis runs from the axis curve's start to its end: a closed curve gives none.
    const Curve3d loop = fullCircle(Vec3(0, 0, 1), 1.0, Vec3::UnitX(), Vec3::UnitY());
    SurfaceOptions o;
    o.axisPoint = loop.evaluate(loop.domainStart());
    o.axisDirection = loop.evaluate(loop.domainEnd()) - o.axisPoint;
    const std::string message = refusal(SurfaceMode::Revolve, {profile()}, o);
    EXPECT_TRUE(startsWith(message, "axis: ")) << message;
}

TEST(DegenerateInput, GivenAnAxisDirectionOfLength1e300_WhenRevolved_ThenTheSameSurfaceAsAUnitDirection)
{
    // Arrange: a direction is a direction whatever its length; 1e300 squared overflows.
    SurfaceOptions unit;
    unit.axisDirection = Vec3::UnitZ();
    SurfaceOptions huge;
    huge.axisDirection = Vec3(0, 0, 1e300);

    // Act
    const Surface3d expected = buildSurface(SurfaceMode::Revolve, {profile()}, unit).surface;
    const Surface3d actual = buildSurface(SurfaceMode::Revolve, {profile()}, huge).surface;

    // Assert
    ASSERT_EQ(actual.points().size(), expected.points().size());
    for (size_t i = 0; i < actual.points().size(); ++i)
        EXPECT_LT((actual.points()[i] - expected.points()[i]).norm(), kExact) << i;
}

TEST(DegenerateInput, GivenAnExtrudeDirectionOfZeroLength_WhenExtruded_ThenRefusedNamingTheDirection)
{
    SurfaceOptions o;
    o.direction = Vec3::Zero();
    EXPECT_EQ(refusal(SurfaceMode::Extrude, {profile()}, o), "direction: zero length, nothing to extrude");
}

TEST(DegenerateInput, GivenAnExtrudeDirectionOfLength1eMinus300_WhenExtruded_ThenRefusedNamingTheDirection)
{
    SurfaceOptions o;
    o.direction = Vec3(0, 1e-300, 0);
    const std::string message = refusal(SurfaceMode::Extrude, {profile()}, o);
    EXPECT_TRUE(startsWith(message, "direction: ")) << message;
}

TEST(DegenerateInput, GivenAnExtrudeDirectionOfLength1e300_WhenExtruded_ThenRefusedNamingTheDirection)
{
    // The profile (size ~3) is below the round-off of coordinates of 1e300.
    SurfaceOptions o;
    o.direction = Vec3(0, 1e300, 0);
    const std::string message = refusal(SurfaceMode::Extrude, {profile()}, o);
    EXPECT_TRUE(startsWith(message, "direction: length 1e+300")) << message;
}

TEST(DegenerateInput, GivenRailsThatAreNotClosed_WhenRailRotated_ThenRefusedNamingTheRail)
{
    const std::vector<Curve3d> curves{cubic({{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}}),
                                      cubic({{1, 0, 3}, {0, 1, 3}, {-1, 0, 3}, {0, -1, 3}}), profile()};
    const std::string message = refusal(SurfaceMode::RailRotation, curves, {});
    EXPECT_TRUE(startsWith(message, "curves[0]: ")) << message;
    EXPECT_NE(message.find("not closed"), std::string::npos) << message;
}

TEST(DegenerateInput, GivenIdenticalOutlines_WhenBoundaryRotated_ThenRefusedSayingTheyCoincide)
{
    const std::string message = refusal(SurfaceMode::BoundaryRotation, {profile(), profile()}, {});
    EXPECT_TRUE(startsWith(message, "curves: ")) << message;
    EXPECT_NE(message.find("coincide"), std::string::npos) << message;
}

TEST(DegenerateInput, GivenANonFiniteOption_WhenBuilt_ThenRefusedNamingTheOption)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    struct Case {
        SurfaceMode mode;
        SurfaceOptions options;
        std::string field;
    };
    std::vector<Case> cases;
    for (SurfaceMode mode : {SurfaceMode::Sweep, SurfaceMode::BoundaryRotation, SurfaceMode::RailRotation, SurfaceMode::Fill}) {
        SurfaceOptions o = optionsFor(mode);
        o.tolerance = nan;
        cases.push_back({mode, o, "tolerance"});
    }
    SurfaceOptions axis;
    axis.axisPoint = Vec3(inf, 0, 0);
    cases.push_back({SurfaceMode::Revolve, axis, "axis"});
    SurfaceOptions angle;
    angle.angleDegrees = nan;
    cases.push_back({SurfaceMode::Revolve, angle, "angle"});
    SurfaceOptions direction;
    direction.direction = Vec3(0, nan, 0);
    cases.push_back({SurfaceMode::Extrude, direction, "direction"});
    for (const Case& c : cases) {
        const std::string message = refusal(c.mode, curvesFor(c.mode), c.options);
        EXPECT_EQ(message, c.field + ": not a finite number") << surfaceModeName(c.mode);
    }
}

TEST(DegenerateInput, GivenTolerance1eMinus300_WhenEachApproximatingModeBuilds_ThenTheToleranceIsClampedAndReported)
{
    for (SurfaceMode mode : {SurfaceMode::Sweep, SurfaceMode::BoundaryRotation, SurfaceMode::RailRotation}) {
        // Arrange: far below what double precision can measure on coordinates of size ~3.
        SurfaceOptions o;
        o.tolerance = 1e-300;
        const std::vector<Curve3d> curves = curvesFor(mode);

        // Act
        const SurfaceBuild b = buildSurface(mode, curves, o);

        // Assert: the floor of approximation_tolerance.h is used and reported, and met.
        EXPECT_GE(b.tolerance, kMinApproximationRelative * 1.0) << surfaceModeName(mode);
        EXPECT_LE(b.maxDeviation, b.tolerance) << surfaceModeName(mode);
    }
}

TEST(DegenerateInput, GivenCurvesThatDoNotCross_WhenGordonBuilt_ThenRefusedNamingTheCurves)
{
    const std::vector<Curve3d> u{cubic({{0, 0, 0}, {0.3, 0, 0}, {0.6, 0, 0}, {1, 0, 0}}),
                                 cubic({{0, 1, 0}, {0.3, 1, 0}, {0.6, 1, 0}, {1, 1, 0}})};
    const std::vector<Curve3d> v{cubic({{5, 5, 5}, {5, 5.3, 5}, {5, 5.6, 5}, {5, 6, 5}}),
                                 cubic({{6, 5, 5}, {6, 5.3, 5}, {6, 5.6, 5}, {6, 6, 5}})};
    try {
        buildGordon(u, v);
        FAIL() << "built a Gordon surface from curves that do not cross";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("do not intersect"), std::string::npos) << e.what();
    }
}

TEST(DegenerateInput, GivenACollapsedCurveInEitherFamily_WhenGordonBuilt_ThenRefusedNamingThatCurve)
{
    const std::vector<Curve3d> u{cubic({{0, 0, 0}, {0.3, 0, 0}, {0.6, 0, 0}, {1, 0, 0}}),
                                 cubic({{0, 1, 0}, {0.3, 1, 0}, {0.6, 1, 0}, {1, 1, 0}})};
    const std::vector<Curve3d> v{cubic({{0, 0, 0}, {0, 0.3, 0}, {0, 0.6, 0}, {0, 1, 0}}),
                                 cubic({{1, 0, 0}, {1, 0.3, 0}, {1, 0.6, 0}, {1, 1, 0}})};
    const auto message = [](const std::vector<Curve3d>& a, const std::vector<Curve3d>& b) -> std::string {
        try {
            buildGordon(a, b);
        } catch (const std::invalid_argument& e) {
            return e.what();
        }
        return "";
    };
    EXPECT_EQ(message({u[0], collapsed()}, v), "curves[1]: degenerate, all control points coincide");
    EXPECT_EQ(message(u, {collapsed(), v[1]}), "v_curves[0]: degenerate, all control points coincide");
}

TEST(DegenerateInput, GivenARevolveWhoseCoordinatesOverflow_WhenBuilt_ThenRefusedInsteadOfReturningInfinity)
{
    // Arrange: a profile near the largest double, 1.5e308 from the axis: the circle's corner
    // control points (radius times (1, 1)) and the squared radius are not doubles.
    const Curve3d far = cubic({{1.5e308, 0, 0}, {1.5e308, 0, 1e307}, {1.5e308, 0, 2e307}, {1.5e308, 0, 3e307}});
    SurfaceOptions o;
    o.axisDirection = Vec3::UnitZ();

    // Act
    const std::string message = refusal(SurfaceMode::Revolve, {far}, o);

    // Assert: named as the result's overflow, not as an input field ("axis", "points[0]").
    EXPECT_EQ(message, "surface: the construction overflows double precision (coordinates too large)");
}
