// The only translation unit of Sculptline that includes OpenVDB (and through it TBB): keep Qt away.
#include "solvers/volume/level_set.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/LevelSetMeasure.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <mutex>

namespace sculptline::solvers::volume {

namespace {

void initializeOpenVdb()
{
    // openvdb::initialize() registers the grid types; it is thread-safe in OpenVDB 10, the flag
    // only saves the lock on later calls.
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
}

// The grids work in index space (a unit transform): the mesh is moved to `origin` and scaled by
// 1 / voxelSize in double precision before the cast to float, so that neither a model far from the
// origin nor one of huge or tiny size loses float precision or overflows (1e200 mm does not fit a
// float; 1e200 / voxel does, the caller bounds it by kMaxVoxelsAcross).
openvdb::FloatGrid::Ptr levelSet(const TriangleMesh& mesh, const openvdb::math::Transform& xform,
                                 const Eigen::Vector3d& origin, double voxelSize)
{
    std::vector<openvdb::Vec3s> points;
    points.reserve(mesh.vertices.size());
    for (const Eigen::Vector3d& v : mesh.vertices) {
        const Eigen::Vector3d local = (v - origin) / voxelSize;
        points.emplace_back(static_cast<float>(local.x()), static_cast<float>(local.y()), static_cast<float>(local.z()));
    }
    std::vector<openvdb::Vec3I> triangles;
    triangles.reserve(mesh.triangles.size());
    for (const Eigen::Vector3i& t : mesh.triangles)
        triangles.emplace_back(static_cast<openvdb::Index32>(t[0]), static_cast<openvdb::Index32>(t[1]),
                               static_cast<openvdb::Index32>(t[2]));
    return openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(xform, points, triangles,
                                                              static_cast<float>(kHalfWidthVoxels));
}

}  // namespace

LevelSetSolid solidFromMeshes(const std::vector<TriangleMesh>& closedMeshes, double voxelSize,
                              const Eigen::Vector3d& origin, double adaptivity)
{
    initializeOpenVdb();
    const openvdb::math::Transform::Ptr xform = openvdb::math::Transform::createLinearTransform(1.0);
    openvdb::FloatGrid::Ptr grid;
    for (const TriangleMesh& mesh : closedMeshes) {
        if (mesh.triangles.empty()) continue;
        openvdb::FloatGrid::Ptr next = levelSet(mesh, *xform, origin, voxelSize);
        if (!grid) {
            grid = next;
        } else {
            openvdb::tools::csgUnion(*grid, *next);  // grid = min(grid, next); next is emptied
        }
    }
    LevelSetSolid out;
    if (!grid) return out;
    out.activeVoxels = static_cast<size_t>(grid->activeVoxelCount());

    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    std::vector<openvdb::Vec4I> quads;
    openvdb::tools::volumeToMesh(*grid, points, triangles, quads, 0.0, adaptivity);
    out.mesh.vertices.reserve(points.size());
    for (const openvdb::Vec3s& p : points) out.mesh.vertices.push_back(origin + voxelSize * Eigen::Vector3d(p.x(), p.y(), p.z()));
    out.mesh.triangles.reserve(triangles.size() + 2 * quads.size());
    for (const openvdb::Vec3I& t : triangles)
        out.mesh.triangles.emplace_back(static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2]));
    for (const openvdb::Vec4I& q : quads) {
        out.mesh.triangles.emplace_back(static_cast<int>(q[0]), static_cast<int>(q[1]), static_cast<int>(q[2]));
        out.mesh.triangles.emplace_back(static_cast<int>(q[0]), static_cast<int>(q[2]), static_cast<int>(q[3]));
    }
    if (out.activeVoxels > 0) {
        out.volume = openvdb::tools::levelSetVolume(*grid) * voxelSize * voxelSize * voxelSize;
        out.area = openvdb::tools::levelSetArea(*grid) * voxelSize * voxelSize;
    }
    return out;
}

}  // namespace sculptline::solvers::volume
