#pragma once
// Curvature of B-spline curves from the kernel's derivatives (do Carmo, Differential Geometry of
// Curves and Surfaces, §1-5): kappa = |C' x C''| / |C'|^3 for 2D and 3D curves, rational or not.
#include "solvers/bspline/bspline_curve.h"

#include <vector>

namespace sculptline::solvers {

/// Curvature (1 / model unit) at u. Where the curve stops (|C'| <= minSpeed, a cusp or a collapsed
/// span) it is undefined and 0 is returned.
/// @param minSpeed  model units per unit parameter, >= 0.
template <int Dim>
double curvature(const BSplineCurve<Dim>& curve, double u, double minSpeed = 0.0);

/// Curvature at `count` >= 2 parameters evenly spaced over [u0, u1] (ends included).
template <int Dim>
std::vector<double> sampleCurvature(const BSplineCurve<Dim>& curve, double u0, double u1, int count, double minSpeed = 0.0);

}  // namespace sculptline::solvers
