// sculptline-cli insert-knot: Boehm knot insertion (The NURBS Book A5.1), shape unchanged.
//
//   {"curve": C, "knot": u, "times": r}                      -> {"curve": C', "elapsed_ms": t}
//   {"surface": S, "direction": "u"|"v", "knot": u, "times": r} -> {"surface": S', "elapsed_ms": t}
//
// "times" is optional (default 1). The knot must lie strictly inside the domain of an open curve or
// surface and its multiplicity may not exceed the degree afterwards; a closed curve accepts any
// value and inserts it once per period, staying closed.
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"

namespace sculptline::cli {
namespace {

// For open curves the kernel reports a multiplicity above the degree against "times"; for closed
// ones it inserts a copy per period and would name one of those copies instead, so check here.
void checkClosedMultiplicity(const solvers::Curve3d& curve, double knot, int times)
{
    const double u = curve.normalizeParameter(knot);
    const int s = solvers::knotMultiplicity(curve.knots(), u);
    if (s + times > curve.degree()) {
        throw InputError("times: knot " + json(knot).dump() + " has multiplicity " + std::to_string(s) + "; inserting it " +
                         std::to_string(times) + " more times exceeds the degree " + std::to_string(curve.degree()));
    }
}

json run(const json& input, const Options&)
{
    const bool isCurve = curveOrSurface(input) == GeometryKind::Curve;
    const double knot = solvers::io::numberFromJson(field(input, "knot"), "knot");
    // The kernel bounds times by degree - multiplicity; the range here only keeps the integer sane.
    const int times = input.contains("times")
                          ? solvers::io::integerFromJson(input["times"], "times", 0, solvers::kMaxDegree + 1)
                          : 1;
    json out;
    if (isCurve) {
        const solvers::Curve3d curve = solvers::io::curveFromJson(field(input, "curve"), "curve");
        if (curve.isClosed()) checkClosedMultiplicity(curve, knot, times);
        const Stopwatch clock;
        const solvers::Curve3d result = runOperation(input, "curve", [&] { return curve.insertKnot(knot, times); });
        const double ms = clock.elapsedMs();
        out["curve"] = solvers::io::toJson(result);
        out["elapsed_ms"] = ms;
    } else {
        const solvers::Surface3d surface = solvers::io::surfaceFromJson(field(input, "surface"), "surface");
        const solvers::Direction direction = directionFromJson(input);
        const Stopwatch clock;
        const solvers::Surface3d result =
            runOperation(input, "surface", [&] { return surface.insertKnot(direction, knot, times); });
        const double ms = clock.elapsedMs();
        out["surface"] = solvers::io::toJson(result);
        out["elapsed_ms"] = ms;
    }
    return out;
}

const SubcommandRegistrar registrar{
    {"insert-knot", "knot insertion: {curve|surface, direction (surface), knot, times} -> {curve|surface}", &run}};

}  // namespace
}  // namespace sculptline::cli
