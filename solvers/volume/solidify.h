#pragma once
// Solids from B-spline surfaces: closed surface sets become the solid they bound, open surfaces
// become shells of a given thickness with square edges (CAD's thicken), and everything is united.
// The work goes through narrow-band level sets (OpenVDB, level_set.h): they make the union exact to
// the voxel and give a watertight mesh of the result, whatever the input surfaces' overlaps.
#include "solvers/volume/progress.h"
#include "solvers/volume/surface_mesh.h"

#include <cstddef>
#include <vector>

namespace sculptline::solvers::volume {

/// Default voxel size = the diagonal of the solid's bounding box / kDefaultVoxelsAcrossDiagonal.
/// 200 voxels along the diagonal put about 115 across a cube's edge: a sphere's volume is then
/// within 0.4 % (measured, tests/volume; README "Solids") and the conversion takes under a second.
constexpr double kDefaultVoxelsAcrossDiagonal = 200.0;
/// With shells, the default voxel is also at most thickness / kDefaultVoxelsAcrossThickness: a wall
/// needs a few voxels across for both faces to be resolved (LevelSetMeasure's smeared delta is 1.5
/// voxels wide on each face). Measured on 1 mm plates: at 4 voxels across within 1.4 %, at 2 voxels
/// 2.4 %, at 1.5 voxels 9 %, at 1 voxel 24 % (README "Solids").
constexpr double kDefaultVoxelsAcrossThickness = 4.0;
/// Thinnest shell converted, in voxels: below it the error above grows past a few percent.
constexpr double kMinVoxelsAcrossThickness = 2.0;
/// The surfaces are tessellated with a chord tolerance of this fraction of the voxel size: the
/// tessellation's error then stays an order of magnitude below the voxel resolution (at a chord
/// error of a whole voxel a sphere's volume would shrink by about 2 %).
constexpr double kChordToleranceVoxels = 0.1;
/// Vertices closer than this fraction of the model's size are one (a revolve's seam, its poles):
/// far below any chord tolerance, far above the round-off of evaluating the same point twice.
constexpr double kWeldRelative = 1e-9;
/// Estimated bytes per narrow-band voxel during a conversion: the float level set (4 bytes), the
/// Int32 closest-triangle index grid MeshToVolume builds beside it (4), leaf-node topology and
/// masks (about 1 per voxel at the narrow band's leaf occupancy), the copy of each operand during a
/// union and VolumeToMesh's per-voxel work (about 4 + 4), partly filled leaves and TBB's per-thread
/// buffers. Measured: 36 bytes per voxel of peak memory above the program's baseline (a sphere at
/// 3.0 and 6.2 million voxels); 48 keeps a third in reserve.
constexpr double kBytesPerBandVoxel = 48.0;
/// Vertices of all the coarse tessellations of a call together (each surface gets at least
/// kMinVerticesPerSurface, in solidify.cpp). The coarse pass only sizes the model and estimates its
/// boundary area for the memory check (which keeps a third in reserve): a smooth surface needs a
/// few thousand vertices at the display's chord tolerance (the revolved sphere: 2,145), and a
/// 90 x 90 grid measures a smooth patch's area far inside that reserve. The refinement's cost grows
/// faster than its vertex count (every round probes every grid line): the fuzzer's degenerate net
/// (tests/fuzz/slow/solid_tessellation.json) took 24,210 vertices and 137 ms of CPU in Release
/// (over 5 s under ASan) with the kernel's million-vertex budget, 7,919 and 15 ms with this one.
constexpr int kCoarseVertexBudget = 8192;
/// Vertices of a fine tessellation per voxel of its surface (area / voxel²): a mesh finer than the
/// voxel grid adds nothing the level set can resolve, and two per voxel still meet the sub-voxel
/// chord tolerance on curvature radii above a few voxels (the sphere at the default voxel uses
/// well under one per surface voxel). Bounds the fine pass's time by the level set's own size.
constexpr double kFineVerticesPerSurfaceVoxel = 2.0;
/// Most voxels along any axis of the model: index coordinates are single-precision floats in
/// MeshToVolume, whose 24-bit mantissa keeps 1/16 voxel resolution up to 2^20 voxels from the origin.
constexpr double kMaxVoxelsAcross = 1 << 20;

struct SolidOptions {
    /// model units, >= 0: open surfaces become shells this thick; 0: no shells, the open surfaces
    /// must close up with one another into the boundary of a solid.
    double thickness = 0.0;
    /// model units, >= 0; 0: the default (kDefaultVoxelsAcrossDiagonal, kDefaultVoxelsAcrossThickness).
    double voxelSize = 0.0;
    /// bytes, >= 0; 0: defaultMemoryLimit().
    double memoryLimit = 0.0;
    /// Told the fraction done between stages and during the level sets; answering false cancels
    /// (solidify throws Cancelled). Empty: not asked.
    Progress progress;
};

struct Solid {
    TriangleMesh mesh;             ///< the solid's boundary, triangles, no normals
    double volume = 0.0;           ///< model units³ (LevelSetMeasure)
    double area = 0.0;             ///< model units² (LevelSetMeasure)
    double voxelSize = 0.0;        ///< model units, the one used
    bool watertight = false;       ///< every edge of mesh shared by exactly two triangles
    size_t activeVoxels = 0;       ///< narrow-band voxels of the united level set
    double estimatedBytes = 0.0;   ///< the estimate the memory check used
};

/// The largest conversion solidify() starts: 1 GiB, or a quarter of the machine's physical memory
/// when that is less. The CLI and the GUI share the machine with the user's other programs; a
/// quarter leaves them room. 1 GiB is some 22 million narrow-band voxels at kBytesPerBandVoxel, far
/// finer than a viewport shows, and bounds a conversion's time: 3 million voxels took 6 s on two
/// cores (README "Solids"), so the largest accepted one takes under a minute, never a hang.
double defaultMemoryLimit();

/// Estimated peak memory of converting a closed boundary of `boundaryArea` (model units²) at
/// `voxelSize`: narrow-band voxels ≈ area / voxel² × 2·kHalfWidthVoxels, times kBytesPerBandVoxel.
double estimateMemory(double boundaryArea, double voxelSize);

/// The solid of `surfaces`:
/// - a surface that is closed by itself (after merging its coincident vertices: a revolved
///   sphere's seam and poles) bounds a solid;
/// - with options.thickness > 0 every other surface becomes a shell (thicken() in surface_mesh.h);
/// - with thickness 0 the other surfaces must together close up (every boundary edge of each lies
///   within half a voxel of another one's boundary) and bound one solid;
/// and all the solids are united.
/// @throws GeometryError naming the field: "surfaces: ..." (none given, no extent, an open
///         surface without thickness that encloses nothing, a solid thinner than a voxel),
///         "thickness: ..." (negative, not finite, thinner than kMinVoxelsAcrossThickness voxels),
///         "voxel_size: ..." (negative, not finite, or
///         needing more than options.memoryLimit, with the smallest voxel size that fits);
///         Cancelled when options.progress answered false.
/// @note The tessellations' vertex budgets (kCoarseVertexBudget, kFineVerticesPerSurfaceVoxel)
///       bound the work before the checks: every input is converted or refused in well under a
///       second before the level sets start (README "Solids").
Solid solidify(const std::vector<Surface3d>& surfaces, const SolidOptions& options = {});

}  // namespace sculptline::solvers::volume
