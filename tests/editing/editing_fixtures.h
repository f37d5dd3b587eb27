#pragma once
// Curves and strokes shared by the editing tests and benchmarks (bench/editing_bench.cpp), so that
// the benchmarked cases are the tested ones.
#include "solvers/bspline/basis.h"
#include "solvers/bspline/bspline_curve.h"
#include "solvers/editing/curve_manipulation.h"

#include <cmath>
#include <vector>

namespace sculptline::editing_fixtures {

// Largest jump of the k-th derivative across any interior knot, relative to its size: the two
// one-sided limits are evaluated exactly from the polynomial pieces on either side (The NURBS Book
// A2.3 on the left span and on the right span), not by finite differences.
template <int Dim>
double maxJump(const solvers::BSplineCurve<Dim>& c, int k)
{
    using Pt = Eigen::Matrix<double, Dim, 1>;
    const auto& U = c.knots();
    const int p = c.degree();
    double worst = 0.0;
    auto piece = [&](int span, double t) {
        const Eigen::MatrixXd d = solvers::basisDerivatives(span, t, p, k, U);
        Pt v = Pt::Zero();
        for (int j = 0; j <= p; ++j) v += d(k, j) * c.points()[(span - p + j) % c.pointCount()];
        return v;
    };
    for (int i = p + 1; i < c.pointCount(); ++i) {
        if (U[i] == U[i - 1] || U[i] == U[i + 1]) continue;  // multiple knots are reported by the caller's checks
        const Pt l = piece(i - 1, U[i]), r = piece(i, U[i]);
        worst = std::max(worst, (l - r).norm() / std::max(1.0, l.norm()));
    }
    return worst;
}

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

/// An open cubic on n points of a helix of radius 10 and pitch 0.8 per point (the drag benchmark's
/// 50-control-point curve).
inline solvers::Curve3d helix(int n)
{
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < n; ++i) pts.emplace_back(10 * std::cos(0.4 * i), 10 * std::sin(0.4 * i), 0.8 * i);
    return solvers::makeClampedUniform<3>(3, pts);
}

/// A drag with 3 constraints (thesis Fig. 6-3): a moving point at 0.45, the tangent at 0.5 and the
/// distance vector from 0.5 to 0.55 kept at their current values.
inline std::vector<solvers::editing::CurveConstraint<3>> dragConstraints(const solvers::Curve3d& c)
{
    using solvers::editing::ConstraintType;
    std::vector<solvers::editing::CurveConstraint<3>> cs(3);
    cs[0].type = ConstraintType::Position;
    cs[0].u = 0.45;
    cs[0].value = c.evaluate(0.45);
    cs[1].type = ConstraintType::Tangent;
    cs[1].u = 0.5;
    cs[1].value = c.derivatives(0.5, 1)[1];
    cs[2].type = ConstraintType::Distance;
    cs[2].u = 0.5;
    cs[2].u2 = 0.55;
    cs[2].value = c.evaluate(0.55) - c.evaluate(0.5);
    return cs;
}

/// The lift benchmark's stroke: 300 samples of a wavy arc, 10 units wide.
inline std::vector<Eigen::Vector2d> liftStroke300()
{
    std::vector<Eigen::Vector2d> stroke;
    for (int i = 0; i < 300; ++i) {
        const double t = i / 299.0;
        stroke.emplace_back(10 * t, 6 * std::sin(2.5 * t) + 0.5 * std::sin(9 * t));
    }
    return stroke;
}

}  // namespace sculptline::editing_fixtures
