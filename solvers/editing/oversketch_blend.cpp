// blend over-sketching: thesis 002 §4.2 (seed 003 §4): control point replacement.
//
// Reading of the garbled formulas, chosen here:
// - eq. 4-23 y'_i = y_i - (1 - scale)·d_i, with d_i the vector from y_i's projection onto C1 to
//   y_i: y'_i = proj(y_i) + scale·(y_i - proj(y_i)). scale 1 follows the stroke, 0 keeps C1.
// - eq. 4-24 M: "the mean distance between neighbour control points of C1"; the speed-weighted
//   rounding in the PDF is unreadable, we take the plain mean of |P_{i+1} - P_i|.
// - eqs. 4-25/4-26: going back from the stroke start P_s over C1's control points (those whose
//   Greville abscissa lies before the start's projection), every CT with M <= |P_s - CT| <= 1.5 M is
//   a candidate; the one whose edge CT -> P_s turns least from the polygon edge CT_{-1} -> CT
//   (Δφ = |d1 - d2|) is CT_s. Symmetric at the end. With no candidate in the band, the first
//   point at least M away is taken.
// - The replacement y_i: a least-squares fit of the stroke in place (see refitInPlace), starting
//   with as many control points as C1's density M gives over the stroke's length and growing until
//   the fit meets the tolerance; a region redrawn again is replaced again, so repeated edits keep
//   the count bounded. Re-parameterisation (§4.2, last bullet): the kept parts keep their knots, the new
//   part gets uniform knots, scaled to fill the old parameter interval between the kept parts (a
//   closed curve keeps its period), so the curve outside the edit keeps its parameters as well as
//   its shape, as local-c2 does (shifting the far part instead moved the far end of a 110-unit curve
//   by 0.3 at its old parameter).
#include "solvers/editing/oversketch.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/editing/constrained_fit.h"
#include "solvers/editing/oversketch_support.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sculptline::solvers::editing::detail {
namespace {

template <int Dim>
using Pt = Eigen::Matrix<double, Dim, 1>;

template <int Dim>
double angleBetween(const Pt<Dim>& a, const Pt<Dim>& b)
{
    const double na = a.norm(), nb = b.norm();
    if (na == 0.0 || nb == 0.0) return 0.0;
    return std::acos(std::clamp(a.dot(b) / (na * nb), -1.0, 1.0));
}

// Cyclic or clamped access to the (unique) control points and their Greville abscissae.
template <int Dim>
struct Polygon {
    std::vector<Pt<Dim>> pts;
    std::vector<double> greville;
    bool closed = false;
    double period = 0.0;
    int size() const { return static_cast<int>(pts.size()); }
    const Pt<Dim>& at(int i) const { return pts[((i % size()) + size()) % size()]; }
};

template <int Dim>
Polygon<Dim> polygonOf(const BSplineCurve<Dim>& c)
{
    Polygon<Dim> poly;
    const int p = c.degree();
    const int n = c.isClosed() ? c.pointCount() - p : c.pointCount();
    poly.closed = c.isClosed();
    poly.period = c.domainEnd() - c.domainStart();
    for (int i = 0; i < n; ++i) {
        poly.pts.push_back(c.points()[i]);
        double g = 0.0;
        for (int j = 1; j <= p; ++j) g += c.knots()[i + j];
        poly.greville.push_back(g / p);
    }
    return poly;
}

// Eqs. 4-25/4-26: walks from `start` in direction `dir` (-1 before the stroke, +1 after it).
// Returns the chosen index (may be outside [0, n) for closed curves: it is taken cyclically) or
// kNone when an open curve has no point on that side.
constexpr int kNone = std::numeric_limits<int>::min();

template <int Dim>
int transitionPoint(const Polygon<Dim>& poly, int start, int dir, const Pt<Dim>& strokeEnd, double M, int maxSteps)
{
    int best = kNone, fallback = kNone;
    double bestPhi = 0.0;
    for (int step = 0, i = start; step < maxSteps; ++step, i += dir) {
        if (!poly.closed && (i < 0 || i >= poly.size())) break;
        const double dd = (strokeEnd - poly.at(i)).norm();
        if (dd > 1.5 * M) {
            if (fallback == kNone) fallback = i;
            break;
        }
        if (dd >= M) {
            const bool hasPrev = poly.closed || (i - dir >= 0 && i - dir < poly.size());
            const Pt<Dim> edge = hasPrev
                                     ? Pt<Dim>(dir < 0 ? poly.at(i) - poly.at(i - dir) : poly.at(i - dir) - poly.at(i))
                                     : Pt<Dim>(Pt<Dim>::Zero());
            const Pt<Dim> toStroke = dir < 0 ? Pt<Dim>(strokeEnd - poly.at(i)) : Pt<Dim>(poly.at(i) - strokeEnd);
            const double phi = angleBetween<Dim>(edge, toStroke);
            if (best == kNone || phi < bestPhi) {
                best = i;
                bestPhi = phi;
            }
        }
        fallback = i;
    }
    return best != kNone ? best : fallback;
}

// Weights of a spliced polygon (rational curves; empty otherwise): kept points keep theirs, the m
// new ones between kept points `left` and `right` (-1: none on that side) are interpolated linearly
// by index, so the untouched parts of the curve keep their weights.
template <int Dim>
std::vector<double> newWeights(const BSplineCurve<Dim>& c, int m, int left, int right)
{
    if (!c.isRational()) return {};
    const double wl = left >= 0 ? c.weight(left) : right >= 0 ? c.weight(right) : 1.0;
    const double wr = right >= 0 ? c.weight(right) : wl;
    std::vector<double> w;
    for (int i = 1; i <= m; ++i) w.push_back(wl + (wr - wl) * i / (m + 1));
    return w;
}

// The spliced polygon with its final knots: the new points `first..last` are fitted to the stroke
// with the kept points fixed. The stroke's samples go only on the spans built from new points alone,
// [K[first + p], K[last + 1]] (chord-length parameters): the p spans on each side that mix kept and
// new points carry no sample, so the new points next to the kept ones are set by the fit's fairing
// term (least second differences, constrained_fit.h) and form the transition, while the stroke
// itself is approximated by an unconstrained spline and so can meet any tolerance with enough points.
// (Spreading the samples between the Greville abscissae of the first and last new point, as before,
// put the stroke's ends on spans pinned by the kept transition points CT_s, CT_e: the fit missed the
// stroke's ends by 2-3x the tolerance however many points were added.) Eq. 4-23 then scales the new
// points towards the original curve.
template <int Dim>
std::vector<Pt<Dim>> refitInPlace(int p, const KnotVector& K, std::vector<Pt<Dim>> P, const std::vector<double>& W,
                                  int first, int last, const StrokeOnCurve<Dim>& st, const BSplineCurve<Dim>& original,
                                  double scale, double& fitError)
{
    const double t0 = K[first + p], t1 = K[last + 1];
    const std::vector<double> chord = chordLengths<Dim>(st.points);
    FixedKnotFit<Dim> fit;
    fit.degree = p;
    fit.knots = K;
    fit.samples = st.points;
    for (double s : chord) fit.params.push_back(t0 + (t1 - t0) * s / chord.back());
    fit.params.back() = t1;
    fit.weights = W;
    fit.fixed.resize(P.size());
    for (int i = 0; i < static_cast<int>(P.size()); ++i) {
        if (i < first || i > last) fit.fixed[i] = P[i];
    }
    P = fitFixedKnots(fit);
    fitError = 0.0;  // at the fit parameters (an upper bound of the distance), before scaling
    double basis[kMaxDegree + 1];
    for (size_t k = 0; k < fit.params.size(); ++k) {
        const int span = std::min(findSpan(p, K, fit.params[k]), last);
        basisFunctions(span, fit.params[k], p, K, basis);
        Pt<Dim> v = Pt<Dim>::Zero();
        double sum = 0.0;
        for (int j = 0; j <= p; ++j) {
            const double bw = basis[j] * (W.empty() ? 1.0 : W[span - p + j]);
            v += bw * P[span - p + j];
            sum += bw;
        }
        fitError = std::max(fitError, (v / sum - st.points[k]).norm());
    }
    if (scale < 1.0) {
        const CurveProjector<Dim> projector(original);
        for (int i = first; i <= last; ++i) {
            const Pt<Dim> foot = projector.project(P[i]).point;
            P[i] = foot + scale * (P[i] - foot);
        }
    }
    return P;
}

}  // namespace

template <int Dim>
BSplineCurve<Dim> oversketchBlend(const BSplineCurve<Dim>& input, const StrokeOnCurve<Dim>& st,
                                  const OversketchOptions& o, std::pair<double, double>& span, double& maxError)
{
    const int p = input.degree();
    double M = 0.0;  // eq. 4-24, of the input curve (refinement below must not change it)
    {
        const Polygon<Dim> poly = polygonOf(input);
        const int edges = poly.closed ? poly.size() : poly.size() - 1;
        for (int i = 0; i < edges; ++i) M += (poly.at(i + 1) - poly.at(i)).norm();
        M = std::max(M / edges, 1e-12 * st.length);
    }

    // The number of replacement points: C1's density over the stroke's length plus the p transition
    // points per side to start with (so that repeated edits keep the count bounded), grown by a
    // quarter until the in-place fit meets the tolerance; at most one per four stroke samples plus
    // the transitions (beyond that it would fit pen noise).
    // The density is capped at one point per stroke sample before it becomes an int: a stroke far
    // longer than C1's polygon edges (6e9 against 15) asked for 4e8 points (a minute and 10 GB).
    const auto& h = st.points;
    const double density = std::min(st.length / M, static_cast<double>(h.size()));
    const int m0 = std::max(p + 1, static_cast<int>(std::lround(density)) + 1) + p;
    const int mMax = std::max(m0, static_cast<int>(h.size()) / 4 + 2 * p);
    const double tol = fitTolerance(o, st.length);
    auto grow = [&](int m) { return std::min(mMax, m + std::max(1, m / 4)); };

    // Closed curves: a stroke around most of the loop leaves a short arc for the two transitions
    // and the kept chain. Eq. 4-25's band shrinks to a quarter of that arc, and when the arc holds
    // too few control points to keep p + 1 of them (one untouched span), it is refined by exact
    // knot insertion (the shape is unchanged) and the attempt repeated, as local-c2 does.
    double Mt = M;
    if (input.isClosed()) {
        const CurveLengths<Dim> len(input);
        const double free = len.total() - (len.lengthAt(st.ue) - len.lengthAt(st.us));
        if (!(free > 0.0)) throw GeometryError("stroke: the over-sketch covers the whole closed curve");
        Mt = std::min(M, 0.25 * free);
    }
    constexpr int kMaxRefinements = 6;
    // C1's mean speed (refinement does not change it).
    const double speed = CurveLengths<Dim>(input).total() / (input.domainEnd() - input.domainStart());
    BSplineCurve<Dim> c = input.isClosed() ? input : input.clamped();
    for (int attempt = 0;; ++attempt) {
        const Polygon<Dim> poly = polygonOf(c);
        const int n = poly.size();

        // Transition control points CT_s, CT_e (eqs. 4-24..4-26).
        const double period = poly.period;
        auto before = [&](double u) {
            int i = -1;
            for (int k = 0; k < n; ++k) {
                if (poly.greville[k] <= u) i = k;
            }
            return i;
        };
        const double us = c.isClosed() ? c.normalizeParameter(st.us) : st.us;
        const double ue = c.isClosed() ? c.normalizeParameter(st.ue) : st.ue;
        int iS = before(us);
        int iE = before(ue) + 1;
        if (c.isClosed() && ue < us) iE += n;  // the stroke crosses the seam
        const int maxSteps = poly.closed ? n / 2 : n;
        const bool openLeftEnd = !c.isClosed() &&
                                 (h.front() - c.evaluate(c.domainStart())).norm() > fitTolerance(o, st.length) &&
                                 st.us <= c.domainStart();
        const bool openRightEnd = !c.isClosed() &&
                                  (h.back() - c.evaluate(c.domainEnd())).norm() > fitTolerance(o, st.length) &&
                                  st.ue >= c.domainEnd();
        const int cs = openLeftEnd ? kNone : transitionPoint(poly, iS, -1, h.front(), Mt, maxSteps);
        const int ce = openRightEnd ? kNone : transitionPoint(poly, iE, +1, h.back(), Mt, maxSteps);

        const auto& U = c.knots();
        const double meanSpacing = (c.domainEnd() - c.domainStart()) / std::max(1, n - (c.isClosed() ? 0 : p));
        auto knotAt = [&](int i) {  // closed curves: the bi-infinite knot sequence
            if (!c.isClosed()) return U[i];
            const int j = i - p;
            const int q = static_cast<int>(std::floor(double(j) / n));
            return U[p + (j - q * n)] + q * period;
        };

        // Parameter lengths, so that the parameter speed does not jump (a jump forces the C2 curve to
        // slow down to a near-cusp in the transition: curvature 22 against the stroke's 0.7, measured).
        // v: C1's mean speed; the stroke's spans get its length at that speed. A transition after the
        // kept point CT_s = a runs from C1(U[a+1]), where the kept curve ends, to the stroke's start
        // P_s over the kept knots U[a+1..a+p] and one new spacing δ_s chosen so that its parameter
        // length matches |P_s - C1(U[a+1])| at speed v; likewise before CT_e = b over U[b+1..b+p].
        // When the kept knots alone are already too long for the gap (CT_s closer than the p - 1 spans
        // its support reaches), CT_s steps back (at most p points): this lengthens the transition
        // beyond eq. 4-25's M..1.5M, which is measured between control points, not curve points.
        const double v = speed;
        const double deltaMin = 0.5 * meanSpacing;
        auto leftGap = [&](int i) {
            return (h.front() - c.evaluate(knotAt(i + 1))).norm() / v - (knotAt(i + p) - knotAt(i + 1));
        };
        auto rightGap = [&](int i) {
            return (h.back() - c.evaluate(knotAt(i + p))).norm() / v - (knotAt(i + p) - knotAt(i + 1));
        };
        int first = cs, last = ce;  // CT_s, CT_e after the gap adjustment (unwrapped indices, first < last)
        const int lowest = c.isClosed() ? std::numeric_limits<int>::min() / 2 : 1;
        for (int k = 0; k < p && first != kNone && first > lowest && leftGap(first) < deltaMin; ++k) --first;
        const int highest = c.isClosed() ? std::numeric_limits<int>::max() / 2 : n - 2;
        for (int k = 0; k < p && last != kNone && last < highest && rightGap(last) < deltaMin; ++k) ++last;
        const int keptMin = p + 1;  // closed: p + 1 kept points leave one span untouched
        if (c.isClosed() && first != kNone && last != kNone && first + n - last + 1 < keptMin) {
            first = cs;  // the loop has no room for longer transitions: keep eq. 4-25's choice
            last = ce;
        }
        if (!c.isClosed() && first != kNone && last != kNone) {
            // Open, kept parts on both sides: the new part must fit in the kept parts' old interval
            // [U[a+p], U[b+1]] (so that they keep their parameters). Where that interval is less than
            // kMinFill of the parameter length the new part wants at C1's speed, the parameter speed
            // would jump more than 1/kMinFill-fold through the transitions (or the knots would
            // collapse, for an interval of zero): CT_s and CT_e step outwards, one each per round,
            // lengthening the transitions, until it fits or the curve's ends are reached.
            constexpr double kMinFill = 0.5;
            auto wanted = [&] {
                return std::max(deltaMin, leftGap(first)) + st.length / v + std::max(deltaMin, rightGap(last));
            };
            while (U[last + 1] - U[first + p] < kMinFill * wanted() && (first > lowest || last < highest)) {
                if (first > lowest) --first;
                if (last < highest) ++last;
            }
            // A curve of so few points that nothing can be kept: the stroke replaces it all.
            if (!(U[last + 1] > U[first + p])) first = last = kNone;
        }
        const double deltaS = first == kNone ? 0.0 : std::max(deltaMin, leftGap(first));
        const double deltaE = last == kNone ? 0.0 : std::max(deltaMin, rightGap(last));

        if (!c.isClosed()) {
            // Open: P' = P[0..a] ++ y ++ P[b..n-1]; knots U[0..a+p], δ_s, the stroke's m - p spans,
            // δ_e, then U[b+1..] shifted.
            const int a = first == kNone ? -1 : first;
            const int b = last == kNone ? n : last;
            if (a >= b) throw GeometryError("stroke: the transitions of the over-sketch overlap");
            for (int m = m0;; m = grow(m)) {
                std::vector<Pt<Dim>> P(poly.pts.begin(), poly.pts.begin() + (a + 1));
                P.resize(P.size() + m, Pt<Dim>::Zero());
                P.insert(P.end(), poly.pts.begin() + b, poly.pts.end());
                const int total = static_cast<int>(P.size());
                // Spacings of the new knots: δ_s, the stroke's m - p spans, δ_e. Between two kept
                // parts they are scaled to fill the old [U[a+p], U[b+1]] exactly, so both kept parts
                // keep their knot values and the curve outside the edit keeps its parameters.
                double hs = st.length / v / (m - p), dS = deltaS, dE = deltaE;
                if (a >= 0 && b < n) {
                    const double k = (U[b + 1] - U[a + p]) / (dS + (m - p) * hs + dE);
                    hs *= k;
                    dS *= k;
                    dE *= k;
                }
                KnotVector K;
                if (a >= 0) {
                    K.assign(U.begin(), U.begin() + a + p + 1);
                    K.push_back(K.back() + dS);
                } else {
                    // The start is replaced: the new part ends where the kept right part begins.
                    K.assign(p + 1, b < n ? U[b + 1] - dE - (m - p) * hs : U[p]);
                }
                const double t0 = K.back();
                for (int i = 1; i <= m - p; ++i) K.push_back(t0 + hs * i);
                const double t1 = K.back();
                if (b < n) {
                    if (a >= 0) K.back() = U[b + 1] - dE;  // no round-off drift into the kept knots
                    for (int i = b + 1; i <= n + p; ++i) K.push_back(U[i]);
                } else {
                    K.insert(K.end(), p, t1);
                }
                std::vector<double> W;
                if (c.isRational()) {
                    W.assign(c.weights().begin(), c.weights().begin() + (a + 1));
                    const std::vector<double> mid = newWeights(c, m, a, b < n ? b : -1);
                    W.insert(W.end(), mid.begin(), mid.end());
                    W.insert(W.end(), c.weights().begin() + b, c.weights().end());
                }
                double err = 0.0;
                P = refitInPlace(p, K, std::move(P), W, a + 1, a + m, st, c, o.scale, err);
                if (err <= tol || m >= mMax) {
                    span = {a >= 0 ? K[a + 1] : K[p], b < n ? K[total - (n - b) + p] : K[total]};
                    maxError = err;
                    return BSplineCurve<Dim>(p, std::move(K), std::move(P), std::move(W));
                }
            }
        }

        // Closed: Q = kept chain CT_e .. CT_s (cyclic) ++ y. Knot spacings: δ_e, the kept chain's old
        // spacings, δ_s, the stroke's m - p spans (periodic; the kept knots keep their values).
        if (first == kNone || last == kNone) throw GeometryError("stroke: no transition found on the closed curve");
        // Unwrapped indices: first <= iS < iE <= last, the kept chain runs from last to first + n.
        const int e = last;
        const int kept = first + n - last + 1;
        // The kept chain's own knot spacings; the new ones must fit in what remains of the period.
        double keptLength = 0.0;
        for (int i = 1; i < kept + p - 1; ++i) keptLength += knotAt(e + i + 1) - knotAt(e + i);
        if (kept < keptMin || kept > n || !(period - keptLength > 1e-9 * period)) {
            if (attempt >= kMaxRefinements) {
                throw GeometryError("stroke: the over-sketch with its transitions covers the whole closed curve");
            }
            c = refineOutside(c, {st.us, st.ue}, 1);
            continue;
        }
        for (int m = m0;; m = grow(m)) {
            const int N = kept + m;
            // The new spacings (δ_e, δ_s and the stroke's m - p spans) are scaled so that the period
            // stays C1's: with the kept knots' values unchanged, the kept arc keeps its parameters.
            std::vector<double> spacing(N, st.length / v / (m - p));
            spacing[0] = deltaE;
            for (int i = 1; i < kept + p - 1; ++i) spacing[i] = knotAt(e + i + 1) - knotAt(e + i);
            spacing[kept + p - 1] = deltaS;
            double newLength = 0.0;
            for (int i = 0; i < N; ++i) {
                if (i == 0 || i >= kept + p - 1) newLength += spacing[i];
            }
            const double k = (period - keptLength) / newLength;
            for (int i = 0; i < N; ++i) {
                if (i == 0 || i >= kept + p - 1) spacing[i] *= k;
            }
            std::vector<Pt<Dim>> Q;
            for (int i = 0; i < kept; ++i) Q.push_back(poly.at(e + i));
            Q.resize(N + p, Pt<Dim>::Zero());
            for (int i = 0; i < p; ++i) Q[N + i] = Q[i];  // wrapped copies of kept (hence fixed) points
            // Unwrapped convention: knots[i] starts the support of point i, spacings periodic.
            KnotVector K(N + 2 * p + 1);
            K[0] = knotAt(e + 1) - spacing[0];
            for (size_t i = 1; i < K.size(); ++i) K[i] = K[i - 1] + spacing[(i - 1) % N];
            std::vector<double> W;
            if (c.isRational()) {
                auto wAt = [&](int i) { return c.weight(((i % n) + n) % n); };
                for (int i = 0; i < kept; ++i) W.push_back(wAt(e + i));
                const double wl = W.back(), wr = W.front();
                for (int i = 1; i <= m; ++i) W.push_back(wl + (wr - wl) * i / (m + 1));
                for (int i = 0; i < p; ++i) W.push_back(W[i]);
            }
            double err = 0.0;
            Q = refitInPlace(p, K, std::move(Q), W, kept, N - 1, st, c, o.scale, err);
            if (err <= tol || m >= mMax) {
                span = {K[kept], K[N + p]};  // spans using any new point: j in [kept, N - 1 + p]
                maxError = err;
                return BSplineCurve<Dim>(p, std::move(K), std::move(Q), std::move(W), true);
            }
        }
    }
}

template BSplineCurve<2> oversketchBlend<2>(const BSplineCurve<2>&, const StrokeOnCurve<2>&, const OversketchOptions&,
                                            std::pair<double, double>&, double&);
template BSplineCurve<3> oversketchBlend<3>(const BSplineCurve<3>&, const StrokeOnCurve<3>&, const OversketchOptions&,
                                            std::pair<double, double>&, double&);

}  // namespace sculptline::solvers::editing::detail
