// sculptline-cli plan: a document's construction plan, states and freedom (../shared/interfaces.md).
#include "tests/cli/cli_runner.h"

#include <gtest/gtest.h>

namespace sculptline::cli_test {
namespace {

/// A plane, two curves on it (one pinned, one fixed), a loft of the two.
json loftDocument()
{
    const json cubic = {{"degree", 3}, {"knots", {0, 0, 0, 0, 1, 1, 1, 1}}};
    json a = cubic, b = cubic;
    a["id"] = 2;
    a["plane"] = 1;
    a["points"] = {{0, 0}, {10, 5}, {20, 5}, {30, 0}};
    b["id"] = 3;
    b["plane"] = 1;
    b["points"] = {{0, 20}, {10, 25}, {20, 25}, {30, 20}};
    b["state"] = "fixed";
    return {{"planes", {{{"id", 1}, {"origin", {0, 0, 0}}, {"normal", {0, 0, 1}}, {"size", 100}}}},
            {"curves", {a, b}},
            {"surfaces", {{{"id", 4}, {"construction", {{"mode", "loft"}, {"curves", {2, 3}}}}}}},
            {"constraints", {{{"curve", 2}, {"type", "position"}, {"u", 0.5}}}}};
}

TEST(CliPlan, PrintsTheStepsInEvaluationOrderWithStatesAndFreedom)
{
    const json out = runOk("plan", {{"document", loftDocument()}});
    // The curves are placed on their plane before the loft is built from them
    ASSERT_EQ(out["steps"].size(), 3u);
    EXPECT_EQ(out["steps"][0]["solve"], json({2}));
    EXPECT_EQ(out["steps"][0]["solver"], "least-change");  // pinned
    EXPECT_EQ(out["steps"][1]["solve"], json({3}));
    EXPECT_EQ(out["steps"][1]["solver"], "placement");
    EXPECT_EQ(out["steps"][2]["solve"], json({4}));
    EXPECT_EQ(out["steps"][2]["solver"], "surface-builder");
    // Each step names its constraints, and "constraints" says what they are
    for (const json& step : out["steps"]) {
        for (const json& id : step["constraints"]) EXPECT_TRUE(out["constraints"].contains(std::to_string(id.get<int>()))) << id;
    }
    const json& loft = out["constraints"][std::to_string(out["steps"][2]["constraints"][0].get<int>())];
    EXPECT_EQ(loft["type"], "construction");
    EXPECT_EQ(loft["sources"], json({2, 3}));
    // States and freedom: curve 3 fixed; the pin takes 2 of curve 2's 8 (4 points in a plane)
    EXPECT_EQ(out["states"]["3"], "fixed");
    EXPECT_EQ(out["states"]["2"], "free");
    EXPECT_EQ(out["dof"]["2"]["total"], 8);
    EXPECT_EQ(out["dof"]["2"]["consumed"], 2);
    EXPECT_EQ(out["dof"]["4"]["consumed"], out["dof"]["4"]["total"]);
    EXPECT_TRUE(out.contains("elapsed_ms"));
}

TEST(CliPlan, ReadsADocumentFromAFile)
{
    const json out = runOk("plan", {{"path", SCULPTLINE_DATA_DIR "/models/surfaces_drag_start.json"}});
    // Seven curves on two planes, four surfaces built from them: eleven steps, surfaces last
    ASSERT_EQ(out["steps"].size(), 11u);
    for (size_t k = 7; k < 11; ++k) EXPECT_EQ(out["steps"][k]["solver"], "surface-builder");
}

TEST(CliPlan, RefusesWhatIsNotADocumentNamingTheField)
{
    for (const json& input : {json{{"document", 5}}, json{{"path", 7}}, json{{"path", "/nonexistent/x.json"}},
                              json::object(), json{{"document", json::object()}, {"path", "x.json"}},
                              json{{"document", {{"constraints", {{{"type", "g1"}, {"targets", {1}}}}}}}}}) {
        const CliResult r = runCli({"plan"}, input.dump());
        EXPECT_EQ(r.status, 2) << input.dump() << "\n" << r.err;
        EXPECT_FALSE(r.err.empty());
    }
}

}  // namespace
}  // namespace sculptline::cli_test
