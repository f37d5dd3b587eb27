// sculptline-cli deform, run as the real binary (../shared/interfaces.md). Given / When / Then.
#include "tests/cli/cli_runner.h"

#include <gtest/gtest.h>
#include <cmath>

using namespace sculptline::cli_test;

namespace {

// Linear constraints hold to round-off (surface ~4 units across; printing keeps 17 digits).
constexpr double kConstraintTolerance = 1e-9;

json flatSurface()
{
    json pts = json::array();
    for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) pts.push_back({i, j, 0.0});
    }
    const json knots = {0, 0, 0, 0, 1.0 / 3, 2.0 / 3, 1, 1, 1, 1};
    return {{"degreeU", 3}, {"degreeV", 3}, {"knotsU", knots}, {"knotsV", knots}, {"countU", 6}, {"countV", 6},
            {"points", pts}};
}

json pull(double z) { return {{"type", "position"}, {"uv", {0.5, 0.5}}, {"value", {2.5, 2.5, z}}}; }

CliResult runDeform(const json& input) { return runCli({"deform"}, input.dump()); }

}  // namespace

TEST(DeformCli, GivenEveryConstraintType_WhenRun_ThenOneResidualEachAndAllMet)
{
    const json input = {
        {"surface", flatSurface()},
        {"constraints",
         {pull(1.0),
          {{"type", "normal"}, {"uv", {0.2, 0.2}}, {"value", {0.1, 0, 1}}},
          {{"type", "curve"},
           {"target", {{"degree", 1}, {"knots", {0, 0, 1, 1}}, {"points", {{0.5, 4, 0.3}, {4.5, 4, 0.3}}}}}},
          {{"type", "curve-tangent"},
           {"domain", {{"degree", 1}, {"knots", {0, 0, 1, 1}}, {"points", {{0.2, 0.1}, {0.8, 0.1}}}}},
           {"value", {0, 1, 0.2}}},
          {{"type", "distance"}, {"uv", {0.1, 0.9}}, {"uv2", {0.9, 0.9}}, {"value", 4.5}}}},
        {"objective", "force"}};
    const json out = runOk("deform", input);
    ASSERT_EQ(out["residuals"].size(), 5u);
    EXPECT_LT(out["max_residual"].get<double>(), kConstraintTolerance);
    EXPECT_FALSE(out["compromise"].get<bool>());
    EXPECT_GE(out["key_points"].size(), 2u);
    EXPECT_EQ(out["moved"].get<int>(), 36);
    EXPECT_TRUE(out.contains("elapsed_ms"));
    EXPECT_EQ(out["surface"]["countU"].get<int>(), 6);
}

TEST(DeformCli, GivenBlockedPointsAndStiffness_WhenRun_ThenBlockedStayAndHalfTheWayIsReached)
{
    json input = {{"surface", flatSurface()}, {"constraints", {pull(2.0)}}, {"stiffness", 0.5},
                  {"blocked", {{0, 0}, {2, 2}}}, {"objective", "displacement"}};
    const json out = runOk("deform", input);
    const auto before = pointsOf(input["surface"]["points"]);
    const auto after = pointsOf(out["surface"]["points"]);
    EXPECT_EQ(after[0], before[0]);
    EXPECT_EQ(after[2 * 6 + 2], before[2 * 6 + 2]);
    // The 4×4 points i, j = 1..4 whose basis functions are non-zero at (0.5, 0.5), less (2, 2).
    EXPECT_EQ(out["moved"].get<int>(), 15);
    const json eval = runOk("eval", {{"surface", out["surface"]}, {"params", {{0.5, 0.5}}}});
    EXPECT_NEAR(eval["points"][0][2].get<double>(), 1.0, kConstraintTolerance);
}

TEST(DeformCli, GivenABoundIn3D_WhenRun_ThenPointsOutsideItStay)
{
    // A closed square around the middle, drawn just above the flat surface (projected onto it).
    const json bound = {{"degree", 1},
                        {"knots", {0, 0, 0.25, 0.5, 0.75, 1, 1}},
                        {"points", {{1, 1, 0.1}, {4, 1, 0.1}, {4, 4, 0.1}, {1, 4, 0.1}, {1, 1, 0.1}}}};
    const json out = runOk("deform", {{"surface", flatSurface()}, {"constraints", {pull(1.0)}}, {"bound", bound}});
    const auto after = pointsOf(out["surface"]["points"]);
    for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) {
            if (i == 0 || i == 5 || j == 0 || j == 5) {
                EXPECT_EQ(after[i * 6 + j].z(), 0.0) << i << ", " << j;
            }
        }
    }
    EXPECT_LT(out["max_residual"].get<double>(), kConstraintTolerance);
}

TEST(DeformCli, GivenContradictoryConstraints_WhenRun_ThenACompromiseNotAnError)
{
    const json out = runOk("deform", {{"surface", flatSurface()}, {"constraints", {pull(1.0), pull(-1.0)}}});
    EXPECT_TRUE(out["compromise"].get<bool>());
    EXPECT_TRUE(out.contains("message"));
}

TEST(DeformCli, GivenInvalidInput_WhenRun_ThenExit2WithOneLineNamingTheField)
{
    const json openBound = {{"degree", 1}, {"knots", {0, 0, 0.5, 1, 1}}, {"points", {{0.1, 0.1}, {0.9, 0.1}, {0.9, 0.9}}}};
    const std::vector<std::pair<json, std::string>> cases = {
        {{{"surface", flatSurface()}, {"constraints", {{{"type", "position"}, {"uv", {1.5, 0.5}}, {"value", {0, 0, 0}}}}}},
         "constraints[0].uv"},
        {{{"surface", flatSurface()}, {"constraints", {pull(1.0)}}, {"bound", openBound}}, "bound"},
        {{{"surface", flatSurface()}, {"constraints", {{{"type", "twist"}}}}}, "constraints[0].type"},
        {{{"surface", flatSurface()}, {"constraints", {pull(1.0)}}, {"stiffness", 0}}, "stiffness"},
        {{{"surface", flatSurface()}, {"constraints", {pull(1.0)}}, {"objective", "least"}}, "objective"},
        {{{"surface", flatSurface()}, {"constraints", {pull(1.0)}}, {"blocked", {{6, 0}}}}, "blocked[0]"},
        {{{"constraints", {pull(1.0)}}}, "surface"},
    };
    for (const auto& [input, name] : cases) {
        const CliResult r = runDeform(input);
        EXPECT_EQ(r.status, 2) << input.dump();
        EXPECT_NE(r.err.find(name), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    // NaN cannot be written in JSON; the text form is refused as malformed input.
    const CliResult nan = runCli({"deform"}, R"({"surface": 1, "constraints": [{"type": "position", "uv": [NaN, 0]}]})");
    EXPECT_EQ(nan.status, 2);
}

TEST(DeformCli, GivenMethodIsocurves_WhenRun_ThenThePointIsMetAsByTheGlobalLeastDisplacement)
{
    const json base = {{"surface", flatSurface()}, {"constraints", {pull(1.0)}}};
    json iso = base;
    iso["method"] = "isocurves";
    json global = base;
    global["objective"] = "displacement";
    const json a = runOk("deform", iso), b = runOk("deform", global);
    EXPECT_LT(a["max_residual"].get<double>(), kConstraintTolerance);
    const auto pa = pointsOf(a["surface"]["points"]), pb = pointsOf(b["surface"]["points"]);
    for (size_t k = 0; k < pa.size(); ++k) EXPECT_LT((pa[k] - pb[k]).norm(), kConstraintTolerance);
}

TEST(DeformCli, GivenIsocurvesAndATargetCurveWithoutDomain_WhenRun_ThenItsKeyPointsAreMet)
{
    // The feet of the key points (global projection) share one v up to ~1e-12: one iso-curve.
    const json target = {{"degree", 1}, {"knots", {0, 0, 1, 1}}, {"points", {{0.5, 4, 0.3}, {4.5, 4, 0.3}}}};
    const json out = runOk("deform", {{"surface", flatSurface()},
                                      {"method", "isocurves"},
                                      {"constraints", {pull(1.0), {{"type", "curve"}, {"target", target}}}}});
    EXPECT_FALSE(out["compromise"].get<bool>());
    EXPECT_LT(out["max_residual"].get<double>(), kConstraintTolerance);
    EXPECT_GE(out["key_points"].size(), 2u);
}

TEST(DeformCli, GivenTangentValuesAndABound_WhenRun_ThenMetAndTheBoundCasesAreReported)
{
    // S_u = (1.2, 0, 0.3) and S_v = (0, 1, 0) at the middle, and a target partly inside a bound.
    const json bound = {{"degree", 1},
                        {"knots", {0, 0, 0.25, 0.5, 0.75, 1, 1}},
                        {"points", {{0.1, 0.1}, {0.9, 0.1}, {0.9, 0.9}, {0.1, 0.9}, {0.1, 0.1}}}};
    const json input = {
        {"surface", flatSurface()},
        {"constraints",
         {{{"type", "tangents"}, {"uv", {0.5, 0.5}}, {"du", {5.0, 0, 1.0}}, {"dv", {0, 5.0, 0}}},
          {{"type", "curve"}, {"target", {{"degree", 1}, {"knots", {0, 0, 1, 1}}, {"points", {{0, 0, 0}, {5, 0, 0}}}}}}}},
        {"bound", bound}};
    const json out = runOk("deform", input);
    EXPECT_LT(out["max_residual"].get<double>(), kConstraintTolerance);
    ASSERT_EQ(out["bound_cases"].size(), 2u);
    EXPECT_EQ(out["bound_cases"][0], "unbounded");  // a tangent is no target curve
    EXPECT_EQ(out["bound_cases"][1], "over");       // the edge v = 0 lies outside the bound
    const json missing = {{"surface", flatSurface()}, {"constraints", {{{"type", "tangents"}, {"uv", {0.5, 0.5}}, {"du", {1, 0, 0}}}}}};
    const CliResult bad = runDeform(missing);
    EXPECT_EQ(bad.status, 2);
    EXPECT_NE(bad.err.find("constraints[0].dv"), std::string::npos) << bad.err;
}

TEST(DeformCli, GivenAnAngle_WhenRun_ThenTheNormalMakesItWithTheDirection)
{
    // The flat surface's normal is z; asked to make 25° with z at the middle.
    const json input = {{"surface", flatSurface()},
                        {"constraints", {{{"type", "angle"}, {"uv", {0.5, 0.5}}, {"value", {0, 0, 1}}, {"angle", 25.0}}}}};
    const json out = runOk("deform", input);
    EXPECT_LT(out["max_residual"].get<double>(), 1e-6);  // radians
    const json bad = {{"surface", flatSurface()},
                      {"constraints", {{{"type", "angle"}, {"uv", {0.5, 0.5}}, {"value", {0, 0, 1}}, {"angle", 190.0}}}}};
    const CliResult r = runDeform(bad);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("constraints[0].angle"), std::string::npos) << r.err;
}
