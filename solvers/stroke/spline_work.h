#pragma once
// Internals of the least-squares fit (lsq_fit.cpp): the spline being fitted, its evaluation in
// power form, foot-point distances and the band / cyclic-band least-squares solves. Not part of
// the stroke library's interface.
#include "solvers/bspline/basis_evaluator.h"
#include "solvers/bspline/periodic.h"
#include "solvers/stroke/lsq_fit.h"
#include "solvers/stroke/power_form.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace sculptline::solvers::stroke::detail {

constexpr int kDegree = 3;
using Vec3 = Eigen::Vector3d;

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
        // Periodic, period 1: U_i = b_{(i-3) mod N} + floor((i-3)/N), i = 0..N+6, so that U_3 = b_0 = 0
        // and U_{N+3} = 1.
        knots = periodicKnots(kDegree, breaks, 1.0);
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
        // C, C', C'' at each span start from the B-spline basis; the cubic term from C'' at the
        // span's end, which is the next span's start value (C2 across the simple breaks), so each
        // break is evaluated once. Only the open curve's end (u = 1) needs its own evaluation;
        // a closed curve's end is its start.
        const int spans = spanCount();
        coef.resize(spans);
        thread_local std::vector<std::array<Vec3, 3>> at;  // storage kept between calls
        at.resize(spans + 1);
        // The basis functions and derivatives at the breaks depend on the knots alone: kept for
        // the knots last seen, which the corrections and minimax rounds of a trial solve again
        // and again (about 60 % of buildPowerForm's instructions on a 30-point curve).
        thread_local KnotVector basisKnots;
        thread_local bool basisClosed = false;
        thread_local std::vector<BasisDerivatives<kDegree, 2>> basisAt;
        if (basisClosed != closed || basisKnots != knots) {
            basisClosed = closed;
            basisKnots = knots;
            basisAt.resize(spans + 1);
            for (int j = 0; j < spans + (closed ? 0 : 1); ++j) {
                const double a = j < spans ? breaks[j] : 1.0;
                // The open knot vector is 0,0,0,b_0,..,b_s,1,1,1 with distinct breaks: b_j starts span j + p.
                const int span = j == spans ? static_cast<int>(knots.size()) - kDegree - 2
                                 : closed   ? findSpan(kDegree, knots, a)
                                            : j + kDegree;
                basisAt[j] = evaluateBasis<kDegree, 2>(knots, span, a);
            }
        }
        for (int j = 0; j <= spans; ++j) {
            if (j == spans && closed) {
                at[j] = at[0];
                break;
            }
            const BasisDerivatives<kDegree, 2>& b = basisAt[j];
            for (int k = 0; k < 3; ++k) at[j][k].setZero();
            for (int q = 0; q <= kDegree; ++q) {
                const Vec3& p = ctrl[b.span - kDegree + q];
                for (int k = 0; k < 3; ++k) at[j][k] += b.d[k][q] * p;
            }
        }
        for (int j = 0; j < spans; ++j) {
            const double h = spanEnd(j) - breaks[j];
            coef[j] = {at[j][0], at[j][1], 0.5 * at[j][2], h > 0.0 ? ((at[j + 1][2] - at[j][2]) / (6.0 * h)).eval() : Vec3::Zero().eval()};
        }
    }
    // Point and first two derivatives at u.
    void eval(double u, Vec3 out[3]) const
    {
        u = wrap(u);
        const int j = spanOf(u);
        const double t = u - breaks[j];
        cubicWithDerivatives(coef[j], t, out[0], out[1], out[2]);
    }
    Vec3 point(double u) const
    {
        u = wrap(u);
        const int j = spanOf(u);
        return cubicPoint(coef[j], u - breaks[j]);
    }
    // Index into breaks of the span holding u (u already wrapped). Evaluations mostly come in
    // increasing u, so the last span found, or the next one, is tried before a binary search.
    mutable int hint = 0;
    int spanOf(double u) const
    {
        // Span j holds [b_j, b_{j+1}); the last span also holds u = 1 (open) or runs to the period
        // end (closed), so only its start is tested.
        const int last = spanCount() - 1;
        for (int j = std::min(hint, last), e = std::min(hint + 1, last); j <= e; ++j) {
            if (u >= breaks[j] && (j == last || u < breaks[j + 1])) return hint = j;
        }
        const auto it = std::upper_bound(breaks.begin(), breaks.end(), u);
        return hint = std::clamp(static_cast<int>(it - breaks.begin()) - 1, 0, last);
    }
};

/// The range sample k's parameter may move in: between its neighbours' (across a closed curve's
/// seam, a period away). Round-off at the seam ((u_0 + 1) - 1 != u_0) can invert the range of a
/// sample whose neighbours coincide, as a sparse loop's corrections produced (the sanitizer
/// build's clamp assertion): it is then the one point lo.
inline std::pair<double, double> neighbourRange(const std::vector<double>& u, size_t k)
{
    const double lo = k > 0 ? u[k - 1] : u.back() - 1.0;
    const double hi = k + 1 < u.size() ? u[k + 1] : u.front() + 1.0;
    return {lo, std::max(lo, hi)};
}

/// One Newton step on f(u) = C'(u).(C(u) - x) (The NURBS Book eq. 6.3), kept inside [lo, hi].
double newtonStep(const Spline& s, const Vec3& x, double u, double lo, double hi);
double distanceAt(const Spline& s, const Vec3& x, double u);
/// |C(u) - x| when within tol, else the best of up to two Newton steps (an upper bound on the
/// true distance either way); *foot receives the parameter used.
double footDistance(const Spline& s, const Vec3& x, double u, double lo, double hi, double tol, double* foot = nullptr);
/// Distance of C(u) to the segment [a, b] (an error only beyond a quarter of the segment).
double rawChordGap(const Spline& s, const Vec3& a, const Vec3& b, double u);
/// The least-squares sums of one span of an open spline over its interior samples (the two end
/// samples are the fixed P_0 and P_n): the Gram block g[q][r] = sum N_q N_r (r <= q) and the
/// moments r[q] = sum N_q X_k of the span's four basis functions. The normal equations are
/// assembled span by span from these, so a trial that changes the basis on a few spans only (a
/// knot removal) recomputes those spans' sums and reuses the others'.
struct SpanSums {
    double g[kDegree + 1][kDegree + 1] = {};
    Vec3 r[kDegree + 1] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    /// One sample's terms: the span's four basis values at it, its weight (1: unweighted, the
    /// same sums to the bit) and its point.
    void add(const double* basis, double w, const Vec3& x)
    {
        for (int q = 0; q <= kDegree; ++q) {
            const double wb = w * basis[q];
            r[q] += wb * x;
            for (int c = 0; c <= q; ++c) g[q][c] += wb * basis[c];
        }
    }
};
/// Sums of the spans first..last of s (knots made; sums grown to s.spanCount() if shorter), each
/// sample's terms times its weight when `weights` (one per entry of S) is given.
void spanSums(const Spline& s, const std::vector<Vec3>& X, const std::vector<int>& S, const std::vector<double>& u,
              int first, int last, std::vector<SpanSums>& sums, const std::vector<double>* weights = nullptr);
/// The sums of s (open, knots made) from oldSums, the sums over the same samples and parameters
/// for the breaks oldBreaks: spans whose six breaks are unchanged keep theirs, the others (around
/// inserted knots) are summed again.
void updateSpanSums(const Spline& s, const std::vector<double>& oldBreaks, const std::vector<SpanSums>& oldSums,
                    const std::vector<Vec3>& X, const std::vector<int>& S, const std::vector<double>& u,
                    std::vector<SpanSums>& sums);
/// Removes the interior break r from t (open; s's breaks, knots made) and gives the sums of the
/// result from `sums`, s's: only the six spans around the break are summed again.
void sumsWithoutBreak(Spline& t, int r, const std::vector<Vec3>& X, const std::vector<int>& S,
                      const std::vector<double>& u, const std::vector<SpanSums>& sums, std::vector<SpanSums>& out);
/// Solves the open least squares (with the fairing term) from the sums of every span and builds the
/// power form.
void solveOpenFromSums(Spline& s, const std::vector<Vec3>& X, const std::vector<int>& S,
                       const std::vector<SpanSums>& sums, double fairing);
/// Least squares with the fairing term for the spline's breaks (makes knots, solves, builds the
/// power form). Open: P_0 and P_n fixed to the first and last sample. `weights` (one per entry of
/// S, positive): a weighted least squares (the minimax rounds, SplineFitOptions::minimaxRounds).
void solve(Spline& s, const std::vector<Vec3>& X, const std::vector<int>& S, const std::vector<double>& u,
           double fairing, const std::vector<double>* weights = nullptr);

/// The largest deviation of every point of the input (foot-point distance) and of every chord between
/// neighbours from s, the samples S at parameters u (lsq_fit.cpp).
double measureAllPoints(const Spline& s, const SplineFitInput& in, const std::vector<int>& S,
                        const std::vector<double>& u, double tol);
/// KnotPlacement::Averaged (averaged_fit.cpp): the samples S (with the last point when open) at
/// their chord parameters u.
SplineFitResult fitAveraged(const SplineFitInput& in, const SplineFitOptions& opt, std::vector<int> S,
                            std::vector<double> u);

}  // namespace sculptline::solvers::stroke::detail
