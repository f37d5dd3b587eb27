#include "solvers/bspline/arc_length.h"

#include "solvers/bspline/geometry_error.h"

#include <algorithm>
#include <array>
#include <cmath>

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

// Recursion limit of the adaptive quadrature: 2^-30 of a span is below any meaningful resolution.
constexpr int kMaxDepth = 30;

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

template <int Dim>
double adaptive(const BSplineCurve<Dim>& c, double a, double b, double whole, double tol, int depth)
{
    const double mid = 0.5 * (a + b);
    const double left = gauss(c, a, mid), right = gauss(c, mid, b);
    if (depth >= kMaxDepth || std::abs(left + right - whole) <= tol) return left + right;
    return adaptive(c, a, mid, left, 0.5 * tol, depth + 1) + adaptive(c, mid, b, right, 0.5 * tol, depth + 1);
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
double spanLength(const BSplineCurve<Dim>& c, double a, double b)
{
    const double whole = gauss(c, a, b);
    return adaptive(c, a, b, whole, kArcLengthRelativeTolerance * std::max(whole, 1e-300), 0);
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
    double total = 0.0;
    for (size_t i = 0; i + 1 < br.size(); ++i) total += spanLength(c, br[i], br[i + 1]);
    return total;
}

template <int Dim>
double arcLength(const BSplineCurve<Dim>& c)
{
    return arcLength(c, c.domainStart(), c.domainEnd());
}

template <int Dim>
ArcLengthParameterization<Dim>::ArcLengthParameterization(const BSplineCurve<Dim>& curve) : curve_(curve)
{
    breaks_ = breakpoints(curve, curve.domainStart(), curve.domainEnd());
    cumulative_.assign(1, 0.0);
    for (size_t i = 0; i + 1 < breaks_.size(); ++i)
        cumulative_.push_back(cumulative_.back() + spanLength(curve, breaks_[i], breaks_[i + 1]));
}

template <int Dim>
double ArcLengthParameterization<Dim>::lengthAt(double u) const
{
    u = std::clamp(u, breaks_.front(), breaks_.back());
    const size_t i = std::min<size_t>(std::upper_bound(breaks_.begin(), breaks_.end(), u) - breaks_.begin() - 1,
                                      breaks_.size() - 2);
    return cumulative_[i] + (u > breaks_[i] ? spanLength(curve_, breaks_[i], u) : 0.0);
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
    const double tol = kArcLengthRelativeTolerance * std::max(totalLength(), 1e-300) * 10;
    for (int iter = 0; iter < 100; ++iter) {
        const double g = spanLength(curve_, breaks_[i], u) - target;
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
