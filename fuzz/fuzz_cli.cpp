// One fuzz target per sculptline-cli subcommand; SCULPTLINE_FUZZ_SUBCOMMAND names it (fuzz/CMakeLists.txt).
// Bytes go through cli::runOnText, main()'s own path from the input text to the output object (parse,
// object check, the subcommand's run(), finite output), and the output is serialized as main()
// prints it. Rejected input (InputError, GeometryError: exit status 2) is fine; any other exception
// is main()'s "internal error" (exit status 1, a bug by the README's contract) and a finding.
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"
#include "fuzz/fuzz_target.h"

#include <cstring>
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

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static const cli::Subcommand* const command = cli::findSubcommand(SCULPTLINE_FUZZ_SUBCOMMAND);
    if (!command) fuzz::fuzzFailure("setup", "no subcommand " SCULPTLINE_FUZZ_SUBCOMMAND);
    const std::string text(reinterpret_cast<const char*>(data), size);
    if (writesFiles(text)) return 0;
    try {
        const nlohmann::json output = cli::runOnText(*command, text, cli::Options{});
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
