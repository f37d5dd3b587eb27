#include "solvers/stroke/lsq_fit.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/stroke/banded_cholesky.h"

#include <Eigen/Sparse>
#include <algorithm>
#include <array>
#include <cmath>

namespace sculptline::solvers::stroke {
namespace {

constexpr int kDegree = 3;
using Vec3 = Eigen::Vector3d;

double safeDiv(double a, double b) { return b == 0.0 ? 0.0 : a / b; }  // 0/0 := 0 for repeated knots

// The spline being fitted: distinct breakpoints (open: 0 = b_0 < .. < b_s = 1; closed: 0 = b_0 < .. <
// b_{N-1} < 1, period 1), the full knot vector and the (unwrapped) control points.
struct Spline {
    bool closed = false;
    std::vector<double> breaks;
    KnotVector knots;
    std::vector<Vec3> ctrl;

    int unknowns() const { return closed ? static_cast<int>(breaks.size()) : static_cast<int>(breaks.size()) + 2; }
    void makeKnots()
    {
        knots.clear();
        if (!closed) {
            knots.assign(kDegree, 0.0);
            knots.insert(knots.end(), breaks.begin(), breaks.end());
            knots.insert(knots.end(), kDegree, 1.0);
            return;
        }
        // Periodic: U_i = b_{(i-3) mod N} + floor((i-3)/N), i = 0..N+6, so that U_3 = b_0 = 0 and U_{N+3} = 1.
        const int n = static_cast<int>(breaks.size());
        for (int i = 0; i <= n + 2 * kDegree; ++i) {
            const int j = i - kDegree;
            const int q = j >= 0 ? j / n : -((-j + n - 1) / n);
            knots.push_back(breaks[j - q * n] + q);
        }
    }
    double wrap(double u) const { return closed ? u - std::floor(u) : std::clamp(u, 0.0, 1.0); }
    // The spline in power form per span (Taylor coefficients at the span start): evaluation is a
    // Horner step, an order of magnitude cheaper than the basis recursion, and the fit evaluates
    // every point a few times per iteration.
    std::vector<std::array<Vec3, 4>> coef;
    int spanCount() const { return static_cast<int>(closed ? breaks.size() : breaks.size() - 1); }
    double spanEnd(int j) const { return j + 1 < static_cast<int>(breaks.size()) ? breaks[j + 1] : 1.0; }
    void buildPowerForm()
    {
        coef.resize(spanCount());
        for (int j = 0; j < spanCount(); ++j) {
            const double a = breaks[j], h = spanEnd(j) - a;
            const int span = findSpan(kDegree, knots, a);
            double d0[3][4], d1[3][4];
            cubicBasisDerivatives(knots, span, a, d0);
            cubicBasisDerivatives(knots, span, a + h, d1);
            Vec3 c[3], e2 = Vec3::Zero();
            for (int k = 0; k < 3; ++k) c[k].setZero();
            for (int q = 0; q < 4; ++q) {
                const Vec3& p = ctrl[span - kDegree + q];
                for (int k = 0; k < 3; ++k) c[k] += d0[k][q] * p;
                e2 += d1[2][q] * p;
            }
            coef[j] = {c[0], c[1], 0.5 * c[2], h > 0.0 ? (e2 - c[2]) / (6.0 * h) : Vec3::Zero().eval()};
        }
    }
    // Point and first two derivatives at u.
    void eval(double u, Vec3 out[3]) const
    {
        u = wrap(u);
        const int j = spanOf(u);
        const double t = u - breaks[j];
        const auto& c = coef[j];
        out[0] = ((c[3] * t + c[2]) * t + c[1]) * t + c[0];
        out[1] = (3.0 * c[3] * t + 2.0 * c[2]) * t + c[1];
        out[2] = 6.0 * c[3] * t + 2.0 * c[2];
    }
    Vec3 point(double u) const
    {
        u = wrap(u);
        const int j = spanOf(u);
        const double t = u - breaks[j];
        const auto& c = coef[j];
        return ((c[3] * t + c[2]) * t + c[1]) * t + c[0];
    }
    // Index into breaks of the span holding u (u already wrapped). Evaluations mostly come in
    // increasing u, so the last span found, or the next one, is tried before a binary search.
    mutable int hint = 0;
    int spanOf(double u) const
    {
        const int count = spanCount();
        for (int j = hint; j < std::min(hint + 2, count); ++j) {
            if (u >= breaks[j] && (u < spanEnd(j) || j == count - 1) && (j > 0 || u >= 0.0)) return hint = j;
        }
        const auto it = std::upper_bound(breaks.begin(), breaks.end(), u);
        return hint = std::clamp(static_cast<int>(it - breaks.begin()) - 1, 0, count - 1);
    }
};

// The four non-zero cubic B-splines on `span` at u: The NURBS Book A2.2 unrolled for p = 3.
void cubicBasis(const KnotVector& U, int span, double u, double N[4])
{
    double left[4], right[4];
    N[0] = 1.0;
    for (int j = 1; j <= kDegree; ++j) {
        left[j] = u - U[span + 1 - j];
        right[j] = U[span + j] - u;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            const double den = right[r + 1] + left[j - r];
            const double temp = den != 0.0 ? N[r] / den : 0.0;
            N[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        N[j] = saved;
    }
}

// One Newton step on f(u) = C'(u).(C(u) - x) (The NURBS Book eq. 6.3), kept inside [lo, hi].
double newtonStep(const Spline& s, const Vec3& x, double u, double lo, double hi)
{
    Vec3 c[3];
    s.eval(u, c);
    const Vec3 r = c[0] - x;
    const double f = c[1].dot(r);
    const double df = c[2].dot(r) + c[1].squaredNorm();
    if (!(df > 0.0)) return u;
    return std::clamp(u - f / df, lo, hi);
}

double distanceAt(const Spline& s, const Vec3& x, double u) { return (s.point(u) - x).norm(); }

// Distance from x to the curve near parameter u: |C(u) - x| when that is within `tol`, else the
// best of up to two Newton steps toward the foot point (inside [lo, hi]). Either way the distance
// to an actual curve point, so an upper bound on the true distance; the Newton steps (costly
// derivatives) are spent only where the cheap bound does not already settle the question.
double footDistance(const Spline& s, const Vec3& x, double u, double lo, double hi, double tol, double* foot = nullptr)
{
    double best = distanceAt(s, x, u), bestU = u;
    for (int it = 0; it < 2 && best > tol; ++it) {
        u = newtonStep(s, x, u, lo, hi);
        const double d = distanceAt(s, x, u);
        if (d < best) {
            best = d;
            bestU = u;
        }
    }
    if (foot) *foot = bestU;
    return best;
}

// Distance from C(u) to the segment [a, b] when the curve leaves it by more than a quarter of the
// segment's length (an excursion where no data holds the curve), else 0: a smooth curve through
// a and b bulges from their chord by its sagitta, which is geometry, not error.
double chordGap(const Spline& s, const Vec3& a, const Vec3& b, double u)
{
    const Vec3 c = s.point(u);
    const Vec3 ab = b - a;
    const double l2 = ab.squaredNorm();
    const double t = l2 > 0.0 ? std::clamp((c - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
    const double gap = (a + t * ab - c).norm();
    return gap > 0.25 * std::sqrt(l2) ? gap : 0.0;
}

// Least squares with the fairing term; open curves keep P_0 = X_first and P_n = X_last fixed
// (The NURBS Book eqs. 9.63-9.67: the fixed points move to the right-hand side).
void solveOpen(Spline& s, const std::vector<Vec3>& X, const std::vector<int>& S, const std::vector<double>& u,
               double fairing)
{
    const int nCtrl = s.unknowns();
    const int nFree = nCtrl - 2;
    const Vec3 first = X[S.front()], last = X[S.back()];
    BandMatrix a(nFree, kDegree);
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(nFree, 3);
    double basis[kDegree + 1];
    int span = kDegree;
    for (size_t k = 1; k + 1 < S.size(); ++k) {
        // Samples come in increasing parameter: walk the span instead of searching for it.
        while (span < nCtrl - 1 && u[k] >= s.knots[span + 1]) ++span;
        cubicBasis(s.knots, span, u[k], basis);
        Vec3 rhs = X[S[k]];
        for (int q = 0; q <= kDegree; ++q) {
            const int i = span - kDegree + q;
            if (i == 0) rhs -= basis[q] * first;
            if (i == nCtrl - 1) rhs -= basis[q] * last;
        }
        for (int q = 0; q <= kDegree; ++q) {
            const int i = span - kDegree + q - 1;  // unknown index
            if (i < 0 || i >= nFree) continue;
            b.row(i) += basis[q] * rhs.transpose();
            for (int r = 0; r <= q; ++r) {
                const int j = span - kDegree + r - 1;
                if (j >= 0) a.add(i, j, basis[q] * basis[r]);
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
            b.row(i) -= lambda * w[t] * fixedPart.transpose();
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
    for (int i = 0; i < nFree; ++i) s.ctrl[i + 1] = b.row(i).transpose();
}

// Periodic least squares: unknowns c_0..c_{N-1}, unwrapped point i is c_{i mod N}; the normal
// matrix is cyclic-banded, factored by a sparse LDL^T (fill-in stays O(N) for a cyclic band).
void solveClosed(Spline& s, const std::vector<Vec3>& X, const std::vector<int>& S, const std::vector<double>& u,
                 double fairing)
{
    const int n = s.unknowns();
    std::vector<Eigen::Triplet<double>> trip;
    trip.reserve(S.size() * 16 + static_cast<size_t>(n) * 9);
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(n, 3);
    double basis[kDegree + 1];
    for (size_t k = 0; k < S.size(); ++k) {
        const double uk = s.wrap(u[k]);
        const int span = findSpan(kDegree, s.knots, uk);
        cubicBasis(s.knots, span, uk, basis);
        for (int q = 0; q <= kDegree; ++q) {
            const int i = (span - kDegree + q) % n;
            b.row(i) += basis[q] * X[S[k]].transpose();
            for (int r = 0; r <= kDegree; ++r) trip.emplace_back(i, (span - kDegree + r) % n, basis[q] * basis[r]);
        }
    }
    const double lambda = fairing * std::max(1.0, static_cast<double>(S.size()) / n);
    for (int c = 0; c < n; ++c) {
        const int idx[3] = {(c + n - 1) % n, c, (c + 1) % n};
        const double w[3] = {1.0, -2.0, 1.0};
        for (int t = 0; t < 3; ++t)
            for (int r = 0; r < 3; ++r) trip.emplace_back(idx[t], idx[r], lambda * w[t] * w[r]);
    }
    Eigen::SparseMatrix<double> a(n, n);
    a.setFromTriplets(trip.begin(), trip.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(a);
    if (ldlt.info() != Eigen::Success) throw GeometryError("stroke: periodic least-squares system is singular");
    const Eigen::MatrixXd x = ldlt.solve(b);
    s.ctrl.resize(n + kDegree);
    for (int i = 0; i < n + kDegree; ++i) s.ctrl[i] = x.row(i % n).transpose();
}

void solve(Spline& s, const std::vector<Vec3>& X, const std::vector<int>& S, const std::vector<double>& u,
           double fairing)
{
    s.makeKnots();
    if (s.closed) solveClosed(s, X, S, u, fairing);
    else solveOpen(s, X, S, u, fairing);
    s.buildPowerForm();
}

// Parameters of all points: piecewise linear in chord length between the samples' parameters.
std::vector<double> checkParameters(const SplineFitInput& in, const std::vector<int>& S,
                                    const std::vector<double>& u)
{
    const auto& X = *in.points;
    const int m = static_cast<int>(X.size());
    std::vector<double> out(m);
    size_t k = 0;
    for (int i = 0; i < m; ++i) {
        while (k + 1 < S.size() && S[k + 1] <= i) ++k;
        const double c0 = in.chord[S[k]], u0 = u[k];
        const bool wrapEnd = k + 1 == S.size();
        const double c1 = wrapEnd ? (in.closed ? 1.0 + in.chord[S[0]] : 1.0) : in.chord[S[k + 1]];
        const double u1 = wrapEnd ? (in.closed ? 1.0 + u[0] : 1.0) : u[k + 1];
        const double t = c1 > c0 ? (in.chord[i] - c0) / (c1 - c0) : 0.0;
        out[i] = u0 + t * (u1 - u0);
    }
    return out;
}

// Inserts one knot into every break interval whose samples deviate by more than the tolerance.
int insertKnots(Spline& s, const std::vector<double>& u, const std::vector<double>& err, double tol, double share,
                std::vector<double>& inserted)
{
    const int spans = static_cast<int>(s.closed ? s.breaks.size() : s.breaks.size() - 1);
    // Only the spans deviating most get a knot this round: a knot changes the fit of its
    // neighbours too, and splitting every span above the tolerance at once overshoots.
    tol = std::max(tol, share * *std::max_element(err.begin(), err.end()));
    std::vector<double> wsum(spans, 0.0), wmax(spans, 0.0);
    for (size_t k = 0; k < u.size(); ++k) {
        const int j = std::min(s.spanOf(s.wrap(u[k])), spans - 1);
        if (err[k] > tol) wsum[j] += err[k];
        wmax[j] = std::max(wmax[j], err[k]);
    }
    std::vector<double> acc(spans, 0.0), newKnots;
    std::vector<char> done(spans, 0);
    for (size_t k = 0; k < u.size(); ++k) {
        const int j = std::min(s.spanOf(s.wrap(u[k])), spans - 1);
        if (wmax[j] <= tol || done[j] || err[k] <= tol) continue;
        acc[j] += err[k];
        if (acc[j] < 0.5 * wsum[j]) continue;
        done[j] = 1;
        const double lo = s.breaks[j];
        const double hi = j + 1 < static_cast<int>(s.breaks.size()) ? s.breaks[j + 1] : 1.0;
        const double h = hi - lo;
        if (h < 1e-9) continue;  // spans below 1e-9 of the piece cannot be resolved in double precision
        newKnots.push_back(std::clamp(s.wrap(u[k]), lo + 0.2 * h, hi - 0.2 * h));
    }
    s.breaks.insert(s.breaks.end(), newKnots.begin(), newKnots.end());
    std::sort(s.breaks.begin(), s.breaks.end());
    inserted = newKnots;
    return static_cast<int>(newKnots.size());
}

// Max deviation over every point (foot-point distance) and every chord between neighbours.
double measureAll(const Spline& s, const SplineFitInput& in, const std::vector<int>& S, const std::vector<double>& u,
                  double tol)
{
    const auto& X = *in.points;
    const int m = static_cast<int>(X.size());
    std::vector<double> cu = checkParameters(in, S, u);
    double worst = 0.0;
    for (int i = 0; i < m; ++i) {
        const double lo = in.closed ? cu[i] - 0.5 : 0.0, hi = in.closed ? cu[i] + 0.5 : 1.0;
        worst = std::max(worst, footDistance(s, X[i], cu[i], lo, hi, tol, &cu[i]));
    }
    for (int i = 0; i + 1 < m || (in.closed && i < m); ++i) {
        const int next = (i + 1) % m;
        const double u1 = next == 0 ? cu[0] + 1.0 : cu[next];
        if (u1 > cu[i]) worst = std::max(worst, chordGap(s, X[i], X[next], 0.5 * (cu[i] + u1)));
    }
    return worst;
}

}  // namespace

void cubicBasisDerivatives(const KnotVector& U, int span, double u, double ders[3][4])
{
    constexpr int p = kDegree;
    double ndu[p + 1][p + 1], left[p + 1], right[p + 1], a[2][p + 1];
    ndu[0][0] = 1.0;
    for (int j = 1; j <= p; ++j) {
        left[j] = u - U[span + 1 - j];
        right[j] = U[span + j] - u;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            ndu[j][r] = right[r + 1] + left[j - r];
            const double temp = safeDiv(ndu[r][j - 1], ndu[j][r]);
            ndu[r][j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
    for (int j = 0; j <= p; ++j) ders[0][j] = ndu[j][p];
    for (int r = 0; r <= p; ++r) {
        int s1 = 0, s2 = 1;
        a[0][0] = 1.0;
        for (int k = 1; k <= 2; ++k) {
            double d = 0.0;
            const int rk = r - k, pk = p - k;
            if (r >= k) {
                a[s2][0] = safeDiv(a[s1][0], ndu[pk + 1][rk]);
                d = a[s2][0] * ndu[rk][pk];
            }
            const int j1 = rk >= -1 ? 1 : -rk;
            const int j2 = (r - 1 <= pk) ? k - 1 : p - r;
            for (int j = j1; j <= j2; ++j) {
                a[s2][j] = safeDiv(a[s1][j] - a[s1][j - 1], ndu[pk + 1][rk + j]);
                d += a[s2][j] * ndu[rk + j][pk];
            }
            if (r <= pk) {
                a[s2][k] = safeDiv(-a[s1][k - 1], ndu[pk + 1][r]);
                d += a[s2][k] * ndu[r][pk];
            }
            ders[k][r] = d;
            std::swap(s1, s2);
        }
    }
    for (int j = 0; j <= p; ++j) {
        ders[1][j] *= p;
        ders[2][j] *= p * (p - 1);
    }
}

SplineFitResult fitCubicSpline(const SplineFitInput& in, const SplineFitOptions& opt)
{
    const auto& X = *in.points;
    const int m = static_cast<int>(X.size());
    if (opt.tolerance <= 0.0) throw GeometryError("tolerance: must be positive");
    if (m < 2 || in.samples.size() < 2 || in.samples.front() != 0) throw GeometryError("stroke: too few samples to fit");
    Spline s;
    s.closed = in.closed;
    s.breaks = {0.0, 1.0};
    if (s.closed) s.breaks = {0.0, 0.2, 0.4, 0.6, 0.8};

    std::vector<int> S = in.samples;
    if (!in.closed && S.back() != m - 1) S.push_back(m - 1);
    std::vector<double> u(S.size());
    for (size_t k = 0; k < S.size(); ++k) u[k] = in.chord[S[k]];
    // Beyond one control point per sample the least squares is interpolation with extra freedom.
    const int maxUnknowns = std::max(in.closed ? 5 : 4, static_cast<int>(m) + 2);

    SplineFitResult res;
    if (opt.knotPlacement == KnotPlacement::Averaged && !in.closed) {
        // The NURBS Book eqs. 9.68-9.69 (de Boor's averaging): n+1 control points get knots that
        // follow the density of the sample parameters; the smallest n within tolerance is found by
        // bisection (the error falls, not strictly, as n grows).
        auto averaged = [&](int nCtrl) {
            Spline t;
            t.breaks = {0.0};
            const int nS = static_cast<int>(u.size());
            const double d = double(nS) / (nCtrl - kDegree);
            for (int j = 1; j < nCtrl - kDegree; ++j) {
                const int i = static_cast<int>(j * d);
                const double a = j * d - i;
                const double knot = (1 - a) * u[std::max(0, i - 1)] + a * u[std::min(nS - 1, i)];
                if (knot > t.breaks.back() + 1e-12 && knot < 1.0 - 1e-12) t.breaks.push_back(knot);
            }
            t.breaks.push_back(1.0);
            solve(t, X, S, u, opt.fairing);
            return std::make_pair(t, measureAll(t, in, S, u, opt.tolerance));
        };
        int lo = 4, hi = std::max(4, static_cast<int>(S.size()));
        auto best = averaged(hi);
        while (lo < hi) {
            const int mid = (lo + hi) / 2;
            auto trial = averaged(mid);
            if (trial.second <= opt.tolerance) {
                hi = mid;
                best = std::move(trial);
            } else {
                lo = mid + 1;
            }
        }
        if (best.first.unknowns() != hi) best = averaged(hi);
        res.maxError = best.second;
        res.converged = res.maxError <= opt.tolerance;
        res.knots = best.first.knots;
        res.points = best.first.ctrl;
        res.samples = S;
        return res;
    }
    std::vector<double> err(S.size());
    std::vector<double> lastInserted;
    for (res.iterations = 1; res.iterations <= opt.maxIterations; ++res.iterations) {
        solve(s, X, S, u, opt.fairing);
        const size_t first = in.closed ? 0 : 1, last = in.closed ? S.size() : S.size() - 1;
        std::fill(err.begin(), err.end(), 0.0);
        for (size_t k = first; k < last; ++k) {
            const double lo = k > 0 ? u[k - 1] : u.back() - 1.0;
            const double hi = k + 1 < u.size() ? u[k + 1] : u[0] + 1.0;
            if (opt.correctParameters) u[k] = newtonStep(s, X[S[k]], u[k], lo, hi);
            err[k] = opt.measureAtFootPoint ? footDistance(s, X[S[k]], u[k], lo, hi, opt.tolerance)
                                            : distanceAt(s, X[S[k]], u[k]);
        }
        const double worst = *std::max_element(err.begin(), err.end());
        if (worst > opt.tolerance && s.unknowns() < maxUnknowns) {
            if (insertKnots(s, u, err, opt.tolerance, opt.insertionShare, lastInserted) > 0) continue;
        }
        // All samples fit (or no more knots help): verify every point, and add the worst offender of
        // each span to the samples so that the next solve sees it.
        std::vector<double> cu = checkParameters(in, S, u);
        const int spans = static_cast<int>(s.breaks.size());
        std::vector<int> offender(spans, -1);
        std::vector<double> offErr(spans, opt.tolerance);
        res.maxError = 0.0;
        for (int i = 0; i < m; ++i) {
            const double lo = in.closed ? cu[i] - 0.5 : 0.0, hi = in.closed ? cu[i] + 0.5 : 1.0;
            const double e = footDistance(s, X[i], cu[i], lo, hi, opt.tolerance, &cu[i]);
            res.maxError = std::max(res.maxError, e);
            const int j = s.spanOf(s.wrap(cu[i]));
            if (e > offErr[j]) {
                offErr[j] = e;
                offender[j] = i;
            }
        }
        // The other direction (curve to data): between two consecutive points the curve must stay
        // near the chord joining them, or it loops where no sample holds it. The offender is the
        // neighbour not yet sampled.
        for (int i = 0; i + 1 < m || (in.closed && i < m); ++i) {
            const int next = (i + 1) % m;
            const double u1 = next == 0 ? cu[0] + 1.0 : cu[next];
            if (!(u1 > cu[i])) continue;
            const double e = chordGap(s, X[i], X[next], 0.5 * (cu[i] + u1));
            res.maxError = std::max(res.maxError, e);
            const int j = s.spanOf(s.wrap(0.5 * (cu[i] + u1)));
            const int pick = std::binary_search(S.begin(), S.end(), next) ? i : next;
            if (e > offErr[j] && !std::binary_search(S.begin(), S.end(), pick)) {
                offErr[j] = e;
                offender[j] = pick;
            }
        }
        bool added = false;
        if (res.maxError > opt.tolerance && s.unknowns() < maxUnknowns) {
            for (int j = 0; j < spans; ++j) {
                const int i = offender[j];
                if (i < 0) continue;
                const auto pos = std::lower_bound(S.begin(), S.end(), i);
                if (pos != S.end() && *pos == i) continue;
                const size_t at = static_cast<size_t>(pos - S.begin());
                S.insert(pos, i);
                const double lo = u[at - 1], hi = at < u.size() ? u[at] : (in.closed ? u[0] + 1.0 : 1.0);
                const double ui = opt.correctParameters ? cu[i] : in.chord[i];
                u.insert(u.begin() + static_cast<long>(at), std::clamp(ui, lo, hi));
                added = true;
            }
        }
        if (!added) break;
        err.resize(S.size());
    }
    if (res.iterations > opt.maxIterations) res.maxError = measureAll(s, in, S, u, opt.tolerance);
    // The last round of insertions may have overshot (a knot fixes its neighbours' spans too): try
    // removing each of its knots again, keeping the removal when the refit stays within tolerance.
    if (opt.removalPass && res.maxError <= opt.tolerance) {
        for (double knot : lastInserted) {
            Spline trial = s;
            const auto it = std::find(trial.breaks.begin(), trial.breaks.end(), knot);
            if (it == trial.breaks.end()) continue;
            trial.breaks.erase(it);
            solve(trial, X, S, u, opt.fairing);
            bool ok = true;
            for (size_t k = 0; ok && k < S.size(); ++k) {
                const double lo = k > 0 ? u[k - 1] : u.back() - 1.0;
                const double hi = k + 1 < u.size() ? u[k + 1] : u[0] + 1.0;
                ok = footDistance(trial, X[S[k]], u[k], lo, hi, opt.tolerance) <= opt.tolerance;
            }
            if (!ok) continue;
            const double e = measureAll(trial, in, S, u, opt.tolerance);
            if (e <= opt.tolerance) {
                s = std::move(trial);
                res.maxError = e;
            }
        }
    }
    res.converged = res.maxError <= opt.tolerance;
    res.knots = s.knots;
    res.points = s.ctrl;
    res.samples = S;
    return res;
}

}  // namespace sculptline::solvers::stroke
