#pragma once
// Internal helpers shared by the over-sketching methods: arc length with wrapping, the break
// points of seed 001 §3 and the blended target polyline h̄. Not part of the public API.
#include "solvers/bspline/arc_length.h"
#include "solvers/bspline/geometry_error.h"
#include "solvers/editing/oversketch.h"

#include <algorithm>
#include <cmath>

namespace sculptline::solvers::editing::detail {

/// Arc length s(u) and its inverse; closed curves continue periodically beyond their domain.
template <int Dim>
class CurveLengths {
public:
    explicit CurveLengths(const BSplineCurve<Dim>& c)
        : table_(c), closed_(c.isClosed()), a_(c.domainStart()), T_(c.domainEnd() - c.domainStart())
    {
    }
    double total() const { return table_.totalLength(); }
    double lengthAt(double u) const
    {
        if (!closed_) return table_.lengthAt(std::clamp(u, a_, a_ + T_));
        const double q = std::floor((u - a_) / T_);
        return table_.lengthAt(std::clamp(u - q * T_, a_, a_ + T_)) + q * total();
    }
    double parameterAt(double s) const
    {
        if (!closed_) return table_.parameterAt(std::clamp(s, 0.0, total()));
        const double q = std::floor(s / total());
        return table_.parameterAt(s - q * total()) + q * T_;
    }

private:
    ArcLengthParameterization<Dim> table_;
    bool closed_;
    double a_, T_;
};

/// Largest knot value <= u (below = true) or smallest >= u, periodic for closed curves.
template <int Dim>
double nearestKnot(const BSplineCurve<Dim>& c, double u, bool below)
{
    const auto& k = c.knots();
    const int p = c.degree();
    const int last = c.pointCount();  // index of the domain end knot
    const double a = c.domainStart(), T = c.domainEnd() - a;
    double shift = 0.0;
    if (c.isClosed()) {
        shift = std::floor((u - a) / T) * T;
        u -= shift;
    }
    u = std::clamp(u, a, a + T);
    if (below) {
        const auto it = std::upper_bound(k.begin() + p, k.begin() + last + 1, u);
        return *(it - 1) + shift;
    }
    const auto it = std::lower_bound(k.begin() + p, k.begin() + last + 1, u);
    return *it + shift;
}

/// Seed 001 §3: u_s, u_e, u_ps = u_s - d1, u_pe = u_e + d2 (arc length), t_k <= u_ps, t_l >= u_pe.
struct Breaks {
    double us = 0, ue = 0, ups = 0, upe = 0, tk = 0, tl = 0, d1 = 0, d2 = 0;
    bool leftFree = false, rightFree = false;      // the new curve's end is pinned to h̄'s end
    bool leftExtend = false, rightExtend = false;  // the stroke runs past that end of the curve
    bool tooWide = false;                          // closed: [t_k, t_l] rounded out to knots spans a whole period
};

template <int Dim>
Breaks breakPoints(const BSplineCurve<Dim>& c, const CurveLengths<Dim>& len, const StrokeOnCurve<Dim>& st,
                   const OversketchOptions& o)
{
    Breaks b;
    b.us = st.us;
    b.ue = st.ue;
    const auto& h = st.points;
    b.d1 = std::max(o.transitionFactor * (c.evaluate(b.us) - h.front()).norm(), o.minTransition * st.length);
    b.d2 = std::max(o.transitionFactor * (c.evaluate(b.ue) - h.back()).norm(), o.minTransition * st.length);
    const double a = c.domainStart(), e = c.domainEnd();
    if (c.isClosed()) {
        // The transitions share what the stroke leaves of the loop; they are shortened to half of
        // it at most so that [t_k, t_l] (rounded out to knots) can stay within one period.
        const double free = len.total() - (len.lengthAt(b.ue) - len.lengthAt(b.us));
        if (free <= 0.0) throw GeometryError("stroke: the over-sketch covers the whole closed curve");
        const double room = 0.5 * free;
        if (b.d1 + b.d2 > room) {
            const double f = room / (b.d1 + b.d2);
            b.d1 *= f;
            b.d2 *= f;
        }
    }
    const double offTol = o.tolerance * st.length;  // "on the curve's end" within the fit tolerance
    const double uTol = 1e-9 * (e - a);
    if (!c.isClosed()) {
        b.leftExtend = b.us <= a + uTol && (h.front() - c.evaluate(a)).norm() > offTol;
        b.rightExtend = b.ue >= e - uTol && (h.back() - c.evaluate(e)).norm() > offTol;
    }
    b.ups = b.leftExtend ? a : len.parameterAt(len.lengthAt(b.us) - b.d1);
    b.upe = b.rightExtend ? e : len.parameterAt(len.lengthAt(b.ue) + b.d2);
    b.tk = nearestKnot(c, b.ups, true);
    b.tl = nearestKnot(c, b.upe, false);
    if (!c.isClosed()) {
        b.leftFree = b.tk <= a;
        b.rightFree = b.tl >= e;
    }
    b.tooWide = c.isClosed() && b.tl - b.tk >= e - a;
    return b;
}

template <int Dim>
struct Target {
    std::vector<double> params;
    std::vector<Eigen::Matrix<double, Dim, 1>> points;
};

constexpr double kTangentSpan = 0.01;

/// Unit direction of the stroke leaving its first point (forward = true) or arriving at its last,
/// measured over kTangentSpan of its length (short enough to be the tangent of a curved stroke,
/// long enough that single-sample pen jitter at the tip does not set it).
template <int Dim>
Eigen::Matrix<double, Dim, 1> strokeTangent(const StrokeOnCurve<Dim>& st, bool atStart)
{
    const auto& h = st.points;
    const int n = static_cast<int>(h.size());
    for (int i = 1; i < n; ++i) {
        const auto& q = atStart ? h[i] : h[n - 1 - i];
        const auto& e = atStart ? h.front() : h.back();
        if ((q - e).norm() >= kTangentSpan * st.length || i == n - 1) {
            return atStart ? Eigen::Matrix<double, Dim, 1>((q - e).normalized())
                           : Eigen::Matrix<double, Dim, 1>((e - q).normalized());
        }
    }
    return Eigen::Matrix<double, Dim, 1>::UnitX();
}

/// Seed 001 §3: h̄ = E^l ∪ B^l ∪ h ∪ B^r ∪ E^r on [t_k, t_l]. E keeps the curve's own parameters;
/// B blends the curve into the line L tangent to the stroke at its end, of length d (Baudel 1994),
/// with the C1 smoothstep weight 3t² - 2t³; the middle gets chord-length parameters on [u_ps, u_pe].
template <int Dim>
Target<Dim> buildTarget(const BSplineCurve<Dim>& c, const CurveLengths<Dim>& /*len*/, const StrokeOnCurve<Dim>& st,
                        const Breaks& b)
{
    using Pt = Eigen::Matrix<double, Dim, 1>;
    constexpr int K = 24;  // samples per piece of h̄ (E^l, B^l, B^r, E^r): enough to pin a few spans
    Target<Dim> t;
    auto smooth = [](double x) { return x * x * (3.0 - 2.0 * x); };
    for (int i = 0; i < K && b.ups > b.tk; ++i) {
        const double u = b.tk + (b.ups - b.tk) * i / K;
        t.params.push_back(u);
        t.points.push_back(c.evaluate(u));
    }
    std::vector<Pt> mid;
    const Pt h0 = st.points.front(), hm = st.points.back();
    if (!b.leftExtend && b.us > b.ups) {
        const Pt tan = strokeTangent(st, true);
        for (int i = 0; i < K; ++i) {
            const double x = double(i) / K;
            const Pt line = h0 - (1.0 - x) * b.d1 * tan;
            mid.push_back((1.0 - smooth(x)) * c.evaluate(b.ups + (b.us - b.ups) * x) + smooth(x) * line);
        }
    }
    mid.insert(mid.end(), st.points.begin(), st.points.end());
    if (!b.rightExtend && b.upe > b.ue) {
        const Pt tan = strokeTangent(st, false);
        for (int i = 1; i <= K; ++i) {
            const double x = double(i) / K;
            const Pt line = hm + x * b.d2 * tan;
            mid.push_back(smooth(1.0 - x) * line + (1.0 - smooth(1.0 - x)) * c.evaluate(b.ue + (b.upe - b.ue) * x));
        }
    }
    std::vector<double> chord(mid.size(), 0.0);
    for (size_t i = 1; i < mid.size(); ++i) chord[i] = chord[i - 1] + (mid[i] - mid[i - 1]).norm();
    // Parameters of the middle: du/ds runs from the curve's own 1/|C'| at u_ps to that at u_pe (plus
    // a parabolic bump so that the total is u_pe - u_ps), so the parameter speed has no jump where
    // E^l and E^r (which keep the curve's parameters) meet the middle; a jump there forces the C2
    // fit into a visible wiggle. Falls back to plain chord length if the bump would go negative.
    const double lm = chord.back();
    const double a0 = 1.0 / std::max(c.derivatives(b.ups, 1)[1].norm(), 1e-300);
    const double a1 = 1.0 / std::max(c.derivatives(b.upe, 1)[1].norm(), 1e-300);
    const double bumpC = lm > 0.0 ? 1.5 * ((b.upe - b.ups) / lm - 0.5 * (a0 + a1)) : 0.0;
    const bool smoothSpeed = !b.leftExtend && !b.rightExtend && std::min(a0, a1) + std::min(0.0, bumpC) > 0.0;
    for (size_t i = 0; i < mid.size(); ++i) {
        const double sg = lm > 0 ? chord[i] / lm : 0.0;
        const double f =
            smoothSpeed
                ? lm * (a0 * sg + 0.5 * (a1 - a0) * sg * sg + bumpC * (2.0 * sg * sg - 4.0 / 3.0 * sg * sg * sg))
                : (b.upe - b.ups) * sg;
        t.params.push_back(b.ups + f);
        t.points.push_back(mid[i]);
    }
    for (int i = 1; i <= K && b.tl > b.upe; ++i) {
        const double u = b.upe + (b.tl - b.upe) * i / K;
        t.params.push_back(u);
        t.points.push_back(c.evaluate(u));
    }
    return t;
}

/// A closed curve with the spans outside [span.first, span.second] split `times` times (exact knot
/// insertion), so that the edit's support fits inside one period. A span reaching outside is split
/// at the middle of its outside part, so that a short uncovered arc inside one long span (a stroke
/// around most of the loop) gets knots too.
template <int Dim>
BSplineCurve<Dim> refineOutside(const BSplineCurve<Dim>& c, std::pair<double, double> span, int times)
{
    BSplineCurve<Dim> r = c;
    const double T = c.domainEnd() - c.domainStart();
    const double L = span.second - span.first;  // covered length, [0, L] in coordinates relative to span.first
    for (int k = 0; k < times; ++k) {
        std::vector<double> mids;
        const auto& kn = r.knots();
        for (int i = r.degree(); i < r.pointCount(); ++i) {
            if (kn[i + 1] <= kn[i]) continue;
            const double rel0 = std::fmod(kn[i] - span.first + 4.0 * T, T), rel1 = rel0 + kn[i + 1] - kn[i];
            // Outside parts (L, T) and (L + T, 2T) of [rel0, rel1]; the longer one is split.
            const double a1 = std::max(rel0, L), b1 = std::min(rel1, T);
            const double a2 = std::max(rel0, L + T), b2 = std::min(rel1, 2.0 * T);
            const bool useFirst = b1 - a1 >= b2 - a2;
            const double lo = useFirst ? a1 : a2, hi = useFirst ? b1 : b2;
            if (hi - lo > 1e-9 * T) mids.push_back(kn[i] + (0.5 * (lo + hi) - rel0));
        }
        std::sort(mids.begin(), mids.end());
        if (mids.empty()) break;
        r = r.refine(mids);
    }
    return r;
}

}  // namespace sculptline::solvers::editing::detail
