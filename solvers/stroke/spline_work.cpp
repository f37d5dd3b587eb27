#include "solvers/stroke/spline_work.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/projection.h"
#include "solvers/stroke/banded_cholesky.h"

#include <optional>

namespace sculptline::solvers::stroke::detail {

// One Newton step on f(u) = C'(u).(C(u) - x) (The NURBS Book eq. 6.3), kept inside [lo, hi].
double newtonStep(const Spline& s, const Vec3& x, double u, double lo, double hi)
{
    Vec3 c[3];
    s.eval(u, c);
    footPointNewtonStep(c[0], c[1], c[2], x, lo, hi, u);
    return u;
}

double distanceAt(const Spline& s, const Vec3& x, double u) { return (s.point(u) - x).norm(); }

// Distance from x to the curve near parameter u: |C(u) - x| when that is within `tol`, else the
// best of up to two Newton steps toward the foot point (inside [lo, hi]). Either way the distance
// to an actual curve point, so an upper bound on the true distance; the Newton steps (costly
// derivatives) are spent only where the cheap bound does not already settle the question.
double footDistance(const Spline& s, const Vec3& x, double u, double lo, double hi, double tol, double* foot)
{
    double best = distanceAt(s, x, u), bestU = u;
    // Each Newton step needs C, C' and C'' at the current u; the evaluation that measures the
    // distance at a new u also serves the next step, so a step costs one evaluation, not two.
    Vec3 c[3];
    if (best > tol) s.eval(u, c);
    for (int it = 0; it < 2 && best > tol; ++it) {
        if (!footPointNewtonStep(c[0], c[1], c[2], x, lo, hi, u)) break;
        s.eval(u, c);
        const double d = (c[0] - x).norm();
        if (d < best) {
            best = d;
            bestU = u;
        }
    }
    if (foot) *foot = bestU;
    return best;
}

// Distance from C(u) to the segment [a, b]. The fit counts it as an error only beyond a quarter of
// the segment's length (an excursion where no data holds the curve): a smooth curve through a and
// b bulges from their chord by its sagitta, which is geometry, not error.
double rawChordGap(const Spline& s, const Vec3& a, const Vec3& b, double u)
{
    const Vec3 c = s.point(u);
    const Vec3 ab = b - a;
    const double l2 = ab.squaredNorm();
    const double t = l2 > 0.0 ? std::clamp((c - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
    return (a + t * ab - c).norm();
}

void spanSums(const Spline& s, const std::vector<Vec3>& X, const std::vector<int>& S, const std::vector<double>& u,
              int first, int last, std::vector<SpanSums>& sums, const std::vector<double>* weights)
{
    const int spans = s.spanCount();
    if (static_cast<int>(sums.size()) < spans) sums.resize(spans);
    for (int i = first; i <= last; ++i) sums[i] = SpanSums{};
    // The interior samples (the end samples are the fixed P_0 and P_n) from span `first` on, in
    // increasing parameter: walk the spans instead of searching for each.
    const size_t kEnd = S.size() - 1;
    size_t k = static_cast<size_t>(std::lower_bound(u.begin() + 1, u.begin() + static_cast<long>(kEnd), s.breaks[first]) - u.begin());
    // The basis of one span at many samples: the knot differences' reciprocals once per span (the
    // breaks are distinct, so every span is non-empty, as SpanBasis requires).
    // (Each span's sums are added up in a local, stored when the samples move on to the next span:
    // the same additions in the same order, without a load and store of the sums per sample.)
    double basis[kDegree + 1];
    int i = first;
    SpanBasis<kDegree> spanBasis(s.knots, i + kDegree);
    SpanSums acc;
    for (; k < kEnd; ++k) {
        if (i < spans - 1 && u[k] >= s.breaks[i + 1]) {
            sums[i] = acc;
            acc = SpanSums{};
            while (i < spans - 1 && u[k] >= s.breaks[i + 1]) ++i;
            if (i > last) return;
            spanBasis = SpanBasis<kDegree>(s.knots, i + kDegree);
        }
        spanBasis.functions(u[k], basis);
        acc.add(basis, weights ? (*weights)[k] : 1.0, X[S[k]]);
    }
    if (i <= last) sums[i] = acc;
}

void updateSpanSums(const Spline& s, const std::vector<double>& oldBreaks, const std::vector<SpanSums>& oldSums,
                    const std::vector<Vec3>& X, const std::vector<int>& S, const std::vector<double>& u,
                    std::vector<SpanSums>& sums)
{
    const int spans = s.spanCount();
    sums.resize(static_cast<size_t>(spans));
    const int oldSpans = static_cast<int>(oldBreaks.size()) - 1;
    // Span i's basis functions depend on the breaks b_{i-2}..b_{i+3} (the clamped ends repeat b_0 and
    // b_last): a span whose six breaks were six consecutive breaks before has the same sums.
    const auto br = [](const std::vector<double>& b, int k) { return b[static_cast<size_t>(std::clamp(k, 0, static_cast<int>(b.size()) - 1))]; };
    int j = 0;  // old span starting at s.breaks[i], if any
    int runStart = -1;
    for (int i = 0; i <= spans; ++i) {
        bool same = false;
        if (i < spans) {
            while (j < oldSpans && oldBreaks[static_cast<size_t>(j)] < s.breaks[static_cast<size_t>(i)]) ++j;
            if (j < oldSpans && oldBreaks[static_cast<size_t>(j)] == s.breaks[static_cast<size_t>(i)]) {
                same = true;
                for (int q = -2; same && q <= 3; ++q) same = br(oldBreaks, j + q) == br(s.breaks, i + q);
                if (same) sums[static_cast<size_t>(i)] = oldSums[static_cast<size_t>(j)];
            }
        }
        if (!same && i < spans && runStart < 0) runStart = i;
        if ((same || i == spans) && runStart >= 0) {
            spanSums(s, X, S, u, runStart, i - 1, sums);
            runStart = -1;
        }
    }
}

void sumsWithoutBreak(Spline& t, int r, const std::vector<Vec3>& X, const std::vector<int>& S,
                      const std::vector<double>& u, const std::vector<SpanSums>& sums, std::vector<SpanSums>& out)
{
    t.breaks.erase(t.breaks.begin() + r);
    t.makeKnots();
    // Spans r-3..r+2 depend on the removed break (span i's basis functions depend on the breaks
    // b_{i-2}..b_{i+3}, the clamped ends repeating b_0 and b_last); they become spans r-3..r+1,
    // summed again. The others keep their sums, shifted by one past the break.
    const int spans = t.spanCount();
    const int lo = std::max(0, r - 3), hi = std::min(spans - 1, r + 1);
    out.resize(static_cast<size_t>(spans));
    std::copy(sums.begin(), sums.begin() + lo, out.begin());
    std::copy(sums.begin() + hi + 2, sums.end(), out.begin() + hi + 1);
    spanSums(t, X, S, u, lo, hi, out);
}

// The normal equations of the open least squares assembled span by span from the sums, with the
// fairing term; P_0 = X_first and P_n = X_last are fixed (The NURBS Book eqs. 9.63-9.67: the
// fixed points move to the right-hand side).
void solveOpenFromSums(Spline& s, const std::vector<Vec3>& X, const std::vector<int>& S,
                       const std::vector<SpanSums>& sums, double fairing)
{
    const int nCtrl = s.unknowns();
    const int nFree = nCtrl - 2;
    const Vec3 first = X[S.front()], last = X[S.back()];
    const auto fixedPoint = [&](int c) -> const Vec3* { return c == 0 ? &first : (c == nCtrl - 1 ? &last : nullptr); };
    // Storage kept between solves, as solve()'s sums.
    thread_local BandMatrix a;
    thread_local std::vector<Vec3> b;
    a.reset(nFree, kDegree);
    b.assign(static_cast<size_t>(nFree), Vec3::Zero());
    for (int i = 0; i < s.spanCount(); ++i) {
        const SpanSums& t = sums[i];
        if (i > 0 && i + kDegree < nCtrl - 1) {
            // An interior span: no fixed point among its control points i..i+3 (free unknowns
            // i-1..i+2), so its sums go straight into the band, row by row (entry (row, row - d) at
            // offset d of the row), in the same order as below.
            for (int q = 0; q <= kDegree; ++q) {
                const int row = i + q - 1;
                b[row] += t.r[q];
                double* band = &a.at(row, row);
                for (int r = 0; r <= q; ++r) band[q - r] += t.g[q][r];
            }
            continue;
        }
        for (int q = 0; q <= kDegree; ++q) {
            const int cq = i + q;  // control point of basis q on span i
            if (fixedPoint(cq)) continue;
            b[cq - 1] += t.r[q];
            for (int r = 0; r <= kDegree; ++r) {
                const double g = r <= q ? t.g[q][r] : t.g[r][q];
                if (const Vec3* fixed = fixedPoint(i + r)) b[cq - 1] -= g * *fixed;
                else if (r <= q) a.at(cq - 1, i + r - 1) += g;
            }
        }
    }
    const double lambda = fairing * std::max(1.0, static_cast<double>(S.size()) / nCtrl);
    for (int c = 1; c + 1 < nCtrl; ++c) {  // rows (1, -2, 1) on control points c-1, c, c+1
        const int idx[3] = {c - 1, c, c + 1};
        const double w[3] = {1.0, -2.0, 1.0};
        Vec3 fixedPart = Vec3::Zero();
        for (int t = 0; t < 3; ++t) {
            if (idx[t] == 0) fixedPart += w[t] * first;
            if (idx[t] == nCtrl - 1) fixedPart += w[t] * last;
        }
        for (int t = 0; t < 3; ++t) {
            const int i = idx[t] - 1;
            if (i < 0 || i >= nFree) continue;
            b[i] -= lambda * w[t] * fixedPart;
            for (int r = 0; r <= t; ++r) {
                const int j = idx[r] - 1;
                if (j >= 0) a.add(i, j, lambda * w[t] * w[r]);
            }
        }
    }
    if (!a.factor()) throw GeometryError("stroke: least-squares system is not positive definite");
    a.solveInPlace(b);
    s.ctrl.assign(nCtrl, Vec3::Zero());
    s.ctrl.front() = first;
    s.ctrl.back() = last;
    for (int i = 0; i < nFree; ++i) s.ctrl[i + 1] = b[i];
    s.buildPowerForm();
}

// Periodic least squares: unknowns c_0..c_{N-1}, unwrapped point i is c_{i mod N}; the normal
// matrix is cyclic-banded (half-bandwidth 3), solved in O(N) by CyclicBandMatrix. (Until session 44
// it was assembled dense and factored by a dense Cholesky up to 96 unknowns, by a sparse LDL^T
// beyond: O(N^3) on the loops' trials, about half the instructions of a 35-point development
// circle's fit.)
// The periodic normal equations into a (lower triangle) and b. The samples' terms are summed per
// span first (the span's four basis functions, evaluated with SpanBasis's reciprocals of the knot
// differences) and added to the matrix once per run of samples in a span: a loop's samples come
// in increasing parameter, but the first can wrap round the seam into the last span.
void assembleClosed(const Spline& s, const std::vector<Vec3>& X, const std::vector<int>& S,
                    const std::vector<double>& u, const std::vector<double>* weights, double lambda,
                    CyclicBandMatrix& a, std::vector<Vec3>& b)
{
    const int n = s.unknowns();
    int run = -1;  // the span whose sums t hold (its control points run..run+3 modulo n)
    SpanSums t;
    const auto flush = [&] {
        if (run < 0) return;
        int idx[kDegree + 1];
        for (int q = 0; q <= kDegree; ++q) idx[q] = (run + q) % n;
        for (int q = 0; q <= kDegree; ++q) {
            b[static_cast<size_t>(idx[q])] += t.r[q];
            for (int c = 0; c <= q; ++c) a.addLower(std::max(idx[q], idx[c]), std::min(idx[q], idx[c]), t.g[q][c]);
        }
    };
    std::optional<SpanBasis<kDegree>> basis;
    for (size_t k = 0; k < S.size(); ++k) {
        const double uk = s.wrap(u[k]);
        const int j = s.spanOf(uk);  // the periodic knots' span j + 3 starts at break j
        if (j != run) {
            flush();
            run = j;
            basis.emplace(s.knots, j + kDegree);
            t = SpanSums{};
        }
        double nk[kDegree + 1];
        basis->functions(uk, nk);
        t.add(nk, weights ? (*weights)[k] : 1.0, X[S[k]]);
    }
    flush();
    // The fairing term: rows (1, -2, 1) on control points c-1, c, c+1 modulo n.
    for (int c = 0; c < n; ++c) {
        const int idx[3] = {(c + n - 1) % n, c, (c + 1) % n};
        const double w[3] = {1.0, -2.0, 1.0};
        for (int t = 0; t < 3; ++t)
            for (int q = 0; q < 3; ++q)
                if (idx[t] >= idx[q]) a.addLower(idx[t], idx[q], lambda * w[t] * w[q]);
    }
}

void solveClosed(Spline& s, const std::vector<Vec3>& X, const std::vector<int>& S, const std::vector<double>& u,
                 double fairing, const std::vector<double>* weights)
{
    const int n = s.unknowns();
    // (The fitters start a loop at five spans and never go below: a guard, not a case.)
    if (n <= CyclicBandMatrix::kBandwidth)
        throw GeometryError("stroke: a closed cubic needs at least 4 control points");
    const double lambda = fairing * std::max(1.0, static_cast<double>(S.size()) / n);
    // Storage kept between solves.
    static_assert(CyclicBandMatrix::kBandwidth == kDegree, "the normal matrix of a periodic cubic");
    thread_local CyclicBandMatrix a;
    thread_local std::vector<Vec3> b;
    a.reset(n);
    b.assign(static_cast<size_t>(n), Vec3::Zero());
    assembleClosed(s, X, S, u, weights, lambda, a, b);
    if (!a.factor()) throw GeometryError("stroke: periodic least-squares system is singular");
    a.solveInPlace(b);
    s.ctrl.resize(n + kDegree);
    for (int i = 0; i < n + kDegree; ++i) s.ctrl[i] = b[static_cast<size_t>(i % n)];
}

void solve(Spline& s, const std::vector<Vec3>& X, const std::vector<int>& S, const std::vector<double>& u,
           double fairing, const std::vector<double>* weights)
{
    s.makeKnots();
    if (s.closed) {
        solveClosed(s, X, S, u, fairing, weights);
        s.buildPowerForm();
        return;
    }
    // The sums' storage is kept between solves (a fit solves a few dozen times; spanSums zeroes
    // the spans it sums, and solveOpenFromSums reads the first spanCount() only).
    thread_local std::vector<SpanSums> sums;
    spanSums(s, X, S, u, 0, s.spanCount() - 1, sums, weights);
    solveOpenFromSums(s, X, S, sums, fairing);
}

}  // namespace sculptline::solvers::stroke::detail
