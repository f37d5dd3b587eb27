// sculptline-cli incidence: the surface through curves drawn on it (seed 000; solvers/incidence,
// solvers/regularization), ../shared/interfaces.md:
//
//   {"surface": S, "curves": [{"domain"?: G, "target"?: H, "fixed"?: bool}..], "method"?: "tsvd" or
//    "mtsvd" (default), "smoothing"?: {"area": α1, "thin_plate": α2, "curvature_variation": α3}, "k"?}
//     -> {"surface": S', "k", "corner", "rows", "cols", "residual", "fixed_residual",
//         "lcurve": {"rho": [..], "eta": [..]}, "hard_rows", "elapsed_ms"}
//
// A curve without a domain is placed by its target's projection; one without a target keeps its
// present image S(G); a fixed one is met exactly.
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"
#include "solvers/incidence/incidence_solve.h"

#include <stdexcept>

namespace sculptline::cli {
namespace {

namespace inc = solvers::incidence;

// The dense incidence system is (rows of H's spaces) x (control points): a surface of this many
// control points and this many curves keep one solve within seconds (the SVD is O(m n²)).
constexpr int kMaxControlPoints = 1000;
constexpr size_t kMaxCurves = 32;

std::vector<double> toVector(const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); }

json run(const json& input, const Options&)
{
    const solvers::Surface3d surface = solvers::io::surfaceFromJson(field(input, "surface"), "surface");
    if (surface.countU() * surface.countV() > kMaxControlPoints) {
        throw InputError("surface: " + std::to_string(surface.countU() * surface.countV()) + " control points, at most " +
                         std::to_string(kMaxControlPoints));
    }
    const json& curves = field(input, "curves");
    if (!curves.is_array() || curves.empty()) throw InputError("curves: expected a non-empty array of {domain?, target?, fixed?}");
    if (curves.size() > kMaxCurves) throw InputError("curves: at most " + std::to_string(kMaxCurves) + " curves");
    std::vector<inc::IncidenceCurve> in;
    for (size_t c = 0; c < curves.size(); ++c) {
        const std::string at = "curves[" + std::to_string(c) + "]";
        const json& k = curves[c];
        if (!k.is_object()) throw InputError(at + ": expected an object");
        inc::IncidenceCurve curve;
        if (k.contains("domain")) {
            const solvers::Curve3d g = solvers::io::curveFromJson(k["domain"], at + ".domain");
            std::vector<Eigen::Vector2d> points;
            for (const auto& p : g.points()) points.emplace_back(p.x(), p.y());
            if (g.isRational()) throw InputError(at + ".domain: a rational domain curve is not supported");
            curve.domain = solvers::Curve2d(g.degree(), g.knots(), points);
        }
        if (k.contains("target")) curve.target = solvers::io::curveFromJson(k["target"], at + ".target");
        if (k.contains("fixed")) {
            if (!k["fixed"].is_boolean()) throw InputError(at + ".fixed: expected true or false");
            curve.fixed = k["fixed"].get<bool>();
        }
        in.push_back(std::move(curve));
    }
    inc::IncidenceOptions options;
    if (input.contains("method")) {
        const json& m = input["method"];
        if (!m.is_string() || (m != "tsvd" && m != "mtsvd")) throw InputError("method: expected tsvd or mtsvd, got " + solvers::io::describeValue(m));
        options.method = m == "tsvd" ? inc::IncidenceMethod::Tsvd : inc::IncidenceMethod::Mtsvd;
    }
    if (input.contains("smoothing")) {
        const json& s = input["smoothing"];
        if (!s.is_object()) throw InputError("smoothing: expected {area, thin_plate, curvature_variation}");
        auto weight = [&](const char* name, double fallback) {
            if (!s.contains(name)) return fallback;
            const double w = solvers::io::numberFromJson(s[name], std::string("smoothing.") + name);
            if (w < 0.0) throw InputError(std::string("smoothing.") + name + ": must be >= 0");
            return w;
        };
        options.area = weight("area", 0.0);
        options.thinPlate = weight("thin_plate", s.contains("area") || s.contains("curvature_variation") ? 0.0 : 1.0);
        options.curvatureVariation = weight("curvature_variation", 0.0);
        if (options.area + options.thinPlate + options.curvatureVariation == 0.0)
            throw InputError("smoothing: at least one weight must be positive");
    }
    if (input.contains("k")) options.k = solvers::io::integerFromJson(input["k"], "k", 1, 1 << 20);

    const Stopwatch clock;
    const inc::IncidenceResult r = [&] {
        try {
            return inc::solveIncidence(surface, in, options);
        } catch (const solvers::GeometryError& e) {
            throw InputError(e.what());
        } catch (const std::invalid_argument& e) {
            throw InputError(e.what());
        }
    }();
    json out;
    out["surface"] = solvers::io::toJson(r.surface);
    out["k"] = r.k;
    out["corner"] = r.corner;
    out["rows"] = r.rows;
    out["cols"] = r.cols;
    out["hard_rows"] = r.hardRows;
    out["residual"] = r.residual;
    out["fixed_residual"] = r.fixedResidual;
    out["lcurve"] = {{"rho", toVector(r.lcurve.rho)}, {"eta", toVector(r.lcurve.eta)}};
    out["elapsed_ms"] = clock.elapsedMs();
    requireFiniteOutput(out);
    return out;
}

const SubcommandRegistrar registrar{
    {"incidence", "surface through curves on it: {surface, curves: [{domain?, target?, fixed?}], method?, smoothing?, k?} -> {surface, k, residual, ..}",
     &run}};

}  // namespace
}  // namespace sculptline::cli
