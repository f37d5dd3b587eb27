#include "app/cli/cli_support.h"

#include <cmath>

namespace sculptline::cli {
namespace {

using solvers::io::numberFromJson;

std::string indexed(const std::string& path, size_t i)
{
    return path + "[" + std::to_string(i) + "]";
}

// Numbers in messages in their shortest round-trip form, so that a boundary value reads exactly.
std::string show(double v)
{
    return json(v).dump();
}

void requireArray(const json& j, const std::string& path)
{
    if (!j.is_array()) throw InputError(path + ": must be an array, got " + std::string(j.type_name()));
}

}  // namespace

const json& field(const json& input, const std::string& key)
{
    const auto it = input.find(key);
    if (it == input.end()) throw InputError(key + ": missing");
    return *it;
}

double optionalLength(const json& input, const std::string& key, double absent, bool zeroAllowed)
{
    const auto it = input.find(key);
    if (it == input.end()) return absent;
    const double v = solvers::io::numberFromJson(*it, key);
    if (zeroAllowed ? !(v >= 0.0) : !(v > 0.0))
        throw InputError(key + (zeroAllowed ? ": must be zero or positive" : ": must be positive"));
    return v;
}

GeometryKind curveOrSurface(const json& input)
{
    const bool curve = input.contains("curve"), surface = input.contains("surface");
    if (curve && surface) throw InputError("surface: give either \"curve\" or \"surface\", not both");
    if (!curve && !surface) throw InputError("curve: missing (give \"curve\" or \"surface\")");
    return curve ? GeometryKind::Curve : GeometryKind::Surface;
}

std::vector<double> numberArray(const json& j, const std::string& path)
{
    requireArray(j, path);
    std::vector<double> out;
    out.reserve(j.size());
    for (size_t i = 0; i < j.size(); ++i) out.push_back(numberFromJson(j[i], indexed(path, i)));
    return out;
}

std::vector<double> curveParams(const json& j, const std::string& path, const solvers::Curve3d& curve)
{
    std::vector<double> params = numberArray(j, path);
    if (curve.isClosed()) return params;
    const double a = curve.domainStart(), b = curve.domainEnd();
    for (size_t i = 0; i < params.size(); ++i) {
        if (params[i] < a || params[i] > b) {
            throw InputError(indexed(path, i) + ": " + show(params[i]) + " is outside the curve's domain [" + show(a) +
                             ", " + show(b) + "]");
        }
    }
    return params;
}

std::vector<std::pair<double, double>> surfaceParams(const json& j, const std::string& path,
                                                     const solvers::Surface3d& surface)
{
    using solvers::Direction;
    requireArray(j, path);
    std::vector<std::pair<double, double>> params;
    params.reserve(j.size());
    for (size_t i = 0; i < j.size(); ++i) {
        const std::string at = indexed(path, i);
        if (!j[i].is_array() || j[i].size() != 2) throw InputError(at + ": must be a pair [u, v]");
        const double uv[2] = {numberFromJson(j[i][0], at + "[0]"), numberFromJson(j[i][1], at + "[1]")};
        for (int k = 0; k < 2; ++k) {
            const Direction d = k == 0 ? Direction::U : Direction::V;
            const double a = surface.domainStart(d), b = surface.domainEnd(d);
            if (uv[k] < a || uv[k] > b) {
                throw InputError(at + "[" + std::to_string(k) + "]: " + show(uv[k]) + " is outside the surface's " +
                                 (k == 0 ? "u" : "v") + " domain [" + show(a) + ", " + show(b) + "]");
            }
        }
        params.emplace_back(uv[0], uv[1]);
    }
    return params;
}

std::vector<Eigen::Vector3d> pointArray(const json& j, const std::string& path)
{
    requireArray(j, path);
    std::vector<Eigen::Vector3d> points;
    points.reserve(j.size());
    for (size_t i = 0; i < j.size(); ++i) points.push_back(solvers::io::pointFromJson(j[i], indexed(path, i)));
    return points;
}

solvers::Direction directionFromJson(const json& input)
{
    const json& d = field(input, "direction");
    if (d == "u") return solvers::Direction::U;
    if (d == "v") return solvers::Direction::V;
    // Not d.dump(): the value is arbitrary input and may be huge or deeply nested.
    throw InputError(std::string("direction: must be \"u\" or \"v\", got ") +
                     (d.is_string() ? "\"" + d.get<std::string>().substr(0, 40) + "\"" : d.type_name()));
}

json toJson(const std::vector<Eigen::Vector3d>& points)
{
    json out = json::array();
    for (const auto& p : points) out.push_back(solvers::io::toJson(p));
    return out;
}

void requireFiniteOutput(const json& output, const std::string& path)
{
    if (output.is_number_float() && !std::isfinite(output.get<double>())) {
        throw InputError(path + ": the result is not a finite number (the input's magnitudes overflow double precision)");
    }
    if (output.is_array()) {
        for (size_t i = 0; i < output.size(); ++i) requireFiniteOutput(output[i], indexed(path, i));
    } else if (output.is_object()) {
        for (const auto& [key, value] : output.items()) requireFiniteOutput(value, path + "." + key);
    }
}

}  // namespace sculptline::cli
