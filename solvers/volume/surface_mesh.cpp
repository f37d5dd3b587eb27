#include "solvers/volume/surface_mesh.h"

#include "solvers/bspline/tessellation.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace sculptline::solvers::volume {

namespace {

// Hash cells are never finer than this fraction of the coordinates' magnitude, so that the cell
// index (coordinate / cell) stays far inside int64 whatever the tolerance asked for.
constexpr double kMinCellRelative = 1e-12;

struct CellKey {
    std::int64_t x, y, z;
    bool operator==(const CellKey& o) const { return x == o.x && y == o.y && z == o.z; }
};

struct CellHash {
    size_t operator()(const CellKey& k) const
    {
        // Teschner et al. 2003, "Optimized Spatial Hashing for Collision Detection of Deformable Objects".
        // In unsigned arithmetic: cell indices reach ~1e12, whose products overflow int64 (UB);
        // unsigned products wrap, which is all a hash needs.
        const auto u = [](std::int64_t v) { return static_cast<std::uint64_t>(v); };
        return static_cast<size_t>(u(k.x) * 73856093ULL ^ u(k.y) * 19349663ULL ^ u(k.z) * 83492791ULL);
    }
};

std::uint64_t edgeKey(int a, int b)
{
    const auto lo = static_cast<std::uint64_t>(std::min(a, b));
    const auto hi = static_cast<std::uint64_t>(std::max(a, b));
    return lo << 32 | hi;
}

}  // namespace

std::pair<Eigen::Vector3d, Eigen::Vector3d> bounds(const std::vector<Eigen::Vector3d>& points)
{
    if (points.empty()) return {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    Eigen::Vector3d lo = points.front(), hi = points.front();
    for (const Eigen::Vector3d& p : points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    return {lo, hi};
}

TriangleMesh weld(const TriangleMesh& mesh, double tolerance)
{
    const auto [lo, hi] = bounds(mesh.vertices);
    const double magnitude = std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
    const double cell = std::max({tolerance, kMinCellRelative * magnitude, std::numeric_limits<double>::min()});
    const bool withNormals = mesh.normals.size() == mesh.vertices.size();

    TriangleMesh out;
    std::vector<int> map(mesh.vertices.size());
    std::unordered_map<CellKey, std::vector<int>, CellHash> cells;
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        const Eigen::Vector3d& p = mesh.vertices[i];
        const CellKey key{static_cast<std::int64_t>(std::floor(p.x() / cell)),
                          static_cast<std::int64_t>(std::floor(p.y() / cell)),
                          static_cast<std::int64_t>(std::floor(p.z() / cell))};
        int found = -1;
        for (int dx = -1; dx <= 1 && found < 0; ++dx)
            for (int dy = -1; dy <= 1 && found < 0; ++dy)
                for (int dz = -1; dz <= 1 && found < 0; ++dz) {
                    const auto it = cells.find({key.x + dx, key.y + dy, key.z + dz});
                    if (it == cells.end()) continue;
                    for (int j : it->second)
                        if ((out.vertices[j] - p).norm() <= tolerance) {
                            found = j;
                            break;
                        }
                }
        if (found < 0) {
            found = static_cast<int>(out.vertices.size());
            out.vertices.push_back(p);
            if (withNormals) out.normals.push_back(Eigen::Vector3d::Zero());
            cells[key].push_back(found);
        }
        if (withNormals) out.normals[found] += mesh.normals[i];
        map[i] = found;
    }
    for (Eigen::Vector3d& n : out.normals) n = n.stableNormalized();
    for (const Eigen::Vector3i& t : mesh.triangles) {
        const Eigen::Vector3i w(map[t[0]], map[t[1]], map[t[2]]);
        if (w[0] != w[1] && w[1] != w[2] && w[0] != w[2]) out.triangles.push_back(w);
    }
    return out;
}

TriangleMesh surfaceMesh(const Surface3d& surface, double chordTolerance, double weldTolerance, int maxVertices)
{
    TessellationTolerance tolerance;
    tolerance.chordTolerance = chordTolerance;
    tolerance.maxVertices = maxVertices;
    const GridMesh grid = tessellate(surface, tolerance);
    TriangleMesh mesh{grid.vertices, grid.triangles, grid.normals};
    mesh = weld(mesh, weldTolerance);
    // Vertices where the surface defines no normal (normal() returned zero, or opposite normals
    // merged at a seam): the area-weighted normal of the triangles around them.
    std::vector<Eigen::Vector3d> faceSum(mesh.vertices.size(), Eigen::Vector3d::Zero());
    for (const Eigen::Vector3i& t : mesh.triangles) {
        const Eigen::Vector3d n =
            (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
        for (int k = 0; k < 3; ++k) faceSum[t[k]] += n;
    }
    for (size_t i = 0; i < mesh.vertices.size(); ++i)
        if (!(mesh.normals[i].squaredNorm() > 0.5)) mesh.normals[i] = faceSum[i].stableNormalized();
    return mesh;
}

std::vector<Edge> boundaryEdges(const TriangleMesh& mesh)
{
    std::unordered_map<std::uint64_t, int> uses;
    for (const Eigen::Vector3i& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++uses[edgeKey(t[k], t[(k + 1) % 3])];
    std::vector<Edge> out;
    for (const Eigen::Vector3i& t : mesh.triangles)
        for (int k = 0; k < 3; ++k)
            if (uses[edgeKey(t[k], t[(k + 1) % 3])] == 1) out.push_back({t[k], t[(k + 1) % 3]});
    return out;
}

bool isWatertight(const std::vector<Eigen::Vector3i>& triangles)
{
    if (triangles.empty()) return false;
    std::unordered_map<std::uint64_t, int> uses;
    uses.reserve(triangles.size() * 2);
    for (const Eigen::Vector3i& t : triangles)
        for (int k = 0; k < 3; ++k) ++uses[edgeKey(t[k], t[(k + 1) % 3])];
    return std::all_of(uses.begin(), uses.end(), [](const auto& e) { return e.second == 2; });
}

double area(const TriangleMesh& mesh)
{
    double sum = 0.0;
    for (const Eigen::Vector3i& t : mesh.triangles)
        sum += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).stableNorm();
    return sum;
}

double enclosedVolume(const TriangleMesh& mesh)
{
    // V = 1/6 sum a . (b x c) over the triangles (divergence theorem on tetrahedra to the origin).
    double sum = 0.0;
    for (const Eigen::Vector3i& t : mesh.triangles)
        sum += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]]));
    return sum / 6.0;
}

TriangleMesh thicken(const TriangleMesh& mesh, double thickness)
{
    const int n = static_cast<int>(mesh.vertices.size());
    const double h = 0.5 * thickness;
    TriangleMesh out;
    out.vertices.reserve(2 * static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) out.vertices.push_back(mesh.vertices[i] + h * mesh.normals[i]);  // top: i
    for (int i = 0; i < n; ++i) out.vertices.push_back(mesh.vertices[i] - h * mesh.normals[i]);  // bottom: n + i
    for (const Eigen::Vector3i& t : mesh.triangles) {
        out.triangles.push_back(t);
        out.triangles.emplace_back(n + t[0], n + t[2], n + t[1]);  // reversed: faces away from the top
    }
    // The top runs through a boundary edge a -> b, so the wall runs b -> a on top and a -> b below:
    // the quad (b_top, a_top, a_bottom, b_bottom), every edge then used once in each direction.
    for (const Edge& e : boundaryEdges(mesh)) {
        const int a = e[0], b = e[1];
        out.triangles.emplace_back(b, a, n + a);
        out.triangles.emplace_back(b, n + a, n + b);
    }
    return out;
}

}  // namespace sculptline::solvers::volume
