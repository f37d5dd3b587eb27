// Binary STL and OBJ (solvers/exchange/mesh_writer.h): Given a surface and a mesh, When they are
// written, Then the bytes follow the format (STL: 80-byte header, uint32 count, 50 bytes a facet)
// and parse back to the kernel's tessellation: its triangle count, its vertex positions, unit normals.
#include "solvers/bspline/tessellation.h"
#include "solvers/exchange/exchange.h"
#include "solvers/exchange/mesh_writer.h"
#include "tests/exchange/exchange_test_geometry.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <sstream>

namespace sculptline::exchange_test {
namespace {

namespace ex = solvers::exchange;

/// STL stores float32: a coordinate up to 25 mm rounds by at most 2^-24 of it, ~1.5e-6 mm; 4e-6
/// covers that on every coordinate of a point.
constexpr double kFloat32Position = 4e-6;
/// A unit normal rounded to float32 has length 1 within a few 2^-24.
constexpr double kFloat32Unit = 1e-6;

std::uint32_t uint32At(const std::string& b, size_t at)
{
    std::uint32_t v = 0;
    for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(b[at + k]);
    return v;
}

double floatAt(const std::string& b, size_t at)
{
    const std::uint32_t bits = uint32At(b, at);
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

Eigen::Vector3d vectorAt(const std::string& b, size_t at)
{
    return {floatAt(b, at), floatAt(b, at + 4), floatAt(b, at + 8)};
}

ex::TriangleMesh tetrahedron()
{
    return {{{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {0, 0, 10}}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
}

TEST(StlWriter, BinaryLayoutHoldsTheTessellationWithUnitNormals)
{
    // Arrange
    ex::ExchangeContent content;
    content.surfaces = {sphereOctant()};
    content.meshes = {tetrahedron()};
    content.curves = {quarterCircle()};  // skipped: STL holds triangles only
    const solvers::GridMesh grid = solvers::tessellate(content.surfaces[0]);
    // Act
    const std::string bytes = ex::encode(content, ex::Format::Stl);
    // Assert
    const size_t facets = grid.triangles.size() + 4;
    ASSERT_EQ(bytes.size(), ex::kStlHeaderBytes + 4 + facets * ex::kStlFacetBytes);
    EXPECT_NE(bytes.substr(0, 5), "solid");
    EXPECT_EQ(uint32At(bytes, 80), facets);
    double side = 0;
    for (size_t f = 0; f < facets; ++f) {
        const size_t at = 84 + f * ex::kStlFacetBytes;
        const Eigen::Vector3d n = vectorAt(bytes, at);
        const Eigen::Vector3d a = vectorAt(bytes, at + 12), b = vectorAt(bytes, at + 24), c = vectorAt(bytes, at + 36);
        EXPECT_NEAR(n.norm(), 1.0, kFloat32Unit) << "facet " << f;
        if (f < grid.triangles.size()) {
            const Eigen::Vector3i& t = grid.triangles[f];
            EXPECT_LT((a - grid.vertices[t[0]]).norm(), kFloat32Position);
            EXPECT_LT((b - grid.vertices[t[1]]).norm(), kFloat32Position);
            EXPECT_LT((c - grid.vertices[t[2]]).norm(), kFloat32Position);
            // The octant is on a sphere about the origin: every facet normal is nearly radial (the
            // largest facet spans about kMaxTurningAngle, so cos > 0.9), all to the same side.
            const double radial = n.dot((a + b + c).normalized());
            EXPECT_GT(std::abs(radial), 0.9) << "facet " << f;
            if (f > 0) {
                EXPECT_EQ(radial > 0, side > 0) << "facet " << f;
            }
            if (f == 0) side = radial;
        }
    }
    // The tetrahedron's last face, (10,0,0) (0,10,0) (0,0,10): normal (1,1,1)/sqrt(3).
    const size_t last = 84 + (facets - 1) * ex::kStlFacetBytes;
    EXPECT_LT((vectorAt(bytes, last) - Eigen::Vector3d(1, 1, 1).normalized()).norm(), kFloat32Unit);
}

TEST(StlWriter, CurvesAloneAreRefused)
{
    ex::ExchangeContent content;
    content.curves = {quarterCircle()};
    EXPECT_THROW(ex::encode(content, ex::Format::Stl), ex::ExchangeError);
}

struct ObjCounts {
    std::vector<Eigen::Vector3d> v;
    std::vector<Eigen::Vector3d> vn;
    std::vector<std::vector<long>> f;  // vertex indices (1-based) of each face
    std::vector<std::vector<long>> l;
    int objects = 0;
};

ObjCounts parseObj(const std::string& text)
{
    ObjCounts out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream ls(line);
        std::string tag;
        ls >> tag;
        if (tag == "v" || tag == "vn") {
            Eigen::Vector3d p;
            ls >> p.x() >> p.y() >> p.z();
            (tag == "v" ? out.v : out.vn).push_back(p);
        } else if (tag == "f" || tag == "l") {
            std::vector<long> idx;
            std::string item;
            while (ls >> item) idx.push_back(std::stol(item.substr(0, item.find('/'))));
            (tag == "f" ? out.f : out.l).push_back(idx);
        } else if (tag == "o") {
            ++out.objects;
        }
    }
    return out;
}

TEST(ObjWriter, CountsAndPositionsAreTheTessellations)
{
    ex::ExchangeContent content;
    content.curves = {quarterCircle()};
    content.surfaces = {sphereOctant(), bicubicPatch()};
    content.meshes = {tetrahedron()};
    const solvers::Polyline line = solvers::tessellate(content.curves[0]);
    const solvers::GridMesh g0 = solvers::tessellate(content.surfaces[0]);
    const solvers::GridMesh g1 = solvers::tessellate(content.surfaces[1]);

    const ObjCounts obj = parseObj(ex::encode(content, ex::Format::Obj));

    EXPECT_EQ(obj.objects, 4);
    ASSERT_EQ(obj.v.size(), line.points.size() + g0.vertices.size() + g1.vertices.size() + 4);
    EXPECT_EQ(obj.vn.size(), g0.normals.size() + g1.normals.size());
    ASSERT_EQ(obj.f.size(), g0.triangles.size() + g1.triangles.size() + 4);
    ASSERT_EQ(obj.l.size(), 1u);
    EXPECT_EQ(obj.l[0].size(), line.points.size());
    // 17 significant digits read back to the same doubles.
    std::vector<Eigen::Vector3d> want(line.points);
    want.insert(want.end(), g0.vertices.begin(), g0.vertices.end());
    want.insert(want.end(), g1.vertices.begin(), g1.vertices.end());
    for (const Eigen::Vector3d& p : tetrahedron().vertices) want.push_back(p);
    for (size_t k = 0; k < want.size(); ++k) EXPECT_EQ(obj.v[k], want[k]) << "vertex " << k;
    // Faces index the right vertices: the second surface's first triangle, and the mesh's last.
    const long base1 = static_cast<long>(line.points.size() + g0.vertices.size()) + 1;
    const std::vector<long>& f1 = obj.f[g0.triangles.size()];
    EXPECT_EQ(f1, (std::vector<long>{base1 + g1.triangles[0][0], base1 + g1.triangles[0][1], base1 + g1.triangles[0][2]}));
    const long baseMesh = static_cast<long>(obj.v.size()) - 4 + 1;
    EXPECT_EQ(obj.f.back(), (std::vector<long>{baseMesh + 1, baseMesh + 2, baseMesh + 3}));
    for (const auto& face : obj.f) {
        for (long i : face) {
            EXPECT_GE(i, 1);
            EXPECT_LE(i, static_cast<long>(obj.v.size()));
        }
    }
    for (const Eigen::Vector3d& n : obj.vn) EXPECT_NEAR(n.norm(), 1.0, 1e-12);
}

TEST(ObjWriter, MeshIndicesOutOfRangeAreNamed)
{
    ex::ExchangeContent content;
    content.meshes = {tetrahedron()};
    content.meshes[0].triangles[2][1] = 4;
    try {
        ex::encode(content, ex::Format::Obj);
        ADD_FAILURE() << "index 4 of 4 vertices accepted";
    } catch (const ex::ExchangeError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("meshes[0].triangles[2][1]: ", 0), 0u) << e.what();
    }
}

}  // namespace
}  // namespace sculptline::exchange_test
