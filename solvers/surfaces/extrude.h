#pragma once
// Extrusion of a profile along a direction or a path (translational sweep, The NURBS Book §8.3
// and §8.4 eq. 8.14; thesis mode 3, "skinning", when the path is the pointer's trace).
#include "solvers/bspline/bspline_surface.h"

namespace sculptline::solvers::surfaces {

/// S(u, v) = profile(u) + v·direction, u along the profile (its degree and knots), v in [0, 1]
/// with degree 1. Exact.
/// @throws GeometryError "direction: zero length" when |direction| has no length at the profile's
///         scale, "curves: the profile is a single point" when the profile has no extent.
Surface3d extrude(const Curve3d& profile, const Eigen::Vector3d& direction);

/// Translational sweep S(u, v) = profile(u) + path(v) - path(v0): the profile is carried along the
/// path without turning, starting where it is. Exact, rational if either curve is (weights
/// w_i·w_j: the tensor product of two rational curves whose sum is taken, eq. 8.14). v runs over
/// the path's domain, u over the profile's.
/// @throws GeometryError "path: ..." when the path has no length, "curves: ..." when the profile is
///         a single point.
Surface3d extrude(const Curve3d& profile, const Curve3d& path);

}  // namespace sculptline::solvers::surfaces
