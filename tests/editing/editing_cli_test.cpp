// sculptline-cli oversketch / lift / constrain-curve, run as the real binary (../shared/interfaces.md).
#include "solvers/io/geometry_json.h"

#include "tests/cli/cli_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

using nlohmann::json;
using namespace sculptline::solvers;

namespace {

using sculptline::cli_test::CliResult;

// The shared runner: no shell, a private scratch directory, so parallel ctest processes never
// share an input file.
CliResult runCli(const std::string& sub, const std::string& input)
{
    return sculptline::cli_test::runCli({sub}, input);
}

json wave()
{
    json pts = json::array();
    for (int i = 0; i < 12; ++i) pts.push_back({double(i), 2.0 * std::sin(0.4 * i)});
    json knots = {0, 0, 0, 0};
    for (int i = 1; i < 9; ++i) knots.push_back(i / 9.0);
    for (int i = 0; i < 4; ++i) knots.push_back(1);
    return {{"degree", 3}, {"knots", knots}, {"points", pts}};
}

json stroke()
{
    json pts = json::array();
    for (int t = 0; t <= 50; ++t) {
        const double x = 3.0 + 4.0 * t / 50.0;
        pts.push_back({x, 2.0 * std::sin(0.4 * x) + std::sin(M_PI * t / 50.0) + 0.3});
    }
    return {{"points", pts}};
}

}  // namespace

TEST(EditingCli, GivenOversketchInput_WhenRun_ThenCurveSpanAndElapsed)
{
    for (const char* method : {"local-c2", "blend"}) {
        const CliResult r = runCli("oversketch", json{{"curve", wave()}, {"stroke", stroke()}, {"method", method}}.dump());
        ASSERT_EQ(r.status, 0) << method;
        const json out = json::parse(r.out);
        const Curve3d c = io::curveFromJson(out["curve"], "curve");
        EXPECT_LT(out["span"][0].get<double>(), out["span"][1].get<double>());
        EXPECT_TRUE(out.contains("elapsed_ms"));
        EXPECT_EQ(out["method"], method);
        // The stroke's middle is on the new curve (within the fit tolerance of either method).
        const Eigen::Vector3d mid(5.0, 2.0 * std::sin(2.0) + 1.3, 0.0);
        double best = 1e9;
        for (int i = 0; i <= 2000; ++i) best = std::min(best, (c.evaluate(i / 2000.0) - mid).norm());
        EXPECT_LT(best, 0.1) << method;
    }
}

TEST(EditingCli, GivenLiftInput_WhenRun_ThenSpaceCurveWithEndDepths)
{
    json pts = json::array();
    for (int t = 0; t < 100; ++t) pts.push_back({10.0 * t / 99.0, 6.0 * std::sin(2.5 * t / 99.0)});
    const CliResult r = runCli("lift", json{{"stroke", {{"points", pts}}}, {"depth", {1.0, 6.0}}}.dump());
    ASSERT_EQ(r.status, 0);
    const Curve3d c = io::curveFromJson(json::parse(r.out)["curve"], "curve");
    EXPECT_NEAR(c.evaluate(c.domainStart()).z(), 1.0, 1e-9);
    EXPECT_NEAR(c.evaluate(c.domainEnd()).z(), 6.0, 1e-9);

    // A view looking along -x: depth maps to -x, the stroke's x to y and its y to z.
    const json view = {{"origin", {0, 0, 0}}, {"right", {0, 1, 0}}, {"up", {0, 0, 1}}, {"depth", {-1, 0, 0}}};
    const CliResult v = runCli("lift", json{{"stroke", {{"points", pts}}}, {"depth", {1.0, 6.0}}, {"view", view}}.dump());
    ASSERT_EQ(v.status, 0);
    const Curve3d cv = io::curveFromJson(json::parse(v.out)["curve"], "curve");
    EXPECT_LT((cv.evaluate(cv.domainEnd()) - Eigen::Vector3d(-6.0, 10.0, 6.0 * std::sin(2.5))).norm(), 1e-9);
}

TEST(EditingCli, GivenConstraints_WhenRun_ThenMetAndReported)
{
    const json in = {{"curve", wave()},
                     {"constraints",
                      {{{"type", "position"}, {"u", 0.4}, {"value", {4, 3}}},
                       {{"type", "distance"}, {"u", 0.6}, {"u2", 0.7}, {"value", 1.5}}}},
                     {"blocked", {0, 11}}};
    const CliResult r = runCli("constrain-curve", in.dump());
    ASSERT_EQ(r.status, 0);
    const json out = json::parse(r.out);
    const Curve3d c = io::curveFromJson(out["curve"], "curve");
    EXPECT_LT((c.evaluate(0.4) - Eigen::Vector3d(4, 3, 0)).norm(), 1e-9);
    EXPECT_NEAR((c.evaluate(0.7) - c.evaluate(0.6)).norm(), 1.5, 1e-9);
    EXPECT_LT(out["max_residual"].get<double>(), 1e-9);
    EXPECT_FALSE(out["compromise"].get<bool>());
}

TEST(EditingCli, GivenRationalCurve_WhenConstrainedAndOversketched_ThenWeightsKeptAndResultsValid)
{
    // Given the wave with weights 0.5 .. 2.1
    json curve = wave();
    json weights = json::array();
    for (int i = 0; i < 12; ++i) weights.push_back(1.3 + 0.8 * std::sin(1.3 * i));
    curve["weights"] = weights;

    // When constrained, Then the constraint holds on the rational result and the weights are kept
    const json in = {{"curve", curve}, {"constraints", {{{"type", "position"}, {"u", 0.4}, {"value", {4, 3}}}}}};
    const CliResult r = runCli("constrain-curve", in.dump());
    ASSERT_EQ(r.status, 0) << r.err;
    const Curve3d c = io::curveFromJson(json::parse(r.out)["curve"], "curve");
    ASSERT_TRUE(c.isRational());
    EXPECT_LT((c.evaluate(0.4) - Eigen::Vector3d(4, 3, 0)).norm(), 1e-9);
    for (int i = 0; i < 12; ++i) EXPECT_DOUBLE_EQ(c.weight(i), weights[i].get<double>());

    // When over-sketched by either method, Then a rational curve comes back
    for (const char* method : {"local-c2", "blend"}) {
        const CliResult o = runCli("oversketch", json{{"curve", curve}, {"stroke", stroke()}, {"method", method}}.dump());
        ASSERT_EQ(o.status, 0) << method << ": " << o.err;
        EXPECT_TRUE(io::curveFromJson(json::parse(o.out)["curve"], "curve").isRational()) << method;
    }
}

TEST(EditingCli, GivenInvalidInputs_WhenRun_ThenExitStatus2)
{
    const json bad[][2] = {
        {"constrain-curve", {{"curve", wave()}, {"constraints", {{{"type", "bogus"}, {"u", 0.4}, {"value", {4, 3}}}}}}},
        {"constrain-curve",
         {{"curve", wave()}, {"constraints", {{{"type", "position"}, {"u", 1.4}, {"value", {4, 3}}}}}}},
        {"constrain-curve", {{"curve", wave()}, {"constraints", json::array()}, {"blocked", {99}}}},
        {"oversketch", {{"curve", wave()}, {"stroke", {{"points", {{1, 1}}}}}}},
        {"oversketch", {{"curve", wave()}, {"stroke", stroke()}, {"method", "foo"}}},
        {"oversketch", {{"curve", wave()}, {"stroke", stroke()}, {"scale", 2}}},
        {"oversketch", {{"curve", wave()}}},
        {"lift", {{"stroke", {{"points", {{1, 1}, {2, 2}}}}}, {"depth", {0}}}},
        {"lift", {{"stroke", {{"points", json::array()}}}, {"depth", {0, 1}}}},
    };
    for (const auto& b : bad)
        EXPECT_EQ(runCli(b[0].get<std::string>(), b[1].dump()).status, 2) << b[1].dump().substr(0, 200);
    EXPECT_EQ(runCli("lift", "{\"stroke\": ").status, 2);
}
