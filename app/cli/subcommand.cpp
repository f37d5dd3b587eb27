#include "app/cli/subcommand.h"

#include "app/cli/cli_support.h"

#include <algorithm>
#include <stdexcept>

namespace sculptline::cli {
namespace {

// A function-local static, so that registrars in other translation units can run in any order
// during static initialization without touching an unconstructed vector.
std::vector<Subcommand>& registry()
{
    static std::vector<Subcommand> commands;
    return commands;
}

}  // namespace

std::vector<Subcommand> subcommands()
{
    std::vector<Subcommand> sorted = registry();
    std::sort(sorted.begin(), sorted.end(), [](const Subcommand& a, const Subcommand& b) { return a.name < b.name; });
    return sorted;
}

json runOnText(const Subcommand& command, const std::string& text, const Options& options)
{
    const json input = solvers::io::parseJson(text);
    if (!input.is_object()) throw InputError(std::string("input: must be a JSON object, got ") + input.type_name());
    json result = command.run(input, options);
    requireFiniteOutput(result);
    return result;
}

const Subcommand* findSubcommand(const std::string& name)
{
    const auto& commands = registry();
    const auto it = std::find_if(commands.begin(), commands.end(), [&](const Subcommand& c) { return c.name == name; });
    return it == commands.end() ? nullptr : &*it;
}

SubcommandRegistrar::SubcommandRegistrar(Subcommand command)
{
    auto& commands = registry();
    const auto same = [&](const Subcommand& c) { return c.name == command.name; };
    // Two files claiming one name is a programming error; fail loudly at start-up rather than
    // silently running whichever registered last.
    if (std::any_of(commands.begin(), commands.end(), same)) {
        throw std::logic_error("sculptline-cli: subcommand '" + command.name + "' registered twice");
    }
    commands.push_back(std::move(command));
}

}  // namespace sculptline::cli
