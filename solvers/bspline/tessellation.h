#pragma once
// Adaptive tessellation of B-spline curves (polylines) and surfaces (triangle grids) for display.
// Pure math: the scene layer turns the result into Coin nodes; nothing here knows about rendering.
#include "solvers/bspline/bspline_surface.h"
#include "solvers/math_constants.h"

#include <Eigen/Core>
#include <vector>

namespace sculptline::solvers {

/// Chord tolerance relative to the geometry's control-polygon size (controlSize()). A shape framed
/// by viewAll spans roughly 1000 pixels, so 1e-3 of its size keeps the chord error near one pixel.
constexpr double kRelativeChordTolerance = 1e-3;
/// Largest turning angle between the tangents (curves) or normals (surfaces) at the two ends of one
/// segment, in radians (10 degrees). Bounds the visible kinks of a polyline and the normal jumps of
/// Gouraud shading even where the chord error is tiny (small, tightly curved features).
constexpr double kMaxTurningAngle = 10.0 * kPi / 180.0;
/// Segments every knot span gets before refinement. With fewer, a span's interior could hide a
/// feature between probes; four per span resolves every cubic piece's inflection pattern.
constexpr int kMinSegmentsPerSpan = 4;
/// Bisection depth limit per initial segment: 2^12 subdivisions, enough for any tolerance the
/// viewer uses, and a guarantee of termination at cusps or degenerate (zero-length) tangents.
constexpr int kMaxRefinementDepth = 12;

/// Vertex budget of one tessellation: a million vertices is about 50 MB of mesh with normals and
/// more than a viewport shows pixel for pixel. Bounds time and memory on hostile input (a document
/// with a huge, wildly oscillating patch) where the tolerances cannot be met.
constexpr int kMaxTessellationVertices = 1000000;

/// Tolerances of a tessellation. chordTolerance <= 0 means "relative": kRelativeChordTolerance
/// times the geometry's controlSize().
struct TessellationTolerance {
    double chordTolerance = 0.0;  ///< model units; maximum distance of the geometry from a chord
    double maxTurningAngle = kMaxTurningAngle;  ///< radians, in (0, pi)
    int minSegmentsPerSpan = kMinSegmentsPerSpan;  ///< >= 1
    int maxVertices = kMaxTessellationVertices;  ///< refinement stops at this many vertices
};

/// A polyline through points on a curve; params[i] is the curve parameter of points[i].
struct Polyline {
    std::vector<Eigen::Vector3d> points;
    std::vector<double> params;
};

/// A triangle mesh laid out as a (rows x cols) grid of samples S(u[r], v[c]); vertex index
/// r * cols + c. Normals are unit (Surface3d::normal), triangles wind counter-clockwise when seen
/// from the side the normals point to.
struct GridMesh {
    std::vector<double> u;  ///< row parameters, increasing
    std::vector<double> v;  ///< column parameters, increasing
    std::vector<Eigen::Vector3d> vertices;
    std::vector<Eigen::Vector3d> normals;
    std::vector<Eigen::Vector3i> triangles;
    int rows() const { return static_cast<int>(u.size()); }
    int cols() const { return static_cast<int>(v.size()); }
};

/// Polyline approximation of `curve` over its whole domain: every knot span is cut into
/// minSegmentsPerSpan segments, then segments are bisected until the curve stays within
/// chordTolerance of each chord (probed at interior points) and the tangent turns by at most
/// maxTurningAngle across it. A closed curve's last point repeats its first.
/// @note Bisection stops once maxVertices points exist (the minimum sampling and the halves already
///       pending in the bisection, at most kMaxRefinementDepth, are still emitted), so
///       the tolerances hold only when the budget suffices; the default is ample for real curves.
Polyline tessellate(const Curve3d& curve, const TessellationTolerance& tolerance = {});

/// Grid mesh of `surface`: per knot span in each direction minSegmentsPerSpan segments, then each
/// parameter interval is bisected while, on any grid line across it, the surface leaves the chord
/// by more than chordTolerance or the normal turns by more than maxTurningAngle. U and V are refined
/// alternately until neither changes, so the bound holds along every grid line of the result.
/// @note As for curves, refinement stops at maxVertices grid vertices (rows * cols).
GridMesh tessellate(const Surface3d& surface, const TessellationTolerance& tolerance = {});

/// The grid mesh of `surface` at given parameters (rows u, columns v; increasing, inside the
/// domain): vertices, normals and triangles as tessellate() makes them, without refinement. A
/// surface rebuilt with the same knots during a drag is re-evaluated on its last adaptive grid:
/// O(vertices) instead of the refinement's probes.
GridMesh meshOnGrid(const Surface3d& surface, std::vector<double> u, std::vector<double> v);

/// The basis functions (values and first derivatives) of a kept grid's rows and columns for
/// surfaces of given degrees and knots. While only the control points (or weights) of a surface
/// change, as in a drag, its mesh on the same grid is a small dense product of these with the net:
/// evaluate() writes exactly the vertices and normals meshOnGrid() makes, without recomputing the
/// basis or the triangles.
class GridBasis {
public:
    struct Line {
        int span = 0;
        Eigen::MatrixXd d;  ///< row 0 values, row 1 first derivatives of the degree+1 functions
    };
    GridBasis(const Surface3d& surface, std::vector<double> u, std::vector<double> v);
    /// True when `surface` has the degrees, knots and control-net size this basis was made for.
    bool fits(const Surface3d& surface) const;
    const std::vector<double>& u() const { return u_; }
    const std::vector<double>& v() const { return v_; }
    /// Vertices and normals (rows x cols, index r * cols + c) of `surface` on the grid, as
    /// meshOnGrid() makes them. `surface` must fit().
    void evaluate(const Surface3d& surface, std::vector<Eigen::Vector3d>& vertices,
                  std::vector<Eigen::Vector3d>& normals) const;

private:
    int degreeU_ = 0, degreeV_ = 0, countU_ = 0, countV_ = 0;
    KnotVector knotsU_, knotsV_;
    std::vector<double> u_, v_;
    std::vector<Line> bu_, bv_;
};
/// Distance from p to the segment [a, b] (a == b allowed).
double distanceToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b);

}  // namespace sculptline::solvers
