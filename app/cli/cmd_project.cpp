// sculptline-cli project: closest points on a curve or surface (the global minimum of the distance).
//
//   {"curve": C, "points": [[x, y, z], ..]}   -> {"params": [u, ..], "points": [..], "distances": [..], "elapsed_ms": t}
//   {"surface": S, "points": [[x, y, z], ..]} -> {"params": [[u, v], ..], "points": [..], "distances": [..], ..}
//
// One projector per input: it samples the geometry once and answers every point from that sampling
// (solvers/bspline/projection.h), so many points cost little more than one.
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"
#include "solvers/bspline/projection.h"

namespace sculptline::cli {
namespace {

// Input is validated before projecting, so a kernel error here comes from arithmetic overflow on
// extreme (finite) magnitudes; its own field names ("parameter") are not input fields, so name the
// point instead.
template <typename Projector>
auto projectOne(const Projector& projector, const std::vector<Eigen::Vector3d>& points, size_t i)
{
    try {
        return projector.project(points[i]);
    } catch (const solvers::GeometryError& e) {
        throw InputError("points[" + std::to_string(i) + "]: cannot be projected (" + e.what() +
                         "); do the magnitudes overflow double precision?");
    }
}

json projectOnCurve(const json& input)
{
    const solvers::Curve3d curve = solvers::io::curveFromJson(field(input, "curve"), "curve");
    const std::vector<Eigen::Vector3d> points = pointArray(field(input, "points"), "points");

    const Stopwatch clock;
    const solvers::CurveProjector<3> projector(curve);
    std::vector<solvers::CurveProjection<3>> found;
    found.reserve(points.size());
    for (size_t i = 0; i < points.size(); ++i) found.push_back(projectOne(projector, points, i));
    const double ms = clock.elapsedMs();

    json out = {{"params", json::array()}, {"points", json::array()}, {"distances", json::array()}};
    for (const auto& f : found) {
        out["params"].push_back(f.u);
        out["points"].push_back(solvers::io::toJson(f.point));
        out["distances"].push_back(f.distance);
    }
    out["elapsed_ms"] = ms;
    return out;
}

json projectOnSurface(const json& input)
{
    const solvers::Surface3d surface = solvers::io::surfaceFromJson(field(input, "surface"), "surface");
    const std::vector<Eigen::Vector3d> points = pointArray(field(input, "points"), "points");

    const Stopwatch clock;
    const solvers::SurfaceProjector projector(surface);
    std::vector<solvers::SurfaceProjection> found;
    found.reserve(points.size());
    for (size_t i = 0; i < points.size(); ++i) found.push_back(projectOne(projector, points, i));
    const double ms = clock.elapsedMs();

    json out = {{"params", json::array()}, {"points", json::array()}, {"distances", json::array()}};
    for (const auto& f : found) {
        out["params"].push_back(json::array({f.u, f.v}));
        out["points"].push_back(solvers::io::toJson(f.point));
        out["distances"].push_back(f.distance);
    }
    out["elapsed_ms"] = ms;
    return out;
}

json run(const json& input, const Options&)
{
    return curveOrSurface(input) == GeometryKind::Curve ? projectOnCurve(input) : projectOnSurface(input);
}

const SubcommandRegistrar registrar{
    {"project", "closest points: {curve|surface, points} -> {params, points, distances}", &run}};

}  // namespace
}  // namespace sculptline::cli
