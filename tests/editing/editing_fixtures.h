#pragma once
// Curves and strokes shared by the editing tests and benchmarks (bench/editing_bench.cpp), so that
// the benchmarked cases are the tested ones.
#include "solvers/bspline/bspline_curve.h"

#include <cmath>
#include <vector>

namespace sculptline::editing_fixtures {

/// An open cubic through n samples of a sine wave, x = 0..n-1.
inline solvers::Curve2d wave(int n)
{
    std::vector<Eigen::Vector2d> pts;
    for (int i = 0; i < n; ++i) pts.emplace_back(i, 2.0 * std::sin(0.4 * i));
    return solvers::makeClampedUniform<2>(3, pts);
}

/// A stroke of `count` samples over the curve's parameter range [u0, u1], raised along the normal
/// by h (sin(pi t) + 0.2): it leaves and rejoins the curve at 0.2 h.
inline std::vector<Eigen::Vector2d> bump(const solvers::Curve2d& c, double u0, double u1, double h, int count)
{
    std::vector<Eigen::Vector2d> s;
    for (int i = 0; i < count; ++i) {
        const double t = double(i) / (count - 1);
        const auto d = c.derivatives(u0 + (u1 - u0) * t, 1);
        const Eigen::Vector2d normal = Eigen::Vector2d(-d[1].y(), d[1].x()).normalized();
        s.push_back(d[0] + h * (std::sin(M_PI * t) + 0.2) * normal);
    }
    return s;
}

/// A closed cubic through 16 points of the ellipse 8 cos a, 5 sin a; its seam is near (8, 0).
inline solvers::Curve2d ellipseLoop()
{
    std::vector<Eigen::Vector2d> loop;
    for (int i = 0; i < 16; ++i) loop.emplace_back(8 * std::cos(i * M_PI / 8), 5 * std::sin(i * M_PI / 8));
    return solvers::makeClosedUniform<2>(3, loop);
}

/// A stroke bulging outwards across ellipseLoop()'s seam, angles -0.5..0.5, 151 samples.
inline std::vector<Eigen::Vector2d> strokeAcrossSeam()
{
    std::vector<Eigen::Vector2d> stroke;
    for (int i = 0; i <= 150; ++i) {
        const double a = -0.5 + 1.0 * i / 150.0;
        stroke.emplace_back((8.0 + 1.5 * std::cos(M_PI * a)) * std::cos(a), 5.5 * std::sin(a));
    }
    return stroke;
}

}  // namespace sculptline::editing_fixtures
