#pragma once
// Curve-surface incidence by exact composition (seed 000 §2.1): for a B-spline surface F and a
// non-rational B-spline curve G in F's parameter domain, the surface curve H = F(G) is a B-spline
// curve whose control points are linear in F's: H = A F, one row of A per control point of H, the
// same A for x, y and z.
//
// Method: on every piece of G between two consecutive breakpoints (G's knots and the parameters
// where G crosses a knot line of F), G stays inside one knot cell of F, where F is one polynomial
// patch of bidegree (p, q). Its Bezier patch points are linear in F's control points (the span's
// Bezier extraction, by knot insertion on an identity matrix); G's piece in Bernstein form gives
// the cell's local coordinates x(s), y(s) as Bernstein polynomials of degree r, and
//     F(G(s)) = sum_kl C(p,k) x^k (1-x)^(p-k) C(q,l) y^l (1-y)^(q-l) b_kl
// is assembled from exact Bernstein products (bernstein.h): the polynomial composition of DeRose,
// Goldman, Hagen and Mann (1993) "unevaluated" in the patch points, degree D = (p + q) r. No
// interpolation, fitting or solve: every step is a convex-type combination, so A is exact up to
// round-off.
#include "solvers/bspline/bspline_curve.h"
#include "solvers/bspline/bspline_surface.h"

#include <Eigen/Sparse>

#include <vector>

namespace sculptline::solvers::incidence {

/// Row-major sparse matrix: the rows of A touch (p+1)(q+1) to a few times that many columns.
using SparseRows = Eigen::SparseMatrix<double, Eigen::RowMajor>;

/// The parametric structure of a surface F: what A depends on (not F's control points).
struct SurfaceStructure {
    int degreeU = 0;
    int degreeV = 0;
    KnotVector knotsU;
    KnotVector knotsV;
    int countU = 0;
    int countV = 0;

    /// The structure of a non-rational surface. @throws GeometryError for a rational one.
    static SurfaceStructure of(const Surface3d& surface);
    /// Columns of A: countU * countV, point (i, j) at column i * countV + j.
    int columnCount() const { return countU * countV; }
};

/// The B-spline space of H = F(G): degree D = (p + q) r on G's domain, clamped, and every interior
/// breakpoint of full multiplicity D, so that H's control polygon is its Bezier pieces joined
/// (piece k's control points are rows k D .. (k + 1) D). Lower multiplicities (D minus the
/// continuity of F across the crossed line or of G at its knot) would be exact too, but the
/// Bezier form needs no knot removal, keeps every row local to one cell of F, and is what the
/// compatibility matrices map into.
struct CompositionSpace {
    int degree = 0;
    KnotVector knots;
    std::vector<double> breakpoints;  ///< interior, sorted: G's knots, the crossings, the extras
    std::vector<double> crossings;    ///< where G crosses (or touches) a knot line of F
    int pointCount() const { return static_cast<int>(knots.size()) - degree - 1; }
    int pieceCount() const { return static_cast<int>(breakpoints.size()) + 1; }
    double start() const { return knots.front(); }
    double end() const { return knots.back(); }
};

/// H's space for F's structure and the domain curve G.
/// @param extraBreakpoints parameters of G's domain to make breakpoints too (e.g. a request
///        curve's knots, so that it can be brought into the space exactly); those outside the
///        open domain are ignored.
/// @throws GeometryError when G is rational, leaves F's domain (by more than 1e-12 of its size) or
///         D exceeds kMaxDegree (30: a bicubic surface takes domain curves up to degree 5).
/// @note Crossings are found per span of G by Bezier root isolation of G_u(t) - u_i and
///       G_v(t) - v_j; values within 1e-9 of the domain length merge, a knot of G winning.
CompositionSpace compositionSpace(const SurfaceStructure& surface, const Curve2d& domainCurve,
                                  const std::vector<double>& extraBreakpoints = {});

/// A and the space of its rows.
struct Composition {
    CompositionSpace space;
    SparseRows matrix;  ///< space.pointCount() x surface.columnCount(); entries below 1e-15 dropped
};

/// A with H = A F exactly (up to round-off), in the space compositionSpace() makes.
Composition compose(const SurfaceStructure& surface, const Curve2d& domainCurve,
                    const std::vector<double>& extraBreakpoints = {});

/// The same composition in the smallest space its continuity justifies: at a knot of G of
/// multiplicity m, H is C^(r-m); where G crosses a knot line of F of multiplicity m, C^(p-m) (or
/// q-m); each breakpoint's multiplicity becomes D minus the least of these (extra breakpoints keep D,
/// for the requests' knots). Made by knot removal (The NURBS Book A5.8) on A's columns, which takes
/// out exactly-removable knots up to round-off: fewer rows, the same curve, rows no longer local to
/// one piece. A knot whose removal would move an entry of A by more than 1e-10 stays.
Composition reduceMultiplicities(const Composition& full, const SurfaceStructure& surface, const Curve2d& domainCurve);

/// F's control points as rows (x, y, z), point (i, j) at row i * countV + j: the F of H = A F.
ControlMatrix surfacePointRows(const Surface3d& surface);

/// The curve with control points A F in the composition's space (H = F(G) when F is the surface
/// A was composed for).
Curve3d applyComposition(const Composition& composition, const Surface3d& surface);

}  // namespace sculptline::solvers::incidence
