#pragma once
// Internal helpers shared by the over-sketching methods: arc length with wrapping, the break
// points of seed 001 §3 and the blended target polyline h̄. Not part of the public API.
#include "solvers/bspline/arc_length.h"
#include "solvers/bspline/curvature.h"
#include "solvers/bspline/geometry_error.h"
#include "solvers/editing/constrained_fit.h"
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

/// Largest curvature of the stroke at the scale of 1/40 of its length: turning angle between
/// successive chords of the stroke resampled by arc length, over the chord length (a pen's jitter
/// below that scale does not count).
template <int Dim>
double strokeCurvature(const StrokeOnCurve<Dim>& st)
{
    constexpr int kChords = 40;
    const auto q = resampleByArcLength<Dim>(st.points, kChords + 1);
    const double step = st.length / kChords;
    double worst = 0.0;
    for (int i = 1; i < kChords; ++i) {
        const Eigen::Matrix<double, Dim, 1> a = q[i] - q[i - 1], b = q[i + 1] - q[i];
        if (a.norm() == 0.0 || b.norm() == 0.0) continue;
        worst = std::max(worst, std::acos(std::clamp(a.dot(b) / (a.norm() * b.norm()), -1.0, 1.0)) / step);
    }
    return worst;
}

/// Largest curvature of the curve sampled on [u0, u1] (closed: may cross the seam).
template <int Dim>
double curveCurvature(const BSplineCurve<Dim>& c, double u0, double u1)
{
    constexpr int kSamples = 64;
    double worst = 0.0;
    for (int i = 0; i <= kSamples; ++i) worst = std::max(worst, curvature(c, c.normalizeParameter(u0 + (u1 - u0) * i / kSamples)));
    return worst;
}

// Transition length for a fair blend (this file's addition to seed 001 §3). The blend B of
// buildTarget moves the curve sideways by δ = |C(u_s) - h_0| and turns it by θ (curve tangent vs
// stroke tangent) over a length d; its extra curvature is about 6δ/d² (a quintic step's second
// derivative peaks at 5.8/d²) plus 4θ/d (a turn by θ over d with zero end curvature). Seed 001's
// d = 3δ gives 2/(3δ), a spike that grows as the stroke starts closer to the curve (measured: 2.3
// against the curve's 0.3 for δ = 0.1). We take the d that keeps that extra curvature within
// κ_ref = max(stroke's, curve's own curvature over the edit, 2/length): 6δ/d² + 4θ/d = κ_ref,
// d = (4θ + sqrt(16θ² + 24δκ_ref)) / (2κ_ref), at most kFairTransitionMax of the stroke's length
// (a stroke crossing a straight line at an angle would otherwise ask for an unbounded blend), and
// never shorter than the seed's d.
constexpr double kFairTransitionMax = 0.5;

inline double fairTransition(double delta, double theta, double kappaRef)
{
    return (4.0 * theta + std::sqrt(16.0 * theta * theta + 24.0 * delta * kappaRef)) / (2.0 * kappaRef);
}

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
    {
        const double kappaRef = std::max({strokeCurvature(st),
                                          curveCurvature(c, len.parameterAt(len.lengthAt(b.us) - b.d1),
                                                         len.parameterAt(len.lengthAt(b.ue) + b.d2)),
                                          2.0 / st.length});
        auto turn = [&](double u, bool atStart) {
            const Eigen::Matrix<double, Dim, 1> t = c.derivatives(u, 1)[1];
            const Eigen::Matrix<double, Dim, 1> s = strokeTangent(st, atStart);
            return t.norm() > 0.0 ? std::acos(std::clamp(t.normalized().dot(s), -1.0, 1.0)) : 0.0;
        };
        const double cap = kFairTransitionMax * st.length;
        b.d1 = std::max(b.d1, std::min(cap, fairTransition((c.evaluate(b.us) - h.front()).norm(), turn(b.us, true),
                                                           kappaRef)));
        b.d2 = std::max(b.d2, std::min(cap, fairTransition((c.evaluate(b.ue) - h.back()).norm(), turn(b.ue, false),
                                                           kappaRef)));
    }
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

/// Seed 001 §3: h̄ = E^l ∪ B^l ∪ h ∪ B^r ∪ E^r on [t_k, t_l]. E keeps the curve's own parameters;
/// the middle gets chord-length parameters on [u_ps, u_pe]. The blends B: the seed (after Baudel
/// 1994) blends the curve into the line tangent to the stroke at its end with a smoothstep weight;
/// that line leaves the curve at the angle θ between curve and stroke, so over a blend of length d
/// the target strays dθ from both and its curvature peaks near 6(δ + dθ)/d² (measured: 2.1 where
/// the stroke has 0.8). We follow the curve itself on [u_ps, u_s] and add two quintic Hermite
/// terms (x from 0 at u_ps to 1 at u_s): H5(x)·D moves it by D = h_0 - C(u_s) and H4(x)·V turns its
/// end tangent onto the stroke's (V = |C'(u_s)|(u_s - u_ps)(t_stroke - t_curve)). Both vanish with
/// their first two derivatives at u_ps, so B meets the kept curve G2, ends at h_0 tangent to the
/// stroke, and adds at most 5.8δ/d² + 4θ/d to the curve's own curvature (fairTransition's model).
template <int Dim>
Target<Dim> buildTarget(const BSplineCurve<Dim>& c, const CurveLengths<Dim>& /*len*/, const StrokeOnCurve<Dim>& st,
                        const Breaks& b)
{
    using Pt = Eigen::Matrix<double, Dim, 1>;
    constexpr int K = 24;  // samples per piece of h̄ (E^l, B^l, B^r, E^r): enough to pin a few spans
    Target<Dim> t;
    for (int i = 0; i < K && b.ups > b.tk; ++i) {
        const double u = b.tk + (b.ups - b.tk) * i / K;
        t.params.push_back(u);
        t.points.push_back(c.evaluate(u));
    }
    std::vector<Pt> mid;
    const Pt h0 = st.points.front(), hm = st.points.back();
    // Quintic Hermite basis functions used by the blends (value 1 or slope 1 at one end, all else 0).
    auto h0Basis = [](double x) { return 1.0 - x * x * x * (10.0 - 15.0 * x + 6.0 * x * x); };
    auto h1Basis = [](double x) { return x - x * x * x * (6.0 - 8.0 * x + 3.0 * x * x); };
    auto h4Basis = [](double x) { return -x * x * x * (4.0 - 7.0 * x + 3.0 * x * x); };
    auto h5Basis = [](double x) { return x * x * x * (10.0 - 15.0 * x + 6.0 * x * x); };
    auto turnTo = [&](double u, double du, const Pt& strokeDir) {
        const Pt d1 = c.derivatives(c.normalizeParameter(u), 1)[1];
        const double v = d1.norm();
        return v > 0.0 ? Pt(v * du * (strokeDir - d1 / v)) : Pt(Pt::Zero());
    };
    if (!b.leftExtend && b.us > b.ups) {
        const double du = b.us - b.ups;
        const Pt D = h0 - c.evaluate(b.us), V = turnTo(b.us, du, strokeTangent(st, true));
        for (int i = 0; i < K; ++i) {
            const double x = double(i) / K;
            mid.push_back(c.evaluate(b.ups + du * x) + h5Basis(x) * D + h4Basis(x) * V);
        }
    }
    mid.insert(mid.end(), st.points.begin(), st.points.end());
    if (!b.rightExtend && b.upe > b.ue) {
        const double du = b.upe - b.ue;
        const Pt D = hm - c.evaluate(b.ue), V = turnTo(b.ue, du, strokeTangent(st, false));
        for (int i = 1; i <= K; ++i) {
            const double x = double(i) / K;
            mid.push_back(c.evaluate(b.ue + du * x) + h0Basis(x) * D + h1Basis(x) * V);
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
