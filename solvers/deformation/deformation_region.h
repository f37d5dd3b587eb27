#pragma once
// Which control points a bound curve lets move (thesis 002_d9515b9d07f9cfd1 §6.2.4, eq. 6-22).
#include "solvers/bspline/bspline_surface.h"

#include <Eigen/Core>
#include <vector>

namespace sculptline::solvers::deformation {

/// Greville abscissa of control point i in direction d: the mean of knots i+1..i+p (The NURBS Book
/// §9.2.1): the parameter a control point sits over.
double grevilleAbscissa(const Surface3d& surface, Direction d, int i);

/// Even-odd point-in-polygon test; `polygon` is closed implicitly (last point joins the first).
bool insidePolygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p);

/// E(Q_ij) of eq. 6-22 for every control point (index i * countV + j): true when its Greville
/// abscissae (ξ_i, η_j) lie inside the bound; all true for an empty bound (global deformation).
std::vector<bool> insideBound(const Surface3d& surface, const std::vector<Eigen::Vector2d>& bound);

}  // namespace sculptline::solvers::deformation
