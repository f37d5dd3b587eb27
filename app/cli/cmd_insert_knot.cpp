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

json run(const json& input, const Options&)
{
    const double knot = solvers::io::numberFromJson(field(input, "knot"), "knot");
    // The kernel bounds times by degree - multiplicity; the range here only keeps the integer sane.
    const int times = input.contains("times")
                          ? solvers::io::integerFromJson(input["times"], "times", 0, solvers::kMaxDegree + 1)
                          : 1;
    return transformGeometry(
        input, [&](const solvers::Curve3d& c) { return c.insertKnot(knot, times); },
        [&](const solvers::Surface3d& s, solvers::Direction d) { return s.insertKnot(d, knot, times); });
}

const SubcommandRegistrar registrar{
    {"insert-knot", "knot insertion: {curve|surface, direction (surface), knot, times} -> {curve|surface}", &run}};

}  // namespace
}  // namespace sculptline::cli
