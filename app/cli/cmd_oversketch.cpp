// sculptline-cli oversketch: redraw part of a curve with a stroke (issue 4; solvers/editing/oversketch.h).
//
//   {"curve": C, "stroke": K, "method": "blend" | "local-c2", "scale": s, "tolerance": e}
//     -> {"curve": C', "span": [u0, u1], "method": m, "max_error": d, "elapsed_ms": t}
//
// "method" defaults to local-c2 (chosen by measurement, see solvers/editing/oversketch.cpp); "scale"
// (blend only, eq. 4-23 of the thesis) defaults to 1; "tolerance" is a fraction of the stroke's
// length (default 0.002).
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"
#include "solvers/editing/oversketch.h"

namespace sculptline::cli {
namespace {

json run(const json& input, const Options&)
{
    const solvers::Curve3d curve = solvers::io::curveFromJson(field(input, "curve"), "curve");
    const json& stroke = field(input, "stroke");
    const std::vector<Eigen::Vector3d> points =
        pointArray(solvers::io::member(stroke, "points", "stroke"), "stroke.points");
    if (points.empty()) throw InputError("stroke.points: empty, a stroke needs points");
    solvers::editing::OversketchOptions options;
    if (input.contains("method")) {
        const json& m = input["method"];
        const auto parsed =
            m.is_string() ? solvers::editing::parseOversketchMethod(m.get<std::string>()) : std::nullopt;
        if (!parsed) throw InputError("method: expected \"blend\" or \"local-c2\", got " + solvers::io::describeValue(m));
        options.method = *parsed;
    }
    if (input.contains("scale")) options.scale = solvers::io::numberFromJson(input["scale"], "scale");
    if (input.contains("tolerance")) options.tolerance = solvers::io::numberFromJson(input["tolerance"], "tolerance");
    if (options.scale < 0.0 || options.scale > 1.0) throw InputError("scale: must be in [0, 1]");
    if (!(options.tolerance > 0.0 && options.tolerance < 1.0)) throw InputError("tolerance: must be in (0, 1)");

    const Stopwatch clock;
    std::pair<double, double> span;
    double maxError = 0.0;
    solvers::Curve3d result = curve;
    try {
        result = solvers::editing::oversketch(curve, points, options, &span, &maxError);
    } catch (const solvers::GeometryError& e) {
        // Editing messages start with the input member they concern ("stroke...", "curve...").
        const std::string message = e.what();
        const std::string top = message.substr(0, message.find_first_of(".:["));
        throw InputError(input.contains(top) ? message : "curve." + message);
    }
    const double ms = clock.elapsedMs();
    json out;
    out["curve"] = solvers::io::toJson(result);
    out["span"] = json::array({span.first, span.second});
    out["method"] = options.method == solvers::editing::OversketchMethod::LocalC2 ? "local-c2" : "blend";
    out["max_error"] = maxError;
    out["elapsed_ms"] = ms;
    requireFiniteOutput(out);
    return out;
}

const SubcommandRegistrar registrar{
    {"oversketch", "over-sketching: {curve, stroke, method, scale} -> {curve, span, max_error}", &run}};

}  // namespace
}  // namespace sculptline::cli
