// Meshes of surfaces for solids (solvers/volume/surface_mesh.h). Given / When / Then.
#include "solvers/volume/surface_mesh.h"
#include "tests/volume/test_shapes.h"

#include "solvers/math_constants.h"

#include <gtest/gtest.h>

namespace vol = sculptline::solvers::volume;
using namespace sculptline::volume_test;

namespace {

// Sums of a few hundred triangle terms of magnitude ~1e4: round-off far below this.
constexpr double kExact = 1e-9;
// The sphere's tessellation at chord tolerance h: inscribed, so its volume is below 4/3πr³ by at
// most the shell of depth h, 4πr²h (relative 3h/r).
constexpr double kChord = 0.01;

}  // namespace

TEST(SurfaceMesh, GivenARevolvedSphere_WhenMeshed_ThenSeamAndPolesAreWeldedAndTheMeshIsClosed)
{
    const double r = 10.0;
    const vol::TriangleMesh mesh = vol::surfaceMesh(sphere(r), kChord, 1e-9);

    EXPECT_TRUE(vol::boundaryEdges(mesh).empty());
    EXPECT_TRUE(vol::isWatertight(mesh.triangles));
    const double exact = 4.0 / 3.0 * sculptline::solvers::kPi * r * r * r;
    const double v = std::abs(vol::enclosedVolume(mesh));
    EXPECT_LT(v, exact);
    EXPECT_GT(v, exact * (1.0 - 3.0 * kChord / r));
    for (const Eigen::Vector3d& n : mesh.normals) EXPECT_NEAR(n.norm(), 1.0, kExact);
}

TEST(SurfaceMesh, GivenAFlatPatch_WhenMeshed_ThenItIsOpenWithItsPerimeterAsBoundary)
{
    const vol::TriangleMesh mesh = vol::surfaceMesh(flatPatch(20, 10), kChord, 1e-9);

    double perimeter = 0.0;
    for (const vol::Edge& e : vol::boundaryEdges(mesh)) perimeter += (mesh.vertices[e[1]] - mesh.vertices[e[0]]).norm();
    EXPECT_NEAR(perimeter, 60.0, kExact);
    EXPECT_FALSE(vol::isWatertight(mesh.triangles));
    EXPECT_NEAR(vol::area(mesh), 200.0, kExact);
}

TEST(SurfaceMesh, GivenAFlatPatch_WhenThickened_ThenAClosedBoxOfAreaTimesThicknessWithSquareEdges)
{
    const double t = 1.0;
    const vol::TriangleMesh shell = vol::thicken(vol::surfaceMesh(flatPatch(20, 10), kChord, 1e-9), t);

    EXPECT_TRUE(vol::isWatertight(shell.triangles));
    // Consistently oriented and closed: the divergence theorem gives the box exactly; a rounded
    // (distance-field) rim would add perimeter × πt²/8 = 23.6.
    EXPECT_NEAR(std::abs(vol::enclosedVolume(shell)), 200.0 * t, kExact);
    const auto [lo, hi] = vol::bounds(shell.vertices);
    EXPECT_TRUE(lo.isApprox(Eigen::Vector3d(0, 0, -0.5), kExact));
    EXPECT_TRUE(hi.isApprox(Eigen::Vector3d(20, 10, 0.5), kExact));
    // Box area: 2·200 + perimeter 60 × t.
    EXPECT_NEAR(vol::area(shell), 460.0, kExact);
}

TEST(SurfaceMesh, GivenCoincidentVertices_WhenWelded_ThenMergedAndDegenerateTrianglesDropped)
{
    vol::TriangleMesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1e-12, 0, 0}, {1, 1, 0}};
    mesh.triangles = {{0, 1, 2}, {3, 1, 4}, {0, 3, 2}};

    const vol::TriangleMesh welded = vol::weld(mesh, 1e-9);

    EXPECT_EQ(welded.vertices.size(), 4u);
    ASSERT_EQ(welded.triangles.size(), 2u);  // {0, 3, 2} collapsed
    EXPECT_EQ(welded.triangles[1][0], 0);
}

TEST(SurfaceMesh, GivenATriangleUsedByThreeFacesAtAnEdge_WhenChecked_ThenNotWatertight)
{
    // A closed tetrahedron is watertight; a fin on one of its edges makes that edge non-manifold.
    std::vector<Eigen::Vector3i> tetra{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
    EXPECT_TRUE(vol::isWatertight(tetra));
    tetra.emplace_back(0, 1, 4);
    EXPECT_FALSE(vol::isWatertight(tetra));
    EXPECT_FALSE(vol::isWatertight({}));
}
