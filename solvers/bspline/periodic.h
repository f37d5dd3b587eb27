#pragma once
// Closed (periodic) B-splines: the bi-infinite periodic extension of a closed curve, cut to a finite
// window, lets every open-curve algorithm work on closed curves. An operation that is itself
// periodic (insert a knot in every period, elevate every segment) is applied to the window; the
// window's middle period is then the closed result, exact because the algorithms are local.
#include "solvers/bspline/knot_algorithms.h"

namespace sculptline::solvers {

/// A periodic control sequence in the unwrapped convention (see BSplineCurve): n+1 rows of which
/// the last `degree` repeat the first `degree`.
struct PeriodicWindow {
    KnotVector knots;      ///< knots of the window
    ControlMatrix points;  ///< rows of the window
    double start = 0.0;    ///< domain start a of the closed curve
    double period = 0.0;   ///< T
};

/// The knot vector, in the unwrapped convention of BSplineCurve, of a closed curve of `degree` whose
/// knots in one period [start, start + period) are `periodKnots` (non-decreasing, its first value
/// `start` with multiplicity m, 1 <= m <= degree; N = periodKnots.size() distinct control points):
/// U_i = L[(i - o) mod N] + floor((i - o) / N) * period for i = 0..N + 2 degree, o = degree + 1 - m,
/// so that the last copy of start is U_degree, the domain is [start, start + period] and
/// U_{i+N} = U_i + period.
/// @throws GeometryError when N < 1, the period is not positive or m is out of range.
KnotVector periodicKnots(int degree, const std::vector<double>& periodKnots, double period);

/// The uniform case: `spans` equal spans per period, U_i = start + period (i - degree) / spans for
/// i = 0..spans + 2 degree (makeClosedUniform: start 0, period = spans).
KnotVector periodicUniformKnots(int degree, int spans, double start = 0.0, double period = 1.0);

/// The periodic extension of a closed curve repeated `periods` times on each side of its domain.
PeriodicWindow periodicExtension(int degree, const KnotVector& knots, const ControlMatrix& points, int periods);

/// Reads the closed curve back from an operated-on window: the unwrapped knots and rows of one
/// period starting at the first window knot >= start (start itself, unless an operation removed
/// that knot), with the last degree rows equal to the first degree rows.
KnotsAndPoints periodicFromWindow(int degree, const KnotVector& windowKnots, const ControlMatrix& windowPoints,
                                  double start, double period);

}  // namespace sculptline::solvers
