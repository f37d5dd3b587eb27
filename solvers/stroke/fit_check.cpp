#include "solvers/stroke/fit_check.h"

#include "solvers/bspline/geometry_error.h"

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
            const std::vector<Vec3> d = c.derivatives(m, 3);
            Span s;
            s.a = a;
            s.b = b;
            s.m = m;
            s.c = {d[0], d[1], 0.5 * d[2], d.size() > 3 ? (d[3] / 6.0).eval() : Vec3::Zero().eval()};
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
        const double t = wrap(u) - s.m;
        p = ((s.c[3] * t + s.c[2]) * t + s.c[1]) * t + s.c[0];
        d1 = (3.0 * s.c[3] * t + 2.0 * s.c[2]) * t + s.c[1];
        d2 = 6.0 * s.c[3] * t + 2.0 * s.c[2];
    }
    Vec3 point(double u) const
    {
        const Span& s = spanAt(wrap(u));
        const double t = wrap(u) - s.m;
        return ((s.c[3] * t + s.c[2]) * t + s.c[1]) * t + s.c[0];
    }
    // Parameters of a polyline whose consecutive points lie at most ~`spacing` apart: per span a
    // count from the largest speed at its ends and middle (a cubic's speed varies little within a
    // span of a fitted stroke; the count is capped so that a wild span cannot explode the work).
    std::vector<double> polylineParameters(double spacing) const
    {
        constexpr int kMaxPerSpan = 512;
        std::vector<double> out;
        for (const Span& s : spans_) {
            Vec3 p, da, dm, db, d2;
            eval(s.a, p, da, d2);
            eval(s.m, p, dm, d2);
            eval(std::nextafter(s.b, s.a), p, db, d2);
            const double len = std::max({da.norm(), dm.norm(), db.norm()}) * (s.b - s.a);
            const int n = static_cast<int>(std::clamp(std::ceil(len / spacing), 1.0, double(kMaxPerSpan)));
            for (int k = 0; k < n; ++k) out.push_back(s.a + (s.b - s.a) * k / n);
        }
        if (!closed_) out.push_back(d1_);
        return out;
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
    for (double e : {lo, hi}) {  // a minimum at a bracket end (a curve end, a C0 corner)
        const double d = (c.point(e) - x).norm();
        if (d < best) best = d, bestU = e;
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

struct Polyline {
    std::vector<double> u;
    std::vector<Vec3> p;
    bool closed = false;
    double spacing = 0.0;  // the largest distance between consecutive points
    int size() const { return static_cast<int>(u.size()); }
    // Neighbouring parameters of point j (wrapping on a closed curve, the domain end for the last point).
    double before(int j, double T) const { return j > 0 ? u[j - 1] : (closed ? u.back() - T : u[0]); }
    double after(int j, double T) const { return j + 1 < size() ? u[j + 1] : (closed ? u[0] + T : u[j]); }
    // Bounding boxes of kBlock consecutive points each, built by the first projectGlobal.
    static constexpr int kBlock = 32;
    std::vector<Eigen::AlignedBox3d> blocks;
    void buildBlocks()
    {
        if (!blocks.empty()) return;
        for (int b = 0; b < size(); b += kBlock) {
            Eigen::AlignedBox3d box(p[b]);
            for (int j = b + 1; j < std::min(b + kBlock, size()); ++j) box.extend(p[j]);
            blocks.push_back(box);
        }
    }
};

// The exact distance: every local minimum of the polyline's distances that could hold a curve point
// closer than the best found (within one polyline spacing of the smallest) is refined. `bound` is a
// curve point's distance from x (so no less than the exact one): the nearest polyline point then
// lies within bound + spacing, and every candidate within bound + 2 spacing, so only the blocks of
// points whose boxes come that near are read (`near`: scratch flags, one per block). A scan of every
// polyline point per projection took 9 % of the jittery flourish's fit; the blocks take it from 12.5
// to 11.9 M instructions (BM_StrokeFitJitter, callgrind), the 16 jittery seeds from 90 to 88 M.
double projectGlobal(const PowerCurve& c, Polyline& pl, const Vec3& x, double bound, double* foot,
                     std::vector<char>& near)
{
    const int n = pl.size();
    const double T = c.end() - c.start();
    pl.buildBlocks();
    const int blocks = static_cast<int>(pl.blocks.size());
    const double radius = bound + 2.0 * pl.spacing;
    near.assign(static_cast<size_t>(blocks), 1);
    const auto dist2 = [&](int j) { return (pl.p[j] - x).squaredNorm(); };
    double smallest = std::numeric_limits<double>::infinity();
    for (int b = 0; b < blocks; ++b) {
        if (pl.blocks[static_cast<size_t>(b)].exteriorDistance(x) > radius) {
            near[static_cast<size_t>(b)] = 0;
            continue;
        }
        for (int j = b * Polyline::kBlock; j < std::min(n, (b + 1) * Polyline::kBlock); ++j)
            smallest = std::min(smallest, dist2(j));
    }
    const double reach = (std::sqrt(smallest) + pl.spacing) * (std::sqrt(smallest) + pl.spacing);
    constexpr double kNone = std::numeric_limits<double>::infinity();
    double best = std::numeric_limits<double>::infinity();
    for (int b = 0; b < blocks; ++b) {
        if (!near[static_cast<size_t>(b)]) continue;
        for (int j = b * Polyline::kBlock; j < std::min(n, (b + 1) * Polyline::kBlock); ++j) {
            const double dj = dist2(j);
            if (dj > reach) continue;
            const double dl = j > 0 ? dist2(j - 1) : (pl.closed ? dist2(n - 1) : kNone);
            const double dr = j + 1 < n ? dist2(j + 1) : (pl.closed ? dist2(0) : kNone);
            if (dj > dl || dj > dr) continue;
            // Each side of the point on its own: the point may be a C0 corner (every span starts a
            // polyline point), where the distance has a minimum on either side and the derivative
            // taken at the corner belongs to one side only (a sample on the side before a corner was
            // measured 0.47 against 0.004 when both sides shared one bracket). Each side is one span's
            // polyline segment, started from its middle.
            for (const auto& [lo, hi] : {std::pair{pl.before(j, T), pl.u[j]}, std::pair{pl.u[j], pl.after(j, T)}}) {
                if (!(hi > lo)) continue;
                double fu = pl.u[j];
                const double e = refineLocal(c, x, lo, hi, 0.5 * (lo + hi), &fu);
                if (e < best) {
                    best = e;
                    if (foot) *foot = c.wrap(fu);
                }
            }
        }
    }
    return best;
}

}  // namespace

SampleDeviation measureSamples(const Curve3d& curve, const std::vector<Eigen::Vector3d>& samples,
                               const std::vector<char>& keep, double resolution, double exactAbove)
{
    if (!(resolution > 0.0) || !std::isfinite(resolution)) throw GeometryError("fit check: resolution must be positive");
    if (!keep.empty() && keep.size() != samples.size()) throw GeometryError("fit check: one keep flag per sample");
    const PowerCurve c(curve);
    Polyline pl;
    pl.closed = c.closed();
    pl.u = c.polylineParameters(resolution);
    pl.p.reserve(pl.u.size());
    for (double u : pl.u) pl.p.push_back(c.point(u));
    for (int j = 0; j + 1 < pl.size() || (pl.closed && j < pl.size()); ++j)
        pl.spacing = std::max(pl.spacing, (pl.p[(j + 1) % pl.size()] - pl.p[j]).norm());

    SampleDeviation out;
    const int m = static_cast<int>(samples.size());
    out.bound.assign(static_cast<size_t>(m), 0.0);
    const int n = pl.size();
    // The samples run along the curve: each starts from the previous one's polyline point and
    // walks downhill along the polyline (a few points per sample), and is searched in full when it
    // ends far from the sample (tracking lost: a seam, a skipped loop). Any polyline point gives a
    // valid bound; the exact projection below settles every sample whose bound could matter.
    int at = -1;
    std::vector<int> near(static_cast<size_t>(m), 0);  // each sample's polyline point
    auto fullScan = [&](const Vec3& x) {
        int bestJ = 0;
        double bd = std::numeric_limits<double>::infinity();
        for (int j = 0; j < n; ++j) {
            const double d = (pl.p[j] - x).squaredNorm();
            if (d < bd) bd = d, bestJ = j;
        }
        return std::make_pair(bestJ, bd);
    };
    auto step = [&](int j, int dir) {
        j += dir;
        if (pl.closed) return (j % n + n) % n;
        return j < 0 || j >= n ? -1 : j;
    };
    for (int i = 0; i < m; ++i) {
        if (!(keep.empty() || keep[i])) continue;
        const Vec3& x = samples[i];
        std::pair<int, double> b;
        if (at < 0) {
            b = fullScan(x);
        } else {
            b = {at, (pl.p[at] - x).squaredNorm()};
            for (const int dir : {1, -1}) {
                for (int j = step(b.first, dir), walked = 0; j >= 0 && walked < n; j = step(j, dir), ++walked) {
                    const double d = (pl.p[j] - x).squaredNorm();
                    if (!(d < b.second)) break;
                    b = {j, d};
                }
            }
            if (std::sqrt(b.second) > 4.0 * resolution) b = fullScan(x);
        }
        at = b.first;
        near[i] = b.first;
        out.bound[i] = std::sqrt(b.second);
    }
    // Exact projection of the samples whose bound could be the maximum, largest bound first: once
    // the exact maximum reaches the next bound, no other sample can exceed it.
    std::vector<int> order;
    std::vector<char> exact(static_cast<size_t>(m), 0);  // bound[i] is sample i's distance
    std::vector<char> scratch;                           // projectGlobal's
    double top = -1.0;
    for (int i = 0; i < m; ++i)
        if ((keep.empty() || keep[i]) && out.bound[i] > top) top = out.bound[i], out.worst = i;
    if (out.worst < 0) return out;
    const int first = out.worst;  // projected in round 0
    for (int round = 0; round < 2; ++round) {
        // Round 0 projects the largest bound only; round 1 every bound above the exact value found
        // or above exactAbove.
        order.clear();
        // (Recomputed per sample: the exact maximum grows as round 1 goes.)
        const auto open = [&](int i) { return out.bound[i] > std::min(out.maxError, exactAbove); };
        for (int i = 0; i < m; ++i)
            if ((keep.empty() || keep[i]) && (round == 0 ? i == first : i != first && open(i))) order.push_back(i);
        std::sort(order.begin(), order.end(), [&](int a, int b) { return out.bound[a] > out.bound[b]; });
        for (int i : order) {
            if (round == 1 && !open(i)) break;
            // Each search starts from the sample's polyline point (round 1 meets no sample whose
            // bound an earlier projection already made exact: that bound is the maximum).
            double foot = pl.u[near[i]];
            if (round == 1) {
                // The polyline bound overestimates by up to half its spacing, so many samples
                // come here: refining beside their own polyline point first (a curve point
                // again, so still a bound) settles most of them without the global search.
                const int j = near[i];
                const double e = refineLocal(c, samples[i], pl.before(j, c.end() - c.start()), pl.after(j, c.end() - c.start()), pl.u[j], &foot);
                if (e < out.bound[i]) out.bound[i] = e;
                if (!open(i)) continue;
            }
            const double e = projectGlobal(c, pl, samples[i], out.bound[i], &foot, scratch);
            if (e < out.bound[i]) out.bound[i] = e;
            exact[static_cast<size_t>(i)] = 1;
            if (out.bound[i] > out.maxError || round == 0) {
                out.maxError = out.bound[i];
                out.worst = i;
            }
        }
    }
    out.maxWithin = out.maxError;
    if (!(out.maxError > exactAbove)) return out;
    // The maximum within exactAbove, as the maximum above: the largest bound projected first, then
    // every bound above the exact value found, largest first, until the exact maximum reaches the
    // next bound.
    int largest = -1;
    for (int i = 0; i < m; ++i)
        if ((keep.empty() || keep[i]) && out.bound[i] <= exactAbove &&
            (largest < 0 || out.bound[i] > out.bound[largest]))
            largest = i;
    out.maxWithin = 0.0;
    if (largest < 0) return out;
    order.assign(1, largest);
    for (int round = 0; round < 2; ++round) {
        if (round == 1) {
            order.clear();
            for (int i = 0; i < m; ++i)
                if ((keep.empty() || keep[i]) && i != largest && out.bound[i] <= exactAbove &&
                    out.bound[i] > out.maxWithin)
                    order.push_back(i);
            std::sort(order.begin(), order.end(), [&](int a, int b) { return out.bound[a] > out.bound[b]; });
        }
        for (int i : order) {
            if (!(out.bound[i] > out.maxWithin)) break;
            if (!exact[static_cast<size_t>(i)]) {
                const int j = near[i];
                double foot = pl.u[j];
                const double e = refineLocal(c, samples[i], pl.before(j, c.end() - c.start()),
                                             pl.after(j, c.end() - c.start()), pl.u[j], &foot);
                if (e < out.bound[i]) out.bound[i] = e;
                if (out.bound[i] > out.maxWithin) {
                    const double g = projectGlobal(c, pl, samples[i], out.bound[i], &foot, scratch);
                    if (g < out.bound[i]) out.bound[i] = g;
                }
            }
            out.maxWithin = std::max(out.maxWithin, out.bound[i]);
        }
    }
    return out;
}

}  // namespace sculptline::solvers::stroke
