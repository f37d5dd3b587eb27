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

namespace sculptline::cli {
namespace {

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
        // Bound the mesh size: at most ~1e5 boundary samples per curve (the solver caps there too).
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
