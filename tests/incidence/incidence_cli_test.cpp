// sculptline-cli incidence, run as the real binary (../shared/interfaces.md). Given / When / Then.
#include "tests/cli/cli_runner.h"

#include <gtest/gtest.h>
#include <cmath>

using namespace sculptline::cli_test;

namespace {

// Fig. 4's layout: an 8 x 10 flat bicubic sheet over 100 x 80, a cubic diagonal domain curve.
json sheet()
{
    json pts = json::array();
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 10; ++j) pts.push_back({100.0 * i / 7, 80.0 * j / 9, 0.0});
    return {{"degreeU", 3}, {"degreeV", 3}, {"knotsU", {0, 0, 0, 0, 0.2, 0.4, 0.6, 0.8, 1, 1, 1, 1}},
            {"knotsV", {0, 0, 0, 0, 1.0 / 7, 2.0 / 7, 3.0 / 7, 4.0 / 7, 5.0 / 7, 6.0 / 7, 1, 1, 1, 1}},
            {"countU", 8}, {"countV", 10}, {"points", pts}};
}

json diagonal() { return {{"degree", 1}, {"knots", {0, 0, 1, 1}}, {"points", {{0.05, 0.05}, {0.95, 0.95}}}}; }

// The diagonal's image raised by a 4 mm arch in the middle (quadratic over the same [0, 1]).
json raisedDiagonal()
{
    return {{"degree", 2}, {"knots", {0, 0, 0, 1, 1, 1}}, {"points", {{5, 4, 0}, {50, 40, 8}, {95, 76, 0}}}};
}

}  // namespace

TEST(IncidenceCli, GivenARaisedDiagonal_WhenRun_ThenTheSurfaceMeetsItAndReportsItsLCurve)
{
    const json out = runOk("incidence", {{"surface", sheet()}, {"curves", {{{"domain", diagonal()}, {"target", raisedDiagonal()}}}}});
    EXPECT_LT(out["residual"].get<double>(), 0.05);
    EXPECT_EQ(out["k"], out["corner"]);
    EXPECT_GT(out["rows"].get<int>(), 0);
    EXPECT_EQ(out["lcurve"]["rho"].size(), out["lcurve"]["eta"].size());
    EXPECT_EQ(out["surface"]["countU"].get<int>(), 8);
    EXPECT_TRUE(out.contains("elapsed_ms"));
}

TEST(IncidenceCli, GivenAFixedEdge_WhenRun_ThenItIsMetExactly)
{
    const json edge = {{"degree", 1}, {"knots", {0, 0, 1, 1}}, {"points", {{0, 0}, {1, 0}}}};
    const json out = runOk("incidence", {{"surface", sheet()},
                                          {"curves", {{{"domain", edge}, {"fixed", true}}, {{"domain", diagonal()}, {"target", raisedDiagonal()}}}},
                                          {"method", "tsvd"}});
    EXPECT_LT(out["fixed_residual"].get<double>(), 1e-9);
    EXPECT_GT(out["hard_rows"].get<int>(), 0);
}

TEST(IncidenceCli, GivenInvalidInput_WhenRun_ThenExit2WithOneLineNamingTheField)
{
    const std::vector<std::pair<json, std::string>> bad = {
        {{{"surface", sheet()}, {"curves", json::array()}}, "curves"},
        {{{"surface", sheet()}, {"curves", {json::object()}}}, "curves[0]"},
        {{{"surface", sheet()}, {"curves", {{{"domain", diagonal()}, {"fixed", 1}}}}}, "curves[0].fixed"},
        {{{"surface", sheet()}, {"curves", {{{"domain", diagonal()}}}}, {"method", "svd"}}, "method"},
        {{{"surface", sheet()}, {"curves", {{{"domain", diagonal()}, {"target", raisedDiagonal()}}}}, {"k", 100000}}, "k"},
        {{{"surface", sheet()}, {"curves", {{{"domain", diagonal()}}}}, {"smoothing", {{"area", -1}}}}, "smoothing.area"},
    };
    for (const auto& [input, name] : bad) {
        const CliResult r = runCli({"incidence"}, input.dump());
        EXPECT_EQ(r.status, 2) << input.dump();
        EXPECT_NE(r.err.find(name), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
}
