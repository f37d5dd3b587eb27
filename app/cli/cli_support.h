#pragma once
// Helpers shared by the subcommand files: reading top-level input fields with messages that name
// them, mapping kernel errors onto input fields, timing, and writing results.
#include "solvers/bspline/geometry_error.h"
#include "solvers/io/geometry_json.h"

#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace sculptline::cli {

using nlohmann::json;
using solvers::io::InputError;

/// Times the computation only: start it after the input has been read and validated, read it
/// before the results are converted to JSON (../shared/interfaces.md, "elapsed_ms").
class Stopwatch {
public:
    Stopwatch() : start_(std::chrono::steady_clock::now()) {}
    double elapsedMs() const
    {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
    }

private:
    std::chrono::steady_clock::time_point start_;
};

/// The top-level member `key`, or InputError "key: missing".
const json& field(const json& input, const std::string& key);

/// The optional top-level number `key` (a tolerance, a resolution: model units), or `absent` when it
/// is not given. It must be finite and positive, or with `zeroAllowed` zero or positive; otherwise
/// InputError "key: must be positive" / "key: must be zero or positive".
double optionalLength(const json& input, const std::string& key, double absent, bool zeroAllowed);

/// Which geometry an input carries: exactly one of "curve" and "surface".
enum class GeometryKind { Curve, Surface };
GeometryKind curveOrSurface(const json& input);

/// An array of finite numbers at `path` (e.g. "params").
std::vector<double> numberArray(const json& j, const std::string& path);

/// Curve parameters at `path`; open curves reject values outside their domain (the kernel would
/// clamp them silently), closed curves accept any finite value (it wraps with the period).
std::vector<double> curveParams(const json& j, const std::string& path, const solvers::Curve3d& curve);

/// Surface parameters [[u, v], ..] at `path`, each inside the surface's domain.
std::vector<std::pair<double, double>> surfaceParams(const json& j, const std::string& path,
                                                     const solvers::Surface3d& surface);

/// Points [[x, y(, z)], ..] at `path`.
std::vector<Eigen::Vector3d> pointArray(const json& j, const std::string& path);

/// The "direction" member, "u" or "v" (required for operations on surfaces).
solvers::Direction directionFromJson(const json& input);

json toJson(const std::vector<Eigen::Vector3d>& points);

/// Runs a kernel operation, turning its GeometryError into an InputError that names the input
/// field. Kernel messages start with the field they concern: either an argument of the operation
/// ("times", "knot", "tolerance"), which is a top-level input member of the same name, or a part of
/// the geometry ("closed", "knots"), which is then prefixed with the geometry's member name.
template <typename F>
auto runOperation(const json& input, const std::string& geometryName, F&& operation)
{
    try {
        return operation();
    } catch (const solvers::GeometryError& e) {
        const std::string message = e.what();
        const std::string name = message.substr(0, message.find(':'));
        if (input.contains(name)) throw InputError(message);
        throw InputError(geometryName + "." + message);
    }
}

/// The shared shape of the geometry-to-geometry subcommands: reads the input's "curve" or "surface"
/// (and "direction" for a surface), applies the matching operation under runOperation, timing it
/// alone, and returns {"curve"|"surface": result, "elapsed_ms": t}.
template <typename CurveOp, typename SurfaceOp>
json transformGeometry(const json& input, CurveOp&& curveOp, SurfaceOp&& surfaceOp)
{
    json out;
    if (curveOrSurface(input) == GeometryKind::Curve) {
        const solvers::Curve3d curve = solvers::io::curveFromJson(field(input, "curve"), "curve");
        const Stopwatch clock;
        const solvers::Curve3d result = runOperation(input, "curve", [&] { return curveOp(curve); });
        out["elapsed_ms"] = clock.elapsedMs();
        out["curve"] = solvers::io::toJson(result);
    } else {
        const solvers::Surface3d surface = solvers::io::surfaceFromJson(field(input, "surface"), "surface");
        const solvers::Direction direction = directionFromJson(input);
        const Stopwatch clock;
        const solvers::Surface3d result = runOperation(input, "surface", [&] { return surfaceOp(surface, direction); });
        out["elapsed_ms"] = clock.elapsedMs();
        out["surface"] = solvers::io::toJson(result);
    }
    return out;
}

/// Throws InputError naming the first non-finite number in a result (an overflow caused by huge
/// but finite input); JSON has no representation for it and nlohmann would write null.
void requireFiniteOutput(const json& output, const std::string& path = "result");

}  // namespace sculptline::cli
