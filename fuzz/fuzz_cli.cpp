// One fuzz target per sculptline-cli subcommand; SCULPTLINE_FUZZ_SUBCOMMAND names it (fuzz/CMakeLists.txt).
// Bytes go through cli::runOnText, main()'s own path from the input text to the output object (parse,
// object check, the subcommand's run(), finite output), and the output is serialized as main()
// prints it. Rejected input (InputError, GeometryError: exit status 2) is fine; any other exception
// is main()'s "internal error" (exit status 1, a bug by the README's contract) and a finding.
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"
#include "fuzz/fuzz_target.h"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdlib.h>
#include <exception>

namespace {

using namespace sculptline;

// recognize writes the learned user model back to a "user_model" given as a file path: a fuzzer
// must not write files wherever its input says, so such inputs are skipped (the object form is fuzzed).
bool writesFiles(const std::string& text)
{
    if (std::strcmp(SCULPTLINE_FUZZ_SUBCOMMAND, "recognize") != 0) return false;
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    return j.is_object() && j.contains("user_model") && !j["user_model"].is_object();
}

// export writes the file its input names: a fuzzer must not write wherever that is. A string
// "path" goes to one file in a private temporary directory (removed at exit), so the writers run on
// every input; a path that is not a string is kept (refused before anything is written). The path
// checks themselves (directories, missing parents) are covered by export_cli_test. The input is
// edited after parsing, not re-serialized (dump() recurses on nesting): runOnText's steps are
// repeated here with the one change.
bool isExport() { return std::strcmp(SCULPTLINE_FUZZ_SUBCOMMAND, "export") == 0; }

nlohmann::json runExport(const cli::Subcommand& command, const std::string& text)
{
    nlohmann::json input = solvers::io::parseJson(text);
    if (!input.is_object()) throw solvers::io::InputError("input: must be a JSON object");
    if (input.contains("path") && input["path"].is_string()) {
        static const std::string path = [] {
            std::string templ = (std::filesystem::temp_directory_path() / "sculptline-fuzz-export-XXXXXX").string();
            if (!mkdtemp(templ.data())) fuzz::fuzzFailure("setup", "cannot create a temporary directory");
            static std::string dir = templ;
            std::atexit([] { std::error_code ec; std::filesystem::remove_all(dir, ec); });
            return (std::filesystem::path(templ) / "out").string();
        }();
        input["path"] = path;
    }
    nlohmann::json result = command.run(input, cli::Options{});
    cli::requireFiniteOutput(result);
    return result;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static const cli::Subcommand* const command = cli::findSubcommand(SCULPTLINE_FUZZ_SUBCOMMAND);
    if (!command) fuzz::fuzzFailure("setup", "no subcommand " SCULPTLINE_FUZZ_SUBCOMMAND);
    const std::string text(reinterpret_cast<const char*>(data), size);
    if (writesFiles(text)) return 0;
    try {
        const nlohmann::json output =
            isExport() ? runExport(*command, text) : cli::runOnText(*command, text, cli::Options{});
        if (output.dump().empty()) fuzz::fuzzFailure(SCULPTLINE_FUZZ_SUBCOMMAND, "empty output");
    } catch (const solvers::io::InputError& e) {
        fuzz::noteRejected(e.what());
    } catch (const solvers::GeometryError& e) {
        fuzz::noteRejected(e.what());
    } catch (const std::exception& e) {
        fuzz::fuzzFailure(SCULPTLINE_FUZZ_SUBCOMMAND, std::string("internal error (exit status 1): ") + e.what());
    }
    return 0;
}
