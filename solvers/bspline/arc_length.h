#pragma once
// Arc length of B-spline curves and the inverse map from length to parameter.
#include "solvers/bspline/bspline_curve.h"

namespace sculptline::solvers {

/// Relative accuracy of the arc-length quadrature: adaptive Gauss-Legendre per knot span is
/// refined until two levels agree to this fraction of the span's length, or to the round-off of the
/// curve's coordinates (a few ulps of their magnitude, whichever is larger), with a bounded number
/// of panels per span: a curve whose points coincide to round-off has its length measured to
/// round-off, quickly.
constexpr double kArcLengthRelativeTolerance = 1e-12;

/// Length of C on [u0, u1] (u0 <= u1; a closed curve may run past its domain end, wrapping).
template <int Dim>
double arcLength(const BSplineCurve<Dim>& curve, double u0, double u1);

/// Length of the whole curve.
template <int Dim>
double arcLength(const BSplineCurve<Dim>& curve);

/// A table of cumulative lengths at the knot breakpoints (computed once) for repeated lookups of
/// the parameter at a given length: s(u) = target is solved by Newton's method on the speed |C'|,
/// safeguarded by bisection in the breakpoint interval that brackets the target.
template <int Dim>
class ArcLengthParameterization {
public:
    explicit ArcLengthParameterization(const BSplineCurve<Dim>& curve);

    double totalLength() const { return cumulative_.back(); }
    /// The parameter u with arcLength(curve, start, u) = s, for s in [0, totalLength()] (clamped).
    double parameterAt(double s) const;
    /// Length from the domain start to u.
    double lengthAt(double u) const;

private:
    BSplineCurve<Dim> curve_;  // a copy: the table must not outlive its curve
    double floor_;             // absolute round-off floor of the quadrature (arc_length.cpp)
    std::vector<double> breaks_;
    std::vector<double> cumulative_;
};

extern template class ArcLengthParameterization<2>;
extern template class ArcLengthParameterization<3>;

}  // namespace sculptline::solvers
