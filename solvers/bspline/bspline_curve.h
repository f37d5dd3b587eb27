#pragma once
// Non-rational and rational B-spline curves in 2D and 3D, open (clamped or not) or closed (periodic).
#include "solvers/bspline/basis.h"

#include <Eigen/Core>
#include <utility>
#include <vector>

namespace sculptline::solvers {

/// A B-spline curve of any degree >= 1 in Dim = 2 or 3 dimensions, with optional positive weights.
///
/// A closed curve uses the unwrapped convention of ../shared/interfaces.md: n+1 control points of
/// which the last `degree` repeat the first `degree`, and knots whose spacing repeats with the
/// period T = knots[n+1] - knots[degree]. Its parameter wraps: evaluate(u) == evaluate(u + T).
///
/// Instances are immutable values; every operation returns a new curve. The constructor validates
/// everything and throws GeometryError, so an existing curve is always valid geometry.
template <int Dim>
class BSplineCurve {
    static_assert(Dim == 2 || Dim == 3, "BSplineCurve supports 2D and 3D");

public:
    using Point = Eigen::Matrix<double, Dim, 1>;

    /// @param weights empty for a non-rational curve, else one positive finite weight per point.
    /// @param closed  mark as periodic; the wrapped points, weights and knot spacings must repeat
    ///                (to 1e-9 relative to the curve's size; they are then made exactly equal).
    /// @throws GeometryError naming the field ("degree", "knots", "points", "weights", "closed").
    BSplineCurve(int degree, KnotVector knots, std::vector<Point> points, std::vector<double> weights = {},
                 bool closed = false);

    /// From rows (x, y[, z]) or, when rational, homogeneous rows (w*x, w*y, [w*z,] w).
    static BSplineCurve fromHomogeneous(int degree, KnotVector knots, const ControlMatrix& rows, bool rational,
                                        bool closed = false);

    int degree() const { return degree_; }
    const KnotVector& knots() const { return knots_; }
    const std::vector<Point>& points() const { return points_; }
    const std::vector<double>& weights() const { return weights_; }
    bool isRational() const { return !weights_.empty(); }
    bool isClosed() const { return closed_; }
    int pointCount() const { return static_cast<int>(points_.size()); }
    double weight(int i) const { return weights_.empty() ? 1.0 : weights_[i]; }

    /// Parameter domain [knots[degree], knots[n+1]].
    double domainStart() const { return knots_[degree_]; }
    double domainEnd() const { return knots_[points_.size()]; }
    /// Closed curves: u mapped into [start, end); open curves: u clamped to [start, end].
    double normalizeParameter(double u) const;

    /// Rows (x, y[, z]) or homogeneous rows (w*x, .., w) when rational.
    ControlMatrix homogeneous() const;

    Point evaluate(double u) const;
    /// C(u) and its derivatives: result[k] = k-th derivative, k = 0..order (zero above the degree
    /// for non-rational curves). The NURBS Book A3.2 and, for rational curves, A4.2.
    std::vector<Point> derivatives(double u, int order) const;

    /// Knot insertion (Boehm, A5.1). A closed curve stays closed (the knot is inserted in every period).
    BSplineCurve insertKnot(double u, int times = 1) const;
    /// Knot refinement (A5.4); x sorted.
    BSplineCurve refine(const std::vector<double>& x) const;
    /// Degree elevation (A5.9).
    BSplineCurve elevate(int times) const;
    /// Removes interior knots greedily while the total deviation stays within `tolerance` (model units,
    /// a bound, not an estimate: The NURBS Book A5.8 with eq. 5.30 for rational curves).
    /// Closed curves stay closed (a removed seam knot moves the domain start to the next knot).
    /// @param removed receives the number of knots removed.
    BSplineCurve removeKnots(double tolerance, int* removed = nullptr) const;

    /// Open curves: the pieces on [start, u] and [u, end]; u strictly inside the domain.
    std::pair<BSplineCurve, BSplineCurve> split(double u) const;
    /// The piece on [u0, u1] as a clamped open curve. Closed curves: u1 may be smaller than u0 or
    /// exceed the end, the piece then runs across the seam; u1 - u0 must not exceed the period.
    BSplineCurve extract(double u0, double u1) const;
    /// A closed curve opened at u: an open clamped curve on [u, u + T] with the same shape.
    BSplineCurve openAt(double u) const;
    /// The same geometry with clamped end knots (a closed curve becomes open at its domain start).
    BSplineCurve clamped() const;

    /// Axis-aligned bounding box diagonal of the control points (a scale for relative tolerances).
    double controlSize() const;
    /// True when the control points coincide up to round-off: their spread in every coordinate is
    /// at most kCollapsedRelative times the largest magnitude of a coordinate (0 = all equal). Such a
    /// curve is a point to double precision: no length, tangent or plane can be measured on it.
    bool isCollapsed() const;

private:
    BSplineCurve() = default;
    void validate();
    void checkPeriodic();

    int degree_ = 0;
    KnotVector knots_;
    std::vector<Point> points_;
    std::vector<double> weights_;
    bool closed_ = false;
};

/// Spread of the control points, relative to their coordinates' magnitude, below which they are
/// the same point up to round-off: about 4500 ulps, so that coordinates computed a few operations
/// apart from one value (a projection, an evaluation, a transformation) still count as equal.
constexpr double kCollapsedRelative = 1e-12;

using Curve2d = BSplineCurve<2>;
using Curve3d = BSplineCurve<3>;

extern template class BSplineCurve<2>;
extern template class BSplineCurve<3>;

/// A closed uniform curve of `degree` through the periodic control polygon `uniquePoints` (not
/// repeated), knots 0, 1, 2, ... (domain [0, uniquePoints.size()]).
template <int Dim>
BSplineCurve<Dim> makeClosedUniform(int degree, const std::vector<typename BSplineCurve<Dim>::Point>& uniquePoints,
                                    const std::vector<double>& uniqueWeights = {});

/// An open uniform clamped curve (knots 0..1 with end multiplicity degree+1) on the given points.
template <int Dim>
BSplineCurve<Dim> makeClampedUniform(int degree, const std::vector<typename BSplineCurve<Dim>::Point>& points,
                                     const std::vector<double>& weights = {});

}  // namespace sculptline::solvers
