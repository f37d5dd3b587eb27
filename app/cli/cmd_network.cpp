// sculptline-cli network: closed loops of curves -> a triangle mesh by topological triangulation,
// SLERP boundary normals and fairing (seed 004 §4; solvers/surfaces/network_mesh.h).
//
//   {"curves": [C..], "loops": [[curve indices]..], "edge_length": h, "fairing": n}
//     -> {"mesh": {"vertices", "triangles", "normals"}, "boundary_vertices": b, "elapsed_ms": t}
//
// "edge_length" (model units, optional) sets the boundary sampling; "fairing" (0..100, default 3)
// the number of fairing passes.
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"
#include "solvers/surfaces/network_mesh.h"

#include <cmath>

namespace sculptline::cli {
namespace {

// Most boundary vertices an "edge_length" may ask for. The triangulation and fairing of the interior
// grow faster than the ring (measured, Release, 100 fairing passes: 10,000 boundary vertices 0.4 s;
// 400,000 took 9.4 s and 0.5 GB), and no input may make sculptline-cli hang; 5,000 vertices is a
// finer boundary than a sketch's display needs (the default is 16 per curve).
constexpr double kMaxBoundaryVertices = 5000;

// Samples per curve for its length here: the polyline through them is within a fraction of a percent
// of a smooth curve's length, and it takes microseconds whatever the curve (an adaptive arc length
// can take seconds on a near-degenerate rational curve).
constexpr int kLengthSamples = 256;

double polylineLength(const solvers::Curve3d& c)
{
    double length = 0.0;
    Eigen::Vector3d prev = c.evaluate(c.domainStart());
    for (int k = 1; k <= kLengthSamples; ++k) {
        const Eigen::Vector3d p = c.evaluate(c.domainStart() + (c.domainEnd() - c.domainStart()) * k / kLengthSamples);
        length += (p - prev).norm();
        prev = p;
    }
    return length;
}

// The boundary vertices meshNetwork would place at edge length h: each curve's length / h.
void checkEdgeLength(const std::vector<solvers::Curve3d>& curves, double h)
{
    double vertices = 0.0, total = 0.0;
    for (const solvers::Curve3d& c : curves) {
        const double length = polylineLength(c);
        total += length;
        vertices += std::ceil(length / h);
    }
    if (vertices > kMaxBoundaryVertices) {
        throw InputError("edge_length: " + solvers::io::describeValue(h) + " would put " + json(vertices).dump() +
                         " vertices on the curves' boundary (total length " + json(total).dump() + "); at most " +
                         json(kMaxBoundaryVertices).dump() + ", so edge_length must be at least " +
                         json(total / kMaxBoundaryVertices).dump());
    }
}

json run(const json& input, const Options&)
{
    const json& curvesJson = field(input, "curves");
    if (!curvesJson.is_array() || curvesJson.empty()) throw InputError("curves: expected a non-empty array of curves");
    std::vector<solvers::Curve3d> curves;
    for (size_t k = 0; k < curvesJson.size(); ++k)
        curves.push_back(solvers::io::curveFromJson(curvesJson[k], "curves[" + std::to_string(k) + "]"));
    const json& loopsJson = field(input, "loops");
    if (!loopsJson.is_array() || loopsJson.empty()) throw InputError("loops: expected a non-empty array of loops");
    std::vector<std::vector<int>> loops;
    for (size_t l = 0; l < loopsJson.size(); ++l) {
        const std::string path = "loops[" + std::to_string(l) + "]";
        if (!loopsJson[l].is_array()) throw InputError(path + ": expected an array of curve indices");
        std::vector<int> loop;
        for (size_t k = 0; k < loopsJson[l].size(); ++k)
            loop.push_back(solvers::io::integerFromJson(loopsJson[l][k], path + "[" + std::to_string(k) + "]", 0,
                                                        static_cast<int>(curves.size()) - 1));
        loops.push_back(std::move(loop));
    }
    solvers::surfaces::NetworkOptions options;
    if (input.contains("edge_length")) {
        options.edgeLength = solvers::io::numberFromJson(input["edge_length"], "edge_length");
        if (!(options.edgeLength > 0.0)) throw InputError("edge_length: must be positive");
        checkEdgeLength(curves, options.edgeLength);
    }
    if (input.contains("fairing")) options.fairingIterations = solvers::io::integerFromJson(input["fairing"], "fairing", 0, 100);

    const Stopwatch clock;
    const solvers::surfaces::NetworkMesh mesh = [&] {
        try {
            return solvers::surfaces::meshNetwork(curves, loops, options);
        } catch (const solvers::GeometryError& e) {
            throw InputError(e.what());  // messages name "loops[..]" or "curves[..]"
        }
    }();
    const double ms = clock.elapsedMs();
    json triangles = json::array();
    for (const Eigen::Vector3i& t : mesh.triangles) triangles.push_back({t[0], t[1], t[2]});
    json out;
    out["mesh"] = {{"vertices", toJson(mesh.vertices)}, {"triangles", triangles}, {"normals", toJson(mesh.normals)}};
    out["boundary_vertices"] = mesh.boundaryVertexCount;
    out["elapsed_ms"] = ms;
    requireFiniteOutput(out);
    return out;
}

const SubcommandRegistrar registrar{
    {"network", "curve network to triangle mesh: {curves, loops: [[indices]..]} -> {mesh}", &run}};

}  // namespace
}  // namespace sculptline::cli
