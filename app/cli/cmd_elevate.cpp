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
    const bool isCurve = curveOrSurface(input) == GeometryKind::Curve;
    const int times =
        input.contains("times") ? solvers::io::integerFromJson(input["times"], "times", 0, solvers::kMaxDegree) : 1;
    json out;
    if (isCurve) {
        const solvers::Curve3d curve = solvers::io::curveFromJson(field(input, "curve"), "curve");
        const Stopwatch clock;
        const solvers::Curve3d result = runOperation(input, "curve", [&] { return curve.elevate(times); });
        const double ms = clock.elapsedMs();
        out["curve"] = solvers::io::toJson(result);
        out["elapsed_ms"] = ms;
    } else {
        const solvers::Surface3d surface = solvers::io::surfaceFromJson(field(input, "surface"), "surface");
        const solvers::Direction direction = directionFromJson(input);
        const Stopwatch clock;
        const solvers::Surface3d result =
            runOperation(input, "surface", [&] { return surface.elevate(direction, times); });
        const double ms = clock.elapsedMs();
        out["surface"] = solvers::io::toJson(result);
        out["elapsed_ms"] = ms;
    }
    return out;
}

const SubcommandRegistrar registrar{
    {"elevate", "degree elevation: {curve|surface, direction (surface), times} -> {curve|surface}", &run}};

}  // namespace
}  // namespace sculptline::cli
