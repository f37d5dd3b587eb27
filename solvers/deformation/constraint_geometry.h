#pragma once
// Constraint geometry shared by the deformation methods: rows of basis coefficients, key points and
// residuals (thesis 002_d9515b9d07f9cfd1 §6.2, Table 6-1). Internal to solvers/deformation.
#include "solvers/deformation/surface_deformation.h"

#include <string>
#include <utility>
#include <vector>

namespace sculptline::solvers::deformation::detail {

/// (control point index i * countV + j, coefficient)
using Coefficients = std::vector<std::pair<int, double>>;

/// "constraints[c]": the field name of constraint c in messages.
std::string at(size_t c);

/// @throws GeometryError naming `field` when uv is not finite or outside the surface's domain.
void requireInDomain(const Surface3d& s, const Eigen::Vector2d& uv, const std::string& field);

/// Coefficients of ∂^(du+dv) S / ∂u^du ∂v^dv at (u, v) on the control points (du + dv ≤ 1).
Coefficients basisCoefficients(const Surface3d& s, double u, double v, int du, int dv);

/// ca·a + cb·b (entries concatenated; equal indices add up when used).
Coefficients combine(const Coefficients& a, double ca, const Coefficients& b, double cb);

/// Two unit vectors spanning the plane normal to the unit vector n.
std::pair<Eigen::Vector3d, Eigen::Vector3d> complement(const Eigen::Vector3d& n);

/// Spans crossed between two domain points in the dominant direction, counted as in eq. 6-24.
int spansCrossed(const Surface3d& s, const Eigen::Vector2d& a, const Eigen::Vector2d& b);

/// Angle (rad) between the lines along a and b, by atan2 (acos loses half the digits near 0).
double angleBetweenLines(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

/// m parameters evenly spaced over [t0, t1] (the middle for m = 1).
std::vector<double> uniformParameters(double t0, double t1, int m);
/// m parameters of c evenly spaced along its length (ends at the domain's ends; m == 1: the middle).
std::vector<double> arcLengthParameters(const BSplineCurve<3>& c, int m);

}  // namespace sculptline::solvers::deformation::detail
