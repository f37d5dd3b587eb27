// sculptline-cli remove-knots: removes interior knots while the shape moves by at most the
// tolerance (The NURBS Book A5.8; a bound, not an estimate).
//
//   {"curve": C, "tolerance": e}                          -> {"curve": C', "removed": n, "elapsed_ms": ms}
//   {"surface": S, "direction": "u"|"v", "tolerance": e}  -> {"surface": S', "removed": n, "elapsed_ms": ms}
//
// "tolerance" is in model units, >= 0. Knots that insertion added come out again only up to
// round-off, so undoing an insertion needs a small positive tolerance (e.g. 1e-9).
// Closed curves stay closed (a knot is removed in every period).
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"

namespace sculptline::cli {
namespace {

json run(const json& input, const Options&)
{
    const bool isCurve = curveOrSurface(input) == GeometryKind::Curve;
    const double tolerance = solvers::io::numberFromJson(field(input, "tolerance"), "tolerance");
    if (tolerance < 0) throw InputError("tolerance: must be >= 0, got " + field(input, "tolerance").dump());
    json out;
    int removed = 0;
    if (isCurve) {
        const solvers::Curve3d curve = solvers::io::curveFromJson(field(input, "curve"), "curve");
        const Stopwatch clock;
        const solvers::Curve3d result =
            runOperation(input, "curve", [&] { return curve.removeKnots(tolerance, &removed); });
        const double ms = clock.elapsedMs();
        out["curve"] = solvers::io::toJson(result);
        out["elapsed_ms"] = ms;
    } else {
        const solvers::Surface3d surface = solvers::io::surfaceFromJson(field(input, "surface"), "surface");
        const solvers::Direction direction = directionFromJson(input);
        const Stopwatch clock;
        const solvers::Surface3d result =
            runOperation(input, "surface", [&] { return surface.removeKnots(direction, tolerance, &removed); });
        const double ms = clock.elapsedMs();
        out["surface"] = solvers::io::toJson(result);
        out["elapsed_ms"] = ms;
    }
    out["removed"] = removed;
    return out;
}

const SubcommandRegistrar registrar{
    {"remove-knots", "knot removal within a tolerance: {curve|surface, direction (surface), tolerance} -> "
                     "{curve|surface, removed}",
     &run}};

}  // namespace
}  // namespace sculptline::cli
