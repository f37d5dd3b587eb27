#include "solvers/exchange/mesh_writer.h"

#include "solvers/bspline/tessellation.h"

#include <Eigen/Geometry>

#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <algorithm>

namespace sculptline::solvers::exchange {
namespace {

// STL is little-endian; the values are written byte by byte so that the layout does not depend
// on the host's byte order.
void putUint32(std::string& out, std::uint32_t v)
{
    for (int b = 0; b < 4; ++b) out.push_back(static_cast<char>((v >> (8 * b)) & 0xffu));
}

void putFloat(std::string& out, double value)
{
    const float f = static_cast<float>(value);
    std::uint32_t bits = 0;
    static_assert(sizeof(bits) == sizeof(f), "float32 expected");
    std::memcpy(&bits, &f, sizeof(f));
    putUint32(out, bits);
}

void putFacet(std::string& out, const Eigen::Vector3d& normal, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
              const Eigen::Vector3d& c)
{
    for (const Eigen::Vector3d* v : {&normal, &a, &b, &c}) {
        for (int k = 0; k < 3; ++k) putFloat(out, (*v)[k]);
    }
    out.push_back('\0');  // attribute byte count, unused
    out.push_back('\0');
}

// A facet whose cross product is below this fraction of its squared edge lengths has no area up to
// round-off: a grid row collapsed to a point (a sphere's pole) leaves copies of that point a few
// ulps apart, and their cross product points anywhere. 1e-12 is ~5000 ulps of the edges' product.
constexpr double kDegenerateFacet = 1e-12;

// The facet's unit normal, or `fallback` normalized when the facet has no area (or the zero vector).
Eigen::Vector3d facetNormal(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                            const Eigen::Vector3d& fallback)
{
    const Eigen::Vector3d n = (b - a).cross(c - a);
    const double length = n.norm();
    const double scale = (b - a).squaredNorm() + (c - a).squaredNorm();
    if (length > kDegenerateFacet * scale && std::isfinite(length)) return n / length;
    const double f = fallback.norm();
    return f > 0.0 ? Eigen::Vector3d(fallback / f) : Eigen::Vector3d::Zero();
}

void appendLine(std::string& out, const char* format, ...) __attribute__((format(printf, 2, 3)));
void appendLine(std::string& out, const char* format, ...)
{
    char buffer[256];
    va_list args;
    va_start(args, format);
    const int n = std::vsnprintf(buffer, sizeof(buffer), format, args);
    va_end(args);
    out.append(buffer, static_cast<size_t>(n > 0 ? std::min<int>(n, sizeof(buffer) - 1) : 0));
}

void appendVertex(std::string& out, const char* tag, const Eigen::Vector3d& p)
{
    appendLine(out, "%s %.17g %.17g %.17g\n", tag, p.x(), p.y(), p.z());
}

}  // namespace

std::string encodeStl(const ExchangeContent& content)
{
    std::vector<GridMesh> grids;
    grids.reserve(content.surfaces.size());
    std::size_t count = 0;
    for (const Surface3d& s : content.surfaces) {
        grids.push_back(tessellate(s));
        count += grids.back().triangles.size();
    }
    for (const TriangleMesh& m : content.meshes) count += m.triangles.size();
    if (count > UINT32_MAX) throw ExchangeError("surfaces: more triangles than STL can count");

    std::string out;
    out.reserve(kStlHeaderBytes + 4 + count * kStlFacetBytes);
    std::string header = "Sculptline binary STL, model units (mm)";
    header.resize(kStlHeaderBytes, ' ');  // a header must not start with "solid" (ASCII STL's keyword)
    out += header;
    putUint32(out, static_cast<std::uint32_t>(count));
    for (const GridMesh& g : grids) {
        for (const Eigen::Vector3i& t : g.triangles) {
            const Eigen::Vector3d& a = g.vertices[t[0]];
            const Eigen::Vector3d& b = g.vertices[t[1]];
            const Eigen::Vector3d& c = g.vertices[t[2]];
            putFacet(out, facetNormal(a, b, c, g.normals[t[0]] + g.normals[t[1]] + g.normals[t[2]]), a, b, c);
        }
    }
    for (const TriangleMesh& m : content.meshes) {
        for (const Eigen::Vector3i& t : m.triangles) {
            const Eigen::Vector3d& a = m.vertices[t[0]];
            const Eigen::Vector3d& b = m.vertices[t[1]];
            const Eigen::Vector3d& c = m.vertices[t[2]];
            putFacet(out, facetNormal(a, b, c, Eigen::Vector3d::Zero()), a, b, c);
        }
    }
    return out;
}

std::string encodeObj(const ExchangeContent& content)
{
    std::string out = "# Sculptline OBJ, model units (mm)\n";
    long next = 1;  // OBJ indices are 1-based and global over the file
    long nextNormal = 1;
    for (size_t i = 0; i < content.curves.size(); ++i) {
        const Polyline line = tessellate(content.curves[i]);
        appendLine(out, "o curve_%zu\n", i);
        for (const Eigen::Vector3d& p : line.points) appendVertex(out, "v", p);
        out += "l";
        for (size_t k = 0; k < line.points.size(); ++k) appendLine(out, " %ld", next + static_cast<long>(k));
        out += "\n";
        next += static_cast<long>(line.points.size());
    }
    for (size_t i = 0; i < content.surfaces.size(); ++i) {
        const GridMesh g = tessellate(content.surfaces[i]);
        appendLine(out, "o surface_%zu\n", i);
        for (const Eigen::Vector3d& p : g.vertices) appendVertex(out, "v", p);
        for (const Eigen::Vector3d& n : g.normals) appendVertex(out, "vn", n);
        for (const Eigen::Vector3i& t : g.triangles) {
            const long a = next + t[0], b = next + t[1], c = next + t[2];
            const long na = nextNormal + t[0], nb = nextNormal + t[1], nc = nextNormal + t[2];
            appendLine(out, "f %ld//%ld %ld//%ld %ld//%ld\n", a, na, b, nb, c, nc);
        }
        next += static_cast<long>(g.vertices.size());
        nextNormal += static_cast<long>(g.normals.size());
    }
    for (size_t i = 0; i < content.meshes.size(); ++i) {
        const TriangleMesh& m = content.meshes[i];
        appendLine(out, "o mesh_%zu\n", i);
        for (const Eigen::Vector3d& p : m.vertices) appendVertex(out, "v", p);
        for (const Eigen::Vector3i& t : m.triangles) {
            appendLine(out, "f %ld %ld %ld\n", next + t[0], next + t[1], next + t[2]);
        }
        next += static_cast<long>(m.vertices.size());
    }
    return out;
}

}  // namespace sculptline::solvers::exchange
