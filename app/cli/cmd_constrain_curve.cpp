// sculptline-cli constrain-curve: direct curve manipulation under constraints (thesis §6.1,
// Fowler & Bartels; solvers/editing/curve_manipulation.h).
//
//   {"curve": C, "constraints": [{"type": t, "u": u, "value": v, "u2": u2}, ..], "blocked": [i, ..],
//    "insert_knots": r}
//     -> {"curve": C', "max_residual": d, "residuals": [..], "rank": r, "compromise": b,
//         "too_few_free_points": b, "message": s, "elapsed_ms": t}
//
// Types: "position" (value = the point C(u)), "tangent" (value = C'(u)), "curvature" (value =
// C''(u)), "distance" (value = C(u2) - C(u) as a vector, or a number: that length along the curve's
// current direction from C(u) to C(u2)). "blocked" lists control points that must not move (unique
// indices for closed curves). "insert_knots" (default 0) first inserts that many rounds of knots next
// to the constraints, which is what the message suggests when the free points are too few.
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"
#include "solvers/editing/curve_manipulation.h"

namespace sculptline::cli {
namespace {

using solvers::editing::ConstraintType;
using solvers::editing::CurveConstraint;

double parameter(const json& c, const std::string& key, const std::string& path, const solvers::Curve3d& curve)
{
    const double u = solvers::io::numberFromJson(solvers::io::member(c, key, path), path + "." + key);
    if (!curve.isClosed() && (u < curve.domainStart() || u > curve.domainEnd())) {
        throw InputError(path + "." + key + ": " + json(u).dump() + " is outside the curve's domain [" +
                         json(curve.domainStart()).dump() + ", " + json(curve.domainEnd()).dump() + "]");
    }
    return u;
}

std::vector<CurveConstraint<3>> constraintsFromJson(const json& j, const solvers::Curve3d& curve)
{
    if (!j.is_array()) throw InputError("constraints: expected an array");
    std::vector<CurveConstraint<3>> out;
    for (size_t i = 0; i < j.size(); ++i) {
        const std::string path = "constraints[" + std::to_string(i) + "]";
        const json& c = j[i];
        if (!c.is_object()) throw InputError(path + ": expected an object");
        const json& type = solvers::io::member(c, "type", path);
        const std::string t = type.is_string() ? type.get<std::string>() : "";
        CurveConstraint<3> k;
        if (t == "position")
            k.type = ConstraintType::Position;
        else if (t == "tangent")
            k.type = ConstraintType::Tangent;
        else if (t == "curvature")
            k.type = ConstraintType::Curvature;
        else if (t == "distance")
            k.type = ConstraintType::Distance;
        else
            throw InputError(path + ".type: expected position, tangent, curvature or distance, got " + solvers::io::describeValue(type));
        k.u = parameter(c, "u", path, curve);
        if (k.type == ConstraintType::Distance) k.u2 = parameter(c, "u2", path, curve);
        const json& v = solvers::io::member(c, "value", path);
        if (k.type == ConstraintType::Distance && v.is_number()) {
            const double length = solvers::io::numberFromJson(v, path + ".value");
            const Eigen::Vector3d d = curve.evaluate(k.u2) - curve.evaluate(k.u);
            if (d.norm() == 0.0) throw InputError(path + ".value: a length needs distinct points C(u) and C(u2)");
            k.value = length * d.normalized();
        } else {
            k.value = solvers::io::pointFromJson(v, path + ".value");
        }
        out.push_back(k);
    }
    return out;
}

json run(const json& input, const Options&)
{
    const solvers::Curve3d curve0 = solvers::io::curveFromJson(field(input, "curve"), "curve");
    const int rounds =
        input.contains("insert_knots") ? solvers::io::integerFromJson(input["insert_knots"], "insert_knots", 0, 8) : 0;
    const auto constraints = constraintsFromJson(field(input, "constraints"), curve0);
    const solvers::Curve3d curve = solvers::editing::insertKnotsNearConstraints(curve0, constraints, rounds);
    std::vector<int> blocked;
    if (input.contains("blocked")) {
        const json& b = input["blocked"];
        if (!b.is_array()) throw InputError("blocked: expected an array of control point indices");
        const int n = curve.isClosed() ? curve.pointCount() - curve.degree() : curve.pointCount();
        for (size_t i = 0; i < b.size(); ++i) {
            blocked.push_back(solvers::io::integerFromJson(b[i], "blocked[" + std::to_string(i) + "]", 0, n - 1));
        }
    }

    const Stopwatch clock;
    solvers::editing::ManipulationReport report;
    const solvers::Curve3d result = runOperation(
        input, "curve", [&] { return solvers::editing::constrainCurve(curve, constraints, blocked, &report); });
    const double ms = clock.elapsedMs();
    json out;
    out["curve"] = solvers::io::toJson(result);
    out["max_residual"] = report.maxResidual;
    out["residuals"] = report.residuals;
    out["rank"] = report.rank;
    out["compromise"] = report.compromise;
    out["too_few_free_points"] = report.tooFewFreePoints;
    out["message"] = report.message;
    out["elapsed_ms"] = ms;
    requireFiniteOutput(out);
    return out;
}

const SubcommandRegistrar registrar{
    {"constrain-curve", "direct manipulation: {curve, constraints, blocked} -> {curve, max_residual, ..}", &run}};

}  // namespace
}  // namespace sculptline::cli
