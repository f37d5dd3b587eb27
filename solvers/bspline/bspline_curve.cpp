#include "solvers/bspline/bspline_curve.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/knot_algorithms.h"
#include "solvers/bspline/periodic.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace sculptline::solvers {
namespace {

// Relative tolerance for recognising a closed curve's repeated points, weights and knot spacings:
// data that went through decimal text (JSON) keeps ~15 significant digits, so 1e-9 of the curve's
// size separates round-off from a genuinely open curve.
constexpr double kPeriodicRelativeTolerance = 1e-9;

// Periods of the periodic extension on each side of the domain: one is enough for the local
// algorithms (each touches at most degree+1 neighbouring points), two leave margin for the extra
// knots that elevation introduces.
constexpr int kWindowPeriods = 2;

}  // namespace

template <int Dim>
BSplineCurve<Dim>::BSplineCurve(int degree, KnotVector knots, std::vector<Point> points, std::vector<double> weights,
                                bool closed)
    : degree_(degree), knots_(std::move(knots)), points_(std::move(points)), weights_(std::move(weights)), closed_(closed)
{
    validate();
}

template <int Dim>
void BSplineCurve<Dim>::validate()
{
    if (degree_ < 1) throw GeometryError("degree: must be at least 1, got " + std::to_string(degree_));
    for (size_t i = 0; i < points_.size(); ++i) {
        if (!points_[i].allFinite()) throw GeometryError("points[" + std::to_string(i) + "]: not a finite number");
    }
    validateKnots(degree_, static_cast<int>(points_.size()), knots_);
    if (!weights_.empty()) {
        if (weights_.size() != points_.size()) {
            throw GeometryError("weights: expected one per point (" + std::to_string(points_.size()) + "), got " +
                                std::to_string(weights_.size()));
        }
        for (size_t i = 0; i < weights_.size(); ++i) {
            if (!std::isfinite(weights_[i])) throw GeometryError("weights[" + std::to_string(i) + "]: not a finite number");
            if (!(weights_[i] > 0.0)) {
                std::ostringstream msg;
                msg << "weights[" << i << "]: must be positive, got " << weights_[i];
                throw GeometryError(msg.str());
            }
        }
    }
    if (closed_) checkPeriodic();
}

template <int Dim>
void BSplineCurve<Dim>::checkPeriodic()
{
    const int p = degree_;
    const int n = pointCount() - 1;
    const int N = n + 1 - p;
    if (N < p + 1) {
        throw GeometryError("closed: a closed curve of degree " + std::to_string(p) + " needs at least " +
                            std::to_string(2 * p + 1) + " points in the unwrapped convention, got " +
                            std::to_string(n + 1));
    }
    const double tolPoints = kPeriodicRelativeTolerance * std::max(1.0, controlSize());
    for (int i = 0; i < p; ++i) {
        if ((points_[i] - points_[N + i]).norm() > tolPoints) {
            throw GeometryError("closed: points[" + std::to_string(N + i) + "] must repeat points[" + std::to_string(i) +
                                "] (the last degree points wrap around)");
        }
        points_[N + i] = points_[i];
        if (!weights_.empty()) {
            if (std::abs(weights_[i] - weights_[N + i]) > kPeriodicRelativeTolerance * weights_[i]) {
                throw GeometryError("closed: weights[" + std::to_string(N + i) + "] must repeat weights[" +
                                    std::to_string(i) + "]");
            }
            weights_[N + i] = weights_[i];
        }
    }
    const double T = knots_[n + 1] - knots_[p];
    const double tolKnots = kPeriodicRelativeTolerance * std::max(1.0, T + std::abs(knots_[p]));
    for (int i = 0; i < 2 * p; ++i) {
        const double here = knots_[i + 1] - knots_[i];
        const double there = knots_[i + N + 1] - knots_[i + N];
        if (std::abs(here - there) > tolKnots) {
            throw GeometryError("closed: knot spacing must repeat with the period (knots[" + std::to_string(i + 1) +
                                "] - knots[" + std::to_string(i) + "] differs from knots[" +
                                std::to_string(i + N + 1) + "] - knots[" + std::to_string(i + N) + "])");
        }
    }
}

template <int Dim>
BSplineCurve<Dim> BSplineCurve<Dim>::fromHomogeneous(int degree, KnotVector knots, const ControlMatrix& rows,
                                                     bool rational, bool closed)
{
    if (rows.cols() != Dim + (rational ? 1 : 0)) throw GeometryError("points: wrong number of coordinates");
    BSplineCurve c;
    c.degree_ = degree;
    c.knots_ = std::move(knots);
    c.closed_ = closed;
    c.points_.resize(rows.rows());
    if (rational) c.weights_.resize(rows.rows());
    for (Eigen::Index i = 0; i < rows.rows(); ++i) {
        if (rational) {
            const double w = rows(i, Dim);
            c.weights_[i] = w;
            c.points_[i] = rows.row(i).template head<Dim>().transpose() / w;
        } else {
            c.points_[i] = rows.row(i).transpose();
        }
    }
    c.validate();
    return c;
}

template <int Dim>
ControlMatrix BSplineCurve<Dim>::homogeneous() const
{
    const int cols = Dim + (isRational() ? 1 : 0);
    ControlMatrix m(pointCount(), cols);
    for (int i = 0; i < pointCount(); ++i) {
        const double w = weight(i);
        m.row(i).template head<Dim>() = (points_[i] * w).transpose();
        if (isRational()) m(i, Dim) = w;
    }
    return m;
}

template <int Dim>
double BSplineCurve<Dim>::normalizeParameter(double u) const
{
    const double a = domainStart(), b = domainEnd();
    if (!std::isfinite(u)) throw GeometryError("parameter: not a finite number");
    if (closed_) {
        const double T = b - a;
        double w = std::fmod(u - a, T);
        if (w < 0) w += T;
        const double r = a + w;
        return r >= b ? a : r;
    }
    return std::clamp(u, a, b);
}

template <int Dim>
typename BSplineCurve<Dim>::Point BSplineCurve<Dim>::evaluate(double u) const
{
    // The NURBS Book A3.1 (A4.1 for rational curves, in homogeneous coordinates).
    u = normalizeParameter(u);
    const int span = findSpan(degree_, knots_, u);
    double N[kMaxDegree + 1];
    basisFunctions(span, u, degree_, knots_, N);
    Point c = Point::Zero();
    double w = 0.0;
    for (int j = 0; j <= degree_; ++j) {
        const int i = span - degree_ + j;
        const double wi = weight(i);
        c += N[j] * wi * points_[i];
        w += N[j] * wi;
    }
    return c / w;
}

template <int Dim>
std::vector<typename BSplineCurve<Dim>::Point> BSplineCurve<Dim>::derivatives(double u, int order) const
{
    if (order < 0) throw GeometryError("derivatives: must be non-negative, got " + std::to_string(order));
    // The NURBS Book A3.2 on homogeneous points, then A4.2 (rational curves).
    u = normalizeParameter(u);
    const int span = findSpan(degree_, knots_, u);
    const int du = std::min(order, degree_);
    const Eigen::MatrixXd nders = basisDerivatives(span, u, degree_, du, knots_);
    std::vector<Point> aders(order + 1, Point::Zero());
    std::vector<double> wders(order + 1, 0.0);
    for (int k = 0; k <= du; ++k) {
        for (int j = 0; j <= degree_; ++j) {
            const int i = span - degree_ + j;
            const double wi = weight(i);
            aders[k] += nders(k, j) * wi * points_[i];
            wders[k] += nders(k, j) * wi;
        }
    }
    if (!isRational()) return aders;
    std::vector<Point> ck(order + 1);
    for (int k = 0; k <= order; ++k) {
        Point v = aders[k];
        for (int i = 1; i <= k; ++i) v -= binomial(k, i) * wders[i] * ck[k - i];
        ck[k] = v / wders[0];
    }
    return ck;
}

template <int Dim>
BSplineCurve<Dim> BSplineCurve<Dim>::insertKnot(double u, int times) const
{
    if (!closed_) {
        KnotsAndPoints r = solvers::insertKnot(degree_, knots_, homogeneous(), u, times);
        return fromHomogeneous(degree_, std::move(r.knots), r.points, isRational());
    }
    const double un = normalizeParameter(u);
    // Checked here, on the knot as given: the window below holds a copy per period, and the
    // window's own check would name one of those copies.
    const int s = knotMultiplicity(knots_, un);
    if (times < 0) throw GeometryError("times: must be non-negative, got " + std::to_string(times));
    if (s + times > degree_) {
        std::ostringstream msg;
        msg << "times: knot " << u << " has multiplicity " << s << "; inserting it " << times
            << " more times exceeds the degree " << degree_;
        throw GeometryError(msg.str());
    }
    std::vector<double> all;
    const PeriodicWindow w = periodicExtension(degree_, knots_, homogeneous(), kWindowPeriods);
    for (int q = -kWindowPeriods; q <= kWindowPeriods; ++q)
        for (int t = 0; t < times; ++t) all.push_back(un + q * w.period);
    KnotsAndPoints r = refineKnots(degree_, w.knots, w.points, all);
    KnotsAndPoints c = periodicFromWindow(degree_, r.knots, r.points, w.start, w.period);
    return fromHomogeneous(degree_, std::move(c.knots), c.points, isRational(), true);
}

template <int Dim>
BSplineCurve<Dim> BSplineCurve<Dim>::refine(const std::vector<double>& x) const
{
    if (!closed_) {
        KnotsAndPoints r = refineKnots(degree_, knots_, homogeneous(), x);
        return fromHomogeneous(degree_, std::move(r.knots), r.points, isRational());
    }
    const PeriodicWindow w = periodicExtension(degree_, knots_, homogeneous(), kWindowPeriods);
    std::vector<double> all;
    for (int q = -kWindowPeriods; q <= kWindowPeriods; ++q)
        for (double v : x) all.push_back(normalizeParameter(v) + q * w.period);
    std::sort(all.begin(), all.end());
    KnotsAndPoints r = refineKnots(degree_, w.knots, w.points, all);
    KnotsAndPoints c = periodicFromWindow(degree_, r.knots, r.points, w.start, w.period);
    return fromHomogeneous(degree_, std::move(c.knots), c.points, isRational(), true);
}

template <int Dim>
BSplineCurve<Dim> BSplineCurve<Dim>::elevate(int times) const
{
    if (!closed_) {
        KnotsAndPoints r = elevateDegree(degree_, knots_, homogeneous(), times);
        return fromHomogeneous(degree_ + times, std::move(r.knots), r.points, isRational());
    }
    const PeriodicWindow w = periodicExtension(degree_, knots_, homogeneous(), kWindowPeriods);
    KnotsAndPoints r = elevateDegree(degree_, w.knots, w.points, times);
    KnotsAndPoints c = periodicFromWindow(degree_ + times, r.knots, r.points, w.start, w.period);
    return fromHomogeneous(degree_ + times, std::move(c.knots), c.points, isRational(), true);
}

template <int Dim>
BSplineCurve<Dim> BSplineCurve<Dim>::removeKnots(double tolerance, int* removed) const
{
    if (!std::isfinite(tolerance) || tolerance < 0) throw GeometryError("tolerance: must be a finite number >= 0");
    KnotVector knots = knots_;
    ControlMatrix pts = homogeneous();
    double budget = removalBudget(pts, Dim, isRational(), tolerance);
    const int groupSize = static_cast<int>(pts.cols());
    if (!closed_) {
        const int count = removeKnotsWithinBudget(degree_, knots, pts, budget, groupSize);
        if (removed) *removed = count;
        return fromHomogeneous(degree_, std::move(knots), pts, isRational());
    }
    // Closed: remove a knot of the middle period of a periodic window, then its copies one period to
    // either side (the same local computation, so the same error, counted once), and read the closed
    // curve back from the middle period.
    const double start = domainStart(), T = domainEnd() - start;
    PeriodicWindow w = periodicExtension(degree_, knots, pts, kWindowPeriods);
    int unique = pointCount() - degree_;
    int count = 0;
    bool progress = true;
    while (progress && budget > 0) {
        progress = false;
        std::vector<double> candidates;
        for (double k : interiorBreakpoints(degree_, w.knots))
            if (k >= start && k < start + T) candidates.push_back(k);
        for (double u : candidates) {
            if (unique <= degree_ + 1) break;
            const RemovalResult r = removeKnot(degree_, w.knots, w.points, u, 1, budget, groupSize);
            if (r.removed == 0) continue;
            for (double copy : {u - T, u + T}) {
                const auto it = std::min_element(w.knots.begin(), w.knots.end(), [&](double x, double y) {
                    return std::abs(x - copy) < std::abs(y - copy);
                });
                removeKnot(degree_, w.knots, w.points, *it, 1, std::numeric_limits<double>::infinity(), groupSize);
            }
            budget -= r.errorBound;
            ++count;
            --unique;
            progress = true;
        }
    }
    if (removed) *removed = count;
    KnotsAndPoints c = periodicFromWindow(degree_, w.knots, w.points, start, T);
    return fromHomogeneous(degree_, std::move(c.knots), c.points, isRational(), true);
}

template <int Dim>
BSplineCurve<Dim> BSplineCurve<Dim>::clamped() const
{
    if (closed_) return openAt(domainStart());
    KnotsAndPoints c = clampEnds(degree_, knots_, homogeneous());
    return fromHomogeneous(degree_, std::move(c.knots), c.points, isRational());
}

template <int Dim>
std::pair<BSplineCurve<Dim>, BSplineCurve<Dim>> BSplineCurve<Dim>::split(double u) const
{
    if (closed_) throw GeometryError("closed: a closed curve has no two pieces; use openAt or extract");
    if (!(u > domainStart() && u < domainEnd())) {
        std::ostringstream msg;
        msg << "parameter: split needs u strictly inside (" << domainStart() << ", " << domainEnd() << "), got " << u;
        throw GeometryError(msg.str());
    }
    return {extract(domainStart(), u), extract(u, domainEnd())};
}

template <int Dim>
BSplineCurve<Dim> BSplineCurve<Dim>::extract(double u0, double u1) const
{
    if (!std::isfinite(u0) || !std::isfinite(u1)) throw GeometryError("parameter: not a finite number");
    if (!closed_) {
        if (!(u0 < u1) || u0 < domainStart() || u1 > domainEnd()) {
            std::ostringstream msg;
            msg << "parameter: extract needs domainStart <= u0 < u1 <= domainEnd, got [" << u0 << ", " << u1
                << "] on [" << domainStart() << ", " << domainEnd() << "]";
            throw GeometryError(msg.str());
        }
        KnotsAndPoints r = extractSegment(degree_, knots_, homogeneous(), u0, u1);
        return fromHomogeneous(degree_, std::move(r.knots), r.points, isRational());
    }
    const double T = domainEnd() - domainStart();
    const double a = normalizeParameter(u0);
    double len = u1 - u0;
    if (len <= 0) {
        const double b = normalizeParameter(u1);
        len = b > a ? b - a : b - a + T;
    }
    if (!(len > 0 && len <= T * (1 + 1e-14))) {
        throw GeometryError("parameter: an extract of a closed curve must span at most one period");
    }
    len = std::min(len, T);
    // One period on each side of the domain covers [a, a + len] for any a in [start, end).
    const PeriodicWindow w = periodicExtension(degree_, knots_, homogeneous(), 1);
    KnotsAndPoints r = extractSegment(degree_, w.knots, w.points, a, a + len);
    return fromHomogeneous(degree_, std::move(r.knots), r.points, isRational());
}

template <int Dim>
BSplineCurve<Dim> BSplineCurve<Dim>::openAt(double u) const
{
    if (!closed_) throw GeometryError("closed: openAt needs a closed curve");
    const double a = normalizeParameter(u);
    return extract(a, a + (domainEnd() - domainStart()));
}

template <int Dim>
double BSplineCurve<Dim>::controlSize() const
{
    Point lo = points_.front(), hi = points_.front();
    for (const Point& q : points_) {
        lo = lo.cwiseMin(q);
        hi = hi.cwiseMax(q);
    }
    // stableNorm: norm() squares, and overflows to infinity for coordinates beyond ~1e154.
    return (hi - lo).stableNorm();
}

template <int Dim>
bool BSplineCurve<Dim>::isCollapsed() const
{
    Point lo = points_.front(), hi = points_.front();
    double magnitude = 0.0;
    for (const Point& q : points_) {
        lo = lo.cwiseMin(q);
        hi = hi.cwiseMax(q);
        magnitude = std::max(magnitude, q.cwiseAbs().maxCoeff());
    }
    return (hi - lo).maxCoeff() <= kCollapsedRelative * magnitude;
}

template <int Dim>
BSplineCurve<Dim> makeClosedUniform(int degree, const std::vector<typename BSplineCurve<Dim>::Point>& unique,
                                    const std::vector<double>& uniqueWeights)
{
    const int N = static_cast<int>(unique.size());
    if (degree < 1) throw GeometryError("degree: must be at least 1");
    if (N < degree + 1) throw GeometryError("points: a closed curve of degree d needs at least d + 1 distinct points");
    std::vector<typename BSplineCurve<Dim>::Point> pts(unique);
    std::vector<double> w(uniqueWeights);
    for (int i = 0; i < degree; ++i) {
        pts.push_back(unique[i]);
        if (!w.empty()) w.push_back(uniqueWeights[i]);
    }
    return BSplineCurve<Dim>(degree, periodicUniformKnots(degree, N, 0.0, N), std::move(pts), std::move(w), true);
}

template <int Dim>
BSplineCurve<Dim> makeClampedUniform(int degree, const std::vector<typename BSplineCurve<Dim>::Point>& points,
                                     const std::vector<double>& weights)
{
    const int n = static_cast<int>(points.size()) - 1;
    if (degree < 1 || n < degree) throw GeometryError("points: degree d needs at least d + 1 points");
    KnotVector knots(static_cast<size_t>(n + degree + 2), 0.0);
    const int spans = n - degree + 1;
    for (int i = 0; i <= n + degree + 1; ++i) {
        if (i <= degree) knots[i] = 0.0;
        else if (i > n) knots[i] = 1.0;
        else knots[i] = static_cast<double>(i - degree) / spans;
    }
    return BSplineCurve<Dim>(degree, std::move(knots), points, weights);
}

template class BSplineCurve<2>;
template class BSplineCurve<3>;
template BSplineCurve<2> makeClosedUniform<2>(int, const std::vector<Eigen::Vector2d>&, const std::vector<double>&);
template BSplineCurve<3> makeClosedUniform<3>(int, const std::vector<Eigen::Vector3d>&, const std::vector<double>&);
template BSplineCurve<2> makeClampedUniform<2>(int, const std::vector<Eigen::Vector2d>&, const std::vector<double>&);
template BSplineCurve<3> makeClampedUniform<3>(int, const std::vector<Eigen::Vector3d>&, const std::vector<double>&);

}  // namespace sculptline::solvers
