// Given JSON input, when sculptline-cli fit / recognize run as a process, then the output follows
// ../shared/interfaces.md and invalid input exits with status 2 and one line naming the field.
#include "solvers/stroke/stroke_json.h"
#include "solvers/stroke/stroke_synthesis.h"
#include "tests/cli/cli_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace sculptline::stroketest {
namespace {

using nlohmann::json;
using namespace solvers::stroke;

using CliRun = cli_test::CliResult;

// The shared runner (tests/cli): no shell, a private scratch directory per process, so parallel
// ctest processes never share input or output files.
CliRun cli(const std::string& sub, const std::string& input)
{
    return cli_test::runCli({sub}, input);
}

std::string strokeJson(const Shape& s)
{
    DrawOptions d;
    d.noise = 0.25;
    return toJson(draw(s, d)).dump();
}

void expectInvalid(const std::string& sub, const std::string& input, const std::string& field)
{
    const CliRun r = cli(sub, input);
    EXPECT_EQ(r.status, 2) << input.substr(0, 80);
    EXPECT_TRUE(r.out.empty());
    EXPECT_NE(r.err.find(field), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(StrokeCli, GivenStroke_WhenFit_ThenCurveCornersSamplesAndErrorWithinTolerance)
{
    const CliRun r = cli("fit", "{\"stroke\": " + strokeJson(polygonShape({{0, 0, 0}, {100, 0, 0}, {100, 80, 0}}, false)) +
                                 ", \"tolerance\": 0.8}");
    ASSERT_EQ(r.status, 0) << r.err;
    const json o = json::parse(r.out);
    EXPECT_EQ(o["curve"]["degree"], 3);
    EXPECT_EQ(o["corners"].size(), 1u);
    EXPECT_GE(o["samples"].size(), 4u);
    EXPECT_EQ(o["tolerance"], 0.8);
    EXPECT_LE(o["max_error"].get<double>(), 0.8);
    ASSERT_TRUE(o["dropped_samples"].is_array());  // no hook, no loop: nothing dropped
    EXPECT_TRUE(o["dropped_samples"].empty());
    ASSERT_TRUE(o["outlier_samples"].is_array());  // noise far below the tolerance: no outlier
    EXPECT_TRUE(o["outlier_samples"].empty());
    EXPECT_TRUE(o.contains("elapsed_ms"));
    EXPECT_EQ(o["curve"]["points"][0].size(), 2u);  // a 2D stroke gives 2D points
}

// "resolution": the pitch the samples are quantized to; the default tolerance is at least that.
// A slow hand's jitter at a third of the tolerance: the samples it puts beyond the tolerance are
// reported as outliers, among the dropped samples, and max_error is that of the rest.
TEST(StrokeCli, GivenJitteryStroke_WhenFit_ThenNoiseOutliersReportedAmongTheDropped)
{
    DrawOptions d;
    d.noise = 0.5;
    const CliRun r = cli("fit", "{\"stroke\": " + toJson(drawWithSamples(flourishShape(300), 1000, d)).dump() + "}");
    ASSERT_EQ(r.status, 0) << r.err;
    const json o = json::parse(r.out);
    const auto outliers = o["outlier_samples"].get<std::vector<int>>();
    const auto dropped = o["dropped_samples"].get<std::vector<int>>();
    EXPECT_FALSE(outliers.empty());
    for (int i : outliers) EXPECT_TRUE(std::binary_search(dropped.begin(), dropped.end(), i)) << i;
    EXPECT_TRUE(o["converged"].get<bool>());
    EXPECT_LE(o["max_error"].get<double>(), o["tolerance"].get<double>());
}

TEST(StrokeCli, GivenResolution_WhenFit_ThenTheToleranceIsAtLeastTheResolution)
{
    const std::string stroke = strokeJson(polygonShape({{0, 0, 0}, {100, 0, 0}, {100, 80, 0}}, false));
    const CliRun r = cli("fit", "{\"stroke\": " + stroke + ", \"resolution\": 2.5}");
    ASSERT_EQ(r.status, 0) << r.err;
    const json o = json::parse(r.out);
    EXPECT_EQ(o["tolerance"], 2.5);  // above 0.5 % of the ~128-unit extent
    EXPECT_LE(o["max_error"].get<double>(), 2.5);
    const CliRun fine = cli("fit", "{\"stroke\": " + stroke + ", \"resolution\": 0.01}");
    ASSERT_EQ(fine.status, 0) << fine.err;
    const CliRun none = cli("fit", "{\"stroke\": " + stroke + "}");
    ASSERT_EQ(none.status, 0) << none.err;
    EXPECT_EQ(json::parse(fine.out)["tolerance"], json::parse(none.out)["tolerance"]);
    EXPECT_EQ(json::parse(fine.out)["curve"], json::parse(none.out)["curve"]);
}

// recognize takes "resolution" as fit does: its fit's default tolerance is at least the resolution,
// so a coarse pitch fits the stroke with fewer control points, a fine one changes nothing.
TEST(StrokeCli, GivenResolution_WhenRecognized_ThenItsFitUsesIt)
{
    const std::string stroke = strokeJson(spiralShape(100, 2.0));
    auto recognize = [&](const std::string& extra) {
        const CliRun r = cli("recognize", "{\"stroke\": " + stroke + ", \"regularize\": false" + extra + "}");
        EXPECT_EQ(r.status, 0) << r.err;
        return r.status == 0 ? json::parse(r.out) : json();
    };
    const json none = recognize(""), fine = recognize(", \"resolution\": 0.01"), coarse = recognize(", \"resolution\": 5");
    ASSERT_TRUE(none["regularized"].contains("points"));
    EXPECT_EQ(fine["regularized"], none["regularized"]);
    EXPECT_LT(coarse["regularized"]["points"].size(), none["regularized"]["points"].size());
    // The same fit as fit's with that resolution (the spiral is neither refitted open nor closed).
    const CliRun f = cli("fit", "{\"stroke\": " + stroke + ", \"resolution\": 5}");
    ASSERT_EQ(f.status, 0) << f.err;
    EXPECT_EQ(coarse["regularized"]["points"], json::parse(f.out)["curve"]["points"]);
}

// "repeat": n fits n times for timing (scripts/compare_splprep.py --time): the same result as one
// fit, the first fit's time as elapsed_ms and the fastest as elapsed_ms_min, which is no more.
TEST(StrokeCli, GivenRepeat_WhenFit_ThenTheSameCurveAndTheFastestTimeReported)
{
    const std::string stroke = strokeJson(spiralShape(100, 2.0));
    const CliRun once = cli("fit", "{\"stroke\": " + stroke + "}");
    const CliRun many = cli("fit", "{\"stroke\": " + stroke + ", \"repeat\": 5}");
    ASSERT_EQ(once.status, 0) << once.err;
    ASSERT_EQ(many.status, 0) << many.err;
    const json a = json::parse(once.out), b = json::parse(many.out);
    EXPECT_EQ(a["curve"], b["curve"]);
    EXPECT_EQ(a["max_error"], b["max_error"]);
    EXPECT_FALSE(a.contains("elapsed_ms_min"));
    ASSERT_TRUE(b.contains("elapsed_ms_min"));
    EXPECT_GT(b["elapsed_ms_min"].get<double>(), 0.0);
    EXPECT_LE(b["elapsed_ms_min"].get<double>(), b["elapsed_ms"].get<double>());
    expectInvalid("fit", "{\"stroke\": " + stroke + ", \"repeat\": 0}", "repeat");
    expectInvalid("fit", "{\"stroke\": " + stroke + ", \"repeat\": 101}", "repeat");
    expectInvalid("fit", "{\"stroke\": " + stroke + ", \"repeat\": 2.5}", "repeat");
    expectInvalid("fit", "{\"stroke\": " + stroke + ", \"repeat\": \"many\"}", "repeat");
}

TEST(StrokeCli, GivenInvalidStrokes_ThenExit2NamingTheField)
{
    expectInvalid("fit", "{\"stroke\": {\"points\": [[0, 0], [1, 1]]}, \"resolution\": -1}", "resolution");
    expectInvalid("fit", "{\"stroke\": {\"points\": []}}", "stroke.points");
    expectInvalid("fit", "{\"stroke\": {\"points\": [[0, 0], [1e999, 1]]}}", "stroke.points[1][0]");
    expectInvalid("fit", "{\"stroke\": {\"points\": [[2, 2], [2, 2], [2, 2]]}}", "stroke.points");
    expectInvalid("fit", "{\"stroke\": {\"points\": [[0, 0], [1, 1]], \"times\": [0]}}", "stroke.times");
    expectInvalid("fit", "{\"stroke\": {\"points\": [[0, 0], [1, 1]]}, \"tolerance\": -1}", "tolerance");
    expectInvalid("fit", "{\"stroke\": {\"points\": [[0, 0], [1, 1, 2]]}}", "stroke.points[1]");
    expectInvalid("fit", "{\"points\": [[0, 0], [1, 1]]}", "stroke");
    expectInvalid("recognize", "{\"strokes\": []}", "strokes");
    expectInvalid("recognize", "{\"stroke\": {\"points\": [[0, 0], [1, 1]]}, \"resolution\": -1}", "resolution");
    expectInvalid("recognize", "{\"stroke\": {\"points\": [[0, 0], [1, 1]]}, \"resolution\": \"fine\"}", "resolution");
    expectInvalid("recognize", "{\"strokes\": [{\"points\": [[0, 0], [1, 0]]}, {\"points\": [[0, 0]]}]}", "strokes[1].points");
    expectInvalid("recognize", "{\"stroke\": {\"points\": [[0, 0], [5, 1]]}, \"user_model\": {\"nodes\": [{\"index\": 1}]}}",
                  "user_model.nodes[0]");
}

TEST(StrokeCli, GivenCircleStroke_WhenRecognized_ThenCircleRankedFirstAndExactRationalCurve)
{
    const CliRun r = cli("recognize", "{\"stroke\": " + strokeJson(circleShape({0, 0, 0}, 60)) + "}");
    ASSERT_EQ(r.status, 0) << r.err;
    const json o = json::parse(r.out);
    EXPECT_EQ(o["shape"], "circle");
    ASSERT_GE(o["candidates"].size(), 2u);
    EXPECT_EQ(o["candidates"][0]["kind"], "circle");
    EXPECT_GE(o["candidates"][0]["score"].get<double>(), o["candidates"][1]["score"].get<double>());
    EXPECT_EQ(o["regularized"]["degree"], 2);
    EXPECT_TRUE(o["regularized"].contains("weights"));
    EXPECT_EQ(o["regularized"].value("closed", false), true);  // a circle is a closed curve
}

TEST(StrokeCli, GivenClosedPrimitiveStrokes_WhenRecognized_ThenRegularizedCurveIsClosedAndOpenOnesAreNot)
{
    const std::vector<std::pair<std::string, Shape>> closedShapes = {
        {"square", polygonShape({{0, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}}, true)},
        {"triangle", polygonShape({{0, 0, 0}, {160, 10, 0}, {70, 120, 0}}, true)},
        {"ellipse", ellipseShape({0, 0, 0}, 120, 60, 0.3)},
    };
    for (const auto& [name, shape] : closedShapes) {
        const CliRun r = cli("recognize", "{\"stroke\": " + strokeJson(shape) + "}");
        ASSERT_EQ(r.status, 0) << r.err;
        const json o = json::parse(r.out);
        EXPECT_EQ(o["shape"], name);
        EXPECT_EQ(o["regularized"].value("closed", false), true) << name;
    }
    const CliRun line = cli("recognize", "{\"stroke\": " + strokeJson(lineShape({0, 0, 0}, {150, 40, 0})) + "}");
    ASSERT_EQ(line.status, 0) << line.err;
    EXPECT_EQ(json::parse(line.out)["regularized"].value("closed", false), false);
}

TEST(StrokeCli, GivenStrokeSequenceAndModelFile_ThenNewPairLearnedOnceAndSaved)
{
    const std::string path = cli_test::scratchPath("stroke_cli_user.json");
    std::remove(path.c_str());
    const std::string input = "{\"strokes\": [" +
                              strokeJson(polygonShape({{0, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}}, true)) + ", " +
                              strokeJson(circleShape({50, 50, 0}, 20)) + "], \"user_model\": \"" + path + "\"}";

    const CliRun first = cli("recognize", input);
    const CliRun second = cli("recognize", input);

    ASSERT_EQ(first.status, 0) << first.err;
    const json a = json::parse(first.out), b = json::parse(second.out);
    EXPECT_EQ(a["strokes"][1]["relations"], json::array({"inside"}));
    EXPECT_TRUE(a["strokes"][1]["learned"].get<bool>());
    EXPECT_FALSE(b["strokes"][1]["learned"].get<bool>());
    EXPECT_EQ(a["strokes"][1]["composite_node"], b["strokes"][1]["composite_node"]);
    const UserModel saved = userModelFromJson(json::parse(std::ifstream(path)), "file");
    EXPECT_EQ(saved.nodes().size(), UserModel::predefined().nodes().size() + 1);
}

TEST(StrokeCli, GivenProfileEdgeAndTopFace_WhenRecognizedAsSequence_ThenPolygonVolumeChainedToTheExtrusion)
{
    const std::string input =
        "{\"strokes\": [" + strokeJson(polygonShape({{0, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}}, true)) + ", " +
        strokeJson(lineShape({100, 100, 0}, {160, 160, 0})) + ", " +
        strokeJson(polygonShape({{60, 60, 0}, {160, 60, 0}, {160, 160, 0}, {60, 160, 0}}, true)) + "]}";

    const CliRun r = cli("recognize", input);

    ASSERT_EQ(r.status, 0) << r.err;
    const json o = json::parse(r.out);
    EXPECT_EQ(o["strokes"][1]["composite"], "extrusion");
    EXPECT_EQ(o["strokes"][2]["composite"], "polygon_volume");
    EXPECT_EQ(o["composite"], "polygon_volume");
    EXPECT_EQ(o["strokes"][2]["pre_node"], o["strokes"][1]["composite_node"]);  // Table 3-2 chain
    EXPECT_EQ(o["strokes"][1]["pre_node"], o["strokes"][0]["node"]);
}

}  // namespace
}  // namespace sculptline::stroketest
