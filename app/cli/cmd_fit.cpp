// sculptline-cli fit: a pen stroke to a cubic B-spline (issue 3; thesis ch. 4 §4.1).
//
//   {"stroke": K, "tolerance": e, "resolution": q, "closed": "auto"|"open"|"closed",
//    "sampling": "dynamic"|"all", "minimize_control_points": b}
//   -> {"curve": C, "corners": [i..], "samples": [i..], "max_error": e, "tolerance": e, "closed": b,
//       "converged": b, "warnings": [..], "elapsed_ms": t}
//
// tolerance is optional (default 0.5 % of the stroke's extent, but at least resolution: the pitch
// the samples are quantized to, e.g. one pixel's footprint; 0 or absent = unknown); corners and samples are indices
// into the input stroke's points. minimize_control_points (default false) tries to remove every
// knot after the fit, not only the last round's: fewer control points, ~2x the time.
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"
#include "solvers/stroke/stroke_json.h"

namespace sculptline::cli {
namespace {

namespace stroke = solvers::stroke;

stroke::FitOptions fitOptions(const json& input)
{
    stroke::FitOptions o;
    o.tolerance = optionalLength(input, "tolerance", 0.0, false);
    o.resolution = optionalLength(input, "resolution", 0.0, true);
    if (input.contains("closed")) {
        const json& c = input["closed"];
        if (c == "auto") o.conditioning.closure = stroke::Closure::Auto;
        else if (c == "open") o.conditioning.closure = stroke::Closure::Open;
        else if (c == "closed") o.conditioning.closure = stroke::Closure::Closed;
        else throw InputError("closed: must be \"auto\", \"open\" or \"closed\"");
    }
    if (input.contains("minimize_control_points")) {
        const json& m = input["minimize_control_points"];
        if (!m.is_boolean()) throw InputError("minimize_control_points: must be true or false");
        o.spline.removal = m.get<bool>() ? stroke::KnotRemoval::AllKnots : stroke::KnotRemoval::LastRound;
    }
    if (input.contains("sampling")) {
        const json& s = input["sampling"];
        if (s != "dynamic" && s != "all") throw InputError("sampling: must be \"dynamic\" or \"all\"");
        o.dynamicSampling = s == "dynamic";
    }
    return o;
}

json run(const json& input, const Options&)
{
    const stroke::Stroke k = stroke::strokeFromJson(field(input, "stroke"), "stroke");
    const stroke::FitOptions o = fitOptions(input);

    const Stopwatch clock;
    stroke::FitResult r = [&] {
        try {
            return stroke::fitStroke(k, o);
        } catch (const solvers::GeometryError& e) {
            throw InputError(e.what());  // the messages name "stroke.points[i]", "stroke.times", "tolerance"
        }
    }();
    const double ms = clock.elapsedMs();

    json out = stroke::fitResultToJson(r, k.dimension);
    out["elapsed_ms"] = ms;
    return out;
}

const SubcommandRegistrar registrar{
    {"fit", "stroke to cubic B-spline: {stroke, tolerance?, resolution?} -> {curve, corners, samples, max_error}", &run}};

}  // namespace
}  // namespace sculptline::cli
