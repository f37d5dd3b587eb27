// Input built to break the program rather than to be wrong: deep nesting and sizes that would make a
// subcommand run for long. Each case is a finding of the fuzz targets (fuzz/, README "Robustness");
// the contract (../shared/interfaces.md, "Errors") holds: exit status 2 and one line naming the field.
#include "cli_runner.h"

#include <gtest/gtest.h>

using namespace sculptline::cli_test;

namespace {

// Deep enough to overflow the 8 MiB main-thread stack of anything that recurses per level (nlohmann's
// dump() takes over 100 bytes of stack per level), small enough (2 MB) to send quickly.
constexpr int kNestingDepth = 1000000;

std::string nested(int depth)
{
    return std::string(depth, '[') + std::string(depth, ']');
}

const std::string kLine = R"({"degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 0]]})";

void expectRejected(const std::string& subcommand, const std::string& text, const std::string& prefix)
{
    const CliResult r = runCli({subcommand}, text);
    EXPECT_EQ(r.status, 2) << subcommand << ": " << r.err.substr(0, 200);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err.rfind("sculptline-cli: " + prefix, 0), 0u) << r.err.substr(0, 200);
}

}  // namespace

TEST(CliHostileInput, GivenDeeplyNestedMethod_WhenOversketch_ThenRejectedNamingMethod)
{
    expectRejected("oversketch", R"({"curve": )" + kLine + R"(, "stroke": {"points": [[0, 0]]}, "method": )" +
                                     nested(kNestingDepth) + "}",
                   "method: expected");
}

TEST(CliHostileInput, GivenDeeplyNestedConstraintType_WhenConstrainCurve_ThenRejectedNamingType)
{
    expectRejected("constrain-curve",
                   R"({"curve": )" + kLine + R"(, "constraints": [{"type": )" + nested(kNestingDepth) +
                       R"(, "u": 0, "value": [0, 0]}]})",
                   "constraints[0].type: expected");
}

TEST(CliHostileInput, GivenDeeplyNestedTolerance_WhenRemoveKnots_ThenRejectedNamingTolerance)
{
    expectRejected("remove-knots", R"({"curve": )" + kLine + R"(, "tolerance": )" + nested(kNestingDepth) + "}",
                   "tolerance: ");
}

TEST(CliHostileInput, GivenTinyEdgeLength_WhenNetwork_ThenRefusedNamingEdgeLength)
{
    // Four edges of a unit square; edge_length 1e-9 asked for 4e9 boundary vertices (the solver capped
    // them at 4e5, which still took 9 s and 0.5 GB).
    const std::string square = R"({"curves": [
        {"degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 0], [1, 0]]},
        {"degree": 1, "knots": [0, 0, 1, 1], "points": [[1, 0], [1, 1]]},
        {"degree": 1, "knots": [0, 0, 1, 1], "points": [[1, 1], [0, 1]]},
        {"degree": 1, "knots": [0, 0, 1, 1], "points": [[0, 1], [0, 0]]}],
        "loops": [[0, 1, 2, 3]], "fairing": 100, "edge_length": )";
    expectRejected("network", square + "1e-9}", "edge_length: 1e-09 would put 4000000000.0 vertices");
    EXPECT_EQ(runCli({"network"}, square + "0.01}").status, 0);  // 400 vertices: fine
}
