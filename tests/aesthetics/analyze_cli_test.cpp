// sculptline-cli analyze, run as the real binary (../shared/interfaces.md): the same analysis as the
// library, the JSON fields of the contract, and clear refusals. Given / When / Then.
#include "solvers/aesthetics/curve_analysis.h"
#include "tests/cli/cli_runner.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace sculptline::cli_test;
namespace aes = sculptline::solvers::aesthetics;
using sculptline::solvers::Curve3d;

namespace {

const std::string kPrefix = "sculptline-cli: ";

// The exact ellipse x = 3 cos t, y = 2 sin t, closed rational quadratic, lying in the plane z = 5.
json ellipseJson()
{
    const double w = std::sqrt(0.5);
    const double unit[8][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
    json pts = json::array(), weights = json::array();
    for (int i = 0; i < 10; ++i) {
        pts.push_back({3 * unit[i % 8][0], 2 * unit[i % 8][1], 5.0});
        weights.push_back(i % 2 ? w : 1.0);
    }
    return {{"degree", 2},
            {"knots", {-0.25, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1.25, 1.25}},
            {"points", pts},
            {"weights", weights},
            {"closed", true}};
}

json sCurveJson()
{
    return {{"degree", 3},
            {"knots", {0, 0, 0, 0, 0.5, 1, 1, 1, 1}},
            {"points", {{0, 0, 0}, {1, 1, 0}, {2, -1, 0}, {3, 1, 0}, {4, 0, 0}}}};
}

TEST(AnalyzeCli, GivenAnEllipse_WhenAnalyzed_ThenItsNameVerticesAndMeasuresAreTheLibrarys)
{
    // Arrange
    const json input{{"curve", ellipseJson()}};
    // Act
    const json out = runOk("analyze", input);
    // Assert: the library on the same curve, flattened the same way.
    const auto lib = aes::analyzeCurve(aes::planarCurve(sculptline::solvers::io::curveFromJson(input["curve"], "curve")));
    EXPECT_EQ(out["name"], "M+m+M+m+");
    EXPECT_EQ(out["name"], lib.name);
    ASSERT_EQ(out["points"].size(), 4u);
    constexpr double kExact = 1e-9;  // the CLI prints shortest round-trip numbers: the library's to round-off
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(out["points"][i]["u"].get<double>(), 0.25 * i, kExact);
        EXPECT_EQ(out["points"][i]["kind"], i % 2 ? "m+" : "M+");
        EXPECT_NEAR(out["points"][i]["curvature"].get<double>(), i % 2 ? 2.0 / 9.0 : 3.0 / 4.0, kExact);
    }
    EXPECT_EQ(out["characteristics"].size(), 4u);
    EXPECT_TRUE(out["closed"].get<bool>());
    EXPECT_NEAR(out["measures"]["sharpness"].get<double>(), 0.75, kExact);
    EXPECT_NEAR(out["measures"]["tension"].get<double>(), *lib.measures.tension, kExact);
    EXPECT_NEAR(out["measures"]["flatness"].get<double>(), lib.measures.flatness, kExact);
    EXPECT_NEAR(out["thresholds"]["distance"].get<double>(), 0.05 * lib.length, kExact);
}

TEST(AnalyzeCli, GivenAnSCurveWithThresholds_WhenAnalyzed_ThenInflectionsNamedAndThresholdsUsed)
{
    // Arrange
    const json input{{"curve", sCurveJson()}, {"thresholds", {{"distance", 0.25}, {"curvature", 0.5}, {"sharp", 4.0}}}};
    // Act
    const json out = runOk("analyze", input);
    // Assert: m- 0 M+ 0 m- (the control polygon zig-zags down, up, down).
    EXPECT_EQ(out["name"], "m-0M+0m-");
    // The tangent turns from 45 degrees (the first leg) to -45 (the last): kappa_avg L = -pi / 2.
    EXPECT_NEAR(out["measures"]["curvature_average"].get<double>() * out["length"].get<double>(), -std::acos(0.0), 1e-12);
    EXPECT_EQ(out["thresholds"]["distance"], 0.25);
    EXPECT_EQ(out["thresholds"]["sharp"], 4.0);
    // The middle maximum is symmetric (the polygon is symmetric about x = 2).
    ASSERT_EQ(out["characteristics"].size(), 3u);
    EXPECT_TRUE(out["characteristics"][1]["symmetric"].get<bool>());
    EXPECT_NEAR(out["characteristics"][1]["u"].get<double>(), 0.5, 1e-12);
}

TEST(AnalyzeCli, GivenImpossibleInput_WhenAnalyzed_ThenExitTwoWithOneLineNamingTheField)
{
    struct Case {
        json input;
        std::string field;
    };
    json nonPlanar = sCurveJson();
    nonPlanar["points"][2] = {2, -1, 3};
    json line{{"degree", 1}, {"knots", {0, 0, 1, 1}}, {"points", {{0, 0, 0}, {1, 1, 0}}}};
    const Case cases[] = {
        {{{"curve", nonPlanar}}, "curve: not planar"},
        {{{"curve", line}}, "curve.degree"},
        {{{"curve", sCurveJson()}, {"thresholds", {{"distance", -1}}}}, "thresholds.distance"},
        {{{"curve", sCurveJson()}, {"thresholds", {{"sharp", "x"}}}}, "thresholds.sharp"},
        {{{"curve", sCurveJson()}, {"thresholds", {{"gamma", 1}}}}, "thresholds.gamma"},
        {{{"curve", sCurveJson()}, {"thresholds", 3}}, "thresholds"},
        {json::object(), "curve: missing"},
    };
    for (const Case& c : cases) {
        // Act
        const CliResult r = runCli({"analyze"}, c.input.dump());
        // Assert
        EXPECT_EQ(r.status, 2) << c.input.dump();
        EXPECT_EQ(r.err.rfind(kPrefix + c.field, 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
}

}  // namespace
