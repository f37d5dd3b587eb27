#include "app/cli/aesthetics_json.h"

#include "app/cli/cli_support.h"

namespace sculptline::cli {
namespace {

std::optional<double> threshold(const json& t, const char* key)
{
    if (!t.contains(key)) return std::nullopt;
    const double v = solvers::io::numberFromJson(t[key], std::string("thresholds.") + key);
    if (v <= 0.0) throw InputError(std::string("thresholds.") + key + ": must be positive, got " + std::to_string(v));
    return v;
}

}  // namespace

json measuresJson(const solvers::aesthetics::Measures& m)
{
    return {{"acceleration", m.acceleration},
            {"sharpness", m.sharpness},
            {"flatness", m.flatness},
            {"convexity", m.convexity},
            {"tension", m.tension ? json(*m.tension) : json(nullptr)},
            {"crown", m.crown},
            {"curvature_min", m.curvatureMin},
            {"curvature_max", m.curvatureMax},
            {"curvature_average", m.curvatureAverage}};
}

solvers::aesthetics::Thresholds thresholdsFromJson(const json& input)
{
    solvers::aesthetics::Thresholds thresholds;
    if (!input.contains("thresholds")) return thresholds;
    const json& t = input["thresholds"];
    if (!t.is_object()) throw InputError("thresholds: expected an object {distance?, curvature?, sharp?}");
    for (const auto& [key, value] : t.items()) {
        if (key != "distance" && key != "curvature" && key != "sharp") {
            throw InputError("thresholds." + key + ": unknown (expected distance, curvature or sharp)");
        }
    }
    thresholds.distance = threshold(t, "distance");
    thresholds.curvature = threshold(t, "curvature");
    thresholds.sharp = threshold(t, "sharp");
    return thresholds;
}

}  // namespace sculptline::cli
