// sculptline-cli surface: surfaces from curves in the modes of issue 6 (solvers/surfaces/).
//
//   {"mode": m, "curves": [C..], ...options} -> {"surface": S, "elapsed_ms": t[, "max_deviation": d, "tolerance": e]}
//
// Modes and options (../shared/interfaces.md): fill [2-4 boundaries] ("tolerance": meet tolerance);
// revolve [profile] {"axis": {"point", "direction"}, "angle": degrees = 360}; extrude [profile]
// {"direction": [..]} or {"path": C}; sweep [profile, path]; loft [sections..] ("degree": cross
// degree = 3); boundary-rotation [left, right]; rail-rotation [rail 1, rail 2, profile]; gordon
// [u-curves..] with {"v_curves": [v-curves..]} (a grid-like network; "tolerance": meet tolerance,
// reports "max_gap" and the iso-parameters "u_params"/"v_params" of the curves). The
// approximating modes (sweep, boundary-rotation, rail-rotation) take "tolerance" (model units) and
// report "max_deviation". G1 "tangents" for fill are not implemented and are refused.
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"
#include "solvers/surfaces/boundary_rotation.h"
#include "solvers/surfaces/coons_fill.h"
#include "solvers/surfaces/extrude.h"
#include "solvers/surfaces/gordon.h"
#include "solvers/surfaces/loft.h"
#include "solvers/surfaces/rail_rotation.h"
#include "solvers/surfaces/revolve.h"
#include "solvers/surfaces/sweep.h"

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

void requireCount(const std::vector<Curve3d>& curves, size_t lo, size_t hi, const std::string& what)
{
    if (curves.size() < lo || curves.size() > hi)
        throw InputError("curves: mode needs " + what + ", got " + std::to_string(curves.size()) + " curves");
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

// Input is read and checked before the clock starts; `build` runs timed.
std::function<Outcome()> prepare(const std::string& mode, const json& input, const std::vector<Curve3d>& c)
{
    if (mode == "fill") {
        requireCount(c, 2, 4, "2, 3 or 4 boundary curves");
        if (input.contains("tangents")) throw InputError("tangents: G1 tangent conditions for fill are not implemented");
        surf::FillOptions o;
        o.meetTolerance = positiveOption(input, "tolerance", 0.0);
        return [c, o] { return Outcome{surf::fill(c, o)}; };
    }
    if (mode == "revolve") {
        requireCount(c, 1, 1, "one profile curve");
        const json& axis = field(input, "axis");
        if (!axis.is_object()) throw InputError("axis: expected {\"point\": [..], \"direction\": [..]}");
        const surf::Axis a{solvers::io::pointFromJson(solvers::io::member(axis, "point", "axis"), "axis.point"),
                           solvers::io::pointFromJson(solvers::io::member(axis, "direction", "axis"), "axis.direction")};
        const double angle = input.contains("angle") ? solvers::io::numberFromJson(input["angle"], "angle") : 360.0;
        return [c, a, angle] { return Outcome{surf::revolve(c[0], a, angle)}; };
    }
    if (mode == "extrude") {
        requireCount(c, 1, 1, "one profile curve");
        if (input.contains("direction") == input.contains("path"))
            throw InputError("direction: extrude needs exactly one of \"direction\" and \"path\"");
        if (input.contains("direction")) {
            const Eigen::Vector3d d = solvers::io::pointFromJson(input["direction"], "direction");
            return [c, d] { return Outcome{surf::extrude(c[0], d)}; };
        }
        const Curve3d path = solvers::io::curveFromJson(input["path"], "path");
        return [c, path] { return Outcome{surf::extrude(c[0], path)}; };
    }
    if (mode == "loft") {
        surf::LoftOptions o;
        if (input.contains("degree")) o.crossDegree = solvers::io::integerFromJson(input["degree"], "degree", 1, 9);
        return [c, o] { return Outcome{surf::loft(c, o)}; };
    }
    const double tol = positiveOption(input, "tolerance", 0.0);
    if (mode == "gordon") {
        const json& vj = field(input, "v_curves");
        if (!vj.is_array()) throw InputError("v_curves: expected an array of curves");
        std::vector<Curve3d> v;
        for (size_t k = 0; k < vj.size(); ++k)
            v.push_back(solvers::io::curveFromJson(vj[k], "v_curves[" + std::to_string(k) + "]"));
        return [c, v, tol] {
            const surf::GordonResult g = surf::gordon(c, v, surf::GordonOptions{tol});
            return Outcome{g.surface, -1.0, 0.0,
                           json{{"max_gap", g.maxGap}, {"u_params", g.uParams}, {"v_params", g.vParams}}};
        };
    }
    if (mode == "sweep") {
        requireCount(c, 2, 2, "[profile, path]");
        return [c, tol] {
            try {
                const surf::SweepResult r = surf::sweep(c[0], c[1], surf::SweepOptions{tol, 513});
                return Outcome{r.surface, r.maxDeviation, r.tolerance};
            } catch (const solvers::GeometryError& e) {
                const std::string m = e.what();
                // The sweep names its path "path"; here the path is curves[1].
                throw InputError(m.rfind("path:", 0) == 0 ? "curves[1] (path):" + m.substr(5) : m);
            }
        };
    }
    if (mode == "boundary-rotation") {
        requireCount(c, 2, 2, "[left outline, right outline]");
        return [c, tol] {
            const surf::ApproximatedSurface r = surf::boundaryRotation(c[0], c[1], {tol, 2049});
            return Outcome{r.surface, r.maxDeviation, r.tolerance};
        };
    }
    if (mode == "rail-rotation") {
        requireCount(c, 3, 3, "[rail 1, rail 2, profile]");
        return [c, tol] {
            const surf::ApproximatedSurface r = surf::railRotation(c[0], c[1], c[2], {tol, 2049});
            return Outcome{r.surface, r.maxDeviation, r.tolerance};
        };
    }
    throw InputError("mode: unknown mode \"" + mode +
                     "\" (fill, revolve, extrude, sweep, loft, boundary-rotation, rail-rotation, gordon)");
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
        } catch (const solvers::GeometryError& e) {
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
