// sculptline-cli eval: points and derivatives of a curve or a surface.
//
//   curve:   {"curve": C, "params": [u, ..], "derivatives": d}
//         -> {"points": [..], "d1": [..], .., "d<d>": [..], "elapsed_ms": t}
//            "dk" holds the k-th derivative C^(k)(u) at every parameter.
//   surface: {"surface": S, "params": [[u, v], ..], "derivatives": d}
//         -> {"points": [..], "du": [..], "dv": [..], "duu": [..], "duv": [..], "dvv": [..], ..}
//            a key of order k = a + b is "d" followed by a letters "u" and b letters "v" and holds
//            d^k S / du^a dv^b; every order 1..d is written, for a = k down to 0 (so order 3 adds
//            "duuu", "duuv", "duvv", "dvvv").
//
// "derivatives" is optional (default 0) and at most kMaxDegree. Open curves and surfaces reject
// parameters outside their domain; closed curves wrap.
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"

namespace sculptline::cli {
namespace {

using solvers::Curve3d;
using solvers::Surface3d;

int derivativeOrder(const json& input)
{
    if (!input.contains("derivatives")) return 0;
    return solvers::io::integerFromJson(input["derivatives"], "derivatives", 0, solvers::kMaxDegree);
}

json evalCurve(const json& input)
{
    const Curve3d curve = solvers::io::curveFromJson(field(input, "curve"), "curve");
    const std::vector<double> params = curveParams(field(input, "params"), "params", curve);
    const int order = derivativeOrder(input);

    const Stopwatch clock;
    // byOrder[k][i]: k-th derivative at params[i].
    std::vector<std::vector<Eigen::Vector3d>> byOrder(order + 1, std::vector<Eigen::Vector3d>(params.size()));
    for (size_t i = 0; i < params.size(); ++i) {
        const std::vector<Eigen::Vector3d> ders = curve.derivatives(params[i], order);
        for (int k = 0; k <= order; ++k) byOrder[k][i] = ders[k];
    }
    const double ms = clock.elapsedMs();

    json out;
    out["points"] = toJson(byOrder[0]);
    for (int k = 1; k <= order; ++k) out["d" + std::to_string(k)] = toJson(byOrder[k]);
    out["elapsed_ms"] = ms;
    return out;
}

std::string surfaceKey(int a, int b)
{
    return a + b == 0 ? "points" : "d" + std::string(a, 'u') + std::string(b, 'v');
}

json evalSurface(const json& input)
{
    const Surface3d surface = solvers::io::surfaceFromJson(field(input, "surface"), "surface");
    const auto params = surfaceParams(field(input, "params"), "params", surface);
    const int order = derivativeOrder(input);

    const Stopwatch clock;
    std::vector<std::vector<std::vector<Eigen::Vector3d>>> ders;  // ders[i][a][b]
    ders.reserve(params.size());
    for (const auto& [u, v] : params) ders.push_back(surface.derivatives(u, v, order));
    const double ms = clock.elapsedMs();

    json out;
    for (int k = 0; k <= order; ++k) {
        for (int a = k; a >= 0; --a) {
            const int b = k - a;
            json column = json::array();
            for (const auto& d : ders) column.push_back(solvers::io::toJson(d[a][b]));
            out[surfaceKey(a, b)] = std::move(column);
        }
    }
    out["elapsed_ms"] = ms;
    return out;
}

json run(const json& input, const Options&)
{
    return curveOrSurface(input) == GeometryKind::Curve ? evalCurve(input) : evalSurface(input);
}

const SubcommandRegistrar registrar{{"eval",
                                     "points and derivatives: {curve|surface, params, derivatives} -> "
                                     "{points, d1.. | du, dv, duu, duv, dvv, ..}",
                                     &run}};

}  // namespace
}  // namespace sculptline::cli
