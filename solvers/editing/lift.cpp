#include "solvers/editing/lift.h"

#include "solvers/bspline/curve_jet.h"
#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/projection.h"
#include "solvers/editing/constrained_fit.h"

#include <algorithm>
#include <cmath>

namespace sculptline::solvers::editing {
namespace {

// Reading of seed 004 chosen here (the PDF text leaves it open): Alg. 2 spaces depths "equally
// among all points of CriticalList"; §3.1 justifies this by Theorem 1 holding "for each of the
// subdivided curve segments". Theorem 1 says more: the equally spaced control depths make the depth
// linear in the Bézier parameter t (Σ B_i(t)·i/n = t). Alg. 1's critical points (extrema of the
// distance from the chord) sit at equally spaced t only for symmetric arcs; on an S-shaped cubic
// they sit at t = 0.211 / 0.789 (roots of 1 - 6t + 6t², chord distance 27t(1-t)(1-2t)), not 1/3 and
// 2/3. Measured on the S cubic (0,0) (1,9) (9,-9) (10,0), depth range 10, max 3D distance to the
// Theorem 1 Bézier: critical depths as Alg. 2 assigns them 0.89 (filter off 0.91, so not the
// filter); the same critical points with their true t and arc-length interpolation between them
// 0.07 (so not the interpolation): the error is in the critical points' depths. The default
// (DepthModel::FittedParameter) therefore takes t from a cubic fitted with parameter correction
// and sets z linear in it: 0.005 on the S cubic, 0.001 / 0.001 / 0.016 / 0.002 / 0.001 on the
// parabola, the symmetric and asymmetric arcs, a second S and a loop-like arc (the Laplacian filter
// accounts for the 0.005; the asymmetric arc's parameter correction for the 0.016). The critical
// points are still computed and reported (Alg. 1). CriticalPoints keeps Alg. 2 as written, with
// Theorem 1 per recursion level (hierarchicalDepths), which beat the flat list when the recursion
// depths are uneven (parabola at threshold 0.003: 0.45 flat). More filter passes help little and
// cost locality, so "a few" = 10.
// Points closer than this fraction of the stroke's extent are one point (pen repeats).
constexpr double kDuplicateRelative = 1e-9;

// One level of Alg. 1 on pts[a..b] plus the recursion. Each critical point is returned with its
// level-wise depth fraction: the k points found on a segment whose ends have fractions fa and fb get
// fa + (fb - fa)·j/(k+1), i.e. Theorem 1 applied to every de Casteljau sub-curve (§3.1: "the above
// theorem still holds good for each of the subdivided curve segments").
void collectCritical(const std::vector<Eigen::Vector2d>& pts, int a, int b, double fa, double fb, double thr,
                     std::vector<std::pair<int, double>>& out)
{
    if (b - a < 2) return;
    const Eigen::Vector2d chord = pts[b] - pts[a];
    const double len = chord.norm();
    std::vector<double> d(b - a + 1, 0.0);
    for (int i = a; i <= b; ++i) {
        const Eigen::Vector2d r = pts[i] - pts[a];
        // Signed distance from the chord line; a closed segment (ends together) has no chord, so
        // the distance from its start point takes its place.
        d[i - a] = len > thr * 1e-6 ? (chord.x() * r.y() - chord.y() * r.x()) / len : r.norm();
    }
    // Extrema with hysteresis: a maximum is confirmed once the distance has dropped `thr` below it,
    // a minimum once it has risen `thr` above it (Alg. 1's R: extrema within thr of L are dropped).
    std::vector<int> cs;
    int hi = 0, lo = 0, mode = 0;  // mode +1: looking for a maximum, -1: a minimum, 0: either
    for (int i = 1; i <= b - a; ++i) {
        if (d[i] > d[hi]) hi = i;
        if (d[i] < d[lo]) lo = i;
        if (mode >= 0 && hi > 0 && hi < b - a && d[hi] - d[i] > thr) {
            if (std::abs(d[hi]) > thr) cs.push_back(a + hi);
            mode = -1;
            lo = i;
        } else if (mode <= 0 && lo > 0 && lo < b - a && d[i] - d[lo] > thr) {
            if (std::abs(d[lo]) > thr) cs.push_back(a + lo);
            mode = +1;
            hi = i;
        }
    }
    if (cs.empty()) return;  // Alg. 1's terminating condition: the segment is close to its chord
    const int k = static_cast<int>(cs.size());
    int prev = a;
    double fprev = fa;
    cs.push_back(b);
    for (int j = 0; j <= k; ++j) {
        const double f = j < k ? fa + (fb - fa) * (j + 1) / (k + 1) : fb;
        collectCritical(pts, prev, cs[j], fprev, f, thr, out);
        if (j < k) out.emplace_back(cs[j], f);
        prev = cs[j];
        fprev = f;
    }
}

// Parameter correction (Hoschek 1988, "Intrinsic parametrization for approximation"; The NURBS
// Book §9.4.1 leaves the parameters fixed): least-squares cubic fit, then each point's parameter
// moved to its foot point on the fit by Newton steps, repeated. For data on a cubic Bézier the
// fixed point is the Bézier's own parameter. The iteration converges linearly: a single span (a
// Bézier) gets up to kCorrections passes, which bring the Theorem 1 tests' depths within 2e-3 of
// the range (measured); a stroke that needs more spans is no Bézier, the fixed point is no longer
// unique, and kCorrectionsSpline passes remove the chord-length parameters' first-order error at a
// bounded cost (a 500-point zigzag: 185 ms with 200 passes per span count, 15 ms with 20).
constexpr int kCorrections = 200;
constexpr int kCorrectionsSpline = 20;
constexpr double kParameterConverged = 1e-7;
// Tolerance of that fit, fraction of the stroke's length: pen jitter is of this order (a 0.2%
// jitter on the S cubic made the 1e-3 output tolerance split the fit into spans and cost 2.7% of
// the depth range against Theorem 1; at 0.5% the single Bézier is kept: 0.3%).
constexpr double kParameterFitTolerance = 0.005;

// The parameter in [0, 1] of each point (first 0, last 1, non-decreasing) of the cubic B-spline
// with the fewest uniform spans (1, 2, 4, ..) that fits the points within `tol` after correction.
std::vector<double> fittedParameters(const std::vector<Eigen::Vector2d>& pts, double tol)
{
    const int n = static_cast<int>(pts.size());
    const std::vector<double> s = chordLengths<2>(pts);
    std::vector<double> t(n);
    for (int i = 0; i < n; ++i) t[i] = s[i] / s.back();
    const int maxSpans = std::max(1, (n - 1) / 8);  // at least 8 points per span
    for (int spans = 1;; spans *= 2) {
        std::vector<double> u = t;
        FixedKnotFit<2> fit;
        fit.degree = 3;
        fit.knots = clampedUniformKnots(3, spans);
        fit.samples = pts;
        fit.fixed.assign(spans + 3, std::nullopt);
        fit.fixed.front() = pts.front();
        fit.fixed.back() = pts.back();
        double err = 0.0;
        for (int pass = 0; pass < (spans == 1 ? kCorrections : kCorrectionsSpline); ++pass) {
            fit.params = u;
            const CurveJet2d c(Curve2d(3, fit.knots, fitFixedKnots(fit)));
            double moved = 0.0;
            err = 0.0;
            for (int i = 1; i + 1 < n; ++i) {
                // One Newton step on (C(x) - p)·C'(x) = 0 per pass (the passes iterate anyway);
                // the error is the fit's at the parameters it was made with (a distance bound).
                Eigen::Vector2d x, d1, d2;
                c.evaluate(u[i], x, d1, d2);
                err = std::max(err, (x - pts[i]).norm());
                const double before = u[i];
                if (!footPointNewtonStep(x, d1, d2, pts[i], 0.0, 1.0, u[i])) continue;
                moved = std::max(moved, std::abs(u[i] - before));
            }
            if (moved < kParameterConverged) break;
            // A single span still off by more than the tolerance after the spline's passes is no
            // Bézier: the remaining passes would only polish a fit that more spans replace.
            if (pass + 1 >= kCorrectionsSpline && err > tol) break;
        }
        for (int i = 1; i < n; ++i) u[i] = std::max(u[i], u[i - 1]);
        if (err <= tol || 2 * spans > maxSpans) return u;
    }
}

}  // namespace

std::vector<int> criticalPoints(const std::vector<Eigen::Vector2d>& pts, double threshold)
{
    std::vector<std::pair<int, double>> found;
    if (pts.size() >= 3) collectCritical(pts, 0, static_cast<int>(pts.size()) - 1, 0.0, 1.0, threshold, found);
    std::vector<int> out;
    for (const auto& f : found) out.push_back(f.first);
    return out;
}

LiftResult liftStroke(const std::vector<Eigen::Vector2d>& stroke, double z0, double z1, const LiftOptions& options,
                      const ViewFrame& view)
{
    if (!std::isfinite(z0) || !std::isfinite(z1)) throw GeometryError("depth: not a finite number");
    for (size_t i = 0; i < stroke.size(); ++i) {
        if (!stroke[i].allFinite())
            throw GeometryError("stroke.points[" + std::to_string(i) + "]: not a finite number");
    }
    if (options.samples < 3 || !(options.lambda > 0.0 && options.lambda < 1.0) || options.filterIterations < 0 ||
        !(options.linearityThreshold > 0.0) || !(options.fitTolerance > 0.0)) {
        throw GeometryError("options: samples >= 3, lambda in (0, 1), iterations >= 0, thresholds > 0 required");
    }
    double extent = 0.0;
    for (const auto& p : stroke) extent = std::max(extent, (p - stroke.front()).norm());
    const auto clean = dropDuplicates<2>(stroke, kDuplicateRelative * extent);
    if (clean.size() < 2 || extent == 0.0) throw GeometryError("stroke.points: need at least two distinct points");

    std::vector<Eigen::Vector3d> lifted;
    std::vector<int> critical;
    const auto pts = resampleByArcLength<2>(clean, options.samples);
    const std::vector<double> s = chordLengths<2>(pts);
    const int n = static_cast<int>(pts.size());

    // Alg. 2: equally spaced depths over first ∪ critical ∪ last (Theorem 1), arc-length in between.
    std::vector<std::pair<int, double>> found;
    collectCritical(pts, 0, n - 1, 0.0, 1.0, options.linearityThreshold * s.back(), found);
    critical.push_back(0);
    std::vector<double> fraction = {0.0};
    for (const auto& f : found) {
        critical.push_back(f.first);
        fraction.push_back(f.second);
    }
    critical.push_back(n - 1);
    fraction.push_back(1.0);
    std::vector<double> z(n, z0);
    if (options.depths == DepthModel::FittedParameter) {
        // Theorem 1 directly: depth linear in the (fitted) curve parameter.
        const std::vector<double> t = fittedParameters(pts, kParameterFitTolerance * s.back());
        for (int i = 0; i < n; ++i) z[i] = z0 + (z1 - z0) * t[i];
    } else {
        const int k = static_cast<int>(critical.size());
        for (int j = 0; j + 1 < k; ++j) {
            const int a = critical[j], b = critical[j + 1];
            const double ta = options.hierarchicalDepths ? fraction[j] : double(j) / (k - 1);
            const double tb = options.hierarchicalDepths ? fraction[j + 1] : double(j + 1) / (k - 1);
            const double za = z0 + (z1 - z0) * ta, zb = z0 + (z1 - z0) * tb;
            for (int i = a; i <= b; ++i) {
                const double t = s[b] > s[a] ? (s[i] - s[a]) / (s[b] - s[a]) : 0.0;
                z[i] = za + t * (zb - za);
            }
        }
    }
    // Laplacian filter on interior depths only, so the ends keep z0 and z1 and nothing shrinks.
    std::vector<double> next = z;
    for (int it = 0; it < options.filterIterations; ++it) {
        for (int i = 1; i + 1 < n; ++i) next[i] = z[i] + options.lambda * (0.5 * (z[i - 1] + z[i + 1]) - z[i]);
        z.swap(next);
        next.front() = z.front();
        next.back() = z.back();
    }

    std::vector<Eigen::Vector3d> world(n);
    for (int i = 0; i < n; ++i) {
        lifted.emplace_back(pts[i].x(), pts[i].y(), z[i]);
        world[i] = view.origin + pts[i].x() * view.right + pts[i].y() * view.up + z[i] * view.depth;
    }

    // The output cubic: clamped uniform knots on chord-length parameters, spans doubled until the
    // fit is within tolerance (ends interpolated).
    const std::vector<double> c3 = chordLengths<3>(world);
    const double total = c3.back() > 0.0 ? c3.back() : 1.0;
    FixedKnotFit<3> fit;
    fit.degree = 3;
    for (double v : c3) fit.params.push_back(v / total);
    fit.samples = world;
    for (int spans = 1;; spans *= 2) {
        fit.knots = clampedUniformKnots(3, spans);
        fit.fixed.assign(spans + 3, std::nullopt);
        fit.fixed.front() = world.front();
        fit.fixed.back() = world.back();
        Curve3d curve(3, fit.knots, fitFixedKnots(fit));
        double err = 0.0;
        for (int i = 0; i < n; ++i) err = std::max(err, (curve.evaluate(fit.params[i]) - world[i]).norm());
        if (err <= options.fitTolerance * total || 2 * spans + 3 > n) {
            return LiftResult{std::move(lifted), std::move(critical), std::move(curve), err};
        }
    }
}

}  // namespace sculptline::solvers::editing
