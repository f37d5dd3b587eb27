#pragma once
// Position and first two derivatives of a curve without allocating.
#include "solvers/bspline/bspline_curve.h"

#include <Eigen/Core>
#include <vector>

namespace sculptline::solvers {

/// C(u), C'(u) and C''(u) of a (rational) curve without allocating: the basis derivatives by The
/// NURBS Book A2.3 on stack arrays (basis.h), the quotient rule (eq. 4.8, A4.2 with k <= 2) for
/// rational curves. For inner loops that evaluate one curve at many parameters (frames along a sweep
/// path, foot-point iterations); BSplineCurve::derivatives allocates on every call.
template <int Dim>
class CurveJet {
public:
    using Point = Eigen::Matrix<double, Dim, 1>;

    explicit CurveJet(const BSplineCurve<Dim>& curve);

    /// x = C(u), d1 = C'(u), d2 = C''(u). u is clamped to the domain, also for a closed curve: its
    /// domain end gives the left-hand limits there (BSplineCurve::derivatives wraps to the start's
    /// right-hand ones instead; they differ where the seam is not smooth enough, e.g. C'' of a
    /// periodic quadratic), so that a sweep can compare the tangents at both ends of a path. At a
    /// knot inside the domain, the right-hand derivatives, as BSplineCurve::derivatives.
    void evaluate(double u, Point& x, Point& d1, Point& d2) const;
    /// C'(u) only (same conventions).
    Point derivative(double u) const;

    int degree() const { return degree_; }
    double domainStart() const { return knots_[degree_]; }
    double domainEnd() const { return knots_[points_.size()]; }

private:
    using Homogeneous = Eigen::Matrix<double, Dim + 1, 1>;

    int degree_;
    bool rational_;
    KnotVector knots_;
    std::vector<Homogeneous> points_;  // (w x, w); w = 1 for a non-rational curve
};

using CurveJet2d = CurveJet<2>;
using CurveJet3d = CurveJet<3>;

extern template class CurveJet<2>;
extern template class CurveJet<3>;

}  // namespace sculptline::solvers
