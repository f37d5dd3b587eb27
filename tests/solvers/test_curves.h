#pragma once
// Shared fixtures for the kernel tests: reference curves with their sources, and dense sampling.
#include "solvers/bspline/bspline_curve.h"
#include "solvers/bspline/bspline_surface.h"

#include <cmath>
#include <vector>

namespace sculptline::solvers::testing {

/// Agreement of two evaluations of the same geometry after an exact algorithm (insertion,
/// elevation, extraction): a few ulps of the coordinates, which are of order 1..10 here.
constexpr double kExact = 1e-12;

/// n+1 equally spaced parameters on [a, b], both ends included.
inline std::vector<double> linspace(double a, double b, int n)
{
    std::vector<double> out;
    for (int i = 0; i <= n; ++i) out.push_back(a + (b - a) * i / n);
    return out;
}

/// The NURBS Book Ex. 2.3 knot vector U = {0,0,0,1,2,3,4,4,5,5,5}, degree 2, with 8 planar points.
inline Curve3d nurbsBookEx23Curve()
{
    std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {1, 2, 0}, {3, 3, 1}, {4, 1, 0}, {6, 0, -1}, {7, 2, 0}, {8, 3, 2}, {9, 0, 0}};
    return Curve3d(2, {0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5}, pts);
}

/// A 3D cubic on knots {0,0,0,0,1,2,3,4,5,5,5,5} (The NURBS Book Ex. 5.1's knot vector).
inline Curve3d nurbsBookEx51Curve()
{
    std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {1, 3, 0}, {3, 4, 1}, {5, 2, 2}, {6, -1, 1}, {8, 0, 0}, {9, 3, -1}, {10, 4, 0}};
    return Curve3d(3, {0, 0, 0, 0, 1, 2, 3, 4, 5, 5, 5, 5}, pts);
}

/// The full unit circle as a 9-point rational quadratic (The NURBS Book §7.5, Fig. 7.16a):
/// knots {0,0,0,1/4,1/4,1/2,1/2,3/4,3/4,1,1,1}, weights alternating 1 and sqrt(2)/2.
inline Curve3d unitCircle()
{
    const double w = std::sqrt(0.5);
    std::vector<Eigen::Vector3d> pts = {{1, 0, 0},  {1, 1, 0},   {0, 1, 0},  {-1, 1, 0}, {-1, 0, 0},
                                        {-1, -1, 0}, {0, -1, 0}, {1, -1, 0}, {1, 0, 0}};
    return Curve3d(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, pts, {1, w, 1, w, 1, w, 1, w, 1});
}

/// A closed uniform cubic through an irregular hexagon, on knots shifted to a non-[0,1] range.
inline Curve3d closedCubic()
{
    std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {4, -1, 1}, {7, 2, 0}, {6, 6, -1}, {2, 7, 0}, {-2, 3, 2}};
    return makeClosedUniform<3>(3, pts);
}

/// A rational cubic with unequal weights on the knot range [-2, 3.5].
inline Curve3d rationalCubic()
{
    std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {1, 2, 1}, {3, 3, 0}, {5, 1, -1}, {6, 4, 0}, {8, 2, 1}, {9, 0, 0}};
    return Curve3d(3, {-2, -2, -2, -2, -0.5, 1, 2.25, 3.5, 3.5, 3.5, 3.5}, pts, {1, 2, 0.5, 1.5, 1, 3, 1});
}

/// Largest distance between two curves evaluated at the same parameters.
template <typename A, typename B>
double maxDistance(const A& a, const B& b, const std::vector<double>& us)
{
    double worst = 0;
    for (double u : us) worst = std::max(worst, (a.evaluate(u) - b.evaluate(u)).norm());
    return worst;
}

}  // namespace sculptline::solvers::testing
