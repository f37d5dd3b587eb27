#pragma once
// JSON <-> strokes and fit results in the formats of ../shared/interfaces.md ("Stroke", `fit`).
// A separate target (stroke_io) so that the numeric stroke code does not depend on a JSON library.
#include "solvers/stroke/stroke_fitter.h"
#include "solvers/stroke/user_model.h"

#include <nlohmann/json_fwd.hpp>
#include <string>

namespace sculptline::solvers::stroke {

/// Reads {"points": [[x,y] or [x,y,z], ..], "times": [..], "pressure": [..]}; `path` names the
/// object in messages ("stroke", "strokes[2]"). Points must all have the same dimension; times and
/// pressure (each in [0, 1]) are optional but, when present, have one value per point.
/// @throws io::InputError naming the field (path.points[3][1], path.times, ...).
Stroke strokeFromJson(const nlohmann::json& j, const std::string& path);

nlohmann::json toJson(const Stroke& s);

/// {"curve": C, "corners": [..], "samples": [..], "max_error": e, "tolerance": t, "closed": b,
///  "warnings": [..]} (indices are raw stroke samples). A 2D stroke gives a curve with 2D points.
nlohmann::json fitResultToJson(const FitResult& r, int dimension);

/// {"shape": kind, "candidates": [{"kind": .., "score": ..}, ..], "regularized": C}.
nlohmann::json recognitionToJson(const Recognition& r, int dimension);

/// {"user": name, "nodes": [{"index": i, "name": .., "pre": i or null, "curr": i or null,
///  "constraint": ..}, ..]}: Table 3-2, one file per user.
nlohmann::json toJson(const UserModel& m);
/// @throws io::InputError naming the field (path.nodes[3].pre, ...).
UserModel userModelFromJson(const nlohmann::json& j, const std::string& path);

}  // namespace sculptline::solvers::stroke
