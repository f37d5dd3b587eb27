// Adaptive tessellation: vertices on the geometry, chord bound by dense sampling, unit and
// consistent normals (solvers/bspline/tessellation.h).
#include "solvers/bspline/tessellation.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>

namespace sculptline::solvers {
namespace {

/// Vertices are evaluations of the geometry: equal up to rounding of the evaluation itself.
constexpr double kOnGeometry = 1e-12;
/// Dense samples between two consecutive vertices for the chord-deviation check.
constexpr int kDenseSamples = 64;
/// Unit length of normals, up to rounding.
constexpr double kUnit = 1e-12;

/// A 3D cubic with a tight turn, an inflection and non-uniform interior knots (millimetres).
Curve3d wigglyCurve()
{
    const std::vector<Eigen::Vector3d> p{{0, 0, 0},    {40, 60, 10}, {80, -50, 20}, {90, 0, 30},
                                         {95, 2, 30},  {120, 40, 0}, {160, 0, -10}};
    return Curve3d(3, {0, 0, 0, 0, 0.2, 0.25, 0.7, 1, 1, 1, 1}, p);
}

/// A bicubic saddle-and-bump patch on 5 x 6 control points over 200 x 200 mm.
Surface3d bumpySurface()
{
    std::vector<Eigen::Vector3d> p;
    for (int i = 0; i < 5; ++i) {
        for (int j = 0; j < 6; ++j) {
            const double x = -100.0 + 50.0 * i, y = -100.0 + 40.0 * j;
            p.emplace_back(x, y, 30.0 * std::sin(0.03 * x) * std::cos(0.025 * y) + (i == 2 && j == 3 ? 60.0 : 0.0));
        }
    }
    return Surface3d(3, 3, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}, {0, 0, 0, 0, 0.3, 0.6, 1, 1, 1, 1}, 5, 6, p);
}

double maxDeviation(const Curve3d& c, const Polyline& line)
{
    double worst = 0.0;
    for (size_t i = 0; i + 1 < line.points.size(); ++i) {
        for (int k = 1; k < kDenseSamples; ++k) {
            const double t = line.params[i] + (line.params[i + 1] - line.params[i]) * k / kDenseSamples;
            worst = std::max(worst, distanceToSegment(c.evaluate(t), line.points[i], line.points[i + 1]));
        }
    }
    return worst;
}

TEST(CurveTessellation, VerticesLieOnTheCurveAndCoverTheDomain)
{
    // Given a cubic with uneven spans / When tessellated with default tolerances
    const Curve3d c = wigglyCurve();
    const Polyline line = tessellate(c);

    // Then every vertex is C(param), params increase and run from end to end
    ASSERT_EQ(line.points.size(), line.params.size());
    ASSERT_GE(line.points.size(), 4u * kMinSegmentsPerSpan + 1);
    EXPECT_EQ(line.params.front(), c.domainStart());
    EXPECT_EQ(line.params.back(), c.domainEnd());
    for (size_t i = 0; i < line.points.size(); ++i) {
        EXPECT_LT((line.points[i] - c.evaluate(line.params[i])).norm(), kOnGeometry);
        if (i > 0) {
            EXPECT_GT(line.params[i], line.params[i - 1]);
        }
    }
}

TEST(CurveTessellation, ChordDeviationBoundHoldsUnderDenseSampling)
{
    const Curve3d c = wigglyCurve();
    for (double tol : {1.0, 0.1, 0.01}) {
        // Given an absolute chord tolerance / When tessellated
        TessellationTolerance t;
        t.chordTolerance = tol;
        const Polyline line = tessellate(c, t);

        // Then the curve between two vertices never leaves the chord by more than tol
        EXPECT_LE(maxDeviation(c, line), tol) << "tolerance " << tol;
    }
}

TEST(CurveTessellation, DefaultToleranceIsRelativeToSizeAndTangentsTurnLittle)
{
    const Curve3d c = wigglyCurve();
    const Polyline line = tessellate(c);
    EXPECT_LE(maxDeviation(c, line), kRelativeChordTolerance * c.controlSize());
    for (size_t i = 0; i + 1 < line.params.size(); ++i) {
        const double h = (line.params[i + 1] - line.params[i]) * 1e-7;
        const Eigen::Vector3d a = c.derivatives(line.params[i] + h, 1)[1];
        const Eigen::Vector3d b = c.derivatives(line.params[i + 1] - h, 1)[1];
        EXPECT_LE(std::atan2(a.cross(b).norm(), a.dot(b)), kMaxTurningAngle + 1e-12);
    }
}

TEST(CurveTessellation, TighterToleranceGivesMoreVertices)
{
    const Curve3d c = wigglyCurve();
    TessellationTolerance coarse, fine;
    coarse.chordTolerance = 1.0;
    fine.chordTolerance = 0.01;
    EXPECT_LT(tessellate(c, coarse).points.size(), tessellate(c, fine).points.size());
}

TEST(CurveTessellation, StraightCurveKeepsTheMinimumSampling)
{
    // Given a line as a clamped cubic: no refinement is needed anywhere
    const Curve3d line = makeClampedUniform<3>(3, {{0, 0, 0}, {10, 0, 0}, {20, 0, 0}, {30, 0, 0}, {40, 0, 0}});
    // Then each of the two spans gets exactly the minimum number of segments
    EXPECT_EQ(tessellate(line).points.size(), 2u * kMinSegmentsPerSpan + 1);
}

TEST(CurveTessellation, ClosedCurveEndsWhereItStarts)
{
    const Curve3d circleish =
        makeClosedUniform<3>(3, {{50, 0, 0}, {0, 50, 0}, {-50, 0, 0}, {0, -50, 0}});
    const Polyline line = tessellate(circleish);
    EXPECT_LT((line.points.front() - line.points.back()).norm(), kOnGeometry * 100);
    EXPECT_LE(maxDeviation(circleish, line), kRelativeChordTolerance * circleish.controlSize());
}

TEST(CurveTessellation, KinkAtAKnotTerminates)
{
    // Given a cubic with a triple interior knot at a corner (C0): the tangent jumps there
    const Curve3d corner(3, {0, 0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1, 1},
                         {{0, 0, 0}, {10, 0, 0}, {20, 0, 0}, {30, 0, 0}, {30, 10, 0}, {30, 20, 0}, {30, 30, 0}});
    // When tessellated / Then refinement stays at the minimum (both sides straight), the corner is a vertex
    const Polyline line = tessellate(corner);
    EXPECT_EQ(line.points.size(), 2u * kMinSegmentsPerSpan + 1);
    EXPECT_LT((line.points[kMinSegmentsPerSpan] - Eigen::Vector3d(30, 0, 0)).norm(), 1e-12);
}

TEST(CurveTessellation, VertexBudgetBoundsAnUnreachableTolerance)
{
    // Given a tolerance far below what the budget allows
    TessellationTolerance t;
    t.chordTolerance = 1e-12;
    t.maxVertices = 100;
    // When tessellated / Then refinement stops at the budget; what is left is the start points of
    // the halves pending in the recursion (one per level) and the minimum sampling of 4 spans
    const Polyline line = tessellate(wigglyCurve(), t);
    EXPECT_LE(line.points.size(), 100u + kMaxRefinementDepth + 4u * kMinSegmentsPerSpan + 1u);
    EXPECT_GE(line.points.size(), 100u);
}

TEST(SurfaceTessellation, VertexBudgetBoundsAnUnreachableTolerance)
{
    TessellationTolerance t;
    t.chordTolerance = 1e-12;
    t.maxVertices = 2000;
    const GridMesh mesh = tessellate(bumpySurface(), t);
    EXPECT_LE(mesh.rows() * mesh.cols(), 2000);
    EXPECT_GE(mesh.rows() * mesh.cols(), 1000) << "the budget should be mostly used";
}

TEST(SurfaceTessellation, GridVerticesLieOnTheSurfaceWithUnitNormals)
{
    const Surface3d s = bumpySurface();
    const GridMesh mesh = tessellate(s);

    ASSERT_EQ(mesh.vertices.size(), static_cast<size_t>(mesh.rows() * mesh.cols()));
    ASSERT_EQ(mesh.normals.size(), mesh.vertices.size());
    EXPECT_EQ(mesh.triangles.size(), static_cast<size_t>(2 * (mesh.rows() - 1) * (mesh.cols() - 1)));
    // At least the fixed sampling: 2 spans in U, 3 in V
    EXPECT_GE(mesh.rows(), 2 * kMinSegmentsPerSpan + 1);
    EXPECT_GE(mesh.cols(), 3 * kMinSegmentsPerSpan + 1);
    for (int r = 0; r < mesh.rows(); ++r) {
        for (int c = 0; c < mesh.cols(); ++c) {
            const size_t i = static_cast<size_t>(r) * mesh.cols() + c;
            EXPECT_LT((mesh.vertices[i] - s.evaluate(mesh.u[r], mesh.v[c])).norm(), kOnGeometry);
            EXPECT_NEAR(mesh.normals[i].norm(), 1.0, kUnit);
            EXPECT_LT((mesh.normals[i] - s.normal(mesh.u[r], mesh.v[c])).norm(), kUnit);
        }
    }
}

/// A rational cone: apex row collapsed at u = 0 (all nine points at the apex), the base an exact
/// rational circle of radius 40 (The NURBS Book §7.5, nine points, weights 1 and sqrt(2)/2).
Surface3d rationalCone()
{
    const double w = std::sqrt(0.5);
    const std::vector<Eigen::Vector2d> square{{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    std::vector<Eigen::Vector3d> p;
    std::vector<double> weights;
    for (int i = 0; i < 2; ++i) {
        for (size_t j = 0; j < square.size(); ++j) {
            p.push_back(i == 0 ? Eigen::Vector3d(0, 0, 60) : Eigen::Vector3d(40 * square[j].x(), 40 * square[j].y(), 0));
            weights.push_back(j % 2 == 1 ? w : 1.0);
        }
    }
    return Surface3d(1, 2, {0, 0, 1, 1}, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, 2, 9, p, weights);
}

TEST(SurfaceTessellation, MeshOnAGivenGridMatchesTheKernelIncludingRationalAndCollapsedEdges)
{
    // Given grids over a polynomial patch and over a rational cone whose apex edge is collapsed
    for (const Surface3d& s : {bumpySurface(), rationalCone()}) {
        std::vector<double> u, v;
        for (int k = 0; k <= 12; ++k) u.push_back(s.domainStart(Direction::U) + (s.domainEnd(Direction::U) - s.domainStart(Direction::U)) * k / 12.0);
        for (int k = 0; k <= 17; ++k) v.push_back(s.domainStart(Direction::V) + (s.domainEnd(Direction::V) - s.domainStart(Direction::V)) * k / 17.0);
        // When the mesh is evaluated on the grid (tensor contraction, no refinement)
        const GridMesh mesh = meshOnGrid(s, u, v);
        // Then every vertex and normal is the kernel's (evaluate, normal with its collapsed-edge limit)
        ASSERT_EQ(mesh.vertices.size(), u.size() * v.size());
        for (size_t r = 0; r < u.size(); ++r) {
            for (size_t c = 0; c < v.size(); ++c) {
                const size_t i = r * v.size() + c;
                EXPECT_LT((mesh.vertices[i] - s.evaluate(u[r], v[c])).norm(), kOnGeometry) << r << "," << c;
                EXPECT_LT((mesh.normals[i] - s.normal(u[r], v[c])).norm(), kUnit) << r << "," << c;
            }
        }
    }
}

TEST(SurfaceTessellation, AKeptGridBasisGivesTheMeshOfAMovedNetBitForBit)
{
    // Given a grid basis made for a polynomial patch and for a rational cone (collapsed apex edge)
    for (const Surface3d& s : {bumpySurface(), rationalCone()}) {
        const GridMesh adaptive = tessellate(s);
        const GridBasis basis(s, adaptive.u, adaptive.v);
        ASSERT_TRUE(basis.fits(s));
        // When the control points move (the knots, degrees and weights stay), as in a drag
        std::vector<Eigen::Vector3d> points = s.points();
        // (the cone's apex row moved as one, so that its edge stays collapsed)
        for (size_t k = 0; k < points.size(); ++k) {
            const double t = k < static_cast<size_t>(s.countV()) ? 0.0 : static_cast<double>(k);
            points[k] += Eigen::Vector3d(0.3 * std::sin(t) + 1.0, 0.2 * t, 1.5 * std::cos(3.0 * t));
        }
        const Surface3d moved(s.degreeU(), s.degreeV(), s.knotsU(), s.knotsV(), s.countU(), s.countV(), points, s.weights());
        ASSERT_TRUE(basis.fits(moved));
        std::vector<Eigen::Vector3d> vertices, normals;
        basis.evaluate(moved, vertices, normals);
        // Then the vertices and normals are exactly those of a mesh made anew on that grid
        const GridMesh fresh = meshOnGrid(moved, adaptive.u, adaptive.v);
        EXPECT_EQ(vertices, fresh.vertices);
        EXPECT_EQ(normals, fresh.normals);
    }
    // And a basis does not fit a surface with other knots or another net size
    const Surface3d a = bumpySurface();
    const GridBasis basis(a, {a.domainStart(Direction::U), a.domainEnd(Direction::U)}, {a.domainStart(Direction::V), a.domainEnd(Direction::V)});
    EXPECT_FALSE(basis.fits(rationalCone()));
    KnotVector knots = a.knotsU();
    knots[knots.size() / 2] += 1e-3;
    EXPECT_FALSE(basis.fits(Surface3d(a.degreeU(), a.degreeV(), knots, a.knotsV(), a.countU(), a.countV(), a.points())));
}

TEST(SurfaceTessellation, NormalsAgreeWithTriangleWinding)
{
    const GridMesh mesh = tessellate(bumpySurface());
    for (const Eigen::Vector3i& t : mesh.triangles) {
        const Eigen::Vector3d face =
            (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
        for (int k = 0; k < 3; ++k) EXPECT_GT(face.dot(mesh.normals[t[k]]), 0.0);
    }
}

TEST(SurfaceTessellation, ChordDeviationBoundHoldsAlongEveryGridLine)
{
    const Surface3d s = bumpySurface();
    TessellationTolerance t;
    t.chordTolerance = 0.05;
    const GridMesh mesh = tessellate(s, t);
    double worst = 0.0;
    const auto at = [&](int r, int c) { return mesh.vertices[static_cast<size_t>(r) * mesh.cols() + c]; };
    for (int r = 0; r < mesh.rows(); ++r) {
        for (int c = 0; c < mesh.cols(); ++c) {
            for (int k = 1; k < kDenseSamples; ++k) {
                const double f = static_cast<double>(k) / kDenseSamples;
                if (r + 1 < mesh.rows()) {
                    const double u = mesh.u[r] + (mesh.u[r + 1] - mesh.u[r]) * f;
                    worst = std::max(worst, distanceToSegment(s.evaluate(u, mesh.v[c]), at(r, c), at(r + 1, c)));
                }
                if (c + 1 < mesh.cols()) {
                    const double v = mesh.v[c] + (mesh.v[c + 1] - mesh.v[c]) * f;
                    worst = std::max(worst, distanceToSegment(s.evaluate(mesh.u[r], v), at(r, c), at(r, c + 1)));
                }
            }
        }
    }
    EXPECT_LE(worst, t.chordTolerance);
}

TEST(SurfaceTessellation, FlatPatchKeepsTheMinimumSampling)
{
    // Given a bilinear-flat bicubic (control points on the plane z = 0)
    std::vector<Eigen::Vector3d> p;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) p.emplace_back(10.0 * i, 10.0 * j, 0.0);
    const Surface3d flat(3, 3, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}, 4, 4, p);
    const GridMesh mesh = tessellate(flat);
    EXPECT_EQ(mesh.rows(), kMinSegmentsPerSpan + 1);
    EXPECT_EQ(mesh.cols(), kMinSegmentsPerSpan + 1);
    for (const auto& n : mesh.normals) EXPECT_LT((n - Eigen::Vector3d::UnitZ()).norm(), kUnit);
}

}  // namespace
}  // namespace sculptline::solvers
