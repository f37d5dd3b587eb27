// sculptline-cli on degenerate input, run as the real binary: every case exits with status 2 and
// one line on stderr naming the field (../shared/interfaces.md, "Errors"), within the runner's time
// limit; tolerances below double precision are clamped and the tolerance used is reported.
#include "tests/cli/cli_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <string>
#include <vector>

using nlohmann::json;
using sculptline::cli_test::CliResult;

namespace {

json cubic(const std::vector<std::array<double, 3>>& pts, const json& knots = {0, 0, 0, 0, 1, 1, 1, 1})
{
    json points = json::array();
    for (const auto& q : pts) points.push_back({q[0], q[1], q[2]});
    return {{"degree", 3}, {"knots", knots}, {"points", points}};
}

// Cubic outlines of two Bezier pieces joined by a knot of multiplicity 4 = degree + 1 at 0.5: the
// pieces need not meet (here they do not: points 3 and 4 differ), the curve is C^-1.
json brokenCubic(double offset)
{
    const json knots = {0, 0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1, 1, 1};
    return cubic({{0, offset, 0}, {1, 0.5 + offset, 0}, {2, 1 + offset, 0}, {3, 0.5 + offset, 0},
                  {4, offset, 0}, {5, -0.5 + offset, 0}, {6, offset, 0}, {7, 0.5 + offset, 0}},
                 knots);
}

json line(std::array<double, 3> a, std::array<double, 3> b)
{
    std::vector<std::array<double, 3>> pts;
    for (int i = 0; i < 4; ++i)
        pts.push_back({a[0] + (b[0] - a[0]) * i / 3, a[1] + (b[1] - a[1]) * i / 3, a[2] + (b[2] - a[2]) * i / 3});
    return cubic(pts);
}

// The full stderr must be exactly one line starting with the program name and the field.
void expectRefused(const json& input, const std::string& fieldAndProblem)
{
    const CliResult r = sculptline::cli_test::runCli({"surface"}, input.dump());
    EXPECT_EQ(r.status, 2) << input.dump().substr(0, 200) << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("sculptline-cli: " + fieldAndProblem, 0), 0u) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not one line: " << r.err;
}

const json kProfile = cubic({{1, 0, 0}, {1.5, 0, 1}, {1.2, 0, 2}, {1, 0, 3}});
const json kPoint = cubic({{2, 3, 4}, {2, 3, 4}, {2, 3, 4}, {2, 3, 4}});

}  // namespace

TEST(DegenerateCli, GivenOutlinesWithAKnotOfMultiplicityDegreePlusOne_WhenBoundaryRotated_ThenExitTwoNamingTheKnots)
{
    // This input dereferenced an empty std::optional (segfault, out of memory or a hang by turns).
    expectRefused({{"mode", "boundary-rotation"}, {"curves", {brokenCubic(0), brokenCubic(3)}}},
                  "curves[0].knots: interior knot 0.5 has multiplicity 4");
}

TEST(DegenerateCli, GivenCurvesWithAKnotOfMultiplicityDegreePlusOne_WhenGordonBuilt_ThenExitTwoNamingTheKnots)
{
    const json v = {line({0, 0, 0}, {0, 3, 0}), line({7, 0.5, 0}, {7, 3.5, 0})};
    expectRefused({{"mode", "gordon"}, {"curves", {brokenCubic(0), brokenCubic(3)}}, {"v_curves", v}},
                  "curves[0].knots: interior knot 0.5 has multiplicity 4");
}

TEST(DegenerateCli, GivenACollapsedProfile_WhenEachModeRuns_ThenExitTwoNamingTheCurve)
{
    const json circle0 = {{"degree", 3},
                          {"closed", true},
                          {"knots", {-0.5, -1.0 / 3, -1.0 / 6, 0, 1.0 / 6, 1.0 / 3, 0.5, 2.0 / 3, 5.0 / 6, 1, 7.0 / 6, 4.0 / 3, 1.5}},
                          {"points", {{1, 0, 0}, {0.5, 0.866, 0}, {-0.5, 0.866, 0}, {-1, 0, 0}, {-0.5, -0.866, 0},
                                      {0.5, -0.866, 0}, {1, 0, 0}, {0.5, 0.866, 0}, {-0.5, 0.866, 0}}}};
    const std::vector<std::pair<json, std::string>> cases{
        {{{"mode", "revolve"}, {"curves", {kPoint}}, {"axis", {{"point", {0, 0, 0}}, {"direction", {0, 0, 1}}}}}, "curves[0]"},
        {{{"mode", "extrude"}, {"curves", {kPoint}}, {"direction", {0, 1, 0}}}, "curves[0]"},
        {{{"mode", "sweep"}, {"curves", {kPoint, line({0, 0, 0}, {0, 0, 3})}}}, "curves[0]"},
        {{{"mode", "loft"}, {"curves", {kProfile, kPoint}}}, "curves[1]"},
        {{{"mode", "boundary-rotation"}, {"curves", {kProfile, kPoint}}}, "curves[1]"},
        {{{"mode", "rail-rotation"}, {"curves", {circle0, circle0, kPoint}}}, "curves[2]"},
        {{{"mode", "fill"}, {"curves", {line({0, 0, 0}, {1, 0, 0}), line({1, 0, 0}, {0, 1, 0}), kPoint}}}, "curves[2]"},
        {{{"mode", "gordon"}, {"curves", {line({0, 0, 0}, {1, 0, 0}), kPoint}}, {"v_curves", {line({0, 0, 0}, {0, 1, 0}), line({1, 0, 0}, {1, 1, 0})}}},
         "curves[1]"},
    };
    for (const auto& [in, field] : cases) expectRefused(in, field + ": degenerate, all control points coincide");
}

TEST(DegenerateCli, GivenTheSameCurveFourTimes_WhenFilled_ThenExitTwoNamingTheRepeat)
{
    expectRefused({{"mode", "fill"}, {"curves", {kProfile, kProfile, kProfile, kProfile}}}, "curves[1]: the same curve as curves[0]");
}

TEST(DegenerateCli, GivenExtrudeDirectionsOfZeroTinyAndHugeLength_WhenRun_ThenExitTwoNamingTheDirection)
{
    for (double length : {0.0, 1e-300, 1e300})
        expectRefused({{"mode", "extrude"}, {"curves", {kProfile}}, {"direction", {0, length, 0}}}, "direction: ");
}

TEST(DegenerateCli, GivenRailRotationWithTolerance1eMinus300_WhenRun_ThenTheToleranceUsedIsClampedAndMet)
{
    // Arrange: rails are closed uniform cubics through 6 points of radius 1 (they pass through
    // radius 5/6 at angle 0: (P5 + 4 P0 + P1) / 6), the profile joins them there.
    const double c = 0.8660254037844386;
    const json knots = {-0.5, -1.0 / 3, -1.0 / 6, 0, 1.0 / 6, 1.0 / 3, 0.5, 2.0 / 3, 5.0 / 6, 1, 7.0 / 6, 4.0 / 3, 1.5};
    const auto rail = [&](double z) {
        const json p = {{1, 0, z}, {0.5, c, z}, {-0.5, c, z}, {-1, 0, z}, {-0.5, -c, z}, {0.5, -c, z}};
        json pts = p;
        for (int i = 0; i < 3; ++i) pts.push_back(p[i]);
        return json{{"degree", 3}, {"closed", true}, {"knots", knots}, {"points", pts}};
    };
    const json in = {{"mode", "rail-rotation"},
                     {"curves", {rail(0), rail(3), cubic({{5.0 / 6, 0, 0}, {0.9, 0, 1}, {0.9, 0, 2}, {5.0 / 6, 0, 3}})}},
                     {"tolerance", 1e-300}};

    // Act: it used to refine to 2046 sections and spin for seconds.
    const CliResult r = sculptline::cli_test::runCli({"surface"}, in.dump());

    // Assert: the floor of solvers/surfaces/approximation_tolerance.h (1e-10 of the coordinates'
    // scale, here about 3) is used, reported and met.
    ASSERT_EQ(r.status, 0) << r.err;
    const json out = json::parse(r.out);
    EXPECT_GE(out.at("tolerance").get<double>(), 1e-10);
    EXPECT_LE(out.at("max_deviation").get<double>(), out.at("tolerance").get<double>());
}

TEST(DegenerateCli, GivenACollapsedCurve_WhenOversketched_ThenExitTwoNamingTheCurve)
{
    json stroke = json::array();
    for (int i = 0; i < 30; ++i) stroke.push_back({1 + 0.1 * i, 2 + 0.05 * i});
    const json in = {{"curve", cubic({{1, 2, 0}, {1, 2, 0}, {1, 2, 0}, {1, 2, 0}})}, {"stroke", {{"points", stroke}}}};
    for (const char* method : {"local-c2", "blend"}) {
        json withMethod = in;
        withMethod["method"] = method;
        const CliResult r = sculptline::cli_test::runCli({"oversketch"}, withMethod.dump());
        EXPECT_EQ(r.status, 2) << method;
        EXPECT_EQ(r.err, "sculptline-cli: curve: degenerate, all control points coincide; nothing to over-sketch\n") << method;
    }
}
