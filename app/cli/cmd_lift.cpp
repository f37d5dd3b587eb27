// sculptline-cli lift: a 2D stroke and its end depths -> the minimum-curvature space curve (seed 004
// §3; solvers/editing/lift.h).
//
//   {"stroke": K (2D), "depth": [z0, z1], "view": V} -> {"curve": C (3D), "critical": [indices], "fit_error": d,
//   "elapsed_ms": t}
//
// The stroke is in view coordinates (x right, y up; a z coordinate is ignored) and depth runs along
// the view direction. The optional "view" {"origin": p, "right": r, "up": u, "depth": d} maps a view
// point (x, y, z) to origin + x·right + y·up + z·depth (orthographic; default: the identity).
// "critical" indexes the stroke resampled to 200 points equally spaced by arc length.
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"
#include "solvers/editing/lift.h"

namespace sculptline::cli {
namespace {

json run(const json& input, const Options&)
{
    const json& stroke = field(input, "stroke");
    const std::vector<Eigen::Vector3d> points =
        pointArray(solvers::io::member(stroke, "points", "stroke"), "stroke.points");
    if (points.empty()) throw InputError("stroke.points: empty, a stroke needs points");
    const std::vector<double> depth = numberArray(field(input, "depth"), "depth");
    if (depth.size() != 2)
        throw InputError("depth: expected [z0, z1], got " + std::to_string(depth.size()) + " numbers");
    solvers::editing::ViewFrame view;
    if (input.contains("view")) {
        const json& v = input["view"];
        if (!v.is_object()) throw InputError("view: expected an object {origin, right, up, depth}");
        if (v.contains("origin")) view.origin = solvers::io::pointFromJson(v["origin"], "view.origin");
        if (v.contains("right")) view.right = solvers::io::pointFromJson(v["right"], "view.right");
        if (v.contains("up")) view.up = solvers::io::pointFromJson(v["up"], "view.up");
        if (v.contains("depth")) view.depth = solvers::io::pointFromJson(v["depth"], "view.depth");
    }
    std::vector<Eigen::Vector2d> flat;
    for (const auto& p : points) flat.emplace_back(p.x(), p.y());

    const Stopwatch clock;
    const solvers::editing::LiftResult r = [&] {
        try {
            return solvers::editing::liftStroke(flat, depth[0], depth[1], {}, view);
        } catch (const solvers::GeometryError& e) {
            throw InputError(e.what());  // messages name "stroke..." or "depth"
        }
    }();
    const double ms = clock.elapsedMs();
    json out;
    out["curve"] = solvers::io::toJson(r.curve);
    out["critical"] = r.critical;
    out["fit_error"] = r.fitError;
    out["elapsed_ms"] = ms;
    requireFiniteOutput(out);
    return out;
}

const SubcommandRegistrar registrar{{"lift", "2D stroke to space curve: {stroke, depth: [z0, z1]} -> {curve}", &run}};

}  // namespace
}  // namespace sculptline::cli
