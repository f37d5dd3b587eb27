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
    const double tolerance = solvers::io::numberFromJson(field(input, "tolerance"), "tolerance");
    if (tolerance < 0) throw InputError("tolerance: must be >= 0, got " + solvers::io::describeValue(field(input, "tolerance")));
    int removed = 0;
    json out = transformGeometry(
        input, [&](const solvers::Curve3d& c) { return c.removeKnots(tolerance, &removed); },
        [&](const solvers::Surface3d& s, solvers::Direction d) { return s.removeKnots(d, tolerance, &removed); });
    out["removed"] = removed;
    return out;
}

const SubcommandRegistrar registrar{
    {"remove-knots", "knot removal within a tolerance: {curve|surface, direction (surface), tolerance} -> "
                     "{curve|surface, removed}",
     &run}};

}  // namespace
}  // namespace sculptline::cli
