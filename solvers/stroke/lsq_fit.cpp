#include "solvers/stroke/lsq_fit.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/stroke/spline_work.h"

#include <algorithm>
#include <cmath>

namespace sculptline::solvers::stroke {
namespace {

using namespace detail;

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
    bool polished = false;
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
        if (opt.polishParameters && !polished && !in.closed && res.maxError > opt.tolerance) {
            polished = true;  // SplineFitOptions::polishParameters: once, with the same knots
            std::vector<double> foot(u.size());
            bool increasing = true;
            for (size_t k = 0; k < S.size(); ++k) {
                foot[k] = k == 0 || k + 1 == S.size() ? u[k] : cu[S[k]];
                increasing = increasing && (k == 0 || foot[k] > foot[k - 1]);
            }
            if (increasing) {
                u = std::move(foot);
                continue;
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
    // The last round of insertions may have overshot (a knot fixes its neighbours' spans too), and
    // earlier knots may have become redundant: try removing them again (SplineFitOptions::removal),
    // keeping a removal when the refit stays within tolerance at the samples and everywhere.
    if (opt.removal != KnotRemoval::None && res.maxError <= opt.tolerance) {
        const std::vector<double> tryRemove =
            opt.removal == KnotRemoval::AllKnots  // every break but the domain ends (closed: b_0)
                ? std::vector<double>(s.breaks.begin() + 1, s.breaks.end() - (in.closed ? 0 : 1))
                : lastInserted;
        for (double knot : tryRemove) {
            Spline trial = s;
            const auto it = std::find(trial.breaks.begin(), trial.breaks.end(), knot);
            if (it == trial.breaks.end()) continue;
            trial.breaks.erase(it);
            if (in.closed && trial.breaks.size() < 5) continue;  // the smallest periodic start
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
