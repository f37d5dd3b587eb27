#pragma once
// Closed triangle meshes -> narrow-band level sets -> their union -> a polygon mesh, volume and
// area. The interface is plain C++ and Eigen; OpenVDB is used only inside level_set.cpp.
#include "solvers/volume/progress.h"
#include "solvers/volume/surface_mesh.h"

namespace sculptline::solvers::volume {

/// Half width of the level sets' narrow band, in voxels: OpenVDB's LEVEL_SET_HALF_WIDTH, the width
/// its measures (LevelSetMeasure's finite differences) and VolumeToMesh are written for.
constexpr double kHalfWidthVoxels = 3.0;

/// VolumeToMesh's adaptivity in [0, 1]: 0 keeps one quad per surface voxel; 0.05 merges flat
/// regions into larger polygons (a 100 mm plate's faces shrink to a few percent of the polygons)
/// while the curved parts keep the voxel resolution, and the mesh stays crack-free.
constexpr double kAdaptivity = 0.05;

struct LevelSetSolid {
    TriangleMesh mesh;         ///< the zero iso-surface, quads split into two triangles, no normals
    double volume = 0.0;       ///< model units³, LevelSetMeasure on the united level set
    double area = 0.0;         ///< model units², likewise
    size_t activeVoxels = 0;   ///< narrow-band voxels of the union
};

/// The union of the solids bounded by `closedMeshes`. Every mesh is converted on its own
/// (MeshToVolume's meshToLevelSet: the sign comes from the mesh being closed, not from its
/// orientation), then united (Composite's csgUnion), so overlapping solids do not leave internal
/// surfaces; the union is meshed at the zero iso-value (VolumeToMesh) and measured (LevelSetMeasure).
/// @param closedMeshes closed triangle meshes, model units; gaps narrower than a voxel are tolerated.
/// @param voxelSize    model units, > 0.
/// @param origin       model point mapped to the grid's origin: the meshes are converted relative to
///                     it, in index units (the grids have a unit transform), so that single-precision
///                     coordinates keep their resolution far from the model's origin and cannot
///                     overflow. Pass the centre of the model's bounds.
/// @note The cost is about proportional to the narrow band's voxel count (estimateMemory() in
///       solidify.h); callers check it first.
/// @param progress told the fraction done (level sets up to 0.8, the mesh 0.9, the measures 1),
///                 also from inside MeshToVolume through its interrupter; answering false stops
///                 the work: @throws Cancelled.
LevelSetSolid solidFromMeshes(const std::vector<TriangleMesh>& closedMeshes, double voxelSize,
                              const Eigen::Vector3d& origin, double adaptivity = kAdaptivity,
                              const Progress& progress = {});

}  // namespace sculptline::solvers::volume
