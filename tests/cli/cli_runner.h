#pragma once
// Runs the real sculptline-cli binary (its path comes from the build as SCULPTLINE_CLI_PATH) with
// stdin from a string and stdout/stderr captured, and loads the JSON fixtures in tests/cli/data.
#include "solvers/io/geometry_json.h"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace sculptline::cli_test {

using nlohmann::json;

struct CliResult {
    /// Exit status; -signal when the program was killed by a signal (a crash), -1000 on time-out.
    int status = 0;
    std::string out;
    std::string err;
};

constexpr int kTimedOut = -1000;

/// Runs `sculptline-cli args...` without a shell (posix_spawn), feeding `stdinText`; gives up after
/// a generous time limit so that a hang fails the test instead of blocking the suite.
CliResult runCli(const std::vector<std::string>& args, const std::string& stdinText = "");

/// Runs a subcommand on `input` (via stdin), expects exit status 0 and empty stderr, and returns the
/// parsed stdout (a JSON object; empty object after a failed expectation).
json runOk(const std::string& subcommand, const json& input);

/// A fixture from tests/cli/data/<name>.
json loadData(const std::string& name);
std::string dataPath(const std::string& name);

/// A path in this process's scratch directory (created on first use, removed at exit).
std::string scratchPath(const std::string& name);

/// Points [[x, y, z], ..] from a CLI output array.
std::vector<Eigen::Vector3d> pointsOf(const json& array);

/// `count` evenly spaced values from a to b inclusive.
std::vector<double> linspace(double a, double b, int count);

}  // namespace sculptline::cli_test
