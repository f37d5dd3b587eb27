#pragma once
// Test curves known exactly: y = f(x) for a polynomial f, as a B-spline. Shared by the aesthetics
// tests (library, CLI, window).
#include "solvers/bspline/bspline_curve.h"
#include "solvers/surfaces/interpolation.h"

#include <functional>
#include <vector>

namespace sculptline::testcurves {

/// y = f(x) for x in [x0, x1], f a polynomial of degree <= `degree`: the degree-`degree` interpolant at
/// degree + 1 uniform parameters is that polynomial exactly (x is linear in the parameter), one Bezier
/// span; then `spans` uniform spans by knot insertion (no shape change), for freedom.
inline solvers::Curve2d polynomialGraph(const std::function<double(double)>& f, double x0, double x1, int degree, int spans)
{
    solvers::ControlMatrix data(degree + 1, 2);
    std::vector<double> params;
    for (int i = 0; i <= degree; ++i) {
        const double t = double(i) / degree, x = x0 + (x1 - x0) * t;
        data.row(i) << x, f(x);
        params.push_back(t);
    }
    const solvers::surfaces::CurveInterpolator interp(params, degree);
    const solvers::ControlMatrix rows = interp.solve(data);
    std::vector<Eigen::Vector2d> cps;
    for (int i = 0; i < rows.rows(); ++i) cps.emplace_back(rows(i, 0), rows(i, 1));
    const solvers::Curve2d bezier(degree, interp.knots(), cps);
    std::vector<double> x;
    for (int k = 1; k < spans; ++k) x.push_back(double(k) / spans);
    return x.empty() ? bezier : bezier.refine(x);
}

/// Thesis Fig. 7-17's curve, "M+0m-0M+": y = x^4 - x^2/2 on [-1.2, 1.2], 8 spans, scaled by `scale`.
inline solvers::Curve2d figure717(double scale = 1.0)
{
    return polynomialGraph([scale](double x) { const double s = x / scale; return scale * (s * s * s * s - 0.5 * s * s); },
                           -1.2 * scale, 1.2 * scale, 4, 8);
}

/// "M+m+M+", a flat-bottomed valley: y = x^4 + x^2/10 on [-1.2, 1.2], 8 spans, scaled by `scale`.
inline solvers::Curve2d flatValley(double scale = 1.0)
{
    return polynomialGraph([scale](double x) { const double s = x / scale; return scale * (s * s * s * s + 0.1 * s * s); },
                           -1.2 * scale, 1.2 * scale, 4, 8);
}

}  // namespace sculptline::testcurves
