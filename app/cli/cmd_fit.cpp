// sculptline-cli fit: a pen stroke to a cubic B-spline (issue 3; thesis ch. 4 §4.1).
//
//   {"stroke": K, "tolerance": e, "resolution": q, "closed": "auto"|"open"|"closed",
//    "sampling": "dynamic"|"all", "minimize_control_points": b}
//   -> {"curve": C, "corners": [i..], "samples": [i..], "max_error": e, "tolerance": e, "closed": b,
//       "converged": b, "warnings": [..], "elapsed_ms": t[, "elapsed_ms_min": t]}
//
// "repeat": n (optional, 1 to 100, default 1) fits the stroke n times for timing: elapsed_ms is the
// first fit's (the cold call, as when the pen lifts) and elapsed_ms_min the fastest of the n (warm);
// every fit gives the same result. scripts/compare_splprep.py --time compares it with the peers'.
//
// tolerance is optional (default 0.5 % of the stroke's extent, but at least resolution: the pitch
// the samples are quantized to, e.g. one pixel's footprint; 0 or absent = unknown); corners and samples are indices
// into the input stroke's points. minimize_control_points (default false) makes the search for
// fewer control points count up from the least instead of predicting the count
// (FitOptions::countUp): the fewest the averaged knots allow, for up to 3x the time on long strokes.
// Every knot is tried for removal after an error-driven fit in both modes (since session 40).
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"
#include "solvers/stroke/stroke_json.h"

#include <algorithm>
#include <string>

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
        o.countUp = m.get<bool>();
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

    constexpr int kMaxRepeat = 100;  // (a fuzzer that finds the field should not multiply its time by more)
    int repeat = 1;
    if (input.contains("repeat")) {
        const json& n = input["repeat"];
        if (!n.is_number_integer() || n.get<long long>() < 1 || n.get<long long>() > kMaxRepeat)
            throw InputError("repeat: must be an integer from 1 to " + std::to_string(kMaxRepeat));
        repeat = n.get<int>();
    }
    const auto fitOnce = [&] {
        try {
            return stroke::fitStroke(k, o);
        } catch (const solvers::GeometryError& e) {
            throw InputError(e.what());  // the messages name "stroke.points[i]", "stroke.times", "tolerance"
        }
    };
    const Stopwatch clock;
    stroke::FitResult r = fitOnce();
    const double ms = clock.elapsedMs();
    double fastest = ms;
    for (int i = 1; i < repeat; ++i) {
        const Stopwatch again;
        const stroke::FitResult warm = fitOnce();
        fastest = std::min(fastest, again.elapsedMs());
    }

    json out = stroke::fitResultToJson(r, k.dimension);
    out["elapsed_ms"] = ms;
    if (repeat > 1) out["elapsed_ms_min"] = fastest;
    return out;
}

const SubcommandRegistrar registrar{
    {"fit", "stroke to cubic B-spline: {stroke, tolerance?, resolution?} -> {curve, corners, samples, max_error}", &run}};

}  // namespace
}  // namespace sculptline::cli
