// The only translation unit of Sculptline that includes OpenVDB (and through it TBB): keep Qt away.
#include "solvers/volume/level_set.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/LevelSetMeasure.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <openvdb/util/NullInterrupter.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
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

// Narrow-band voxels a level set converts per second on one of this machine's cores (README
// "Solids": 1.3-1.8 million with the benchmark); only paces the progress bar, see below.
constexpr double kLevelSetVoxelsPerSecond = 1.5e6;

// OpenVDB's cancellation hook: MeshToVolume asks wasInterrupted() between (and inside) its passes,
// every few hundredths of a millisecond, possibly from several TBB threads; the answer is latched so
// one "cancel" stops them all. OpenVDB 10 asks without a percentage (-1), so the fraction reported
// is paced by time against what the narrow band's size lets expect, 1 - exp(-elapsed / expected):
// it moves while the work does and approaches the stage's end without claiming it.
class ProgressInterrupter : public openvdb::util::NullInterrupter {
public:
    ProgressInterrupter(const Progress& progress, double from, double to, double expectedSeconds)
        : progress_(progress), from_(from), to_(to), expected_(std::max(expectedSeconds, 1e-3)),
          start_(std::chrono::steady_clock::now())
    {
    }
    bool wasInterrupted(int percent = -1) override
    {
        if (cancelled_.load(std::memory_order_relaxed)) return true;
        if (!progress_) return false;
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        const double done = percent < 0 ? 1.0 - std::exp(-elapsed / expected_) : std::min(percent, 100) / 100.0;
        std::lock_guard<std::mutex> lock(mutex_);  // the callback need not be re-entrant
        // Some passes do give a percentage, of that pass only: the fraction never goes back.
        done_ = std::max(done_, done);
        if (!progress_(from_ + (to_ - from_) * done_)) cancelled_ = true;
        return cancelled_;
    }
    bool cancelled() const { return cancelled_; }

private:
    const Progress& progress_;
    double from_, to_, expected_;
    double done_ = 0.0;
    std::chrono::steady_clock::time_point start_;
    std::atomic<bool> cancelled_{false};
    std::mutex mutex_;
};

// The grids work in index space (a unit transform): the mesh is moved to `origin` and scaled by
// 1 / voxelSize in double precision before the cast to float, so that neither a model far from the
// origin nor one of huge or tiny size loses float precision or overflows (1e200 mm does not fit a
// float; 1e200 / voxel does, the caller bounds it by kMaxVoxelsAcross).
openvdb::FloatGrid::Ptr levelSet(const TriangleMesh& mesh, const openvdb::math::Transform& xform,
                                 const Eigen::Vector3d& origin, double voxelSize, ProgressInterrupter& interrupter)
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
    openvdb::FloatGrid::Ptr grid = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(
        interrupter, xform, points, triangles, static_cast<float>(kHalfWidthVoxels));
    if (interrupter.cancelled()) throw Cancelled();  // the grid is partial
    return grid;
}

}  // namespace

LevelSetSolid solidFromMeshes(const std::vector<TriangleMesh>& closedMeshes, double voxelSize,
                              const Eigen::Vector3d& origin, double adaptivity, const Progress& progress)
{
    // Shares of the work (fractions of the whole), measured roughly on a sphere: the level sets
    // take most of it, meshing and measuring the union the rest.
    constexpr double kLevelSetsDone = 0.8, kMeshDone = 0.9;
    initializeOpenVdb();
    const openvdb::math::Transform::Ptr xform = openvdb::math::Transform::createLinearTransform(1.0);
    openvdb::FloatGrid::Ptr grid;
    const double share = kLevelSetsDone / static_cast<double>(std::max<size_t>(closedMeshes.size(), 1));
    for (size_t k = 0; k < closedMeshes.size(); ++k) {
        const TriangleMesh& mesh = closedMeshes[k];
        reportProgress(progress, share * static_cast<double>(k));
        if (mesh.triangles.empty()) continue;
        const double bandVoxels = area(mesh) / (voxelSize * voxelSize) * 2.0 * kHalfWidthVoxels;
        ProgressInterrupter interrupter(progress, share * static_cast<double>(k), share * static_cast<double>(k + 1),
                                        bandVoxels / kLevelSetVoxelsPerSecond);
        openvdb::FloatGrid::Ptr next = levelSet(mesh, *xform, origin, voxelSize, interrupter);
        if (!grid) {
            grid = next;
        } else {
            openvdb::tools::csgUnion(*grid, *next);  // grid = min(grid, next); next is emptied
        }
    }
    reportProgress(progress, kLevelSetsDone);
    LevelSetSolid out;
    if (!grid) return out;
    out.activeVoxels = static_cast<size_t>(grid->activeVoxelCount());

    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    std::vector<openvdb::Vec4I> quads;
    openvdb::tools::volumeToMesh(*grid, points, triangles, quads, 0.0, adaptivity);
    reportProgress(progress, kMeshDone);
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
    reportProgress(progress, 1.0);
    return out;
}

}  // namespace sculptline::solvers::volume
