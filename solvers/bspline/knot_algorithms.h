#pragma once
// Knot insertion, refinement, degree elevation and knot removal on a (homogeneous) control matrix.
// These work on any number of columns: curves pass their homogeneous points, surfaces pass a whole
// row or column of their net as one wide "point" so every row is changed by the same knots.
#include "solvers/bspline/basis.h"

namespace sculptline::solvers {

struct KnotsAndPoints {
    KnotVector knots;
    ControlMatrix points;
};

/// Inserts u `times` times (Boehm's algorithm, The NURBS Book A5.1). The multiplicity of u may not
/// exceed the degree afterwards (degree+1 at the two domain ends).
/// @throws GeometryError if u is outside the domain or the multiplicity would be exceeded.
KnotsAndPoints insertKnot(int degree, const KnotVector& knots, const ControlMatrix& points, double u, int times);

/// Inserts all the (sorted, non-decreasing) values of x at once. The NURBS Book, A5.4.
KnotsAndPoints refineKnots(int degree, const KnotVector& knots, const ControlMatrix& points, const std::vector<double>& x);

/// The same geometry on its domain [U[p], U[n+1]] with clamped ends (both end knots of multiplicity
/// degree+1); points whose basis functions live only outside the domain are dropped.
KnotsAndPoints clampEnds(int degree, const KnotVector& knots, const ControlMatrix& points);

/// The piece on [u0, u1] (inside the domain) as a clamped curve: u0 and u1 are inserted up to
/// multiplicity degree and the outside is dropped. Works for unclamped knot vectors too.
KnotsAndPoints extractSegment(int degree, const KnotVector& knots, const ControlMatrix& points, double u0, double u1);

/// Raises the degree by `times` without changing the curve. The NURBS Book, A5.9 (Bezier
/// decomposition, elevation of each segment, knot removal back to the original continuity).
KnotsAndPoints elevateDegree(int degree, const KnotVector& knots, const ControlMatrix& points, int times);

/// Result of one attempt to remove a knot.
struct RemovalResult {
    int removed = 0;          ///< how many times the knot value was removed (0..requested)
    double errorBound = 0.0;  ///< upper bound on the max distance the removal moved the geometry
};

/// Removes the interior knot value u up to `times` times, each time only if the removal moves the
/// geometry by at most `tolerance` (The NURBS Book, A5.8). The distance between two control
/// "points" is the largest Euclidean distance over consecutive groups of `groupSize` columns, so a
/// surface row counts as many points; pass groupSize = points.cols() for a single curve. The knot
/// vector and points are changed in place. The bound is computed in the coordinates given; a
/// rational caller converts its Euclidean tolerance to homogeneous space (The NURBS Book eq. 5.30).
RemovalResult removeKnot(int degree, KnotVector& knots, ControlMatrix& points, double u, int times, double tolerance,
                         int groupSize);

/// Round-off floor of knot removal, relative to the geometry's size: a knot that insertion put there
/// comes back out with differences of a few ulps, so tolerance 0 removes exactly-removable knots.
constexpr double kRemovalRoundOff = 1e-12;

/// The budget, in the coordinates of `points`, for removing knots within the Euclidean `tolerance`:
/// the tolerance itself for non-rational rows; for homogeneous rows (groups of dim+1 columns, the
/// last the weight) tolerance * wmin / (1 + |P|max) (The NURBS Book eq. 5.30). Never below the
/// round-off floor kRemovalRoundOff * (1 + |P|max).
double removalBudget(const ControlMatrix& points, int dim, bool rational, double tolerance);

/// Greedy removal (A5.8 on each distinct interior knot, repeated while any goes) that spends at
/// most `budget` of summed error bounds; keeps at least degree+1 rows. Returns the count removed.
int removeKnotsWithinBudget(int degree, KnotVector& knots, ControlMatrix& points, double& budget, int groupSize);

}  // namespace sculptline::solvers
