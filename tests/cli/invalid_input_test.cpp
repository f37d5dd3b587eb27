// Every kind of invalid input, for every subcommand and both geometry kinds: exit status 2,
// nothing on stdout, exactly one line on stderr that starts with the offending field
// (../shared/interfaces.md, "Errors").
#include "cli_runner.h"

#include <gtest/gtest.h>

#include <cctype>
#include <functional>

using namespace sculptline::cli_test;

namespace {

struct InvalidCase {
    std::string name;
    std::string subcommand;
    std::string text;            // the input as sent on stdin
    std::string expectedPrefix;  // what stderr must start with after "sculptline-cli: "
};

struct Subject {
    std::string subcommand;
    json valid;              // a valid input
    std::string geometry;    // "curve" or "surface"
    std::string ownField;    // a required field besides the geometry ("" when none)
    json ownWrongType;       // a mistyped value for ownField (or for "times" when ownField is empty)
    json ownInfinite;        // ownField with an infinite number (as the marker kInfMarker)
    std::string ownInfiniteField;
};

// JSON cannot carry infinity; a marker number is replaced by 1e999 in the text, which parses as inf.
constexpr double kInfMarker = 123456.789;

std::string withInfinity(const json& j)
{
    std::string text = j.dump();
    const std::string marker = json(kInfMarker).dump();
    for (size_t at = text.find(marker); at != std::string::npos; at = text.find(marker)) text.replace(at, marker.size(), "1e999");
    return text;
}

std::vector<Subject> subjects()
{
    const json curve = loadData("quarter_circle.json");
    const json surface = loadData("quarter_cylinder.json");
    const json inf = kInfMarker;
    return {
        {"eval", {{"curve", curve}, {"params", {0.5}}}, "curve", "params", "x", json::array({inf}), "params[0]: not a finite number"},
        {"eval", {{"surface", surface}, {"params", {{0.5, 0.5}}}}, "surface", "params", 3, {{0.5, inf}}, "params[0][1]: not a finite number"},
        {"insert-knot", {{"curve", curve}, {"knot", 0.5}}, "curve", "knot", "x", inf, "knot: not a finite number"},
        {"insert-knot", {{"surface", surface}, {"knot", 0.5}, {"direction", "u"}}, "surface", "knot", json::array(), inf, "knot: not a finite number"},
        {"elevate", {{"curve", curve}, {"times", 1}}, "curve", "", "x", inf, "times: not a finite number"},
        {"elevate", {{"surface", surface}, {"times", 1}, {"direction", "v"}}, "surface", "", 1.5, inf, "times: not a finite number"},
        {"remove-knots", {{"curve", curve}, {"tolerance", 1e-6}}, "curve", "tolerance", "x", inf, "tolerance: not a finite number"},
        {"remove-knots", {{"surface", surface}, {"tolerance", 1e-6}, {"direction", "u"}}, "surface", "tolerance", true, inf, "tolerance: not a finite number"},
        {"project", {{"curve", curve}, {"points", {{1, 1, 0}}}}, "curve", "points", "x", {{inf, 0, 0}}, "points[0][0]: not a finite number"},
        {"project", {{"surface", surface}, {"points", {{1, 1, 1}}}}, "surface", "points", json::object(), {{0, inf, 0}}, "points[0][1]: not a finite number"},
    };
}

std::vector<InvalidCase> invalidCases()
{
    std::vector<InvalidCase> cases;
    for (const Subject& s : subjects()) {
        const std::string g = s.geometry;
        const bool isCurve = g == "curve";
        const std::string knots = isCurve ? "knots" : "knotsU", degree = isCurve ? "degree" : "degreeU";
        const std::string tag = s.subcommand + "_" + g + "_";
        auto add = [&](const std::string& what, const std::string& text, const std::string& prefix) {
            cases.push_back({tag + what, s.subcommand, text, prefix});
        };
        auto mutated = [&](const std::function<void(json&)>& change) {
            json j = s.valid;
            change(j);
            return j;
        };
        const std::string text = s.valid.dump();
        add("MalformedJson", text.substr(0, text.size() - 1), "input: malformed JSON");
        add("EmptyInput", "", "input: malformed JSON");
        add("NaNLiteral", "{\"" + g + "\": NaN}", "input: malformed JSON");
        add("NotAnObject", "[" + text + "]", "input: must be a JSON object");
        add("MissingGeometry", mutated([&](json& j) { j.erase(g); }).dump(), "curve: missing");
        add("MissingKnots", mutated([&](json& j) { j[g].erase(knots); }).dump(), g + "." + knots + ": missing");
        add("GeometryNotAnObject", mutated([&](json& j) { j[g] = json::array(); }).dump(), g + ": must be a JSON object");
        add("DegreeWrongType", mutated([&](json& j) { j[g][degree] = "two"; }).dump(), g + "." + degree + ": must be an integer");
        add("PointsWrongType", mutated([&](json& j) { j[g]["points"] = 5; }).dump(), g + ".points: must be an array");
        add("PointWrongSize", mutated([&](json& j) { j[g]["points"][1] = {1}; }).dump(), g + ".points[1]: a point must be");
        add("WrongKnotCount", mutated([&](json& j) { j[g][knots].erase(j[g][knots].size() - 1); }).dump(),
            g + "." + knots + ": expected 6 knots");
        add("DecreasingKnots", mutated([&](json& j) { j[g][knots] = {0, 0, 0.5, 0.2, 1, 1}; }).dump(),
            g + "." + knots + "[3]: knots must be non-decreasing");
        add("InfiniteCoordinate", withInfinity(mutated([&](json& j) { j[g]["points"][1][0] = kInfMarker; })),
            g + ".points[1][0]: not a finite number");
        add("InfiniteKnot", withInfinity(mutated([&](json& j) { j[g][knots][5] = kInfMarker; })),
            g + "." + knots + "[5]: not a finite number");
        add("NegativeWeight", mutated([&](json& j) { j[g]["weights"][1] = -0.5; }).dump(), g + ".weights[1]: must be");
        add("ZeroWeight", mutated([&](json& j) { j[g]["weights"][0] = 0; }).dump(), g + ".weights[0]: must be");
        add("DegreeZero", mutated([&](json& j) { j[g][degree] = 0; }).dump(), g + "." + degree + ": must be between 1 and");
        add("DegreeHuge", mutated([&](json& j) { j[g][degree] = 1e300; }).dump(), g + "." + degree + ": must be between 1 and");
        const std::string own = s.ownField.empty() ? "times" : s.ownField;
        if (!s.ownField.empty()) add("MissingOwnField", mutated([&](json& j) { j.erase(own); }).dump(), own + ": missing");
        add("OwnFieldWrongType", mutated([&](json& j) { j[own] = s.ownWrongType; }).dump(), own + ": must be");
        add("OwnFieldInfinite", withInfinity(mutated([&](json& j) { j[own] = s.ownInfinite; })), s.ownInfiniteField);
        if (!isCurve) {
            add("BothGeometries", mutated([&](json& j) { j["curve"] = loadData("quarter_circle.json"); }).dump(),
                "surface: give either");
            add("CountMismatch", mutated([&](json& j) { j[g]["countV"] = 3; }).dump(), g + ".");
        }
    }
    return cases;
}

// gtest prints parameters; show the case, not the bytes of the struct.
void PrintTo(const InvalidCase& c, std::ostream* os)
{
    *os << c.subcommand << " " << c.name << ": " << c.text.substr(0, 120);
}

class CliInvalidInput : public ::testing::TestWithParam<InvalidCase> {};

}  // namespace

TEST_P(CliInvalidInput, ExitsWithStatus2AndOneLineNamingTheField)
{
    const InvalidCase& c = GetParam();
    const CliResult r = runCli({c.subcommand}, c.text);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.out, "");
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not exactly one line: " << r.err;
    EXPECT_EQ(r.err.rfind("sculptline-cli: " + c.expectedPrefix, 0), 0u) << "expected prefix: " << c.expectedPrefix
                                                                          << "\n got: " << r.err;
}

INSTANTIATE_TEST_SUITE_P(AllSubcommands, CliInvalidInput, ::testing::ValuesIn(invalidCases()),
                         [](const ::testing::TestParamInfo<InvalidCase>& info) {
                             std::string name = info.param.name;
                             for (char& ch : name)
                                 if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                             return name;
                         });
