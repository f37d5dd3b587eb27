#pragma once
// Surface of revolution with exact rational circles (The NURBS Book §8.5, A8.1; thesis mode 2).
#include "solvers/bspline/bspline_surface.h"

namespace sculptline::solvers::surfaces {

struct Axis {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  ///< any non-zero length
};

/// Revolves `profile` about `axis` by `angleDegrees` (counter-clockwise about the axis direction,
/// right-hand rule). u runs along the profile (its own degree and knots, clamped, domain kept),
/// v around the axis on [0, 1], degree 2, one rational arc per <= 90 degrees (A8.1), so every
/// iso-curve u = const is an exact circular arc and S(u, 0) = profile(u).
/// @param angleDegrees in (0, 360].
/// @throws GeometryError "axis: zero-length direction", "angle: ...", "curves: the profile lies
///         on the axis" or "is a single point" (nothing to revolve), or "curves: the profile
///         crosses the axis" (the surface would pass through itself; ending on the axis is fine).
Surface3d revolve(const Curve3d& profile, const Axis& axis, double angleDegrees = 360.0);

/// Distance of x from the axis line.
double distanceFromAxis(const Axis& axis, const Eigen::Vector3d& x);

}  // namespace sculptline::solvers::surfaces
