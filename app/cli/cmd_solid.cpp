// sculptline-cli solid: the solid that surfaces bound, or the shells of open surfaces, united and
// meshed through narrow-band level sets (solvers/volume/solidify.h).
//
//   {"surfaces": [S..], "thickness"?: t (model units, >= 0; open surfaces become shells t thick),
//    "voxel_size"?: v (model units, > 0; default: bounding-box diagonal / 200, and at most t / 4
//    with shells)}
//     -> {"mesh": {"vertices", "triangles"}, "volume", "area", "voxel_size", "watertight",
//         "active_voxels", "elapsed_ms"}
//
// Refused with the field named: an open surface without thickness that meets no other (it encloses
// nothing), a shell or solid less than two voxels thick, a voxel size whose level set would need
// more memory than solidify's limit (the message gives the smallest voxel size that fits).
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"
#include "solvers/volume/solidify.h"

namespace sculptline::cli {
namespace {

namespace vol = solvers::volume;

// Most surfaces in one call: each is tessellated at a sub-voxel chord tolerance (up to a million
// vertices, tessellation.h), so the count bounds the time spent before the memory check can help.
constexpr size_t kMaxSurfaces = 256;

json run(const json& input, const Options&)
{
    const json& surfacesJson = field(input, "surfaces");
    if (!surfacesJson.is_array() || surfacesJson.empty()) throw InputError("surfaces: expected a non-empty array of surfaces");
    if (surfacesJson.size() > kMaxSurfaces)
        throw InputError("surfaces: " + std::to_string(surfacesJson.size()) + " surfaces, at most " + std::to_string(kMaxSurfaces));
    std::vector<solvers::Surface3d> surfaces;
    for (size_t k = 0; k < surfacesJson.size(); ++k)
        surfaces.push_back(solvers::io::surfaceFromJson(surfacesJson[k], "surfaces[" + std::to_string(k) + "]"));
    vol::SolidOptions options;
    if (input.contains("thickness")) {
        options.thickness = solvers::io::numberFromJson(input["thickness"], "thickness");
        if (options.thickness < 0.0) throw InputError("thickness: must be >= 0, got " + solvers::io::describeValue(input["thickness"]));
    }
    if (input.contains("voxel_size")) {
        options.voxelSize = solvers::io::numberFromJson(input["voxel_size"], "voxel_size");
        if (!(options.voxelSize > 0.0))
            throw InputError("voxel_size: must be positive, got " + solvers::io::describeValue(input["voxel_size"]));
    }

    const Stopwatch clock;
    const vol::Solid solid = [&] {
        try {
            return vol::solidify(surfaces, options);
        } catch (const solvers::GeometryError& e) {
            throw InputError(e.what());  // messages start with "surfaces[..]", "thickness" or "voxel_size"
        }
    }();
    const double ms = clock.elapsedMs();

    json triangles = json::array();
    for (const Eigen::Vector3i& t : solid.mesh.triangles) triangles.push_back({t[0], t[1], t[2]});
    json out;
    out["mesh"] = {{"vertices", toJson(solid.mesh.vertices)}, {"triangles", std::move(triangles)}};
    out["volume"] = solid.volume;
    out["area"] = solid.area;
    out["voxel_size"] = solid.voxelSize;
    out["watertight"] = solid.watertight;
    out["active_voxels"] = solid.activeVoxels;
    out["elapsed_ms"] = ms;
    requireFiniteOutput(out);
    return out;
}

const SubcommandRegistrar registrar{
    {"solid",
     "solid of closed surfaces or shells of open ones, united, through level sets: {surfaces, thickness?, voxel_size?} "
     "-> {mesh, volume, area, voxel_size, watertight}",
     &run}};

}  // namespace
}  // namespace sculptline::cli
