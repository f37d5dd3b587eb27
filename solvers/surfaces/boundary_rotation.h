#pragma once
// Boundary-based rotation surface (thesis §5.2.1, Fig. 5-8): two outline curves Cl, Cr; each
// iso-curve u = const is the circle centred at Q(u) = (Cl(u) + Cr(u)) / 2, perpendicular to the
// outlines' plane A, through Cl(u) and Cr(u).
#include "solvers/bspline/bspline_surface.h"

namespace sculptline::solvers::surfaces {

/// A surface that approximates its construction: the deviation it reached and the tolerance used.
struct ApproximatedSurface {
    Surface3d surface;
    double maxDeviation = 0.0;  ///< model units, measured on dense samples
    double tolerance = 0.0;
};

struct ApproximationOptions {
    /// Model units; <= 0 means kDefaultApproximationRelative times the defining curves' size.
    double tolerance = 0.0;
    /// Bound on the control points per direction the refinement may reach.
    int maxPoints = 2049;
};

/// 1e-4 of the model's size: a tenth of a pixel when the model spans the viewport.
constexpr double kDefaultApproximationRelative = 1e-4;

/// Reading of the garbled eqs. 5-4..5-6: with D(u) = (Cl(u) - Cr(u)) / 2 and n the normal of the
/// outlines' best-fit plane A, the circle is O_u(θ) = Q(u) + cos θ·D(u) + sin θ·E(u), where E(u) is
/// D(u) turned by 90 degrees within the plane spanned by D(u) and n (|E| = |D|), so O(0) = Cl(u),
/// O(π) = Cr(u) (eq. 5-4), centre Q (eq. 5-5), and the rotation of eq. 5-6 is the one about the
/// axis through Q perpendicular to D and n. Eq. 5-7 (outline points moving with their drawing
/// plane) is the caller's: it passes the outlines in world coordinates.
///
/// Instead of interpolating sampled circle points (the thesis's eq. 5-8), Q and D are kept exactly
/// in the outlines' compatible layout, the circle is the exact rational one (9 points, A7.1 style),
/// and only E(u) = |D(u)|·e(u) (not polynomial) is approximated, by interpolation at the Greville
/// abscissae, splitting each span where |E - E*| > tolerance (into pieces by the interpolant's
/// h^(p+1) error) until it is within tolerance everywhere. The surface's distance from the
/// thesis's surface is |sin θ|·|E - E*|, so maxDeviation bounds it. C0 corners of the outlines stay
/// C0 knots of the surface: sharp features and rotational creases are kept (thesis §5.2.1).
/// u runs along the outlines (on [0, 1]), v around the circles (v = 0 at Cl, 1/2 at Cr). An outline
/// drawn the other way round (its ends nearer the other's opposite ends) is reversed first.
/// @throws GeometryError for rational outlines, outlines that coincide everywhere, or outlines that
///         lie on one line (no plane A).
ApproximatedSurface boundaryRotation(const Curve3d& left, const Curve3d& right, const ApproximationOptions& options = {});

/// The exact construction at (u, θ) for testing and deviation checks (u in [0, 1] on the normalized outlines).
Eigen::Vector3d boundaryRotationPoint(const Curve3d& left, const Curve3d& right, const Eigen::Vector3d& planeNormal,
                                      double u, double theta);

/// Normal of the best-fit plane through dense samples of the curves (smallest principal axis).
/// @throws GeometryError ("curves: ...") when the samples lie on a line.
Eigen::Vector3d bestFitPlaneNormal(const std::vector<Curve3d>& curves);

}  // namespace sculptline::solvers::surfaces
