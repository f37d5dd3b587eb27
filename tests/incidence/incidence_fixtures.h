#pragma once
// Surfaces and domain curves shared by the incidence tests and benchmarks (seed 000 Fig. 4: an 8x10
// bicubic surface with a cubic, 8-control-point domain curve across its diagonal).
#include "solvers/bspline/bspline_surface.h"

#include <cmath>
#include <vector>

namespace sculptline::incidence_test {

using solvers::Curve2d;
using solvers::Curve3d;
using solvers::KnotVector;
using solvers::Surface3d;

/// Clamped knots on [0, 1] for `count` points of `degree`; `skew` in (-0.3, 0.3] makes the interior
/// uneven (larger ones can make the knots decrease).
inline KnotVector clampedKnots(int degree, int count, double skew = 0.0)
{
    KnotVector knots(static_cast<size_t>(degree + 1), 0.0);
    const int spans = count - degree;
    for (int i = 1; i < spans; ++i) {
        const double s = static_cast<double>(i) / spans;
        knots.push_back(s + skew * s * (1.0 - s) * std::sin(7.0 * s));
    }
    knots.insert(knots.end(), static_cast<size_t>(degree + 1), 1.0);
    return knots;
}

/// A surface (bicubic by default) over a 100 x 80 sheet with a wavy height: countU x countV points.
inline Surface3d wavySurface(int countU, int countV, double skew = 0.3, int degreeU = 3, int degreeV = 3)
{
    std::vector<Surface3d::Point> points;
    for (int i = 0; i < countU; ++i)
        for (int j = 0; j < countV; ++j) {
            const double x = 100.0 * i / (countU - 1), y = 80.0 * j / (countV - 1);
            points.emplace_back(x + 3.0 * std::sin(0.9 * j), y + 2.0 * std::cos(1.3 * i),
                                12.0 * std::sin(0.7 * i) * std::cos(0.5 * j) + 0.5 * i * j);
        }
    return Surface3d(degreeU, degreeV, clampedKnots(degreeU, countU, skew), clampedKnots(degreeV, countV, -skew), countU, countV,
                     points);
}

/// Fig. 4's surface: 8 x 10 bicubic.
inline Surface3d figureFourSurface() { return wavySurface(8, 10); }

/// A cubic domain curve with `count` points on the straight diagonal from (0.04, 0.07) to (0.96,
/// 0.93), unevenly spaced (its parameterization is not the line's arc length).
inline Curve2d diagonalCurve(int count = 8)
{
    std::vector<Curve2d::Point> points;
    for (int i = 0; i < count; ++i) {
        const double s = static_cast<double>(i) / (count - 1);
        const double w = s + 0.08 * std::sin(3.0 * s) * s * (1.0 - s);
        points.emplace_back(0.04 + 0.92 * w, 0.07 + 0.86 * w);
    }
    return Curve2d(3, clampedKnots(3, count, 0.2), points);
}

/// A cubic S-shaped domain curve with `count` points, crossing knot lines in both directions.
inline Curve2d curvedCurve(int count = 8)
{
    std::vector<Curve2d::Point> points;
    for (int i = 0; i < count; ++i) {
        const double s = static_cast<double>(i) / (count - 1);
        points.emplace_back(0.1 + 0.8 * s, 0.5 + 0.38 * std::sin(2.0 * 3.14159 * s));
    }
    return Curve2d(3, clampedKnots(3, count), points);
}

/// The iso line u = u0 as a cubic domain curve from v = 0 to v = 1 (4 points, one Bezier piece).
inline Curve2d isoCurveU(double u0)
{
    std::vector<Curve2d::Point> points;
    for (int i = 0; i < 4; ++i) points.emplace_back(u0, i / 3.0);
    return Curve2d(3, clampedKnots(3, 4), points);
}

}  // namespace sculptline::incidence_test
