#pragma once
// Non-rational and rational tensor-product B-spline surfaces.
#include "solvers/bspline/bspline_curve.h"

#include <array>

namespace sculptline::solvers {

enum class Direction { U, V };

/// A tensor-product B-spline surface S(u, v) = sum_i sum_j N_i(u) N_j(v) P_ij (rational when
/// weights are given). Point (i, j) — i along U, j along V — is at index i * countV + j, as in the
/// JSON format. Immutable and validated at construction like BSplineCurve.
template <int Dim>
class BSplineSurface {
    static_assert(Dim == 2 || Dim == 3, "BSplineSurface supports 2D and 3D");

public:
    using Point = Eigen::Matrix<double, Dim, 1>;

    /// @throws GeometryError naming the field ("degreeU", "knotsV", "points", "countU", ...).
    BSplineSurface(int degreeU, int degreeV, KnotVector knotsU, KnotVector knotsV, int countU, int countV,
                   std::vector<Point> points, std::vector<double> weights = {});

    int degreeU() const { return degree_[0]; }
    int degreeV() const { return degree_[1]; }
    int degree(Direction d) const { return degree_[index(d)]; }
    const KnotVector& knotsU() const { return knots_[0]; }
    const KnotVector& knotsV() const { return knots_[1]; }
    const KnotVector& knots(Direction d) const { return knots_[index(d)]; }
    int countU() const { return count_[0]; }
    int countV() const { return count_[1]; }
    int count(Direction d) const { return count_[index(d)]; }
    const std::vector<Point>& points() const { return points_; }
    const std::vector<double>& weights() const { return weights_; }
    bool isRational() const { return !weights_.empty(); }
    const Point& point(int i, int j) const { return points_[static_cast<size_t>(i) * count_[1] + j]; }
    double weight(int i, int j) const { return weights_.empty() ? 1.0 : weights_[static_cast<size_t>(i) * count_[1] + j]; }

    double domainStart(Direction d) const { return knots(d)[degree(d)]; }
    double domainEnd(Direction d) const { return knots(d)[count(d)]; }

    Point evaluate(double u, double v) const;
    /// evaluate(us[a], vs[b]) for every pair, at index a * vs.size() + b (to round-off): each
    /// parameter's span and basis functions are found once, and the control rows are contracted in
    /// v once per v parameter, so a point costs p + 1 products instead of (p + 1)(q + 1).
    std::vector<Point> evaluateGrid(const std::vector<double>& us, const std::vector<double>& vs) const;
    /// result[k][l] = d^(k+l) S / du^k dv^l for k + l <= order (entries with k + l > order are zero).
    /// The NURBS Book A3.6 on homogeneous points, then A4.4 for rational surfaces.
    std::vector<std::vector<Point>> derivatives(double u, double v, int order) const;
    /// Unit normal Su x Sv / |Su x Sv| (3D only); falls back to second derivatives at degenerate
    /// points (a collapsed edge), and returns zero when no direction is defined.
    Point normal(double u, double v) const;

    BSplineSurface insertKnot(Direction d, double t, int times = 1) const;
    BSplineSurface refine(Direction d, const std::vector<double>& x) const;
    BSplineSurface elevate(Direction d, int times) const;
    /// Removes knots in direction d while the whole surface moves by at most `tolerance`.
    BSplineSurface removeKnots(Direction d, double tolerance, int* removed = nullptr) const;
    /// The piece on [u0, u1] x [v0, v1] as a surface with clamped knots.
    BSplineSurface extract(double u0, double u1, double v0, double v1) const;
    /// The two pieces on either side of t in direction d.
    std::pair<BSplineSurface, BSplineSurface> split(Direction d, double t) const;
    /// The iso-parametric curve at fixed t in direction d (varying along the other direction).
    BSplineCurve<Dim> isoCurve(Direction d, double t) const;

    /// Control rows grouped for the curve algorithms: row r = all homogeneous points with index r in
    /// direction d, concatenated along the other direction.
    ControlMatrix groupedRows(Direction d) const;
    static BSplineSurface fromGroupedRows(Direction d, int degreeU, int degreeV, KnotVector knotsU, KnotVector knotsV,
                                          const ControlMatrix& rows, bool rational);

private:
    static int index(Direction d) { return d == Direction::U ? 0 : 1; }

    std::array<int, 2> degree_{};
    std::array<KnotVector, 2> knots_;
    std::array<int, 2> count_{};
    std::vector<Point> points_;
    std::vector<double> weights_;
};

using Surface3d = BSplineSurface<3>;

extern template class BSplineSurface<2>;
extern template class BSplineSurface<3>;

}  // namespace sculptline::solvers
