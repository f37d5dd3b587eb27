#pragma once
// A cubic span in power form (Taylor coefficients c0..c3 about a point of the span): its point and
// first two derivatives by Horner's rule. Shared by the least squares' splines (spline_work.h) and
// the fit check's curves (fit_check.cpp), which evaluate every sample a few times per solve.
#include <Eigen/Core>

#include <array>

namespace sculptline::solvers::stroke::detail {

// Component by component, in the order of operations of the vector expressions
// ((c3 t + c2) t + c1) t + c0, (3 c3 t + 2 c2) t + c1 and 6 c3 t + 2 c2, which Eigen evaluated with
// a temporary each: the same values, in fewer instructions (fitStroke on BM_StrokeFitWarm/0, callgrind:
// 59.17 -> 56.02 M with Spline::eval alone, about 5 %).
inline void cubicWithDerivatives(const std::array<Eigen::Vector3d, 4>& c, double t, Eigen::Vector3d& p,
                                 Eigen::Vector3d& d1, Eigen::Vector3d& d2)
{
    for (int k = 0; k < 3; ++k) {
        const double c0 = c[0][k], c1 = c[1][k], c2 = c[2][k], c3 = c[3][k];
        p[k] = ((c3 * t + c2) * t + c1) * t + c0;
        d1[k] = ((3.0 * c3) * t + 2.0 * c2) * t + c1;
        d2[k] = (6.0 * c3) * t + 2.0 * c2;
    }
}

inline Eigen::Vector3d cubicPoint(const std::array<Eigen::Vector3d, 4>& c, double t)
{
    Eigen::Vector3d p;
    for (int k = 0; k < 3; ++k) p[k] = ((c[3][k] * t + c[2][k]) * t + c[1][k]) * t + c[0][k];
    return p;
}

}  // namespace sculptline::solvers::stroke::detail
