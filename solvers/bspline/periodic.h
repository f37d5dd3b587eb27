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

/// The periodic extension of a closed curve repeated `periods` times on each side of its domain.
PeriodicWindow periodicExtension(int degree, const KnotVector& knots, const ControlMatrix& points, int periods);

/// Reads the closed curve back from an operated-on window: the unwrapped knots and rows of one
/// period starting at the first window knot >= start (start itself, unless an operation removed
/// that knot), with the last degree rows equal to the first degree rows.
KnotsAndPoints periodicFromWindow(int degree, const KnotVector& windowKnots, const ControlMatrix& windowPoints,
                                  double start, double period);

}  // namespace sculptline::solvers
