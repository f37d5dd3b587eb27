#pragma once
// Rail-based rotation surface (thesis §5.2.2, Fig. 5-10): two closed rails C1(v), C2(v) and a
// profile C3(u) from C1 to C2, carried around the axis through the rails' bounding-box centres.
#include "solvers/surfaces/boundary_rotation.h"

namespace sculptline::solvers::surfaces {

/// Reading of eq. 5-9 (garbled: "M_i p0 = p, M_i p'0 = p'; C_i(u) = M_i C3(u)"): for the angle θ
/// about the axis OO', P(θ) and P'(θ) are the points of C1 and C2 in the half-plane at angle θ
/// from the profile's ends P0 = C3(0), P'0 = C3(1). M_θ is the similarity that rotates by θ about
/// the axis, then turns the rotated chord P0P'0 onto PP' by the smallest rotation and scales it to
/// |PP'|, and translates P0 to P: so M P0 = P and M P'0 = P' (the "transformation from line P0P'0
/// to line PP'"), and with circular coaxial rails it is the plain surface of revolution.
/// Sections C_θ = M_θ C3 are exact (control points mapped); the surface interpolates them by a
/// periodic uniform cubic at θ_k = 2πk/K (v = θ / 2π on [0, 1]; knots unclamped in v, so the seam
/// is C2 like the rest), K starting at 16 and grown by the h^4 estimate (K·(1.25 r)^(1/4), r =
/// deviation / tolerance) until the distance from the exact construction, measured at the quarter
/// points between sections (profile samples 1/(2n) apart), is within tolerance (or K + 3 reaches
/// maxPoints).
/// u runs along the profile (its degree and knots, clamped), v around the axis.
/// @param rail1, rail2 closed curves (periodic, or open with coinciding ends), each going once
///        around the axis and star-shaped about it (every half-plane at the axis cuts it once).
/// @throws GeometryError naming the curve: rail not closed, profile not connecting the rails, rail
///         not going once around the axis, rational profile... (see the message).
ApproximatedSurface railRotation(const Curve3d& rail1, const Curve3d& rail2, const Curve3d& profile,
                                 const ApproximationOptions& options = {});

/// Control rows (K distinct ones, then the first three repeated) of the closed uniform cubic (knots
/// periodicUniformKnots(3, K), domain [0, 1]) that passes through data row k at v = k/K. O(K) per
/// column.
/// @throws GeometryError when data.rows() < 3.
ControlMatrix periodicCubicInterpolation(const ControlMatrix& data);

}  // namespace sculptline::solvers::surfaces
