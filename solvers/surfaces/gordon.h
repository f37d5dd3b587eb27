#pragma once
// Gordon surface through a grid-like curve network (W. J. Gordon 1969; The NURBS Book §10.5):
// S = L1 + L2 - T, where L1 skins the u-curves, L2 skins the v-curves and T interpolates their
// intersection grid, all made compatible (thesis eq. 5-3: a compatible network of curves).
#include "solvers/bspline/bspline_surface.h"

#include <vector>

namespace sculptline::solvers::surfaces {

struct GordonOptions {
    /// Largest distance (model units) at which a u-curve and a v-curve still count as intersecting;
    /// <= 0 means 1e-4 × the network's size (as for fill).
    double meetTolerance = 0.0;
};

struct GordonResult {
    Surface3d surface;
    std::vector<double> uParams;  ///< u at which the v-curves lie (S(u_l, v) traces v-curve l)
    std::vector<double> vParams;  ///< v at which the u-curves lie
    double maxGap = 0.0;          ///< largest distance between intersecting curves; the curves are met to it
};

/// Curves of each family may come in any order and orientation; they are sorted along the other
/// family and oriented consistently. Every u-curve must meet every v-curve once (the first and last
/// curves of each family bound the patch: curves are trimmed to their first and last intersection).
/// Each curve is reparameterized piecewise affinely (split at its intersections, pieces mapped onto
/// the common intersection parameters: exact, shape unchanged, C0 knots at the intersections) so
/// that all curves of a family meet the other family at the same parameters, which Gordon's
/// construction requires. Non-rational curves only.
/// @throws GeometryError ("curves: ...") for fewer than two curves in a family, rational curves, or a
///         pair of curves that does not intersect within tolerance.
GordonResult gordon(const std::vector<Curve3d>& uCurves, const std::vector<Curve3d>& vCurves,
                    const GordonOptions& options = {});

}  // namespace sculptline::solvers::surfaces
