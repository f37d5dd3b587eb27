#pragma once
// The surface a set of curves starts from in Interpolation mode (seed 000 §3.1): a flat bicubic
// sheet over them, which the incidence solve (incidence_solve.h) then bends through the curves. It is
// the prior of that solve (TSVD keeps the part of it the curves do not determine, eq. 4), so it is
// the plainest surface that spans them: their least-squares plane, over their extent in it.
#include "solvers/bspline/bspline_surface.h"

#include <Eigen/Core>
#include <vector>

namespace sculptline::solvers::incidence {

/// Control points per direction of a spanning sheet by default: 16 × 16 bicubic. A fixed closed rim
/// (seed 000's dome, Fig. 2) holds every basis function whose support it crosses; on a 10 × 10 net
/// that is all of them but the four corners, and nothing inside can bulge. At 16 the spans are a
/// thirteenth of the extent and a few dozen functions lie wholly inside a rim that spans it.
constexpr int kSpanningSheetCount = 16;
/// The sheet's margin around the curves' extent, as a fraction of its larger side: curves that touch
/// the extent's edge (a rim) stay inside the domain, where their pre-images are found by projection.
constexpr double kSpanningSheetMargin = 0.05;

/// A flat degree-3 sheet spanning `points` (the curves, sampled): in their least-squares plane
/// (through the centroid, normal along the smallest principal axis), over their bounding rectangle
/// in that plane along the principal axes, grown by `margin`. Uniform clamped knots on [0, 1] in
/// both directions, control points at the Greville abscissae: the sheet is that plane exactly, with a
/// linear (u, v) parametrization.
/// @throws GeometryError when the points are fewer than three, not finite, or lie on one line
/// (they span no surface), or count < 4.
Surface3d spanningSheet(const std::vector<Eigen::Vector3d>& points, int count = kSpanningSheetCount,
                        double margin = kSpanningSheetMargin);

/// `surface` refined by knot insertion (its shape unchanged) to at least `count` control points per
/// direction, uniform new knots between the present ones: room for curves drawn across it to bend it
/// (a fill of four cubic boundaries has 4 × 4 points, four of them inside).
Surface3d refinedForIncidence(const Surface3d& surface, int count = kSpanningSheetCount);

/// A sheet whose boundary is a closed curve (seed 000's dome, Fig. 2: the rim A), and the rim's
/// pre-image: the domain's boundary.
struct BoundedSheet {
    Surface3d surface;
    /// Degree 1, closed, over the rim's parameter domain: the domain's four corners at the rim's
    /// quarter parameters, so that surface(domain(t)) = rim(t) exactly.
    Curve2d rimDomain;
};

/// A sheet bounded by `rim`, a closed curve (a fixed rim's rows then hold only the boundary's
/// control points: a rim drawn inside a sheet would hold every basis function whose support it
/// crosses, and a coarse net could not bulge inside it). The rim is cut at its quarter parameters
/// into four sides, and the sheet is their Coons patch (solvers/surfaces/coons_fill.h), refined by
/// knot insertion (the shape unchanged) to at least `count` control points per direction so that
/// its inside can follow curves drawn across it.
/// @throws GeometryError when `rim` is not closed or is rational, or the quarters do not fill (a
/// degenerate rim).
BoundedSheet sheetBoundedBy(const Curve3d& rim, int count = kSpanningSheetCount);

}  // namespace sculptline::solvers::incidence
