#include "model/document_solids.h"

#include "model/document.h"
#include "solvers/io/geometry_json.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

namespace sculptline::model {
namespace io = solvers::io;
using nlohmann::json;

namespace {

/// The documents' bound on coordinates (document.cpp's kMaxExtent: Coin draws in float).
constexpr double kMaxSolidCoordinate = 1e6;

solvers::volume::TriangleMesh meshFromJson(const json& j, const std::string& path)
{
    if (!j.is_object()) throw io::InputError(path + ": must be an object");
    const json& vertices = io::member(j, "vertices", path);
    const json& triangles = io::member(j, "triangles", path);
    if (!vertices.is_array() || !triangles.is_array()) throw io::InputError(path + ": vertices and triangles must be arrays");
    if (vertices.size() > kMaxSolidMeshElements || triangles.size() > kMaxSolidMeshElements)
        throw io::InputError(path + ": more than " + std::to_string(kMaxSolidMeshElements) + " vertices or triangles");
    solvers::volume::TriangleMesh mesh;
    mesh.vertices.reserve(vertices.size());
    for (size_t i = 0; i < vertices.size(); ++i) {
        const std::string v = path + ".vertices[" + std::to_string(i) + "]";
        mesh.vertices.push_back(io::pointFromJson(vertices[i], v));
        // As every coordinate of a document (document.h): Coin draws in float.
        if (mesh.vertices.back().cwiseAbs().maxCoeff() > kMaxSolidCoordinate)
            throw io::InputError(v + ": coordinates must lie within +-1e6 model units");
    }
    const int last = static_cast<int>(mesh.vertices.size()) - 1;
    mesh.triangles.reserve(triangles.size());
    for (size_t i = 0; i < triangles.size(); ++i) {
        const std::string t = path + ".triangles[" + std::to_string(i) + "]";
        if (!triangles[i].is_array() || triangles[i].size() != 3) throw io::InputError(t + ": expected [i, j, k]");
        if (last < 0) throw io::InputError(t + ": the mesh has no vertices");
        Eigen::Vector3i tri;
        for (int c = 0; c < 3; ++c) tri[c] = io::integerFromJson(triangles[i][c], t + "[" + std::to_string(c) + "]", 0, last);
        mesh.triangles.push_back(tri);
    }
    return mesh;
}

double nonNegative(const json& j, const std::string& path)
{
    const double x = io::numberFromJson(j, path);
    if (!(x >= 0.0)) throw io::InputError(path + ": must be >= 0");
    return x;
}

}  // namespace

void readSolids(const json& j, SceneDocument& doc, std::set<int>& usedIds)
{
    const auto it = j.find("solids");
    if (it == j.end()) return;
    if (!it->is_array()) throw io::InputError("solids: must be an array");
    std::set<int> surfaceIds(doc.surfaceIds.begin(), doc.surfaceIds.end());
    for (const SceneDocument::ConstructedSurface& c : doc.constructed) surfaceIds.insert(c.id);
    surfaceIds.erase(0);
    for (size_t i = 0; i < it->size(); ++i) {
        const json& s = (*it)[i];
        const std::string path = "solids[" + std::to_string(i) + "]";
        if (!s.is_object()) throw io::InputError(path + ": must be an object");
        SceneDocument::SolidSpec spec;
        spec.id = io::integerFromJson(io::member(s, "id", path), path + ".id", 1, 1 << 30);
        if (!usedIds.insert(spec.id).second) throw io::InputError(path + ".id: used by another entity");
        const json& surfaces = io::member(s, "surfaces", path);
        if (!surfaces.is_array() || surfaces.empty()) throw io::InputError(path + ".surfaces: expected an array of surface ids");
        for (size_t k = 0; k < surfaces.size(); ++k) {
            const std::string field = path + ".surfaces[" + std::to_string(k) + "]";
            const int id = io::integerFromJson(surfaces[k], field, 1, 1 << 30);
            if (!surfaceIds.count(id)) throw io::InputError(field + ": no surface has id " + std::to_string(id));
            if (id >= spec.id) throw io::InputError(field + ": must be smaller than the solid's id");
            spec.surfaces.push_back(id);
        }
        const json& mode = io::member(s, "mode", path);
        const std::optional<SolidMode> parsed = mode.is_string() ? solidModeFromName(mode.get<std::string>()) : std::nullopt;
        if (!parsed) throw io::InputError(path + ".mode: must be \"closed\" or \"shell\"");
        spec.recipe.mode = *parsed;
        if (const auto t = s.find("thickness"); t != s.end()) spec.recipe.thickness = nonNegative(*t, path + ".thickness");
        if (const auto v = s.find("voxel_size"); v != s.end()) spec.recipe.voxelSize = nonNegative(*v, path + ".voxel_size");
        if (const std::string error = validate(spec.recipe); !error.empty()) throw io::InputError(path + "." + error);
        if (const auto r = s.find("result"); r != s.end()) {
            const std::string rp = path + ".result";
            if (!r->is_object()) throw io::InputError(rp + ": must be an object");
            solvers::volume::Solid result;
            result.mesh = meshFromJson(io::member(*r, "mesh", rp), rp + ".mesh");
            result.volume = nonNegative(io::member(*r, "volume", rp), rp + ".volume");
            result.area = nonNegative(io::member(*r, "area", rp), rp + ".area");
            result.voxelSize = nonNegative(io::member(*r, "voxel_size", rp), rp + ".voxel_size");
            // Recomputed rather than trusted: the file may have been edited.
            result.watertight = solvers::volume::isWatertight(result.mesh.triangles);
            spec.result = std::move(result);
        }
        if (const auto st = s.find("state"); st != s.end()) {
            if (!st->is_string() || (*st != "fixed" && *st != "free")) throw io::InputError(path + ".state: must be \"fixed\" or \"free\"");
            spec.fixed = *st == "fixed";
        }
        doc.solids.push_back(std::move(spec));
    }
}

json solidToJson(const Entity& e)
{
    const SolidRecipe& r = *e.solidRecipe;
    json entry{{"id", e.id}, {"surfaces", e.inputs}, {"mode", solidModeName(r.mode)}};
    if (r.mode == SolidMode::Shell) entry["thickness"] = r.thickness;
    if (r.voxelSize > 0.0) entry["voxel_size"] = r.voxelSize;
    if (e.solid && !e.solidStale()) {
        json vertices = json::array(), triangles = json::array();
        for (const Eigen::Vector3d& v : e.solid->mesh.vertices) vertices.push_back(io::toJson(v));
        for (const Eigen::Vector3i& t : e.solid->mesh.triangles) triangles.push_back({t[0], t[1], t[2]});
        entry["result"] = {{"mesh", {{"vertices", std::move(vertices)}, {"triangles", std::move(triangles)}}},
                           {"volume", e.solid->volume},
                           {"area", e.solid->area},
                           {"voxel_size", e.solid->voxelSize},
                           {"watertight", e.solid->watertight}};
    }
    return entry;  // "state" is written with every entity's (model_document.cpp)
}

}  // namespace sculptline::model
