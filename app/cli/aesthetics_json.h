#pragma once
// JSON of the aesthetic analysis, shared by `analyze` and `aesthetic` (../shared/interfaces.md).
#include "solvers/aesthetics/curve_analysis.h"

#include <nlohmann/json.hpp>

namespace sculptline::cli {

/// {"acceleration", "sharpness", "flatness", "convexity", "tension" (null where the turns cancel),
///  "crown", "curvature_min", "curvature_max", "curvature_average"}
nlohmann::json measuresJson(const solvers::aesthetics::Measures& m);

/// The optional "thresholds": {"distance"?, "curvature"?, "sharp"?} of an input, each positive.
/// @throws InputError naming the field.
solvers::aesthetics::Thresholds thresholdsFromJson(const nlohmann::json& input);

}  // namespace sculptline::cli
