#pragma once
// The sculptline-cli subcommand registry. Each subcommand lives in its own file (cmd_<name>.cpp) and
// registers itself with a file-scope SubcommandRegistrar, so adding one is one new source file plus
// one line in app/cli/CMakeLists.txt; main.cpp never changes. cli_commands is an OBJECT library so
// that the linker keeps those otherwise unreferenced registrar objects.
#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace sculptline::cli {

/// Command-line options shared by every subcommand (after `sculptline-cli SUBCOMMAND [INPUT]`).
/// Later subcommands add their own fields here when they need a flag.
struct Options {
    /// --pretty: indent the output JSON (numbers are unchanged: always the shortest round-trip form).
    bool pretty = false;
};

/// One subcommand: input is the parsed top-level JSON object (already checked to be an object); the
/// result is the output object, including "elapsed_ms" (see Stopwatch in cli_support.h).
/// Invalid input is reported by throwing solvers::io::InputError (or solvers::GeometryError) whose
/// message starts with the offending field; main() turns it into exit status 2.
struct Subcommand {
    std::string name;
    std::string help;
    std::function<nlohmann::json(const nlohmann::json& input, const Options& options)> run;
};

/// All registered subcommands, sorted by name.
std::vector<Subcommand> subcommands();

/// What main() does with a subcommand's input text, minus the I/O: parses `text` as JSON, checks it is
/// an object, runs the subcommand and checks the result is finite. The fuzz targets (fuzz/) call
/// this, so they exercise exactly the path of the command line.
/// @throws solvers::io::InputError or solvers::GeometryError for invalid input (exit status 2).
nlohmann::json runOnText(const Subcommand& command, const std::string& text, const Options& options);

/// The registered subcommand called `name`, or nullptr.
const Subcommand* findSubcommand(const std::string& name);

/// Registers at static-initialization time: `const SubcommandRegistrar reg{{"eval", "...", &run}};`
struct SubcommandRegistrar {
    explicit SubcommandRegistrar(Subcommand command);
};

}  // namespace sculptline::cli
