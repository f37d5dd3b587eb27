#include "solvers/volume/solidify.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/volume/level_set.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <unistd.h>
#include <unordered_map>

namespace sculptline::solvers::volume {

namespace {

constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;
constexpr double kMaxMemoryLimit = 1.0 * kGiB;
constexpr double kMemoryFractionOfRam = 0.25;
// Chord tolerance of the first, coarse tessellation that only sizes the model and estimates the
// memory: the display's (tessellation.h), relative to the model's size.
constexpr double kCoarseChordRelative = 1e-3;
// The tessellations of one call share kMaxTessellationVertices (a million vertices, about 100 MB of
// meshes), each surface getting at least this many: many surfaces cannot multiply the time spent
// before the memory check, at the price of a coarser tessellation of each when there are hundreds.
constexpr int kMinVerticesPerSurface = 4096;
// Boundary segments are sampled into the coverage hash at most this many times in total, so that
// the closure check stays linear in the boundary size whatever the tolerance.
constexpr double kMaxCoverageSamples = 1e6;

std::string number(double x)
{
    std::ostringstream s;
    s.precision(4);
    s << x;
    return s.str();
}

double boundaryLength(const TriangleMesh& mesh)
{
    double sum = 0.0;
    for (const Edge& e : boundaryEdges(mesh)) sum += (mesh.vertices[e[1]] - mesh.vertices[e[0]]).norm();
    return sum;
}

double pointSegmentDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    const Eigen::Vector3d ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (a + t * ab - p).norm();
}

struct Segment {
    Eigen::Vector3d a, b;
    int surface;
};

// The first open surface (index into `meshes`) with a boundary edge whose midpoint is farther than
// `tolerance` from every other surface's boundary, or -1 when all boundaries are met. A spatial hash
// of points sampled along the segments at half a cell keeps it linear.
int firstUnmatchedSurface(const std::vector<TriangleMesh>& meshes, const std::vector<int>& ids, double tolerance)
{
    std::vector<Segment> segments;
    double total = 0.0;
    for (size_t k = 0; k < meshes.size(); ++k)
        for (const Edge& e : boundaryEdges(meshes[k])) {
            segments.push_back({meshes[k].vertices[e[0]], meshes[k].vertices[e[1]], static_cast<int>(k)});
            total += (segments.back().b - segments.back().a).norm();
        }
    const double cell = std::max({2.0 * tolerance, total / kMaxCoverageSamples, std::numeric_limits<double>::min()});
    auto keyOf = [cell](const Eigen::Vector3d& p) {
        return std::array<std::int64_t, 3>{static_cast<std::int64_t>(std::floor(p.x() / cell)),
                                           static_cast<std::int64_t>(std::floor(p.y() / cell)),
                                           static_cast<std::int64_t>(std::floor(p.z() / cell))};
    };
    struct KeyHash {
        size_t operator()(const std::array<std::int64_t, 3>& k) const
        {
            return static_cast<size_t>(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL);
        }
    };
    std::unordered_map<std::array<std::int64_t, 3>, std::vector<int>, KeyHash> cells;
    for (size_t s = 0; s < segments.size(); ++s) {
        const double len = (segments[s].b - segments[s].a).norm();
        const int steps = static_cast<int>(std::ceil(len / (0.5 * cell)));
        for (int i = 0; i <= steps; ++i) {
            const double t = steps == 0 ? 0.0 : static_cast<double>(i) / steps;
            std::vector<int>& bucket = cells[keyOf(segments[s].a + t * (segments[s].b - segments[s].a))];
            if (bucket.empty() || bucket.back() != static_cast<int>(s)) bucket.push_back(static_cast<int>(s));
        }
    }
    for (const Segment& seg : segments) {
        const Eigen::Vector3d m = 0.5 * (seg.a + seg.b);
        const auto key = keyOf(m);
        bool met = false;
        for (int dx = -1; dx <= 1 && !met; ++dx)
            for (int dy = -1; dy <= 1 && !met; ++dy)
                for (int dz = -1; dz <= 1 && !met; ++dz) {
                    const auto it = cells.find({key[0] + dx, key[1] + dy, key[2] + dz});
                    if (it == cells.end()) continue;
                    for (int other : it->second)
                        if (segments[other].surface != seg.surface &&
                            pointSegmentDistance(m, segments[other].a, segments[other].b) <= tolerance) {
                            met = true;
                            break;
                        }
                }
        if (!met) return ids[seg.surface];
    }
    return -1;
}

void requireNonNegative(double x, const char* field, const char* meaning)
{
    if (!std::isfinite(x)) throw GeometryError(std::string(field) + ": not a finite number");
    if (x < 0.0) throw GeometryError(std::string(field) + ": must be >= 0 (" + meaning + "), got " + number(x));
}

}  // namespace

double defaultMemoryLimit()
{
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long pageSize = sysconf(_SC_PAGE_SIZE);
    if (pages <= 0 || pageSize <= 0) return kMaxMemoryLimit;
    return std::min(kMaxMemoryLimit, kMemoryFractionOfRam * static_cast<double>(pages) * static_cast<double>(pageSize));
}

double estimateMemory(double boundaryArea, double voxelSize)
{
    const double voxels = boundaryArea / (voxelSize * voxelSize) * 2.0 * kHalfWidthVoxels;
    return voxels * kBytesPerBandVoxel;
}

Solid solidify(const std::vector<Surface3d>& input, const SolidOptions& options)
{
    requireNonNegative(options.thickness, "thickness", "0 means no shells");
    requireNonNegative(options.voxelSize, "voxel_size", "0 means the default");
    requireNonNegative(options.memoryLimit, "memory limit", "0 means the default");
    if (input.empty()) throw GeometryError("surfaces: no surface given");

    // The model's size from its control points (a B-spline lies in their convex hull).
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d hi = -lo;
    for (const Surface3d& s : input)
        for (const Eigen::Vector3d& p : s.points()) {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
    const double controlDiagonal = (hi - lo).stableNorm();
    if (!std::isfinite(controlDiagonal) || !(controlDiagonal > 0.0))
        throw GeometryError("surfaces: the model has no finite, non-zero extent (bounding-box diagonal " +
                            number(controlDiagonal) + ")");
    // Everything below works on the surfaces moved so that their control box is centred on the
    // origin (exact: B-splines, rational ones too, are affine invariant), and the mesh moves back at
    // the end. Far from the origin the kernel's tessellation refines on round-off: a sphere of
    // radius 10 centred 3.7e6 from the origin took 939,364 vertices and 20 s instead of 2,145.
    const Eigen::Vector3d shift = 0.5 * (lo + hi);
    std::vector<Surface3d> surfaces;
    surfaces.reserve(input.size());
    for (const Surface3d& s : input) {
        std::vector<Eigen::Vector3d> points = s.points();
        for (Eigen::Vector3d& p : points) p -= shift;
        surfaces.emplace_back(s.degreeU(), s.degreeV(), s.knotsU(), s.knotsV(), s.countU(), s.countV(), std::move(points),
                              s.weights());
    }
    const double weldTolerance = kWeldRelative * controlDiagonal;
    const int surfaceCount = static_cast<int>(std::min<size_t>(surfaces.size(), static_cast<size_t>(kMaxTessellationVertices)));
    const int coarseBudget = std::max(kMinVerticesPerSurface, kCoarseVertexBudget / surfaceCount);
    const int fineShare = std::max(kMinVerticesPerSurface, kMaxTessellationVertices / surfaceCount);
    // Shares of the progress: the tessellations and checks, then the level sets (level_set.h).
    constexpr double kCoarseDone = 0.05, kFineDone = 0.15;

    // Coarse meshes: the solid's bounds, its boundary area and which surfaces close on themselves.
    const double t = options.thickness;
    std::vector<char> closed(surfaces.size());
    double boundaryArea = 0.0;
    std::vector<Eigen::Vector3d> corners;
    std::vector<Eigen::Vector3d> openCorners;  // of the surfaces that must close up together
    std::vector<double> extents(surfaces.size(), std::numeric_limits<double>::infinity());
    std::vector<double> areas(surfaces.size(), 0.0);
    for (size_t k = 0; k < surfaces.size(); ++k) {
        reportProgress(options.progress, kCoarseDone * static_cast<double>(k) / static_cast<double>(surfaces.size()));
        const TriangleMesh coarse = surfaceMesh(surfaces[k], kCoarseChordRelative * controlDiagonal, weldTolerance, coarseBudget);
        areas[k] = area(coarse);
        closed[k] = boundaryEdges(coarse).empty();
        const bool shell = !closed[k] && t > 0.0;
        boundaryArea += shell ? 2.0 * areas[k] + t * boundaryLength(coarse) : areas[k];
        const auto [a, b] = bounds(shell ? thicken(coarse, t).vertices : coarse.vertices);
        corners.push_back(a);
        corners.push_back(b);
        if (closed[k] || shell) {
            extents[k] = (b - a).minCoeff();
        } else {
            openCorners.push_back(a);
            openCorners.push_back(b);
        }
    }
    if (!std::isfinite(boundaryArea))
        throw GeometryError("surfaces: the model's area overflows a double (bounding-box diagonal " + number(controlDiagonal) + ")");
    const auto [modelLo, modelHi] = bounds(corners);
    const double diagonal = (modelHi - modelLo).stableNorm();
    const bool anyShell = t > 0.0 && std::find(closed.begin(), closed.end(), 0) != closed.end();

    double voxel = options.voxelSize;
    if (voxel == 0.0) {
        voxel = diagonal / kDefaultVoxelsAcrossDiagonal;
        if (anyShell) voxel = std::min(voxel, t / kDefaultVoxelsAcrossThickness);
    }
    if (!std::isfinite(diagonal) || !(voxel > 0.0))
        throw GeometryError("surfaces: the model has no finite, non-zero extent (bounding-box diagonal " + number(diagonal) + ")");
    if (anyShell && t < kMinVoxelsAcrossThickness * voxel)
        throw GeometryError("thickness: " + number(t) + " is less than " + number(kMinVoxelsAcrossThickness) +
                            " voxels (voxel_size " + number(voxel) + "), the shell's two faces would not be told apart; "
                            "use a voxel_size of at most " + number(t / kMinVoxelsAcrossThickness));
    // A solid less than two voxels across is not resolved: MeshToVolume marks voxels near it inside
    // or out by chance (a sphere of radius 0.01 at voxel 1 measured 0.5 instead of 4e-6).
    // (The open surfaces that close up together are checked once they are known to.)
    const auto requireResolved = [voxel](double extent, const std::string& what) {
        if (extent < kMinVoxelsAcrossThickness * voxel)
            throw GeometryError("voxel_size: " + number(voxel) + " is more than 1/" + number(kMinVoxelsAcrossThickness) +
                                " of the smallest extent " + number(extent) + " of " + what +
                                "; use a voxel_size of at most " + number(extent / kMinVoxelsAcrossThickness));
    };
    for (size_t k = 0; k < surfaces.size(); ++k) requireResolved(extents[k], "surfaces[" + std::to_string(k) + "]");
    const double across = (modelHi - modelLo).maxCoeff() / voxel;
    if (!(across <= kMaxVoxelsAcross))
        throw GeometryError("voxel_size: " + number(voxel) + " puts " + number(across) + " voxels across the model, at most " +
                            number(kMaxVoxelsAcross) + "; use at least " + number((modelHi - modelLo).maxCoeff() / kMaxVoxelsAcross));
    const double limit = options.memoryLimit > 0.0 ? options.memoryLimit : defaultMemoryLimit();
    const double bytes = estimateMemory(boundaryArea, voxel);
    if (!(bytes <= limit)) {
        const double fitting = voxel * std::sqrt(bytes / limit);
        throw GeometryError("voxel_size: " + number(voxel) + " would need about " + number(bytes / (1024.0 * 1024.0)) +
                            " MB for the level set (boundary area " + number(boundaryArea) + ", limit " +
                            number(limit / (1024.0 * 1024.0)) + " MB); use a voxel size of at least " + number(fitting));
    }

    // Fine meshes at a sub-voxel chord tolerance, then the closed meshes that bound the solids.
    const double chord = std::min(kCoarseChordRelative * controlDiagonal, kChordToleranceVoxels * voxel);
    std::vector<TriangleMesh> solids;
    std::vector<TriangleMesh> open;
    std::vector<int> openIds;
    for (size_t k = 0; k < surfaces.size(); ++k) {
        reportProgress(options.progress, kCoarseDone + (kFineDone - kCoarseDone) * static_cast<double>(k) / static_cast<double>(surfaces.size()));
        const double surfaceVoxels = areas[k] / (voxel * voxel);
        const int budget = static_cast<int>(std::clamp(kFineVerticesPerSurfaceVoxel * surfaceVoxels,
                                                       static_cast<double>(kMinVerticesPerSurface), static_cast<double>(fineShare)));
        TriangleMesh mesh = surfaceMesh(surfaces[k], chord, weldTolerance, budget);
        if (boundaryEdges(mesh).empty()) {
            solids.push_back(std::move(mesh));
        } else if (t > 0.0) {
            solids.push_back(thicken(mesh, t));
        } else {
            open.push_back(std::move(mesh));
            openIds.push_back(static_cast<int>(k));
        }
    }
    if (!open.empty()) {
        const int unmatched = firstUnmatchedSurface(open, openIds, 0.5 * voxel);
        if (unmatched >= 0)
            throw GeometryError("surfaces[" + std::to_string(unmatched) +
                                "]: is open and its boundary meets no other surface, so the surfaces enclose "
                                "nothing; give a thickness to make shells of open surfaces");
        const auto [openLo, openHi] = bounds(openCorners);
        requireResolved((openHi - openLo).minCoeff(), "the solid the open surfaces enclose");
        TriangleMesh together;
        for (const TriangleMesh& m : open) {
            const int offset = static_cast<int>(together.vertices.size());
            together.vertices.insert(together.vertices.end(), m.vertices.begin(), m.vertices.end());
            for (const Eigen::Vector3i& tri : m.triangles) together.triangles.push_back(tri + Eigen::Vector3i::Constant(offset));
        }
        solids.push_back(std::move(together));
    }

    reportProgress(options.progress, kFineDone);
    Progress levelSetProgress;
    if (options.progress)
        levelSetProgress = [&](double f) { return options.progress(kFineDone + (1.0 - kFineDone) * f); };
    const LevelSetSolid levelSet = solidFromMeshes(solids, voxel, 0.5 * (modelLo + modelHi), kAdaptivity, levelSetProgress);
    if (levelSet.mesh.triangles.empty() || !(levelSet.volume > 0.0))
        throw GeometryError("surfaces: the solid is thinner than the voxel size " + number(voxel) +
                            ", nothing of it is left; use a smaller voxel_size");
    if (!std::isfinite(levelSet.volume) || !std::isfinite(levelSet.area))
        throw GeometryError("surfaces: the solid's volume or area overflows a double (model size " + number(diagonal) + ")");
    Solid out;
    out.mesh = levelSet.mesh;
    for (Eigen::Vector3d& v : out.mesh.vertices) v += shift;
    out.volume = levelSet.volume;
    out.area = levelSet.area;
    out.voxelSize = voxel;
    out.watertight = isWatertight(out.mesh.triangles);
    out.activeVoxels = levelSet.activeVoxels;
    out.estimatedBytes = bytes;
    return out;
}

}  // namespace sculptline::solvers::volume
