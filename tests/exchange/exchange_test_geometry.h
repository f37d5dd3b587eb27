#pragma once
// Shapes whose exact geometry is known, for the exchange tests: a rational quarter circle, closed
// periodic curves, an unclamped open cubic, and a rational sphere octant (The NURBS Book §7.3 and
// §8.5: circular arcs as rational quadratics, surfaces of revolution as their tensor products).
#include "solvers/bspline/bspline_surface.h"

#include <cmath>
#include <vector>

namespace sculptline::exchange_test {

using solvers::Curve3d;
using solvers::Surface3d;

/// The unit quarter circle in the xy-plane, degree 2, weights 1, sqrt(2)/2, 1 (NURBS Book Ex. 7.1).
inline Curve3d quarterCircle()
{
    return Curve3d(2, {0, 0, 0, 1, 1, 1}, {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {1, std::sqrt(0.5), 1});
}

/// A closed uniform cubic through a skew hexagon (mm), in the kernel's unwrapped form.
inline Curve3d closedCubic()
{
    const std::vector<Eigen::Vector3d> hexagon{{10, 0, 0}, {5, 9, 2}, {-5, 9, 0}, {-10, 0, -2}, {-5, -9, 0}, {5, -8, 3}};
    return solvers::makeClosedUniform<3>(3, hexagon);
}

/// A closed rational quadratic with non-uniform knots: the unwrapped form of 5 unique poles, the
/// knot spans from the domain start on `spacing` long (by default period 6; a zero makes a double
/// knot, at the seam when it is the first or the last).
inline Curve3d closedRational(const std::vector<double>& spacing = {1, 0.5, 2, 1, 1.5})
{
    const std::vector<Eigen::Vector3d> poles{{3, 0, 0}, {2, 2, 1}, {-1, 3, 0}, {-3, 0, 1}, {0, -3, 0}};
    const std::vector<double> w{1.0, 0.6, 1.4, 0.8, 1.2};
    const int p = 2;
    std::vector<Eigen::Vector3d> points(poles);
    std::vector<double> weights(w);
    for (int i = 0; i < p; ++i) {
        points.push_back(poles[i]);
        weights.push_back(w[i]);
    }
    // knots t_0..t_{n+p+1}, n + 1 = 7 points: 10 knots; t_p = 0, spacings repeat with the period.
    std::vector<double> knots(10);
    knots[p] = 0.0;
    for (int i = p + 1; i < 10; ++i) knots[i] = knots[i - 1] + spacing[(i - p - 1) % 5];
    for (int i = p - 1; i >= 0; --i) knots[i] = knots[i + 1] - spacing[(i - p + 5 * 10) % 5];
    return Curve3d(p, knots, points, weights, true);
}

/// An open cubic whose knot vector is not clamped (the domain is [t_3, t_5]).
inline Curve3d unclampedCubic()
{
    return Curve3d(3, {0, 1, 2, 3, 4, 5, 6, 7, 8}, {{0, 0, 0}, {1, 2, 0}, {3, 3, 1}, {5, 1, 2}, {6, -1, 0}});
}

/// The sphere octant x, y, z >= 0 of radius `r`: the quarter-circle meridian from the equator to
/// the pole (U) revolved by 90 degrees about z (V); biquadratic, weights w_i * w_j.
inline Surface3d sphereOctant(double r = 25.0)
{
    const double h = std::sqrt(0.5);
    const double meridianR[3] = {r, r, 0};
    const double meridianZ[3] = {0, r, r};
    const double meridianW[3] = {1, h, 1};
    const double turnW[3] = {1, h, 1};
    std::vector<Eigen::Vector3d> points;
    std::vector<double> weights;
    for (int i = 0; i < 3; ++i) {
        const double q = meridianR[i];
        const Eigen::Vector3d turn[3] = {{q, 0, meridianZ[i]}, {q, q, meridianZ[i]}, {0, q, meridianZ[i]}};
        for (int j = 0; j < 3; ++j) {
            points.push_back(turn[j]);
            weights.push_back(meridianW[i] * turnW[j]);
        }
    }
    return Surface3d(2, 2, {0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}, 3, 3, points, weights);
}

/// A bicubic patch with an interior knot in U, non-rational (mm).
inline Surface3d bicubicPatch()
{
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < 5; ++i) {
        for (int j = 0; j < 4; ++j) points.emplace_back(10.0 * i, 12.0 * j, 3.0 * std::sin(i + 2.0 * j));
    }
    return Surface3d(3, 3, {0, 0, 0, 0, 0.4, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}, 5, 4, points);
}

}  // namespace sculptline::exchange_test
