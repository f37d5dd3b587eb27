// sculptline-cli's command line: help, version, unknown or missing subcommands, unreadable files,
// and inputs built to crash a parser. Errors follow the contract: exit 2, one stderr line, no stdout.
#include "cli_runner.h"

#include <gtest/gtest.h>

using namespace sculptline::cli_test;

namespace {
const std::vector<std::string> kSubcommands{"eval", "insert-knot", "elevate", "remove-knots", "project"};

void expectInvalid(const CliResult& r, const std::string& prefix)
{
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.out, "");
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not exactly one line: " << r.err;
    EXPECT_EQ(r.err.rfind("sculptline-cli: " + prefix, 0), 0u) << r.err;
}
}  // namespace

TEST(CliArguments, HelpListsEverySubcommand)
{
    const CliResult r = runCli({"--help"});
    EXPECT_EQ(r.status, 0);
    for (const auto& name : kSubcommands) EXPECT_NE(r.out.find("\n  " + name + " "), std::string::npos) << name;
}

TEST(CliArguments, SubcommandHelp)
{
    const CliResult r = runCli({"project", "--help"});
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.out.find("closest points"), std::string::npos) << r.out;
}

TEST(CliArguments, Version)
{
    const CliResult r = runCli({"--version"});
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out, std::string(SCULPTLINE_VERSION) + "\n");
}

TEST(CliArguments, UnknownSubcommand)
{
    expectInvalid(runCli({"evaluate"}, "{}"), "subcommand: unknown 'evaluate'");
}

TEST(CliArguments, MissingSubcommand)
{
    expectInvalid(runCli({}, "{}"), "subcommand: missing");
}

TEST(CliArguments, MissingFileForEverySubcommand)
{
    const std::string missing = scratchPath("does-not-exist.json");
    for (const auto& name : kSubcommands) expectInvalid(runCli({name, missing}), "input: cannot open '" + missing + "'");
}

TEST(CliArguments, DirectoryAsInput)
{
    expectInvalid(runCli({"eval", SCULPTLINE_CLI_TEST_DATA}), "input: cannot read");
}

TEST(CliArguments, UnknownOptionAndExtraArgument)
{
    expectInvalid(runCli({"eval", "--frobnicate"}, "{}"), "arguments: ");
    expectInvalid(runCli({"eval", dataPath("quarter_circle.json"), "extra.json"}, "{}"), "arguments: ");
}

// Deep nesting must not overflow the stack anywhere (parser, destructor, error message).
TEST(CliArguments, DeeplyNestedJsonDoesNotCrash)
{
    const int depth = 200000;
    const std::string nested = std::string(depth, '[') + std::string(depth, ']');
    expectInvalid(runCli({"eval"}, nested), "input: must be a JSON object");
    const std::string surface = loadData("quarter_cylinder.json").dump();
    expectInvalid(runCli({"insert-knot"}, "{\"surface\": " + surface + ", \"knot\": 0.5, \"direction\": " + nested + "}"),
                  "direction: must be");
    const std::string curve = loadData("quarter_circle.json").dump();
    expectInvalid(runCli({"elevate"}, "{\"curve\": " + curve + ", \"times\": " + nested + "}"), "times: must be");
}

// Finite input whose result overflows double precision is an input error, not a null in the output.
TEST(CliArguments, OverflowingResultIsRejected)
{
    const json curve = {{"degree", 2}, {"knots", {0, 0, 0, 1, 1, 1}}, {"points", {{1e308, 0}, {-1e308, 0}, {1e308, 0}}}};
    expectInvalid(runCli({"eval"}, json{{"curve", curve}, {"params", {0.0}}, {"derivatives", 1}}.dump()), "result.d1[0][0]: ");
}

TEST(CliArguments, PrettyOutputParsesToTheSameResult)
{
    const json input = {{"curve", loadData("quarter_circle.json")}, {"params", {0.25}}};
    const CliResult plain = runCli({"eval"}, input.dump());
    const CliResult pretty = runCli({"eval", "--pretty"}, input.dump());
    ASSERT_EQ(plain.status, 0);
    ASSERT_EQ(pretty.status, 0);
    EXPECT_NE(pretty.out.find("\n  "), std::string::npos);
    EXPECT_EQ(json::parse(plain.out)["points"], json::parse(pretty.out)["points"]);
}

// Parameters outside an open curve's domain would be clamped silently by the kernel: rejected.
TEST(CliArguments, ParameterOutsideTheDomain)
{
    expectInvalid(runCli({"eval"}, json{{"curve", loadData("quarter_circle.json")}, {"params", {0.5, 1.5}}}.dump()),
                  "params[1]: 1.5 is outside the curve's domain [0.0, 1.0]");
    expectInvalid(
        runCli({"eval"}, json{{"surface", loadData("quarter_cylinder.json")}, {"params", {{0.5, -0.1}}}}.dump()),
        "params[0][1]: -0.1 is outside");
    expectInvalid(runCli({"eval"}, json{{"curve", loadData("quarter_circle.json")}, {"params", {0.5}}, {"derivatives", 31}}.dump()),
                  "derivatives: must be between 0 and 30");
}
