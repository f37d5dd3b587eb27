#pragma once
// JSON <-> geometry in the formats of ../shared/interfaces.md ("JSON geometry"). Plain data only:
// this target links the solvers and nlohmann_json, nothing graphical.
#include "solvers/bspline/bspline_surface.h"

#include <nlohmann/json_fwd.hpp>
#include <stdexcept>
#include <string>

namespace sculptline::solvers::io {

/// Malformed or invalid JSON input. what() is one line that names the field (as a JSON path such as
/// "curve.knots[3]") and the problem; the CLI prints it and exits with status 2.
class InputError : public std::runtime_error {
public:
    explicit InputError(const std::string& what) : std::runtime_error(what) {}
};

/// Reads a curve object; `path` names it in messages ("curve", "curves[2]"). 2D points mean z = 0.
Curve3d curveFromJson(const nlohmann::json& j, const std::string& path);
/// Reads a surface object (point (i, j) at index i*countV + j).
Surface3d surfaceFromJson(const nlohmann::json& j, const std::string& path);
/// Reads one point [x, y] or [x, y, z].
Eigen::Vector3d pointFromJson(const nlohmann::json& j, const std::string& path);
/// Reads a finite number.
double numberFromJson(const nlohmann::json& j, const std::string& path);
/// Reads an integer within [lo, hi].
int integerFromJson(const nlohmann::json& j, const std::string& path, int lo, int hi);
/// A short description of an input value for a message: a number or a short string as written, a
/// long string cut, anything else its type ("array", "object"). Never j.dump() of input: its recursion
/// follows the nesting, and deeply nested input ([[[[...) would overflow the stack.
std::string describeValue(const nlohmann::json& j);
/// The member `key` of object j, or an InputError naming path.key when it is missing.
const nlohmann::json& member(const nlohmann::json& j, const std::string& key, const std::string& path);

nlohmann::json toJson(const Curve3d& c);
nlohmann::json toJson(const Surface3d& s);
nlohmann::json toJson(const Eigen::Vector3d& p);

/// Parses text as JSON, turning parse errors into InputError ("input: malformed JSON (...)"); a number
/// that overflows a double (1e999) is named by its path ("curve.points[1][0]: not a finite number").
nlohmann::json parseJson(const std::string& text);

}  // namespace sculptline::solvers::io
