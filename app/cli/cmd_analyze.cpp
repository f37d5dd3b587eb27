// sculptline-cli analyze: the aesthetic analysis of a planar curve (thesis ch. 7; solvers/aesthetics):
// its characteristic points (curvature extrema and inflections, exact per span), its name on
// Leyton's process grammar, the characteristics of each extremum and the FIORES measures.
//
//   {"curve": C (planar; a 3D curve is analyzed in its plane), "thresholds"?: {"distance": γ,
//    "curvature": β, "sharp": μ}}
//     -> {"name", "points": [{"u", "kind", "curvature", "arc_length"}..],
//         "characteristics": [{"u", "kind", "dk_left", "dk_right", "d_left", "d_right", "range_left",
//                              "range_right", "small_visibility", "sharp_corner", "symmetric", "redundant"}..],
//         "measures": {"acceleration", "sharpness", "flatness", "convexity", "tension" (null when the
//                      curve's turns cancel), "crown", "curvature_min", "curvature_max", "curvature_average"},
//         "lcg": [{"u0", "u1", "slope", "r2"}..], "length", "closed", "thresholds": {"distance",
//         "curvature", "sharp"}, "elapsed_ms"}
#include "app/cli/aesthetics_json.h"
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"
#include "solvers/aesthetics/curve_analysis.h"

namespace sculptline::cli {
namespace {

namespace aes = solvers::aesthetics;

json run(const json& input, const Options&)
{
    const solvers::Curve3d curve3 = solvers::io::curveFromJson(field(input, "curve"), "curve");
    const aes::Thresholds thresholds = thresholdsFromJson(input);
    const Stopwatch clock;
    const aes::CurveAnalysis a = runOperation(input, "curve", [&] { return aes::analyzeCurve(aes::planarCurve(curve3), thresholds); });
    const double ms = clock.elapsedMs();
    json out;
    out["name"] = a.name;
    out["points"] = json::array();
    for (const auto& p : a.points) {
        out["points"].push_back({{"u", p.u}, {"kind", aes::codon(p.kind)}, {"curvature", p.curvature}, {"arc_length", p.arcLength}});
    }
    out["characteristics"] = json::array();
    for (const auto& c : a.characteristics) {
        const auto& p = a.points[c.point];
        out["characteristics"].push_back({{"u", p.u},
                                          {"kind", aes::codon(p.kind)},
                                          {"point", c.point},
                                          {"dk_left", c.dkLeft},
                                          {"dk_right", c.dkRight},
                                          {"d_left", c.dLeft},
                                          {"d_right", c.dRight},
                                          {"range_left", c.rangeLeft},
                                          {"range_right", c.rangeRight},
                                          {"small_visibility", c.smallVisibility},
                                          {"sharp_corner", c.sharpCorner},
                                          {"symmetric", c.symmetric},
                                          {"redundant", c.redundant}});
    }
    out["measures"] = measuresJson(a.measures);
    out["lcg"] = json::array();
    for (const auto& s : a.lcg) out["lcg"].push_back({{"u0", s.u0}, {"u1", s.u1}, {"slope", s.slope}, {"r2", s.r2}});
    out["length"] = a.length;
    out["closed"] = a.closed;
    out["thresholds"] = {{"distance", a.gamma}, {"curvature", a.beta}, {"sharp", a.mu}};
    out["elapsed_ms"] = ms;
    requireFiniteOutput(out);
    return out;
}

const SubcommandRegistrar registrar{
    {"analyze",
     "aesthetic analysis of a planar curve: {curve, thresholds?: {distance, curvature, sharp}} -> {name, points, "
     "characteristics, measures, lcg}",
     &run}};

}  // namespace
}  // namespace sculptline::cli
