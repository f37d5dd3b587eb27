// sculptline-cli deform: constraint-based surface deformation (thesis 002_d9515b9d07f9cfd1 §6.2;
// solvers/deformation/surface_deformation.h).
//
//   {"surface": S, "constraints": [..], "bound"?: closed curve (2D points: domain (u, v); 3D: projected
//    onto the surface), "stiffness"?: λ in (0, 1], "blocked"?: [[i, j]..], "objective"?:
//    "displacement" | "force" (default), "method"?: "global" (default) | "isocurves" (thesis eqs.
//    6-17, 6-18: position and curve constraints only; the objective is not used)}
//     -> {"surface": S', "residuals": [..], "max_residual", "moved", "key_points": [[x, y, z]..],
//         "compromise", "message"?, "rank", "rows", "elapsed_ms"}
//
// Constraints (../shared/interfaces.md): position {uv, value}, normal {uv, value}, curve {target,
// domain?, key_points?}, curve-tangent {domain, value, key_points?}, distance {uv, uv2, value}; and
// (README) tangents {uv, du, dv}: the tangent values S_u, S_v there (Table 6-1); angle {uv, value,
// angle}: the normal there makes `angle` degrees with value (non-linear, chord-Newton steps).
// Residuals: model units for position, curve (largest over the key points) and distance; radians
// for normal and curve-tangent (at stiffness 1).
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"
#include "solvers/bspline/projection.h"
#include "solvers/deformation/isocurve_deformation.h"
#include "solvers/deformation/surface_deformation.h"
#include "solvers/math_constants.h"

#include <cmath>

namespace sculptline::cli {
namespace {

namespace dfm = solvers::deformation;

// A bound curve's ends must meet to within this fraction of its size (round-off of a written file).
constexpr double kClosedRelativeTolerance = 1e-9;
// Bound polygon: samples of the bound curve per knot span, and at most kMaxBoundSamples in all (each
// 3D sample is one global projection; 4096 keeps the polygon finer than any net's Greville grid
// while bounding the time a hostile input with thousands of spans can take).
constexpr int kBoundSamplesPerSpan = 32;
constexpr int kMaxBoundSamples = 4096;

Eigen::Vector2d uvFromJson(const json& j, const std::string& path, const solvers::Surface3d& s)
{
    if (!j.is_array() || j.size() != 2) throw InputError(path + ": expected [u, v]");
    const Eigen::Vector2d uv(solvers::io::numberFromJson(j[0], path + "[0]"),
                             solvers::io::numberFromJson(j[1], path + "[1]"));
    if (uv.x() < s.domainStart(solvers::Direction::U) || uv.x() > s.domainEnd(solvers::Direction::U) ||
        uv.y() < s.domainStart(solvers::Direction::V) || uv.y() > s.domainEnd(solvers::Direction::V)) {
        throw InputError(path + ": " + j.dump() + " is outside the surface's domain [" +
                         json(s.domainStart(solvers::Direction::U)).dump() + ", " +
                         json(s.domainEnd(solvers::Direction::U)).dump() + "] x [" +
                         json(s.domainStart(solvers::Direction::V)).dump() + ", " +
                         json(s.domainEnd(solvers::Direction::V)).dump() + "]");
    }
    return uv;
}

bool isPlanarJson(const json& curve)
{
    return curve.is_object() && curve.contains("points") && curve["points"].is_array() && !curve["points"].empty() &&
           curve["points"][0].is_array() && curve["points"][0].size() == 2;
}

solvers::BSplineCurve<2> domainCurve(const json& j, const std::string& path, const solvers::Surface3d& s)
{
    const solvers::Curve3d c = solvers::io::curveFromJson(j, path);
    std::vector<Eigen::Vector2d> pts;
    for (const auto& p : c.points()) pts.emplace_back(p.x(), p.y());
    solvers::BSplineCurve<2> g(c.degree(), c.knots(), pts, c.weights(), c.isClosed());
    // The domain curve must stay in the domain: its control polygon bounds it (convex hull).
    for (size_t i = 0; i < pts.size(); ++i) uvFromJson(json::array({pts[i].x(), pts[i].y()}), path + ".points[" + std::to_string(i) + "]", s);
    return g;
}

std::vector<dfm::SurfaceConstraint> constraintsFromJson(const json& j, const solvers::Surface3d& s)
{
    if (!j.is_array()) throw InputError("constraints: expected an array");
    std::vector<dfm::SurfaceConstraint> out;
    for (size_t i = 0; i < j.size(); ++i) {
        const std::string path = "constraints[" + std::to_string(i) + "]";
        const json& c = j[i];
        if (!c.is_object()) throw InputError(path + ": expected an object");
        const json& type = solvers::io::member(c, "type", path);
        const std::string t = type.is_string() ? type.get<std::string>() : "";
        dfm::SurfaceConstraint k;
        if (t == "position" || t == "normal") {
            k.type = t == "position" ? dfm::SurfaceConstraintType::Position : dfm::SurfaceConstraintType::Normal;
            k.uv = uvFromJson(solvers::io::member(c, "uv", path), path + ".uv", s);
            k.value = solvers::io::pointFromJson(solvers::io::member(c, "value", path), path + ".value");
            if (k.type == dfm::SurfaceConstraintType::Normal && k.value.norm() == 0.0) {
                throw InputError(path + ".value: the normal must not be the zero vector");
            }
        } else if (t == "curve") {
            k.type = dfm::SurfaceConstraintType::Curve;
            k.target = solvers::io::curveFromJson(solvers::io::member(c, "target", path), path + ".target");
            if (c.contains("domain")) k.domain = domainCurve(c["domain"], path + ".domain", s);
        } else if (t == "curve-tangent") {
            k.type = dfm::SurfaceConstraintType::CurveTangent;
            k.domain = domainCurve(solvers::io::member(c, "domain", path), path + ".domain", s);
            k.value = solvers::io::pointFromJson(solvers::io::member(c, "value", path), path + ".value");
            if (k.value.norm() == 0.0) throw InputError(path + ".value: the tangent must not be the zero vector");
        } else if (t == "angle") {
            k.type = dfm::SurfaceConstraintType::Angle;
            k.uv = uvFromJson(solvers::io::member(c, "uv", path), path + ".uv", s);
            k.value = solvers::io::pointFromJson(solvers::io::member(c, "value", path), path + ".value");
            if (k.value.norm() == 0.0) throw InputError(path + ".value: the direction must not be the zero vector");
            const double degrees = solvers::io::numberFromJson(solvers::io::member(c, "angle", path), path + ".angle");
            if (!(degrees >= 0.0 && degrees <= 180.0)) throw InputError(path + ".angle: must be in [0, 180] degrees");
            k.angle = degrees * solvers::kPi / 180.0;
        } else if (t == "tangents") {
            k.type = dfm::SurfaceConstraintType::Tangents;
            k.uv = uvFromJson(solvers::io::member(c, "uv", path), path + ".uv", s);
            k.value = solvers::io::pointFromJson(solvers::io::member(c, "du", path), path + ".du");
            k.value2 = solvers::io::pointFromJson(solvers::io::member(c, "dv", path), path + ".dv");
        } else if (t == "distance") {
            k.type = dfm::SurfaceConstraintType::Distance;
            k.uv = uvFromJson(solvers::io::member(c, "uv", path), path + ".uv", s);
            k.uv2 = uvFromJson(solvers::io::member(c, "uv2", path), path + ".uv2", s);
            k.distance = solvers::io::numberFromJson(solvers::io::member(c, "value", path), path + ".value");
            if (k.distance < 0.0) throw InputError(path + ".value: a distance must be >= 0");
        } else {
            throw InputError(path + ".type: expected position, normal, curve, curve-tangent, tangents, angle or distance, got " +
                             solvers::io::describeValue(type));
        }
        if ((k.type == dfm::SurfaceConstraintType::Curve || k.type == dfm::SurfaceConstraintType::CurveTangent) &&
            c.contains("key_points")) {
            k.keyPoints = solvers::io::integerFromJson(c["key_points"], path + ".key_points", 1, dfm::kMaxKeyPoints);
        }
        out.push_back(std::move(k));
    }
    return out;
}

std::vector<Eigen::Vector2d> boundFromJson(const json& j, const solvers::Surface3d& s)
{
    const solvers::Curve3d c = solvers::io::curveFromJson(j, "bound");
    const bool planar = isPlanarJson(j);
    const Eigen::Vector3d a = c.evaluate(c.domainStart()), b = c.evaluate(c.domainEnd());
    double size = 0.0;
    for (const auto& p : c.points()) size = std::max(size, (p - c.points().front()).norm());
    if (!c.isClosed() && (a - b).norm() > kClosedRelativeTolerance * std::max(size, 1.0)) {
        throw InputError("bound: the curve is not closed (its ends are " + json((a - b).norm()).dump() + " apart)");
    }
    const int spans = std::max(1, static_cast<int>(solvers::interiorBreakpoints(c.degree(), c.knots()).size()) + 1);
    const int samples = std::min(kMaxBoundSamples, kBoundSamplesPerSpan * spans);
    std::optional<solvers::SurfaceProjector> projector;
    if (!planar) projector.emplace(s);
    std::vector<Eigen::Vector2d> polygon;
    for (int k = 0; k < samples; ++k) {
        const Eigen::Vector3d p = c.evaluate(c.domainStart() + (c.domainEnd() - c.domainStart()) * k / samples);
        if (planar) {
            polygon.emplace_back(p.x(), p.y());
        } else {
            const solvers::SurfaceProjection f = projector->project(p);
            polygon.emplace_back(f.u, f.v);
        }
    }
    return polygon;
}

json run(const json& input, const Options&)
{
    const solvers::Surface3d surface = solvers::io::surfaceFromJson(field(input, "surface"), "surface");
    const auto constraints = constraintsFromJson(field(input, "constraints"), surface);
    dfm::DeformationOptions options;
    if (input.contains("stiffness")) {
        options.stiffness = solvers::io::numberFromJson(input["stiffness"], "stiffness");
        if (!(options.stiffness > 0.0 && options.stiffness <= 1.0)) {
            throw InputError("stiffness: " + input["stiffness"].dump() + " is outside (0, 1]");
        }
    }
    if (input.contains("blocked")) {
        const json& b = input["blocked"];
        if (!b.is_array()) throw InputError("blocked: expected an array of [i, j] control point indices");
        for (size_t i = 0; i < b.size(); ++i) {
            const std::string path = "blocked[" + std::to_string(i) + "]";
            if (!b[i].is_array() || b[i].size() != 2) throw InputError(path + ": expected [i, j]");
            options.blocked.push_back({solvers::io::integerFromJson(b[i][0], path + "[0]", 0, surface.countU() - 1),
                                       solvers::io::integerFromJson(b[i][1], path + "[1]", 0, surface.countV() - 1)});
        }
    }
    if (input.contains("objective")) {
        const json& o = input["objective"];
        const std::string name = o.is_string() ? o.get<std::string>() : "";
        if (name == "displacement")
            options.objective = dfm::Objective::Displacement;
        else if (name == "force")
            options.objective = dfm::Objective::Force;
        else
            throw InputError("objective: expected displacement or force, got " + solvers::io::describeValue(o));
    }
    bool isocurves = false;
    if (input.contains("method")) {
        const json& m = input["method"];
        const std::string name = m.is_string() ? m.get<std::string>() : "";
        if (name != "global" && name != "isocurves") {
            throw InputError("method: expected global or isocurves, got " + solvers::io::describeValue(m));
        }
        isocurves = name == "isocurves";
    }
    if (input.contains("bound")) options.bound = boundFromJson(input["bound"], surface);

    const Stopwatch clock;
    dfm::DeformationReport report;
    // The solver's messages already name the input field (constraints[i].uv, blocked[k], stiffness).
    const solvers::Surface3d result = [&] {
        try {
            return isocurves ? dfm::deformByIsocurves(surface, constraints, options, &report)
                             : dfm::deformSurface(surface, constraints, options, &report);
        } catch (const solvers::GeometryError& e) {
            throw InputError(e.what());
        }
    }();
    const double ms = clock.elapsedMs();
    json out;
    out["surface"] = solvers::io::toJson(result);
    out["residuals"] = report.residuals;
    out["max_residual"] = report.maxResidual;
    out["moved"] = report.moved;
    out["key_points"] = toJson(report.keyPoints);
    out["compromise"] = report.compromise || report.tooFewFreePoints;
    if (!report.message.empty()) out["message"] = report.message;
    if (!options.bound.empty() && !isocurves) {
        json cases = json::array();
        for (dfm::BoundCase c : report.boundCases) cases.push_back(dfm::boundCaseName(c));
        out["bound_cases"] = std::move(cases);
    }
    if (!isocurves) out["rank"] = report.rank;  // the iso-curve method solves many small systems
    out["rows"] = report.constraintRows;
    out["elapsed_ms"] = ms;
    requireFiniteOutput(out);
    return out;
}

const SubcommandRegistrar registrar{
    {"deform", "surface deformation: {surface, constraints, bound?, stiffness?, blocked?} -> {surface, residuals, ..}",
     &run}};

}  // namespace
}  // namespace sculptline::cli
