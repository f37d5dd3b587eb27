#include "solvers/bspline/bspline_surface.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/knot_algorithms.h"

#include <Eigen/Geometry>
#include <cmath>
#include <sstream>

namespace sculptline::solvers {
template <int Dim>
BSplineSurface<Dim>::BSplineSurface(int degreeU, int degreeV, KnotVector knotsU, KnotVector knotsV, int countU,
                                    int countV, std::vector<Point> points, std::vector<double> weights)
    : degree_{degreeU, degreeV}, knots_{std::move(knotsU), std::move(knotsV)}, count_{countU, countV},
      points_(std::move(points)), weights_(std::move(weights))
{
    if (degreeU < 1) throw GeometryError("degreeU: must be at least 1, got " + std::to_string(degreeU));
    if (degreeV < 1) throw GeometryError("degreeV: must be at least 1, got " + std::to_string(degreeV));
    if (countU < 1) throw GeometryError("countU: must be positive, got " + std::to_string(countU));
    if (countV < 1) throw GeometryError("countV: must be positive, got " + std::to_string(countV));
    const size_t expected = static_cast<size_t>(countU) * static_cast<size_t>(countV);
    if (points_.size() != expected) {
        std::ostringstream msg;
        msg << "points: expected countU * countV = " << expected << " points, got " << points_.size();
        throw GeometryError(msg.str());
    }
    for (size_t i = 0; i < points_.size(); ++i) {
        if (!points_[i].allFinite()) throw GeometryError("points[" + std::to_string(i) + "]: not a finite number");
    }
    validateKnots(degreeU, countU, knots_[0], "knotsU");
    validateKnots(degreeV, countV, knots_[1], "knotsV");
    if (!weights_.empty()) {
        if (weights_.size() != expected) {
            throw GeometryError("weights: expected one per point (" + std::to_string(expected) + "), got " +
                                std::to_string(weights_.size()));
        }
        for (size_t i = 0; i < weights_.size(); ++i) {
            if (!std::isfinite(weights_[i]) || !(weights_[i] > 0.0)) {
                throw GeometryError("weights[" + std::to_string(i) + "]: must be a finite positive number");
            }
        }
    }
}

template <int Dim>
typename BSplineSurface<Dim>::Point BSplineSurface<Dim>::evaluate(double u, double v) const
{
    if (!std::isfinite(u) || !std::isfinite(v)) throw GeometryError("params: not a finite number");
    // The NURBS Book A3.5 / A4.3 in homogeneous coordinates, without the derivative machinery.
    const int p = degree_[0], q = degree_[1];
    u = std::clamp(u, domainStart(Direction::U), domainEnd(Direction::U));
    v = std::clamp(v, domainStart(Direction::V), domainEnd(Direction::V));
    const int uspan = findSpan(p, knots_[0], u);
    const int vspan = findSpan(q, knots_[1], v);
    double Nu[kMaxDegree + 1], Nv[kMaxDegree + 1];
    basisFunctions(uspan, u, p, knots_[0], Nu);
    basisFunctions(vspan, v, q, knots_[1], Nv);
    Point sum = Point::Zero();
    double w = 0.0;
    for (int r = 0; r <= p; ++r) {
        const int i = uspan - p + r;
        for (int c = 0; c <= q; ++c) {
            const int j = vspan - q + c;
            const double b = Nu[r] * Nv[c] * weight(i, j);
            sum += b * point(i, j);
            w += b;
        }
    }
    return sum / w;
}

template <int Dim>
std::vector<typename BSplineSurface<Dim>::Point> BSplineSurface<Dim>::evaluateGrid(const std::vector<double>& us,
                                                                                 const std::vector<double>& vs) const
{
    struct Basis {
        int span = 0;
        double N[kMaxDegree + 1] = {};
    };
    auto bases = [this](const std::vector<double>& ts, int d) {
        std::vector<Basis> out(ts.size());
        const Direction dir = d == 0 ? Direction::U : Direction::V;
        for (size_t k = 0; k < ts.size(); ++k) {
            if (!std::isfinite(ts[k])) throw GeometryError("params: not a finite number");
            const double t = std::clamp(ts[k], domainStart(dir), domainEnd(dir));
            out[k].span = findSpan(degree_[d], knots_[d], t);
            basisFunctions(out[k].span, t, degree_[d], knots_[d], out[k].N);
        }
        return out;
    };
    const std::vector<Basis> bu = bases(us, 0), bv = bases(vs, 1);
    const int p = degree_[0], q = degree_[1];
    const size_t nV = vs.size();
    // The tensor product in two passes (The NURBS Book §3.4 in homogeneous coordinates): each
    // control row contracted with the v basis at every v parameter, then (p + 1) of those rows with
    // the u basis at each u parameter: (q + 1) products per row and v, and (p + 1) per point,
    // instead of (p + 1)(q + 1) per point.
    using Homogeneous = Eigen::Matrix<double, Dim + 1, 1>;
    std::vector<Homogeneous> rows(static_cast<size_t>(count_[0]) * nV, Homogeneous::Zero());
    const bool rational = isRational();
    for (int i = 0; i < count_[0]; ++i) {
        const Point* P = points_.data() + static_cast<size_t>(i) * count_[1];
        const double* W = rational ? weights_.data() + static_cast<size_t>(i) * count_[1] : nullptr;
        Homogeneous* R = rows.data() + static_cast<size_t>(i) * nV;
        for (size_t b = 0; b < nV; ++b) {
            Homogeneous h = Homogeneous::Zero();
            for (int c = 0; c <= q; ++c) {
                const int j = bv[b].span - q + c;
                const double f = bv[b].N[c] * (W ? W[j] : 1.0);
                h.template head<Dim>() += f * P[j];
                h[Dim] += f;
            }
            R[b] = h;
        }
    }
    std::vector<Point> out;
    out.reserve(us.size() * nV);
    for (const Basis& a : bu) {
        for (size_t b = 0; b < nV; ++b) {
            Homogeneous h = Homogeneous::Zero();
            for (int r = 0; r <= p; ++r) h += a.N[r] * rows[static_cast<size_t>(a.span - p + r) * nV + b];
            out.push_back(h.template head<Dim>() / h[Dim]);
        }
    }
    return out;
}

template <int Dim>
std::vector<std::vector<typename BSplineSurface<Dim>::Point>> BSplineSurface<Dim>::derivatives(double u, double v,
                                                                                              int order) const
{
    if (order < 0) throw GeometryError("derivatives: must be non-negative, got " + std::to_string(order));
    if (!std::isfinite(u) || !std::isfinite(v)) throw GeometryError("params: not a finite number");
    const int p = degree_[0], q = degree_[1];
    u = std::clamp(u, domainStart(Direction::U), domainEnd(Direction::U));
    v = std::clamp(v, domainStart(Direction::V), domainEnd(Direction::V));
    // The NURBS Book A3.6 on the homogeneous net.
    const int du = std::min(order, p), dv = std::min(order, q);
    const int uspan = findSpan(p, knots_[0], u);
    const int vspan = findSpan(q, knots_[1], v);
    const Eigen::MatrixXd Nu = basisDerivatives(uspan, u, p, du, knots_[0]);
    const Eigen::MatrixXd Nv = basisDerivatives(vspan, v, q, dv, knots_[1]);
    using HPoint = Eigen::Matrix<double, Dim + 1, 1>;
    std::vector<std::vector<HPoint>> a(order + 1, std::vector<HPoint>(order + 1, HPoint::Zero()));
    std::vector<HPoint> temp(q + 1);
    for (int k = 0; k <= du; ++k) {
        for (int s = 0; s <= q; ++s) {
            temp[s].setZero();
            for (int r = 0; r <= p; ++r) {
                const int i = uspan - p + r, j = vspan - q + s;
                const double w = weight(i, j);
                HPoint h;
                h.template head<Dim>() = point(i, j) * w;
                h[Dim] = w;
                temp[s] += Nu(k, r) * h;
            }
        }
        const int dd = std::min(order - k, dv);
        for (int l = 0; l <= dd; ++l)
            for (int s = 0; s <= q; ++s) a[k][l] += Nv(l, s) * temp[s];
    }
    // The NURBS Book A4.4: from derivatives of (wS, w) to derivatives of S.
    std::vector<std::vector<Point>> skl(order + 1, std::vector<Point>(order + 1, Point::Zero()));
    for (int k = 0; k <= order; ++k) {
        for (int l = 0; l <= order - k; ++l) {
            Point v1 = a[k][l].template head<Dim>();
            for (int j = 1; j <= l; ++j) v1 -= binomial(l, j) * a[0][j][Dim] * skl[k][l - j];
            for (int i = 1; i <= k; ++i) {
                v1 -= binomial(k, i) * a[i][0][Dim] * skl[k - i][l];
                Point v2 = Point::Zero();
                for (int j = 1; j <= l; ++j) v2 += binomial(l, j) * a[i][j][Dim] * skl[k - i][l - j];
                v1 -= binomial(k, i) * v2;
            }
            skl[k][l] = v1 / a[0][0][Dim];
        }
    }
    return skl;
}

template <int Dim>
typename BSplineSurface<Dim>::Point BSplineSurface<Dim>::normal(double u, double v) const
{
    if constexpr (Dim != 3) {
        (void)u;
        (void)v;
        return Point::Zero();
    } else {
        // Scale-free thresholds: a first derivative below kCollapsed times the other is rounding
        // noise of a collapsed edge (its direction is meaningless), and a cross product below
        // kDegenerate times |Su||Sv| means parallel derivatives.
        constexpr double kCollapsed = 1e-12;
        constexpr double kDegenerate = 1e-12;
        const auto d = derivatives(u, v, 2);
        const double su = d[1][0].norm(), sv = d[0][1].norm();
        const bool suCollapsed = su <= kCollapsed * sv, svCollapsed = sv <= kCollapsed * su;
        Point n = d[1][0].cross(d[0][1]);
        if (!suCollapsed && !svCollapsed && n.norm() > kDegenerate * su * sv) return n.normalized();
        // At a collapsed edge the normal is the limit from the inside of the domain: with Sv = 0
        // along u = u0, Sv(u0 + h) ~ h Suv, so N ~ h (Su x Suv), whose sign depends on the side h of
        // the interior: negative when the edge is the end of the domain (likewise for Su = 0).
        if (suCollapsed || (!svCollapsed && su <= sv)) {
            const double side = std::min(v, domainEnd(Direction::V)) >= domainEnd(Direction::V) ? -1.0 : 1.0;
            n = side * d[1][1].cross(d[0][1]);
        } else {
            const double side = std::min(u, domainEnd(Direction::U)) >= domainEnd(Direction::U) ? -1.0 : 1.0;
            n = side * d[1][0].cross(d[1][1]);
        }
        return n.norm() > 0 ? Point(n.normalized()) : Point::Zero();
    }
}

template <int Dim>
ControlMatrix BSplineSurface<Dim>::groupedRows(Direction d) const
{
    const int h = Dim + (isRational() ? 1 : 0);
    const int rows = count(d);
    const int other = d == Direction::U ? count_[1] : count_[0];
    ControlMatrix m(rows, static_cast<Eigen::Index>(other) * h);
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < other; ++c) {
            const int i = d == Direction::U ? r : c;
            const int j = d == Direction::U ? c : r;
            const double w = weight(i, j);
            m.row(r).segment(static_cast<Eigen::Index>(c) * h, Dim) = (point(i, j) * w).transpose();
            if (isRational()) m(r, static_cast<Eigen::Index>(c) * h + Dim) = w;
        }
    }
    return m;
}

template <int Dim>
BSplineSurface<Dim> BSplineSurface<Dim>::fromGroupedRows(Direction d, int degreeU, int degreeV, KnotVector knotsU,
                                                        KnotVector knotsV, const ControlMatrix& m, bool rational)
{
    const int h = Dim + (rational ? 1 : 0);
    const int rows = static_cast<int>(m.rows());
    const int other = static_cast<int>(m.cols()) / h;
    const int cu = d == Direction::U ? rows : other;
    const int cv = d == Direction::U ? other : rows;
    std::vector<Point> pts(static_cast<size_t>(cu) * cv);
    std::vector<double> w(rational ? pts.size() : 0);
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < other; ++c) {
            const int i = d == Direction::U ? r : c;
            const int j = d == Direction::U ? c : r;
            const size_t idx = static_cast<size_t>(i) * cv + j;
            const double wt = rational ? m(r, static_cast<Eigen::Index>(c) * h + Dim) : 1.0;
            pts[idx] = m.row(r).segment(static_cast<Eigen::Index>(c) * h, Dim).transpose() / wt;
            if (rational) w[idx] = wt;
        }
    }
    return BSplineSurface(degreeU, degreeV, std::move(knotsU), std::move(knotsV), cu, cv, std::move(pts), std::move(w));
}

namespace {

template <int Dim>
BSplineSurface<Dim> rebuild(const BSplineSurface<Dim>& s, Direction d, int newDegree, KnotsAndPoints r)
{
    const bool u = d == Direction::U;
    return BSplineSurface<Dim>::fromGroupedRows(d, u ? newDegree : s.degreeU(), u ? s.degreeV() : newDegree,
                                                u ? std::move(r.knots) : s.knotsU(), u ? s.knotsV() : std::move(r.knots),
                                                r.points, s.isRational());
}

}  // namespace

template <int Dim>
BSplineSurface<Dim> BSplineSurface<Dim>::insertKnot(Direction d, double t, int times) const
{
    return rebuild(*this, d, degree(d), solvers::insertKnot(degree(d), knots(d), groupedRows(d), t, times));
}

template <int Dim>
BSplineSurface<Dim> BSplineSurface<Dim>::refine(Direction d, const std::vector<double>& x) const
{
    return rebuild(*this, d, degree(d), refineKnots(degree(d), knots(d), groupedRows(d), x));
}

template <int Dim>
BSplineSurface<Dim> BSplineSurface<Dim>::elevate(Direction d, int times) const
{
    return rebuild(*this, d, degree(d) + times, elevateDegree(degree(d), knots(d), groupedRows(d), times));
}

template <int Dim>
BSplineSurface<Dim> BSplineSurface<Dim>::removeKnots(Direction d, double tolerance, int* removed) const
{
    if (!std::isfinite(tolerance) || tolerance < 0) throw GeometryError("tolerance: must be a finite number >= 0");
    KnotsAndPoints cur{knots(d), groupedRows(d)};
    const int h = Dim + (isRational() ? 1 : 0);
    double budget = removalBudget(cur.points, Dim, isRational(), tolerance);
    const int count = removeKnotsWithinBudget(degree(d), cur.knots, cur.points, budget, h);
    if (removed) *removed = count;
    return rebuild(*this, d, degree(d), std::move(cur));
}

template <int Dim>
BSplineSurface<Dim> BSplineSurface<Dim>::extract(double u0, double u1, double v0, double v1) const
{
    const auto check = [&](Direction d, double a, double b, const char* name) {
        if (!std::isfinite(a) || !std::isfinite(b) || !(a < b) || a < domainStart(d) || b > domainEnd(d)) {
            std::ostringstream msg;
            msg << name << ": extract range [" << a << ", " << b << "] must be increasing and inside ["
                << domainStart(d) << ", " << domainEnd(d) << "]";
            throw GeometryError(msg.str());
        }
    };
    check(Direction::U, u0, u1, "u");
    check(Direction::V, v0, v1, "v");
    const BSplineSurface inU =
        rebuild(*this, Direction::U, degreeU(), extractSegment(degreeU(), knotsU(), groupedRows(Direction::U), u0, u1));
    return rebuild(inU, Direction::V, degreeV(),
                   extractSegment(degreeV(), inU.knotsV(), inU.groupedRows(Direction::V), v0, v1));
}

template <int Dim>
std::pair<BSplineSurface<Dim>, BSplineSurface<Dim>> BSplineSurface<Dim>::split(Direction d, double t) const
{
    if (!(t > domainStart(d) && t < domainEnd(d))) {
        throw GeometryError("parameter: split needs a value strictly inside the domain");
    }
    const double u0 = domainStart(Direction::U), u1 = domainEnd(Direction::U);
    const double v0 = domainStart(Direction::V), v1 = domainEnd(Direction::V);
    if (d == Direction::U) return {extract(u0, t, v0, v1), extract(t, u1, v0, v1)};
    return {extract(u0, u1, v0, t), extract(u0, u1, t, v1)};
}

template <int Dim>
BSplineCurve<Dim> BSplineSurface<Dim>::isoCurve(Direction d, double t) const
{
    if (!std::isfinite(t)) throw GeometryError("parameter: not a finite number");
    // Evaluate the grouped rows of direction d as one wide curve at t: the result is the control
    // polygon of the iso-curve in the other direction.
    const int p = degree(d);
    t = std::clamp(t, domainStart(d), domainEnd(d));
    const int span = findSpan(p, knots(d), t);
    double N[kMaxDegree + 1];
    basisFunctions(span, t, p, knots(d), N);
    const ControlMatrix rows = groupedRows(d);
    Eigen::RowVectorXd wide = Eigen::RowVectorXd::Zero(rows.cols());
    for (int j = 0; j <= p; ++j) wide += N[j] * rows.row(span - p + j);
    const int h = Dim + (isRational() ? 1 : 0);
    const Direction other = d == Direction::U ? Direction::V : Direction::U;
    ControlMatrix pts(count(other), h);
    for (int c = 0; c < count(other); ++c) pts.row(c) = wide.segment(static_cast<Eigen::Index>(c) * h, h);
    return BSplineCurve<Dim>::fromHomogeneous(degree(other), knots(other), pts, isRational());
}

template class BSplineSurface<2>;
template class BSplineSurface<3>;

}  // namespace sculptline::solvers
