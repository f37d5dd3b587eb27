#include "solvers/stroke/fit_check.h"

#include "solvers/bspline/basis_evaluator.h"
#include "solvers/bspline/geometry_error.h"
#include "solvers/stroke/power_form.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace sculptline::solvers::stroke {
namespace {

using Vec3 = Eigen::Vector3d;

// The curve in power form per knot span, Taylor coefficients at the span's middle (a cubic is its
// own Taylor polynomial there, and the middle avoids the one-sided limits at the knots): a point
// costs a Horner step, far less than the basis recursion, and the check evaluates many.
class PowerCurve {
public:
    explicit PowerCurve(const Curve3d& c) : closed_(c.isClosed()), d0_(c.domainStart()), d1_(c.domainEnd())
    {
        if (c.degree() > 3 || c.isRational()) throw GeometryError("fit check: needs a polynomial curve of degree <= 3");
        const auto& U = c.knots();
        for (size_t i = 0; i + 1 < U.size(); ++i) {
            const double a = std::max(U[i], d0_), b = std::min(U[i + 1], d1_);
            if (!(b > a)) continue;
            const double m = 0.5 * (a + b);
            Span s;
            s.a = a;
            s.b = b;
            s.m = m;
            if (c.degree() == 3) {
                // The span's basis functions and their derivatives at m, fixed-size (the generic
                // derivatives() allocates: 2.9 k instructions a span, 9 % of a 1,000-sample measure).
                const BasisDerivatives<3, 3> nb = evaluateBasis<3, 3>(U, static_cast<int>(i), m);
                constexpr double kTaylor[4] = {1.0, 1.0, 0.5, 1.0 / 6.0};
                for (int k = 0; k <= 3; ++k) {
                    Vec3 v = Vec3::Zero();
                    for (int j = 0; j <= 3; ++j) v += nb.d[k][j] * c.points()[i - 3 + j];
                    s.c[k] = kTaylor[k] * v;
                }
            } else {
                const std::vector<Vec3> d = c.derivatives(m, 3);
                s.c = {d[0], d[1], 0.5 * d[2], d.size() > 3 ? (d[3] / 6.0).eval() : Vec3::Zero().eval()};
            }
            spans_.push_back(s);
        }
        if (spans_.empty()) throw GeometryError("fit check: the curve has an empty domain");
    }
    double start() const { return d0_; }
    double end() const { return d1_; }
    bool closed() const { return closed_; }
    double wrap(double u) const
    {
        if (!closed_) return std::clamp(u, d0_, d1_);
        const double T = d1_ - d0_;
        return u - std::floor((u - d0_) / T) * T;
    }
    // Point, first and second derivative at u.
    void eval(double u, Vec3& p, Vec3& d1, Vec3& d2) const
    {
        const Span& s = spanAt(wrap(u));
        detail::cubicWithDerivatives(s.c, wrap(u) - s.m, p, d1, d2);
    }
    // The same on span j's polynomial, whichever span u lies in (a span's end from inside it).
    void evalSpan(int j, double u, Vec3& p, Vec3& d1, Vec3& d2) const
    {
        const Span& s = spans_[j];
        detail::cubicWithDerivatives(s.c, u - s.m, p, d1, d2);
    }
    Vec3 point(double u) const
    {
        const Span& s = spanAt(wrap(u));
        return detail::cubicPoint(s.c, wrap(u) - s.m);
    }
    int spanCount() const { return static_cast<int>(spans_.size()); }
    double spanStart(int j) const { return spans_[j].a; }
    double spanEnd(int j) const { return spans_[j].b; }
    // The span holding u (wrapped).
    int spanOf(double u) const { return static_cast<int>(&spanAt(wrap(u)) - spans_.data()); }
    // The box of span j's Bezier points (B0 = C(a), B1 = C(a) + h C'(a) / 3, B2 = C(b) - h C'(b) / 3,
    // B3 = C(b), h = b - a): the span lies in their convex hull, so no point of it is nearer to x
    // than the box is (The NURBS Book §1.4, the convex hull property).
    Eigen::AlignedBox3d hullBox(int j) const
    {
        const Span& s = spans_[j];
        const double h = s.b - s.a, ta = s.a - s.m, tb = s.b - s.m;
        const auto at = [&](double t, Vec3& p, Vec3& d) {
            p = ((s.c[3] * t + s.c[2]) * t + s.c[1]) * t + s.c[0];
            d = (3.0 * s.c[3] * t + 2.0 * s.c[2]) * t + s.c[1];
        };
        Vec3 p0, d0, p3, d3;
        at(ta, p0, d0);
        at(tb, p3, d3);
        Eigen::AlignedBox3d box(p0);
        box.extend(p3);
        box.extend((p0 + h / 3.0 * d0).eval());
        box.extend((p3 - h / 3.0 * d3).eval());
        return box;
    }
    // Parameters and points of span j's polyline, consecutive points at most ~`spacing` apart: a
    // count from the largest speed at the span's ends and middle (a cubic's speed varies little
    // within a span of a fitted stroke; the count is capped so that a wild span cannot explode the
    // work). Both ends are included.
    void spanPolyline(int j, double spacing, std::vector<double>& u, std::vector<Vec3>& p) const
    {
        constexpr int kMaxPerSpan = 512;
        const Span& s = spans_[j];
        const auto speed = [&](double t) { return ((3.0 * s.c[3] * t + 2.0 * s.c[2]) * t + s.c[1]).norm(); };
        const double len = std::max({speed(s.a - s.m), speed(0.0), speed(s.b - s.m)}) * (s.b - s.a);
        const int n = static_cast<int>(std::clamp(std::ceil(len / spacing), 1.0, double(kMaxPerSpan)));
        u.resize(static_cast<size_t>(n) + 1);
        p.resize(static_cast<size_t>(n) + 1);
        for (int k = 0; k <= n; ++k) {
            const double uk = k == n ? s.b : s.a + (s.b - s.a) * k / n;
            const double t = uk - s.m;
            u[k] = uk;
            p[k] = ((s.c[3] * t + s.c[2]) * t + s.c[1]) * t + s.c[0];
        }
    }

private:
    struct Span {
        double a = 0, b = 0, m = 0;
        std::array<Vec3, 4> c;
    };
    const Span& spanAt(double u) const
    {
        const int last = static_cast<int>(spans_.size()) - 1;
        if (hint_ <= last && u >= spans_[hint_].a && (hint_ == last || u < spans_[hint_].b)) return spans_[hint_];
        int lo = 0, hi = last;
        while (lo < hi) {
            const int mid = (lo + hi + 1) / 2;
            if (spans_[mid].a <= u) lo = mid;
            else hi = mid - 1;
        }
        hint_ = lo;
        return spans_[lo];
    }
    bool closed_;
    double d0_, d1_;
    std::vector<Span> spans_;
    mutable int hint_ = 0;
};

// The local minimum of |C(u) - x| in [lo, hi] from `u`: Newton on f(u) = C'(u).(C(u) - x) (The
// NURBS Book eq. 6.3) kept inside a bracket that shrinks by the sign of f, bisecting where Newton
// would leave it (Numerical Recipes' rtsafe). Returns the smallest distance met (each is the
// distance to a curve point) and its parameter in *foot.
double refineLocal(const PowerCurve& c, const Vec3& x, double lo, double hi, double u, double* foot)
{
    constexpr int kMaxIterations = 40;  // Newton converges in < 8 from a polyline minimum; the rest bisects
    double best = std::numeric_limits<double>::infinity(), bestU = u;
    // A minimum at a bracket end (a curve end, a C0 corner). The distance's slope at each end, from
    // inside the bracket: where neither end's slope leads into the bracket there is no minimum
    // inside it (the bracket is a polyline segment, too short for the distance to turn twice), and
    // the Newton steps would only bisect toward the end (~40 steps).
    double slope[2];
    for (int k = 0; k < 2; ++k) {
        const double e = k == 0 ? lo : hi;
        Vec3 p, d1, d2;
        c.eval(k == 0 ? lo : std::nextafter(hi, lo), p, d1, d2);
        slope[k] = d1.dot(p - x);
        const double d = (c.point(e) - x).norm();
        if (d < best) best = d, bestU = e;
    }
    if (!(slope[0] < 0.0) || !(slope[1] > 0.0)) {
        if (foot) *foot = bestU;
        return best;
    }
    const double resolution = 8 * std::numeric_limits<double>::epsilon() * std::max({1.0, std::abs(lo), std::abs(hi)});
    for (int it = 0; it < kMaxIterations && hi - lo > resolution; ++it) {
        Vec3 p, d1, d2;
        c.eval(u, p, d1, d2);
        const Vec3 r = p - x;
        const double d = r.norm();
        if (d < best) best = d, bestU = u;
        const double f = d1.dot(r), df = d2.dot(r) + d1.squaredNorm();
        if (f == 0.0) break;
        (f < 0.0 ? lo : hi) = u;
        double next = df > 0.0 ? u - f / df : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - u) <= resolution) break;
        u = next;
    }
    if (foot) *foot = bestU;
    return best;
}

// The exact distance from a point to the curve, by the spans' polylines, each built on first use:
// a search reads only the spans whose hull box (PowerCurve::hullBox) comes nearer than the best
// distance known, and of those every local minimum of the polyline's distances that could hold a
// curve point nearer than the best found (within the span's polyline spacing of the smallest) is
// refined. (It was one polyline of the whole curve, built for every measure, which also tracked
// the samples: 35 % of the fit of BM_StrokeFit/200, most of it building the polyline.)
class SpanSearch {
public:
    SpanSearch(const PowerCurve& c, double spacing)
        : c_(c), spacing_(spacing), pieces_(static_cast<size_t>(c.spanCount()))
    {
        boxes_.reserve(pieces_.size());
        for (int j = 0; j < c.spanCount(); ++j) boxes_.push_back(c.hullBox(j));
    }
    // The distance from x to the curve where it is below `bound` (else `bound`), its parameter in
    // *foot when found.
    double project(const Vec3& x, double bound, double* foot)
    {
        candidates_.clear();
        for (int j = 0; j < c_.spanCount(); ++j)
            if (boxes_[static_cast<size_t>(j)].exteriorDistance(x) <= bound) candidates_.push_back(j);
        double smallest = std::numeric_limits<double>::infinity();
        for (int j : candidates_) {
            Piece& pc = piece(j);
            pc.d2.resize(pc.u.size());
            for (size_t k = 0; k < pc.u.size(); ++k)
                smallest = std::min(smallest, pc.d2[k] = (pc.p[k] - x).squaredNorm());
        }
        double best = bound;
        for (int j : candidates_) {
            const Piece& pc = pieces_[static_cast<size_t>(j)];
            const double r = std::sqrt(smallest) + pc.spacing;
            const double reach = r * r;
            const size_t n = pc.u.size();
            for (size_t k = 0; k < n; ++k) {
                const double dk = pc.d2[k];
                if (dk > reach || (k > 0 && dk > pc.d2[k - 1]) || (k + 1 < n && dk > pc.d2[k + 1])) continue;
                // Each side of the point on its own: a span's end may be a C0 corner, where the
                // distance has a minimum on either side and the derivative taken at the corner
                // belongs to one side only (a sample on the side before a corner was measured 0.47
                // against 0.004 when both sides shared one bracket).
                for (const auto& [lo, hi] : {std::pair{k > 0 ? pc.u[k - 1] : pc.u[k], pc.u[k]},
                                             std::pair{pc.u[k], k + 1 < n ? pc.u[k + 1] : pc.u[k]}}) {
                    if (!(hi > lo)) continue;
                    double fu = pc.u[k];
                    const double e = refineLocal(c_, x, lo, hi, 0.5 * (lo + hi), &fu);
                    if (e < best) {
                        best = e;
                        if (foot) *foot = c_.wrap(fu);
                    }
                }
            }
        }
        return best;
    }

private:
    struct Piece {
        std::vector<double> u;
        std::vector<Vec3> p;
        std::vector<double> d2;  // scratch: the squared distances of the point projected
        double spacing = -1.0;   // the largest distance between consecutive points; < 0: not built
    };
    Piece& piece(int j)
    {
        Piece& pc = pieces_[static_cast<size_t>(j)];
        if (pc.spacing >= 0.0) return pc;
        c_.spanPolyline(j, spacing_, pc.u, pc.p);
        pc.spacing = 0.0;
        for (size_t k = 0; k + 1 < pc.p.size(); ++k) pc.spacing = std::max(pc.spacing, (pc.p[k + 1] - pc.p[k]).norm());
        return pc;
    }
    const PowerCurve& c_;
    double spacing_;
    std::vector<Piece> pieces_;
    std::vector<Eigen::AlignedBox3d> boxes_;
    std::vector<int> candidates_;
};

// The nearest point to x that Newton's iteration on f(u) = C'(u).(C(u) - x) (The NURBS Book eq.
// 6.3) reaches from parameter u0. The steps stay in their span: one that would leave it stops at the
// span's end, and from there, if the distance still falls beyond it, the iteration goes on in the
// next span (on a closed curve round the seam), never back into one it left: a C0 corner (a fitted
// stroke's corner, a triple knot) where the distance falls toward it from both sides is the
// nearest point, where Newton across the corner would jump from leg to leg. Returns the smallest
// distance met, a curve point's, so an upper bound on the distance: within `slack` of the local
// minimum's once a step moves the foot by less than `slack` (Newton's error is then about its next
// step), and that minimum is the distance wherever the samples run along the curve and u0 is
// predicted from the previous samples' feet (1-3 steps). It stops where the distance is not convex
// (far from the curve): the bound is then whatever it met, and the caller searches in full where
// that is far.
double trackLocal(const PowerCurve& c, const Vec3& x, double u0, double slack, double* foot)
{
    constexpr int kMaxSteps = 16;
    double best2 = std::numeric_limits<double>::infinity(), u = c.wrap(u0), bestU = u;
    const double slack2 = slack * slack;
    const int spans = c.spanCount();
    int span = c.spanOf(u), dir = 0;  // dir: the way the iteration last changed span
    for (int it = 0; it < kMaxSteps; ++it) {
        Vec3 p, d1, d2;
        c.evalSpan(span, u, p, d1, d2);
        const Vec3 r = p - x;
        const double d = r.squaredNorm();
        if (d < best2) best2 = d, bestU = u;
        const double speed2 = d1.squaredNorm();
        const double f = d1.dot(r), df = d2.dot(r) + speed2;
        if (!(df > 0.0)) break;
        double next = u - f / df;
        const double a = c.spanStart(span), b = c.spanEnd(span);
        // (A step cut short at the span's end is no sign of convergence: from a start just inside a
        // span, the cut step to its end can be shorter than `slack` while the minimum lies in the
        // next span, a whole step away. Stopping there left a bound of 0.63 where the sample's
        // distance is 0.34: session 53, the flourish of FitTolerance.GivenFittedCurves_*.)
        bool cut = false;
        if (next > b || next < a) {
            const int way = next > b ? 1 : -1;
            const double end = way > 0 ? b : a;
            if (u != end) {
                next = end;
                cut = true;
            } else {
                // At the span's end with the distance still falling beyond it.
                const bool curveEnd = !c.closed() && (way > 0 ? span == spans - 1 : span == 0);
                if (curveEnd || dir == -way) break;
                dir = way;
                span = (span + way + spans) % spans;
                u = way > 0 ? c.spanStart(span) : c.spanEnd(span);
                continue;
            }
        }
        const double step = next - u;
        if (!cut && !(step * step * speed2 > slack2)) break;
        u = next;
    }
    *foot = bestU;
    return std::sqrt(best2);
}

// Each kept sample's distance bound and foot parameter, tracked along the curve: projected by
// Newton from the previous one's foot (trackLocal, the first from the curve's start), and searched in
// full where that ends far from it (tracking lost: a seam, a skipped loop; `exact` marks those).
// Each start is the previous foot moved on as far as the one before it moved (the samples' pace
// along the curve changes slowly), unwrapped on a closed curve. The bounds are within kTrackSlack *
// resolution of the local minimum's distance (a hundredth of the fitter's tolerance, whose
// resolution is half the tolerance). `foot` may be null.
template <class Kept>
void track(const PowerCurve& c, SpanSearch& search, const std::vector<Vec3>& samples, const Kept& kept,
           double resolution, std::vector<double>& bound, std::vector<double>* foot, std::vector<char>& exact)
{
    constexpr double kTrackSlack = 2e-2;
    const double lost = 4.0 * resolution;
    const double period = c.end() - c.start();
    const int m = static_cast<int>(samples.size());
    double u = c.start(), pace = 0.0;
    for (int i = 0; i < m; ++i) {
        if (!kept(i)) continue;
        double f = u;
        double e = trackLocal(c, samples[i], u + pace, kTrackSlack * resolution, &f);
        if (e > lost) {
            e = search.project(samples[i], e, &f);
            exact[static_cast<size_t>(i)] = 1;
            pace = 0.0;
        } else {
            // (The step on a closed curve is taken the short way round the seam.)
            pace = f - u;
            if (c.closed()) pace -= std::round(pace / period) * period;
        }
        bound[static_cast<size_t>(i)] = e;
        if (foot) (*foot)[static_cast<size_t>(i)] = c.wrap(f);
        u = f;
    }
}

}  // namespace

SampleDeviation measureSamples(const Curve3d& curve, const std::vector<Eigen::Vector3d>& samples,
                               const std::vector<char>& keep, double resolution, double exactAbove)
{
    if (!(resolution > 0.0) || !std::isfinite(resolution)) throw GeometryError("fit check: resolution must be positive");
    if (!keep.empty() && keep.size() != samples.size()) throw GeometryError("fit check: one keep flag per sample");
    const PowerCurve c(curve);
    SpanSearch search(c, resolution);

    SampleDeviation out;
    const int m = static_cast<int>(samples.size());
    out.bound.assign(static_cast<size_t>(m), 0.0);
    const auto kept = [&](int i) { return keep.empty() || keep[static_cast<size_t>(i)] != 0; };
    // The samples tracked along the curve (track): any curve point gives a valid bound; the exact
    // projection below settles every sample whose bound could matter.
    std::vector<char> exact(static_cast<size_t>(m), 0);  // bound[i] is sample i's distance
    out.foot.assign(static_cast<size_t>(m), 0.0);
    track(c, search, samples, kept, resolution, out.bound, &out.foot, exact);
    // Exact projection of the samples whose bound could be the maximum, largest bound first: once
    // the exact maximum reaches the next bound, no other sample can exceed it.
    std::vector<int> order;
    double top = -1.0;
    for (int i = 0; i < m; ++i)
        if (kept(i) && out.bound[i] > top) top = out.bound[i], out.worst = i;
    if (out.worst < 0) return out;
    const auto settle = [&](int i) {
        if (exact[static_cast<size_t>(i)]) return;
        double foot = 0.0;
        out.bound[i] = search.project(samples[i], out.bound[i], &foot);
        exact[static_cast<size_t>(i)] = 1;
    };
    const int first = out.worst;
    settle(first);
    out.maxError = out.bound[first];
    // Every other bound above the exact maximum found or above exactAbove, largest first.
    const auto open = [&](int i) { return out.bound[i] > std::min(out.maxError, exactAbove); };
    for (int i = 0; i < m; ++i)
        if (kept(i) && i != first && open(i)) order.push_back(i);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return out.bound[a] > out.bound[b]; });
    for (int i : order) {
        if (!open(i)) break;
        settle(i);
        if (out.bound[i] > out.maxError) {
            out.maxError = out.bound[i];
            out.worst = i;
        }
    }
    out.maxWithin = out.maxError;
    if (!(out.maxError > exactAbove)) return out;
    // The maximum within exactAbove, as the maximum above: the largest bound projected first, then
    // every bound above the exact value found, largest first, until the exact maximum reaches the
    // next bound.
    int largest = -1;
    for (int i = 0; i < m; ++i)
        if (kept(i) && out.bound[i] <= exactAbove && (largest < 0 || out.bound[i] > out.bound[largest])) largest = i;
    out.maxWithin = 0.0;
    if (largest < 0) return out;
    settle(largest);
    out.maxWithin = out.bound[largest];
    order.clear();
    for (int i = 0; i < m; ++i)
        if (kept(i) && i != largest && out.bound[i] <= exactAbove && out.bound[i] > out.maxWithin) order.push_back(i);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return out.bound[a] > out.bound[b]; });
    for (int i : order) {
        if (!(out.bound[i] > out.maxWithin)) break;
        settle(i);
        out.maxWithin = std::max(out.maxWithin, out.bound[i]);
    }
    return out;
}

StrayMeasure measureStray(const Curve3d& curve, const std::vector<Eigen::Vector3d>& samples,
                          const std::vector<char>& keep, double tolerance, double chordShare, double resolution,
                          const std::vector<double>* feet, double stopAbove)
{
    if (!(resolution > 0.0) || !std::isfinite(resolution))
        throw GeometryError("fit check: resolution must be positive");
    if (!(tolerance > 0.0) || !std::isfinite(tolerance)) throw GeometryError("fit check: tolerance must be positive");
    if (!keep.empty() && keep.size() != samples.size()) throw GeometryError("fit check: one keep flag per sample");
    if (feet && feet->size() != samples.size()) throw GeometryError("fit check: one foot parameter per sample");
    StrayMeasure out;
    // The kept samples: the polyline's vertices, in the order drawn.
    std::vector<int> kept;
    for (int i = 0; i < static_cast<int>(samples.size()); ++i)
        if (keep.empty() || keep[static_cast<size_t>(i)] != 0) kept.push_back(i);
    const int n = static_cast<int>(kept.size());
    if (n < 2) return out;
    const PowerCurve c(curve);
    std::vector<double> tracked;
    if (!feet) {
        SpanSearch search(c, resolution);
        std::vector<double> bound(samples.size(), 0.0);
        std::vector<char> exact(samples.size(), 0);
        tracked.assign(samples.size(), 0.0);
        const auto isKept = [&](int i) { return keep.empty() || keep[static_cast<size_t>(i)] != 0; };
        track(c, search, samples, isKept, resolution, bound, &tracked, exact);
        feet = &tracked;
    }
    // The polyline's segments q -> q + 1 between kept samples (a loop's last back to its first):
    // start, direction over its squared length, and the reciprocal of its allowance.
    const bool closed = c.closed();
    const int segments = closed ? n : n - 1;
    struct Segment {
        Vec3 a, ab;
        double inverseLength2 = 0.0, inverseAllowance = 0.0;
    };
    std::vector<Segment> seg(static_cast<size_t>(segments));
    for (int q = 0; q < segments; ++q) {
        Segment& g = seg[static_cast<size_t>(q)];
        g.a = samples[static_cast<size_t>(kept[static_cast<size_t>(q)])];
        g.ab = samples[static_cast<size_t>(kept[static_cast<size_t>((q + 1) % n)])] - g.a;
        const double l2 = g.ab.squaredNorm();
        g.inverseLength2 = l2 > 0.0 ? 1.0 / l2 : 0.0;
        g.inverseAllowance = 1.0 / (tolerance + chordShare * std::sqrt(l2));
    }
    const auto distance = [&](int q, const Vec3& x) {
        const Segment& g = seg[static_cast<size_t>(q)];
        const double t = std::clamp((x - g.a).dot(g.ab) * g.inverseLength2, 0.0, 1.0);
        return (g.a + t * g.ab - x).norm();
    };
    // A point's excess over one segment: its distance over the segment's allowance.
    const auto excessOver = [&](int q, const Vec3& x) {
        return distance(q, x) * seg[static_cast<size_t>(q)].inverseAllowance;
    };
    const auto validSegment = [&](int q) { return q >= 0 && q < segments; };
    // The kept samples in the order of their feet along the curve (the order drawn unless the
    // curve doubles back past a sample).
    std::vector<int> order(static_cast<size_t>(n));
    for (int q = 0; q < n; ++q) order[static_cast<size_t>(q)] = q;
    const auto footAt = [&](int q) { return (*feet)[static_cast<size_t>(kept[static_cast<size_t>(q)])]; };
    // (Nearly in order already, a noisy sample's foot before its neighbour's now and then: an
    // insertion sort costs a comparison a sample and a move an inversion, where stable_sort's merges
    // cost 3 % of a dense stroke's fit. Past kInsertionMoves moves a sample (a curve doubling back
    // past many samples) stable_sort finishes. Both keep equal feet in the order drawn, so the order
    // is stable_sort's either way.)
    constexpr long kInsertionMoves = 8;
    long moves = 0;
    const auto footBefore = [&](int a, int b) { return footAt(a) < footAt(b); };
    for (int q = 1; q < n && moves <= kInsertionMoves * n; ++q) {
        const int v = order[static_cast<size_t>(q)];
        int i = q;
        for (; i > 0 && footBefore(v, order[static_cast<size_t>(i - 1)]); --i, ++moves)
            order[static_cast<size_t>(i)] = order[static_cast<size_t>(i - 1)];
        order[static_cast<size_t>(i)] = v;
    }
    if (moves > kInsertionMoves * n) std::stable_sort(order.begin(), order.end(), footBefore);
    std::vector<double> u;
    std::vector<Vec3> p;
    Vec3 worstPoint = Vec3::Zero();
    int r = -1;  // order[r] is the last sample whose foot is at or before the curve point (-1: none)
    for (int j = 0; j < c.spanCount() && !(out.excess > stopAbove); ++j) {
        c.spanPolyline(j, resolution, u, p);
        for (size_t k = 0; k < u.size(); ++k) {
            while (r + 1 < n && footAt(order[static_cast<size_t>(r + 1)]) <= u[k]) ++r;
            // The samples whose feet bracket the point (before the first foot or past the last: a
            // loop's last and first, an open curve's end sample alone), and the segments at either.
            const int A = r >= 0 ? order[static_cast<size_t>(r)] : closed ? order.back() : order.front();
            const int B = r + 1 < n ? order[static_cast<size_t>(r + 1)] : closed ? order.front() : order.back();
            // (The segment from A first, the chord the point is usually nearest; the others only
            // while the point could still be the worst: its least excess only falls, and one no
            // more than out.excess changes nothing.)
            double excess = std::numeric_limits<double>::infinity();
            for (int q : {A, A - 1, B - 1, B}) {
                if (closed) q = (q + n) % n;
                if (validSegment(q)) excess = std::min(excess, excessOver(q, p[k]));
                if (excess <= out.excess) break;
            }
            // Beyond those: the whole polyline (a curve that cuts across to another part of the
            // stroke is not straying). The scan ends once the point cannot be the worst: its least
            // excess only falls, and one no more than out.excess changes nothing.
            if (excess > 1.0)
                for (int q = 0; q < segments && excess > out.excess; ++q) excess = std::min(excess, excessOver(q, p[k]));
            if (excess > out.excess) {
                out.excess = excess;
                out.parameter = u[k];
                out.after = kept[static_cast<size_t>(A)];
                worstPoint = p[k];
            }
        }
    }
    out.distance = std::numeric_limits<double>::infinity();
    for (int q = 0; q < segments; ++q) out.distance = std::min(out.distance, distance(q, worstPoint));
    return out;
}

}  // namespace sculptline::solvers::stroke
