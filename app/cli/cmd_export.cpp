// sculptline-cli export: curves, surfaces and meshes to a CAD or mesh file (solvers/exchange).
//
//   {"curves"?: [C..], "surfaces"?: [S..], "meshes"?: [M..], "format": "step" | "iges" | "stl" | "obj",
//    "path": file}
//     -> {"path": file, "format", "bytes": size written, "elapsed_ms"}
//
// STEP (AP214) and IGES carry the exact B-splines and refuse meshes; STL (binary) holds triangles
// only (surfaces tessellated, curves skipped beside them, refused alone); OBJ takes everything
// (curves as polylines). The file is created or replaced; a path that cannot be written is refused
// before any work.
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"
#include "solvers/exchange/exchange.h"

namespace sculptline::cli {
namespace {

namespace ex = solvers::exchange;

// Bounds on one request, so that no input makes the command run for minutes: each surface may be
// tessellated up to kMaxTessellationVertices (solvers/bspline/tessellation.h), about a second on
// hostile input, so the item count is the time bound; a mesh is copied, not refined.
constexpr size_t kMaxItems = 1000;
constexpr size_t kMaxMeshElements = 2000000;

const json* optionalArray(const json& input, const std::string& key)
{
    if (!input.contains(key)) return nullptr;
    const json& a = input[key];
    if (!a.is_array()) throw InputError(key + ": expected an array, got " + solvers::io::describeValue(a));
    if (a.size() > kMaxItems) {
        throw InputError(key + ": " + std::to_string(a.size()) + " items, at most " + std::to_string(kMaxItems));
    }
    return &a;
}

ex::TriangleMesh meshFromJson(const json& j, const std::string& path)
{
    if (!j.is_object()) throw InputError(path + ": expected a mesh object, got " + solvers::io::describeValue(j));
    ex::TriangleMesh mesh;
    const json& vertices = solvers::io::member(j, "vertices", path);
    const json& triangles = solvers::io::member(j, "triangles", path);
    if (!vertices.is_array() || vertices.empty()) throw InputError(path + ".vertices: expected a non-empty array of points");
    if (!triangles.is_array() || triangles.empty()) {
        throw InputError(path + ".triangles: expected a non-empty array of [i, j, k]");
    }
    if (vertices.size() > kMaxMeshElements || triangles.size() > kMaxMeshElements) {
        throw InputError(path + ": more than " + std::to_string(kMaxMeshElements) + " vertices or triangles");
    }
    for (size_t i = 0; i < vertices.size(); ++i) {
        mesh.vertices.push_back(solvers::io::pointFromJson(vertices[i], path + ".vertices[" + std::to_string(i) + "]"));
    }
    const int last = static_cast<int>(vertices.size()) - 1;
    for (size_t i = 0; i < triangles.size(); ++i) {
        const std::string t = path + ".triangles[" + std::to_string(i) + "]";
        if (!triangles[i].is_array() || triangles[i].size() != 3) throw InputError(t + ": expected [i, j, k]");
        Eigen::Vector3i tri;
        for (int c = 0; c < 3; ++c) tri[c] = solvers::io::integerFromJson(triangles[i][c], t + "[" + std::to_string(c) + "]", 0, last);
        mesh.triangles.push_back(tri);
    }
    return mesh;
}

json run(const json& input, const Options&)
{
    const json& formatJson = field(input, "format");
    const std::optional<ex::Format> format =
        formatJson.is_string() ? ex::formatFromName(formatJson.get<std::string>()) : std::nullopt;
    if (!format) throw InputError("format: expected step, iges, stl or obj, got " + solvers::io::describeValue(formatJson));
    const json& pathJson = field(input, "path");
    if (!pathJson.is_string() || pathJson.get<std::string>().empty()) {
        throw InputError("path: expected a file name, got " + solvers::io::describeValue(pathJson));
    }
    const std::string path = pathJson.get<std::string>();

    ex::ExchangeContent content;
    if (const json* curves = optionalArray(input, "curves")) {
        for (size_t i = 0; i < curves->size(); ++i) {
            content.curves.push_back(solvers::io::curveFromJson((*curves)[i], "curves[" + std::to_string(i) + "]"));
        }
    }
    if (const json* surfaces = optionalArray(input, "surfaces")) {
        for (size_t i = 0; i < surfaces->size(); ++i) {
            content.surfaces.push_back(solvers::io::surfaceFromJson((*surfaces)[i], "surfaces[" + std::to_string(i) + "]"));
        }
    }
    if (const json* meshes = optionalArray(input, "meshes")) {
        for (size_t i = 0; i < meshes->size(); ++i) {
            content.meshes.push_back(meshFromJson((*meshes)[i], "meshes[" + std::to_string(i) + "]"));
        }
    }

    const Stopwatch clock;
    std::uintmax_t bytes = 0;
    try {
        bytes = ex::writeFile(content, *format, path);
    } catch (const ex::ExchangeError& e) {  // its message starts with the field
        throw InputError(e.what());
    }
    json out;
    out["elapsed_ms"] = clock.elapsedMs();
    out["path"] = path;
    out["format"] = ex::formatName(*format);
    out["bytes"] = bytes;
    return out;
}

const SubcommandRegistrar registrar{
    {"export",
     "write a CAD or mesh file: {curves?, surfaces?, meshes?, format: step|iges|stl|obj, path} -> {path, bytes}",
     &run}};

}  // namespace
}  // namespace sculptline::cli
