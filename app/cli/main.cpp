// sculptline-cli SUBCOMMAND [INPUT.json|-] [--pretty]
//
// Reads one JSON object (file, or stdin when INPUT is absent or "-"), runs the subcommand and writes
// one JSON object to stdout (../shared/interfaces.md, "sculptline-cli"). Exit status: 0 on success;
// 2 on invalid input or arguments, with exactly one line "sculptline-cli: <field>: <problem>" on
// stderr and nothing on stdout; 1 on an internal error (a bug: input that passed validation made
// the program fail), also with one line on stderr.
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <new>

namespace {

using sculptline::cli::InputError;
using sculptline::cli::json;

constexpr int kExitInvalidInput = 2;
constexpr int kExitInternalError = 1;
// Bounds the memory a runaway input (e.g. `sculptline-cli eval < /dev/zero`) can take, so that the
// program fails fast instead of appearing to hang; far above any real geometry file.
constexpr size_t kMaxInputBytes = size_t{256} << 20;
constexpr size_t kMaxMessageChars = 400;

// The contract promises exactly one stderr line: fold line breaks and cap the length (a message
// may quote part of the input).
int fail(int status, std::string message)
{
    for (char& c : message)
        if (c == '\n' || c == '\r') c = ' ';
    if (message.size() > kMaxMessageChars) message = message.substr(0, kMaxMessageChars) + "...";
    std::cerr << "sculptline-cli: " << message << '\n';
    return status;
}

std::string readAll(FILE* file, const std::string& name)
{
    std::string text;
    char buffer[1 << 16];
    size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0) {
        text.append(buffer, n);
        if (text.size() > kMaxInputBytes) {
            throw InputError("input: " + name + " is larger than " + std::to_string(kMaxInputBytes >> 20) + " MiB");
        }
    }
    if (std::ferror(file)) throw InputError("input: cannot read " + name + ": " + std::strerror(errno));
    return text;
}

std::string readInput(const std::string& path)
{
    if (path.empty() || path == "-") return readAll(stdin, "stdin");
    struct Close {
        void operator()(FILE* f) const { std::fclose(f); }
    };
    const std::unique_ptr<FILE, Close> file(std::fopen(path.c_str(), "rb"));
    if (!file) throw InputError("input: cannot open '" + path + "': " + std::strerror(errno));
    return readAll(file.get(), "'" + path + "'");
}

int runSubcommand(const sculptline::cli::Subcommand& command, const std::string& inputPath,
                  const sculptline::cli::Options& options)
{
    std::string output;
    try {
        const json result = sculptline::cli::runOnText(command, readInput(inputPath), options);
        // nlohmann writes doubles in their shortest round-trip form, so nothing is lost.
        output = result.dump(options.pretty ? 2 : -1);
    } catch (const InputError& e) {
        return fail(kExitInvalidInput, e.what());
    } catch (const sculptline::solvers::GeometryError& e) {
        return fail(kExitInvalidInput, e.what());
    } catch (const std::bad_alloc&) {
        return fail(kExitInvalidInput, "input: too large to process (out of memory)");
    } catch (const std::exception& e) {
        return fail(kExitInternalError, std::string("internal error in ") + command.name + ": " + e.what());
    }
    std::cout << output << '\n' << std::flush;
    if (!std::cout) return fail(kExitInternalError, "output: cannot write to stdout");
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    const std::vector<sculptline::cli::Subcommand> commands = sculptline::cli::subcommands();
    std::string names;
    for (const auto& c : commands) names += (names.empty() ? "" : ", ") + c.name;

    // Checked before CLI11 so that the message names the subcommand the way the contract asks
    // (CLI11 would say "The following arguments were not expected").
    if (argc < 2) return fail(kExitInvalidInput, "subcommand: missing; one of " + names + " (see --help)");
    const std::string first = argv[1];
    const bool known = std::any_of(commands.begin(), commands.end(), [&](const auto& c) { return c.name == first; });
    if (!first.empty() && first[0] != '-' && !known) {
        return fail(kExitInvalidInput, "subcommand: unknown '" + first + "'; one of " + names);
    }

    CLI::App app{"sculptline-cli: Sculptline's geometry kernel from the command line. Reads one JSON object\n"
                 "(INPUT.json, or stdin when INPUT is absent or '-') and writes one JSON object to stdout.\n"
                 "Formats: README.md, section sculptline-cli. Invalid input: exit status 2 and one line on stderr."};
    app.set_version_flag("--version", SCULPTLINE_VERSION);
    app.require_subcommand(1);
    std::string inputPath = "-";
    sculptline::cli::Options options;
    const sculptline::cli::Subcommand* selected = nullptr;
    for (const auto& command : commands) {
        CLI::App* sub = app.add_subcommand(command.name, command.help);
        sub->add_option("input", inputPath, "INPUT.json, or - for stdin (the default)");
        sub->add_flag("--pretty", options.pretty, "indent the output JSON");
        sub->callback([&selected, &command] { selected = &command; });
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        return fail(kExitInvalidInput, std::string("arguments: ") + e.what());
    }
    if (!selected) return fail(kExitInvalidInput, "subcommand: missing; one of " + names);
    return runSubcommand(*selected, inputPath, options);
}
