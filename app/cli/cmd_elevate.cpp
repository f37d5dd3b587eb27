// sculptline-cli elevate: degree elevation (The NURBS Book A5.9), shape unchanged.
//
//   {"curve": C, "times": t}                          -> {"curve": C', "elapsed_ms": ms}
//   {"surface": S, "direction": "u"|"v", "times": t}  -> {"surface": S', "elapsed_ms": ms}
//
// "times" is optional (default 1); the elevated degree may not exceed kMaxDegree. Curves and
// surfaces with unclamped ends come back clamped (A5.9 works on clamped knot vectors).
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"

namespace sculptline::cli {
namespace {

json run(const json& input, const Options&)
{
    const int times =
        input.contains("times") ? solvers::io::integerFromJson(input["times"], "times", 0, solvers::kMaxDegree) : 1;
    return transformGeometry(
        input, [&](const solvers::Curve3d& c) { return c.elevate(times); },
        [&](const solvers::Surface3d& s, solvers::Direction d) { return s.elevate(d, times); });
}

const SubcommandRegistrar registrar{
    {"elevate", "degree elevation: {curve|surface, direction (surface), times} -> {curve|surface}", &run}};

}  // namespace
}  // namespace sculptline::cli
