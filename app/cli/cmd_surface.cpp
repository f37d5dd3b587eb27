// sculptline-cli surface: surfaces from curves in the modes of issue 6 (solvers/surfaces/).
//
//   {"mode": m, "curves": [C..], ...options} -> {"surface": S, "elapsed_ms": t[, "max_deviation": d, "tolerance": e]}
//
// Modes and options (../shared/interfaces.md): fill [2-4 boundaries] ("tolerance": meet tolerance;
// "tangents": [{"curve": index, "surface": S}..] G1 to the adjacent surface S along curves[index],
// "angle_tolerance" in degrees (default 0.1); reports "max_tangent_angle" in degrees);
// revolve [profile] {"axis": {"point", "direction"}, "angle": degrees = 360}; extrude [profile]
// {"direction": [..]} or {"path": C}; sweep [profile, path]; loft [sections..] ("degree": cross
// degree = 3); boundary-rotation [left, right]; rail-rotation [rail 1, rail 2, profile]; gordon
// [u-curves..] with {"v_curves": [v-curves..]} (a grid-like network; "tolerance": meet tolerance,
// reports "max_gap" and the iso-parameters "u_params"/"v_params" of the curves). The
// approximating modes (sweep, boundary-rotation, rail-rotation) take "tolerance" (model units) and
// report "max_deviation". The modes are built by solvers/surfaces/surface_modes (shared with the GUI).
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"
#include "model/surface_recipe.h"
#include "solvers/surfaces/surface_modes.h"

#include <functional>

namespace sculptline::cli {
namespace {

using solvers::Curve3d;
using solvers::Surface3d;
namespace surf = solvers::surfaces;

std::vector<Curve3d> readCurves(const json& input)
{
    const json& curves = field(input, "curves");
    if (!curves.is_array()) throw InputError("curves: expected an array of curves");
    std::vector<Curve3d> out;
    for (size_t k = 0; k < curves.size(); ++k)
        out.push_back(solvers::io::curveFromJson(curves[k], "curves[" + std::to_string(k) + "]"));
    return out;
}

double positiveOption(const json& input, const std::string& key, double fallback)
{
    if (!input.contains(key)) return fallback;
    const double x = solvers::io::numberFromJson(input[key], key);
    if (!(x > 0.0)) throw InputError(key + ": must be positive");
    return x;
}

// The outcome of one mode: the surface, and for approximating modes the deviation reached.
struct Outcome {
    Surface3d surface;
    double deviation = -1.0;
    double tolerance = 0.0;
    json extra = json::object();
};

// Gordon takes two curve families, so it is not one of the shared surface modes.
std::function<Outcome()> prepareGordon(const json& input, const std::vector<Curve3d>& c)
{
    const double tol = positiveOption(input, "tolerance", 0.0);
    const json& vj = field(input, "v_curves");
    if (!vj.is_array()) throw InputError("v_curves: expected an array of curves");
    std::vector<Curve3d> v;
    for (size_t k = 0; k < vj.size(); ++k)
        v.push_back(solvers::io::curveFromJson(vj[k], "v_curves[" + std::to_string(k) + "]"));
    return [c, v, tol] {
        const surf::GordonResult g = surf::buildGordon(c, v, surf::GordonOptions{tol});
        return Outcome{g.surface, -1.0, 0.0, json{{"max_gap", g.maxGap}, {"u_params", g.uParams}, {"v_params", g.vParams}}};
    };
}

// Input is read and checked before the clock starts; `build` runs timed (solvers/surfaces/surface_modes).
std::function<Outcome()> prepare(const std::string& name, const json& input, const std::vector<Curve3d>& c)
{
    // The model's construction table (model/surface_recipe.h) names the modes; a network is a mesh
    // (the network subcommand), not a surface.
    const std::optional<model::Construction> construction = model::constructionFromName(name);
    if (!construction || model::describe(*construction).makesMesh) {
        throw InputError("mode: unknown mode \"" + name +
                         "\" (fill, revolve, extrude, sweep, loft, boundary-rotation, rail-rotation, gordon)");
    }
    const model::ConstructionInfo& info = model::describe(*construction);
    if (*construction == model::Construction::Gordon) return prepareGordon(input, c);
    // Every mode that approximates reads "tolerance" before anything else (the order of the checks
    // decides which of several mistakes is reported).
    const double tolerance = (info.options & model::kToleranceOption) ? positiveOption(input, "tolerance", 0.0) : 0.0;
    const surf::SurfaceMode mode = *info.solverMode;
    try {
        surf::checkCurveCount(mode, c.size());
    } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
    }
    surf::SurfaceOptions o;
    switch (mode) {
    case surf::SurfaceMode::Fill:
        o.tolerance = positiveOption(input, "tolerance", 0.0);
        if (input.contains("tangents")) {
            const json& tj = input["tangents"];
            if (!tj.is_array() || tj.empty())
                throw InputError("tangents: expected a non-empty array of {\"curve\": index, \"surface\": S}");
            for (size_t k = 0; k < tj.size(); ++k) {
                const std::string path = "tangents[" + std::to_string(k) + "]";
                if (!tj[k].is_object()) throw InputError(path + ": expected {\"curve\": index, \"surface\": S}");
                const int curve = solvers::io::integerFromJson(solvers::io::member(tj[k], "curve", path), path + ".curve", 0,
                                                               static_cast<int>(c.size()) - 1);
                o.fillTangents.push_back(
                    {curve, solvers::io::surfaceFromJson(solvers::io::member(tj[k], "surface", path), path + ".surface")});
            }
        }
        if (input.contains("angle_tolerance")) {
            o.fillAngleToleranceDegrees = solvers::io::numberFromJson(input["angle_tolerance"], "angle_tolerance");
            if (!(o.fillAngleToleranceDegrees > 0.0 && o.fillAngleToleranceDegrees < 90.0))
                throw InputError("angle_tolerance: must be in (0, 90) degrees");
        }
        break;
    case surf::SurfaceMode::Revolve: {
        const json& axis = field(input, "axis");
        if (!axis.is_object()) throw InputError("axis: expected {\"point\": [..], \"direction\": [..]}");
        o.axisPoint = solvers::io::pointFromJson(solvers::io::member(axis, "point", "axis"), "axis.point");
        o.axisDirection = solvers::io::pointFromJson(solvers::io::member(axis, "direction", "axis"), "axis.direction");
        if (input.contains("angle")) o.angleDegrees = solvers::io::numberFromJson(input["angle"], "angle");
        break;
    }
    case surf::SurfaceMode::Extrude:
        if (input.contains("direction") == input.contains("path"))
            throw InputError("direction: extrude needs exactly one of \"direction\" and \"path\"");
        if (input.contains("direction")) o.direction = solvers::io::pointFromJson(input["direction"], "direction");
        else o.extrudePath = solvers::io::curveFromJson(input["path"], "path");
        break;
    case surf::SurfaceMode::Loft:
        if (input.contains("degree")) o.loftDegree = solvers::io::integerFromJson(input["degree"], "degree", 1, 9);
        break;
    case surf::SurfaceMode::Sweep:
    case surf::SurfaceMode::BoundaryRotation:
    case surf::SurfaceMode::RailRotation: o.tolerance = tolerance; break;
    }
    return [mode, c, o] {
        const surf::SurfaceBuild b = surf::buildSurface(mode, c, o);
        json extra = json::object();
        if (b.maxTangentAngleDegrees >= 0.0)
            extra = {{"max_tangent_angle", b.maxTangentAngleDegrees}, {"angle_tolerance", o.fillAngleToleranceDegrees}};
        return Outcome{b.surface, b.maxDeviation, b.tolerance, extra};
    };
}

json run(const json& input, const Options&)
{
    const json& modeJson = field(input, "mode");
    if (!modeJson.is_string()) throw InputError("mode: expected a string");
    const std::vector<Curve3d> curves = readCurves(input);
    const std::function<Outcome()> build = prepare(modeJson.get<std::string>(), input, curves);
    const Stopwatch clock;
    const Outcome r = [&] {
        try {
            return build();
        } catch (const std::invalid_argument& e) {
            throw InputError(e.what());  // messages name "curves[..]", "axis", "angle", "direction", "path"
        }
    }();
    const double ms = clock.elapsedMs();
    json out;
    out["surface"] = solvers::io::toJson(r.surface);
    if (r.deviation >= 0.0) {
        out["max_deviation"] = r.deviation;
        out["tolerance"] = r.tolerance;
    }
    for (const auto& [key, value] : r.extra.items()) out[key] = value;
    out["elapsed_ms"] = ms;
    requireFiniteOutput(out);
    return out;
}

const SubcommandRegistrar registrar{
    {"surface", "surface from curves: {mode, curves, ..} -> {surface} (fill, revolve, extrude, sweep, loft, "
                "boundary-rotation, rail-rotation, gordon)",
     &run}};

}  // namespace
}  // namespace sculptline::cli
