// Curve networks → triangle meshes (seed 004 §4): a disk topology per loop, shared curves shared,
// planar loops stay planar, a sphere octant is faired onto (near) the sphere, bad loops refused.
#include "solvers/bspline/geometry_error.h"
#include "solvers/surfaces/network_mesh.h"
#include "surface_checks.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

using namespace sculptline::solvers;
using namespace sculptline::solvers::surfaces;
using namespace sculptline::surfaces_test;

namespace {

Curve3d line(const Vec3& a, const Vec3& b) { return Curve3d(1, {0, 0, 1, 1}, {a, b}); }

// Edge use counts: boundary edges once, interior edges twice, in opposite directions.
void expectManifoldDisk(const NetworkMesh& m, const std::vector<Eigen::Vector3i>& tris, int expectedEuler)
{
    std::map<std::pair<int, int>, int> directed;
    std::set<int> used;
    for (const Eigen::Vector3i& t : tris)
        for (int e = 0; e < 3; ++e) {
            ++directed[{t[e], t[(e + 1) % 3]}];
            used.insert(t[e]);
        }
    std::set<std::pair<int, int>> undirected;
    for (const auto& [e, count] : directed) {
        EXPECT_EQ(count, 1) << "edge used twice in one direction: a flipped triangle";
        undirected.insert({std::min(e.first, e.second), std::max(e.first, e.second)});
    }
    const int euler = static_cast<int>(used.size()) - static_cast<int>(undirected.size()) + static_cast<int>(tris.size());
    EXPECT_EQ(euler, expectedEuler);
    (void)m;
}

}  // namespace

TEST(NetworkMesh, GivenPlanarSquareLoop_WhenMeshed_ThenPlanarDiskFacingTheNormal)
{
    const std::vector<Curve3d> c{line({0, 0, 0}, {2, 0, 0}), line({2, 0, 0}, {2, 2, 0}), line({0, 2, 0}, {2, 2, 0}),
                                 line({0, 0, 0}, {0, 2, 0})};
    const NetworkMesh m = meshNetwork(c, {{0, 1, 2, 3}}, NetworkOptions{0.1, 0.0, 3, 0.5});
    EXPECT_GT(static_cast<int>(m.vertices.size()), m.boundaryVertexCount);  // interior vertices exist
    for (const Vec3& p : m.vertices) EXPECT_NEAR(p.z(), 0.0, 1e-12);
    for (const Vec3& n : m.normals) EXPECT_NEAR(n.z(), 1.0, 1e-9);
    for (const Eigen::Vector3i& t : m.triangles) {
        const Vec3 g = (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]);
        EXPECT_GT(g.z(), 0.0);  // counter-clockwise seen from +z
        for (int k = 0; k < 3; ++k) {
            EXPECT_GE(m.vertices[t[k]].x(), -1e-12);
            EXPECT_LE(m.vertices[t[k]].x(), 2 + 1e-12);
        }
    }
    expectManifoldDisk(m, m.triangles, 1);
}

TEST(NetworkMesh, GivenSphereOctant_WhenMeshed_ThenFairedNearTheSphere)
{
    const Curve3d xy = fullCircle(Vec3::Zero(), 1.0, Vec3::UnitX(), Vec3::UnitY()).extract(0.0, 0.25);
    const Curve3d yz = fullCircle(Vec3::Zero(), 1.0, Vec3::UnitY(), Vec3::UnitZ()).extract(0.0, 0.25);
    const Curve3d zx = fullCircle(Vec3::Zero(), 1.0, Vec3::UnitZ(), Vec3::UnitX()).extract(0.0, 0.25);
    const NetworkMesh m = meshNetwork({xy, yz, zx}, {{0, 1, 2}}, NetworkOptions{0.05, 0.0, 5, 2.0});
    double worst = 0.0;
    for (size_t i = 0; i < m.vertices.size(); ++i) {
        worst = std::max(worst, std::abs(m.vertices[i].norm() - 1.0));
        EXPECT_GT(m.normals[i].dot(m.vertices[i].normalized()), 0.9) << i;  // outward, near radial
    }
    // Without fairing the centroid-based initial positions sit up to ~40% of the radius inside; the
    // faired mesh is within 8% everywhere but at the fan centre, which is the least constrained
    // (measured 12%: seed 004 calls the result "a coarse representation" to be refined further).
    EXPECT_LT(worst, 0.15);
    for (size_t i = 0; i + 1 < m.vertices.size(); ++i) EXPECT_LT(std::abs(m.vertices[i].norm() - 1.0), 0.08) << i;
    const NetworkMesh unfaired = meshNetwork({xy, yz, zx}, {{0, 1, 2}}, NetworkOptions{0.05, 0.0, 0, 2.0});
    double unfairedWorst = 0.0;
    for (const Vec3& p : unfaired.vertices) unfairedWorst = std::max(unfairedWorst, std::abs(p.norm() - 1.0));
    EXPECT_GT(unfairedWorst, 2 * worst);  // fairing is what brings the mesh to the sphere
    expectManifoldDisk(m, m.triangles, 1);
}

TEST(NetworkMesh, GivenTwoLoopsSharingACurve_WhenMeshed_ThenOneConnectedMesh)
{
    const std::vector<Curve3d> c{line({0, 0, 0}, {1, 0, 0}), line({1, 0, 0}, {2, 0, 0}), line({2, 0, 0}, {2, 1, 0}),
                                 line({2, 1, 0}, {1, 1, 0}), line({1, 1, 0}, {0, 1, 0}), line({0, 1, 0}, {0, 0, 0}),
                                 line({1, 0, 0}, {1, 1, 0})};
    const NetworkMesh m = meshNetwork(c, {{0, 6, 4, 5}, {1, 2, 3, 6}}, NetworkOptions{0.1, 0.0, 2, 0.5});
    for (size_t i = 0; i < static_cast<size_t>(m.boundaryVertexCount); ++i)
        for (size_t j = i + 1; j < static_cast<size_t>(m.boundaryVertexCount); ++j)
            EXPECT_GT((m.vertices[i] - m.vertices[j]).norm(), 1e-9);  // shared curve sampled once
    expectManifoldDisk(m, m.triangles, 1);  // the two disks glue into one disk
}

TEST(NetworkMesh, GivenOpenOrBadLoops_WhenMeshed_ThenClearErrors)
{
    const std::vector<Curve3d> c{line({0, 0, 0}, {1, 0, 0}), line({1, 0, 0}, {1, 1, 0}), line({1, 1, 0}, {0, 1, 0})};
    EXPECT_THROW(meshNetwork(c, {{0, 1, 2}}), GeometryError);  // does not close
    EXPECT_THROW(meshNetwork(c, {{0, 2}}), GeometryError);     // 2 does not start at 0's end
    EXPECT_THROW(meshNetwork(c, {{0, 7}}), GeometryError);     // no such curve
    EXPECT_THROW(meshNetwork(c, {{}}), GeometryError);
}

TEST(NetworkMesh, GivenALoopOfOneCollapsedCurve_WhenMeshed_ThenRefusedNamingTheCurve)
{
    // A closed "curve" that is a point: its normals came out NaN (reported as an overflow).
    const Curve3d point = cubic({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}});
    try {
        meshNetwork({line({0, 0, 0}, {1, 0, 0}), point}, {{1}});
        FAIL() << "meshed a point";
    } catch (const GeometryError& e) {
        EXPECT_STREQ(e.what(), "curves[1]: degenerate, all control points coincide");
    }
}
