#include "solvers/bspline/arc_length.h"

#include "solvers/bspline/geometry_error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace sculptline::solvers {
namespace {

// 7-point Gauss-Legendre nodes and weights on [-1, 1] (Abramowitz & Stegun, Table 25.4).
constexpr std::array<double, 7> kNodes = {0.0,
                                          0.4058451513773971669066064,
                                          -0.4058451513773971669066064,
                                          0.7415311855993944398638648,
                                          -0.7415311855993944398638648,
                                          0.9491079123427585245261897,
                                          -0.9491079123427585245261897};
constexpr std::array<double, 7> kWeights = {0.4179591836734693877551020, 0.3818300505051189449503698,
                                            0.3818300505051189449503698, 0.2797053914892766679014678,
                                            0.2797053914892766679014678, 0.1294849661688696932706114,
                                            0.1294849661688696932706114};

// Recursion limit of the adaptive quadrature. With the absolute floor below, a smooth span stops
// after a few levels; what still recurses is a span whose speed |C'| has a kink (a cusp, where C'
// vanishes) and Gauss-Legendre converges only as h^2 there. Depth 20 resolves 1e-6 of a span, and
// the evaluation budget bounds the work of one span whatever its shape.
constexpr int kMaxDepth = 20;
// At most this many Gauss-Legendre panels per knot span (7 speed evaluations each): about 1 ms.
constexpr int kMaxPanelsPerSpan = 2048;
// Absolute floor of the quadrature error, in ulps of the curve's coordinates: C' is a difference
// of control points of magnitude M divided by knot spacings, so each speed sample carries a
// round-off of a few p * eps * M / du, and a panel of width h an error of about p * eps * M * h/du.
// Summed over a span that is a few eps * M * p, whatever the refinement: asking for less than this
// (a curve whose control points agree to 1e-14 of their magnitude, where |C'| is pure round-off)
// can never be met, and the relative tolerance alone recursed 30 levels deep on every panel (2^30
// panels per span). 64 leaves a margin for the dozen roundings of each evaluation (de Boor's
// triangle, the rational quotient, the norm).
constexpr double kRoundOffUlps = 64.0;

template <int Dim>
double speed(const BSplineCurve<Dim>& c, double u)
{
    return c.derivatives(u, 1)[1].norm();
}

template <int Dim>
double gauss(const BSplineCurve<Dim>& c, double a, double b)
{
    const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
    double sum = 0.0;
    for (size_t i = 0; i < kNodes.size(); ++i) sum += kWeights[i] * speed(c, mid + half * kNodes[i]);
    return sum * half;
}

// Adaptive Gauss-Legendre: the relative tolerance halves with each level (the error sums over
// panels), the absolute floor does not (it is the round-off of the curve's magnitude, the same in
// every panel); `budget` counts the panels the span may still split into.
template <int Dim>
double adaptive(const BSplineCurve<Dim>& c, double a, double b, double whole, double tol, double floor, int depth,
                int& budget)
{
    const double mid = 0.5 * (a + b);
    const double left = gauss(c, a, mid), right = gauss(c, mid, b);
    if (depth >= kMaxDepth || budget <= 0 || std::abs(left + right - whole) <= std::max(tol, floor)) return left + right;
    budget -= 2;
    return adaptive(c, a, mid, left, 0.5 * tol, floor, depth + 1, budget) +
           adaptive(c, mid, b, right, 0.5 * tol, floor, depth + 1, budget);
}

// The largest magnitude of the curve's (Cartesian) control coordinates: the scale of its round-off.
template <int Dim>
double coordinateMagnitude(const BSplineCurve<Dim>& c)
{
    double m = 0.0;
    for (const auto& q : c.points()) m = std::max(m, q.cwiseAbs().maxCoeff());
    return m;
}

// Breakpoints of the curve covering [u0, u1], unwrapped for closed curves.
template <int Dim>
std::vector<double> breakpoints(const BSplineCurve<Dim>& c, double u0, double u1)
{
    std::vector<double> out{u0};
    const int p = c.degree();
    const double a = c.domainStart(), b = c.domainEnd(), T = b - a;
    std::vector<double> base(c.knots().begin() + p, c.knots().begin() + c.pointCount() + 1);
    base.erase(std::unique(base.begin(), base.end()), base.end());
    const double qLo = c.isClosed() ? std::floor((u0 - a) / T) : 0.0;
    const double qHi = c.isClosed() ? std::floor((u1 - a) / T) : 0.0;
    for (double q = qLo; q <= qHi; q += 1.0) {
        for (double k : base) {
            const double v = k + q * T;
            if (v > u0 && v < u1) out.push_back(v);
        }
    }
    out.push_back(u1);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

template <int Dim>
double spanLength(const BSplineCurve<Dim>& c, double a, double b, double floor)
{
    const double whole = gauss(c, a, b);
    int budget = kMaxPanelsPerSpan;
    return adaptive(c, a, b, whole, kArcLengthRelativeTolerance * whole, floor, 0, budget);
}

template <int Dim>
double roundOffFloor(const BSplineCurve<Dim>& c)
{
    return kRoundOffUlps * std::numeric_limits<double>::epsilon() * c.degree() * coordinateMagnitude(c);
}

}  // namespace

template <int Dim>
double arcLength(const BSplineCurve<Dim>& c, double u0, double u1)
{
    if (!std::isfinite(u0) || !std::isfinite(u1)) throw GeometryError("parameter: not a finite number");
    if (u1 < u0) throw GeometryError("parameter: arc length needs u0 <= u1");
    if (!c.isClosed()) {
        u0 = c.normalizeParameter(u0);
        u1 = c.normalizeParameter(u1);
    }
    const std::vector<double> br = breakpoints(c, u0, u1);
    const double floor = roundOffFloor(c);
    double total = 0.0;
    for (size_t i = 0; i + 1 < br.size(); ++i) total += spanLength(c, br[i], br[i + 1], floor);
    return total;
}

template <int Dim>
double arcLength(const BSplineCurve<Dim>& c)
{
    return arcLength(c, c.domainStart(), c.domainEnd());
}

template <int Dim>
ArcLengthParameterization<Dim>::ArcLengthParameterization(const BSplineCurve<Dim>& curve)
    : curve_(curve), floor_(roundOffFloor(curve))
{
    breaks_ = breakpoints(curve, curve.domainStart(), curve.domainEnd());
    cumulative_.assign(1, 0.0);
    for (size_t i = 0; i + 1 < breaks_.size(); ++i)
        cumulative_.push_back(cumulative_.back() + spanLength(curve, breaks_[i], breaks_[i + 1], floor_));
}

template <int Dim>
double ArcLengthParameterization<Dim>::lengthAt(double u) const
{
    u = std::clamp(u, breaks_.front(), breaks_.back());
    const size_t i = std::min<size_t>(std::upper_bound(breaks_.begin(), breaks_.end(), u) - breaks_.begin() - 1,
                                      breaks_.size() - 2);
    return cumulative_[i] + (u > breaks_[i] ? spanLength(curve_, breaks_[i], u, floor_) : 0.0);
}

template <int Dim>
double ArcLengthParameterization<Dim>::parameterAt(double s) const
{
    if (!std::isfinite(s)) throw GeometryError("length: not a finite number");
    if (s <= 0) return breaks_.front();
    if (s >= totalLength()) return breaks_.back();
    const size_t i = std::upper_bound(cumulative_.begin(), cumulative_.end(), s) - cumulative_.begin() - 1;
    double lo = breaks_[i], hi = breaks_[i + 1];
    const double target = s - cumulative_[i];
    const double segment = cumulative_[i + 1] - cumulative_[i];
    double u = lo + (hi - lo) * (target / segment);
    // Newton on g(u) = len(breaks_[i], u) - target with a bisection fallback (g is monotone).
    // Never below the quadrature's round-off floor: on a curve whose speed is round-off noise the
    // relative target cannot be met, and bisection then ends the loop at the resolution of u.
    const double tol = std::max(kArcLengthRelativeTolerance * totalLength() * 10, floor_);
    for (int iter = 0; iter < 100; ++iter) {
        const double g = spanLength(curve_, breaks_[i], u, floor_) - target;
        if (std::abs(g) <= tol) break;
        if (g > 0) hi = u;
        else lo = u;
        const double sp = speed(curve_, u);
        double next = sp > 0 ? u - g / sp : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (hi - lo <= 1e-15 * std::max(1.0, std::abs(u))) break;
        u = next;
    }
    return u;
}

template double arcLength<2>(const BSplineCurve<2>&, double, double);
template double arcLength<3>(const BSplineCurve<3>&, double, double);
template double arcLength<2>(const BSplineCurve<2>&);
template double arcLength<3>(const BSplineCurve<3>&);
template class ArcLengthParameterization<2>;
template class ArcLengthParameterization<3>;

}  // namespace sculptline::solvers
