#pragma once
// Surfaces for the deformation tests and benchmarks: clamped uniform bicubic nets of any size.
#include "solvers/bspline/bspline_surface.h"

#include <cmath>

namespace sculptline::deformtest {

/// Clamped uniform knots on [0, 1] for `count` control points of `degree`.
inline solvers::KnotVector clampedUniform(int count, int degree)
{
    solvers::KnotVector k(static_cast<size_t>(degree + 1), 0.0);
    const int inner = count - degree - 1;
    for (int i = 1; i <= inner; ++i) k.push_back(static_cast<double>(i) / (inner + 1));
    k.insert(k.end(), static_cast<size_t>(degree + 1), 1.0);
    return k;
}

/// A nu × nv bicubic net over [0, nu−1] × [0, nv−1] with a gentle bump z = amplitude·sin·sin
/// (symmetric about the middle in both directions).
inline solvers::Surface3d wavySurface(int nu, int nv, double amplitude = 0.5, int degree = 3)
{
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < nu; ++i) {
        for (int j = 0; j < nv; ++j) {
            const double z = amplitude * std::sin(3.14159265358979 * i / (nu - 1)) * std::sin(3.14159265358979 * j / (nv - 1));
            pts.emplace_back(i, j, z);
        }
    }
    return solvers::Surface3d(degree, degree, clampedUniform(nu, degree), clampedUniform(nv, degree), nu, nv, pts);
}

}  // namespace sculptline::deformtest
