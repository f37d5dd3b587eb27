// KnotPlacement::Averaged (lsq_fit.h): knots averaged over the samples' parameters, Hoschek's
// parameter corrections, and for a fixed count the minimax rounds (Lawson) and the equidistributed
// breaks that the stroke fitter's minimax trials ask for.
#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/projection.h"
#include "solvers/stroke/spline_work.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

namespace sculptline::solvers::stroke {
namespace detail {

// One trial count's curve and the largest distance of the samples at their parameters (for a
// search without a fixed count, of every point: measureAll).
struct Trial {
    Spline curve;
    double error = std::numeric_limits<double>::infinity();
    std::vector<double> params;  // the samples' parameters `error` was measured at (fixed counts)
};

}  // namespace detail

struct AveragedTrialCache::State {
    // The input the state is of.
    std::vector<int> samples;
    std::vector<double> params;
    std::vector<Eigen::Vector3d> points;
    bool closed = false;
    // FITPACK's insertion (AveragedFit::insertedBreaks): the breaks before the first knot inserted,
    // the knots inserted in order, and whether no span is left with a sample inside.
    std::vector<double> start, inserted;
    bool started = false, exhausted = false;
    // Each count's best trial before its equidistributions, and the options it was made with
    // (AveragedFit::made).
    struct Made {
        detail::Trial trial;
        std::array<double, 6> options;
    };
    std::map<int, Made> trials;
    // Each count's last trial (its best, as returned), and the removal trials' seeds: the last
    // trials of the counts the caller named (AveragedTrialCache::seed; AveragedFit::removeFrom).
    std::map<int, detail::Trial> last, seeds;
};

AveragedTrialCache::AveragedTrialCache() : state(std::make_unique<State>())
{
}
AveragedTrialCache::~AveragedTrialCache() = default;

void AveragedTrialCache::seed(int count)
{
    const auto it = state->last.find(count);
    if (it != state->last.end()) state->seeds[count] = it->second;
}

bool AveragedTrialCache::seeded(int count) const
{
    return state->seeds.count(count) > 0;
}

namespace detail {
namespace {

// Parameter corrections of a fixed averaged-knot count (SplineFitOptions::averagedControlPoints)
// stop once the error they are heading for stays above this multiple of the tolerance: the error
// after c corrections times the last correction's ratio (e_c / e_{c-1}) raised to the corrections
// left. The ratios grow from correction to correction (convergence slows: on the flourish of
// BM_StrokeFit/200, 0.78, 0.85, 0.875, 0.878, 0.881 at 20 control points; 0.90, 0.97, 0.98, 0.99 at
// 13), so the projection is optimistic and a count it gives up would not have fitted; the margin
// covers the few ratios that fall again (21 control points: 0.903, 0.899, 0.897). Counts far from
// fitting (the search's first climbs) then cost two or three solves instead of nine.
constexpr double kCorrectionRejection = 1.1;
// SplineFitOptions::minimaxRounds: the largest error of the least squares (in tolerances) the
// minimax rounds try to bring within the tolerance, and the least weight (of a mean of one).
constexpr double kMinimaxReach = 1.5;
constexpr double kMinimaxWeightFloor = 1e-3;
// SplineFitOptions::equidistributions: a span's error is taken as at least this share of the mean
// span's, so that spans the curve already fits are not emptied of breaks (their error would grow).
constexpr double kEquidistributionFloor = 0.2;
// An equidistributed trial starts from the parameters the trial before it ended at (corrected
// toward that curve's foot points, which the moved breaks change little) and makes the last this
// many of the SplineFitOptions::averagedCorrections, where a trial from the chord parameters makes
// them all. On the development strokes (unistroke-report --fit-dev): 56,156 control points from
// the chord parameters, 55,955 / 55,999 / 55,984 from the trial before's with 1 / 2 / 3
// corrections, 56,037 with none; least-squares solves 147,469 -> 146,252 with 1.
// compare_splprep.py --dev circle: 147 -> 150 of the 150 development circles meet the fewer peer
// with 1 (149 with 2).
constexpr int kEquidistributionCorrections = 1;
// FITPACK's insertion places a knot only at a sample this far inside its span (the breaks of
// averagedBreaks are kept as far apart).
constexpr double kKnotGap = 1e-12;

// The averaged-knot fit of one input: the trials share the samples and their chord parameters;
// the trial being made corrects its own copy (uc_).
class AveragedFit {
public:
    AveragedFit(const SplineFitInput& in, const SplineFitOptions& opt, std::vector<int> S, std::vector<double> u)
        : in_(in), opt_(opt), X_(*in.points), S_(std::move(S)), u_(std::move(u))
    {
        // (Without a cache the state is this fit's own, and no input needs recognizing.)
        if (!opt_.trialCache) return;
        state_ = opt_.trialCache->state.get();
        const int nS = static_cast<int>(S_.size());
        bool same = state_->closed == in_.closed && state_->samples == S_ && state_->params == u_;
        for (int k = 0; same && k < nS; ++k) same = state_->points[k] == X_[S_[k]];
        if (same) return;
        // (The seeds of the removal trials carry over to other points on the same rows: the breaks
        // and parameters of a count taken on the drawn points start those on the smoothed ones.)
        std::map<int, Trial> seeds;
        if (state_->closed == in_.closed && state_->samples == S_) seeds = std::move(state_->seeds);
        *state_ = {};
        state_->seeds = std::move(seeds);
        state_->samples = S_;
        state_->params = u_;
        state_->closed = in_.closed;
        state_->points.resize(S_.size());
        for (int k = 0; k < nS; ++k) state_->points[k] = X_[S_[k]];
    }

    SplineFitResult run()
    {
        // (Closed: at least the five spans of the smallest periodic start, fewer unknowns than samples.)
        const int least = in_.closed ? 5 : 4;
        int lo = least, hi = std::max(least, static_cast<int>(S_.size()) - (in_.closed ? 1 : 0));
        if (opt_.averagedControlPoints > 0) lo = hi = std::clamp(opt_.averagedControlPoints, least, hi);
        Trial best;
        if (opt_.removalTrials > 0 && opt_.averagedControlPoints > 0) {
            removeFrom(hi, best);
        } else {
            best = opt_.seedBreaks ? onSeedBreaks(hi) : made(hi);
            equidistribute(hi, best);
        }
        if (opt_.trialCache && opt_.averagedControlPoints > 0 && !opt_.averagedResume && !opt_.averagedStopWhenWithin &&
            std::isfinite(best.error) && !best.params.empty())
            state_->last[hi] = best;
        while (lo < hi) {
            const int mid = (lo + hi) / 2;
            Trial t = trial(mid, nullptr);
            if (t.error <= opt_.tolerance) {
                hi = mid;
                best = std::move(t);
            } else {
                lo = mid + 1;
            }
        }
        // (A fixed count is solved once: its knots may merge, leaving fewer unknowns, and solving it
        // again would give the same.)
        if (opt_.averagedControlPoints == 0 && best.curve.unknowns() != hi) best = trial(hi, nullptr);
        res_.maxError = best.error;
        res_.converged = res_.maxError <= opt_.tolerance;
        res_.knots = best.curve.knots;
        res_.points = best.curve.ctrl;
        res_.samples = S_;
        return std::move(res_);
    }

private:
    // The NURBS Book eqs. 9.68-9.69 (de Boor's averaging): n+1 control points get knots that
    // follow the density of the sample parameters. A closed curve (periodic, period 1) of N
    // control points has N spans, one break each: b_0 = 0 and b_j at the parameter j N_s / N
    // samples along (interpolated between two), so that every span holds N_s / N samples, the
    // periodic form of the same averaging. Empty when a closed curve's breaks merge below the
    // smallest periodic start (five spans).
    std::vector<double> averagedBreaks(int nCtrl) const
    {
        const std::vector<double>& u = u_;
        const int nS = static_cast<int>(u.size());
        std::vector<double> b = {0.0};
        const auto add = [&](double knot) {
            if (knot > b.back() + 1e-12 && knot < 1.0 - 1e-12) b.push_back(knot);
        };
        if (in_.closed) {
            const double d = double(nS) / nCtrl;
            for (int j = 1; j < nCtrl; ++j) {
                const int i = static_cast<int>(j * d);
                const double a = j * d - i;
                const double next = i + 1 < nS ? u[i + 1] : 1.0;
                add((1 - a) * u[std::min(i, nS - 1)] + a * next);
            }
            if (b.size() < 5) b.clear();
            return b;
        }
        if (nCtrl >= nS) {
            // Interpolation: The NURBS Book eq. 9.8 (each knot the mean of p parameters), which
            // keeps every sample inside the support of its own basis function (Schoenberg-
            // Whitney); eq. 9.69 at n = m can leave a span empty and its neighbour two.
            for (int j = 1; j < nS - kDegree; ++j) {
                double knot = 0.0;
                for (int i = j; i < j + kDegree; ++i) knot += u[i];
                add(knot / kDegree);
            }
        } else {
            const double d = double(nS) / (nCtrl - kDegree);
            for (int j = 1; j < nCtrl - kDegree; ++j) {
                const int i = static_cast<int>(j * d);
                const double a = j * d - i;
                add((1 - a) * u[std::max(0, i - 1)] + a * u[std::min(nS - 1, i)]);
            }
        }
        b.push_back(1.0);
        return b;
    }

    // What the minimax rounds aim for (SplineFitOptions::minimaxWithin; 0: the tolerance).
    double roundsTarget() const { return opt_.minimaxWithin > 0.0 ? opt_.minimaxWithin : opt_.tolerance; }

    // The trial of nCtrl control points on the averaged knots, and where it misses and
    // SplineFitOptions::insertedTrials asks, the trial on FITPACK's (the better kept); taken from
    // the cache when a trial of the same count and options made it before.
    Trial made(int nCtrl)
    {
        // (A trial that stops once its samples fit, or resumes one, is not kept: its curve depends on
        // the state it stopped or resumed at. FITPACK's knots are tried only where a trial is.)
        const bool kept = opt_.averagedControlPoints > 0 && !opt_.averagedResume && !opt_.averagedStopWhenWithin;
        const std::array<double, 6> options = {opt_.tolerance,
                                               opt_.fairing,
                                               static_cast<double>(opt_.averagedCorrections),
                                               static_cast<double>(opt_.minimaxRounds),
                                               opt_.minimaxWithin,
                                               opt_.insertedTrials ? 1.0 : 0.0};
        if (kept) {
            const auto it = state_->trials.find(nCtrl);
            if (it != state_->trials.end() && it->second.options == options) return it->second.trial;
        }
        // (A trial misses where its rounds end above what they aim for, minimaxWithin: on the smoothed
        // points that is less than the tolerance. Tried only beyond the tolerance until session 51:
        // 46,039 against 45,964 control points on the development strokes, with the minimax trials
        // on the drawn points first: fit_minimax.cpp, minimaxTrials.)
        const double within = roundsTarget();
        Trial best = trial(nCtrl, nullptr);
        if (opt_.insertedTrials && kept && best.error > within) {
            const std::vector<double> nb = insertedBreaks(nCtrl);
            if (!nb.empty()) {
                Trial b = trial(nCtrl, &nb);
                if (b.error < best.error) best = std::move(b);
            }
        }
        if (kept && opt_.trialCache) state_->trials[nCtrl] = {best, options};
        return best;
    }

    // FITPACK's knot placement (P. Dierckx, Curve and Surface Fitting with Splines, 1993, ch. 5;
    // FITPACK's fpcurf and fpknot): from the fewest spans, a least squares on the chord parameters,
    // then a knot at the middle sample inside the span whose squared distances sum the most (the
    // lower of two middles; FITPACK's upper one: 56,485 control points on the development strokes
    // against 56,474), one knot per solve, until nCtrl control points.
    // Where the noise is near the tolerance the knots follow the shape's error, not the samples'
    // density. Empty when no sample is left inside a span to insert at.
    std::vector<double> insertedBreaks(int nCtrl)
    {
        AveragedTrialCache::State& q = *state_;
        const int nS = static_cast<int>(u_.size());
        if (!q.started) {
            q.started = true;
            q.start = in_.closed ? averagedBreaks(5) : std::vector<double>{0.0, 1.0};
        }
        if (q.start.empty()) return {};  // (a loop too sparse for five spans)
        Spline c;
        c.closed = in_.closed;
        c.breaks = q.start;
        // (The sequence's first knots: one control point each.)
        const size_t have = std::min(q.inserted.size(), static_cast<size_t>(std::max(0, nCtrl - c.unknowns())));
        c.breaks.insert(c.breaks.end(), q.inserted.begin(), q.inserted.begin() + static_cast<std::ptrdiff_t>(have));
        std::sort(c.breaks.begin(), c.breaks.end());
        // A span of the last solve: its squared distances' sum and its first and last sample inside.
        struct Gap {
            double sum;
            int first, last;
        };
        thread_local std::vector<Gap> gaps;
        while (c.unknowns() < nCtrl && !q.exhausted) {
            solve(c, X_, S_, u_, opt_.fairing);
            const int spans = c.spanCount();
            gaps.assign(static_cast<size_t>(spans), {0.0, -1, -1});
            for (int k = 0; k < nS; ++k) {
                const double d = distanceAt(c, X_[S_[k]], u_[k]);
                const int j = c.spanOf(c.wrap(u_[k]));
                gaps[j].sum += d * d;
                if (u_[k] > c.breaks[j] + kKnotGap && u_[k] < c.spanEnd(j) - kKnotGap) {
                    if (gaps[j].first < 0) gaps[j].first = k;
                    gaps[j].last = k;
                }
            }
            const Gap* pick = nullptr;
            for (const Gap& g : gaps)
                if (g.first >= 0 && (!pick || g.sum > pick->sum)) pick = &g;
            if (!pick) {
                q.exhausted = true;
                break;
            }
            // (Inserting several knots per solve, each span's sum shared between its parts by
            // their samples as FITPACK's fpknot does, cost control points: on the development
            // strokes 56,588-56,597 against 56,474 with a quarter to a half of the spans' count
            // per solve.)
            const double knot = u_[(pick->first + pick->last) / 2];
            c.breaks.insert(std::upper_bound(c.breaks.begin(), c.breaks.end(), knot), knot);
            q.inserted.push_back(knot);  // (c has every knot of the sequence: it grows only here)
        }
        if (c.unknowns() != nCtrl) return {};
        return c.breaks;
    }

    // One count: the least squares on the averaged (or `given`) breaks, Hoschek's corrections
    // (SplineFitOptions::averagedCorrections), and for a fixed count that misses by little the
    // minimax rounds. `start`: the parameters to start from instead of the chord parameters (an
    // equidistributed trial's, kEquidistributionCorrections).
    Trial trial(int nCtrl, const std::vector<double>* given, const std::vector<double>* start = nullptr)
    {
        // This trial's parameters (corrected below), or those a stopped fit of the same count left.
        const AveragedCorrectionState* resume = opt_.averagedControlPoints > 0 ? opt_.averagedResume : nullptr;
        uc_ = resume ? resume->parameters : start ? *start : u_;
        if (uc_.size() != u_.size()) throw GeometryError("averaged fit: the state to resume is of another input");
        Trial t;
        t.curve.closed = in_.closed;
        t.curve.breaks = given ? *given : averagedBreaks(nCtrl);
        if (t.curve.breaks.empty()) {
            t.curve.breaks = {0.0};
            return t;  // (infinite error: no curve)
        }
        Spline& c = t.curve;
        solve(c, X_, S_, uc_, opt_.fairing);
        // An open curve's end samples are its end points P_0 and P_n; a closed curve has none,
        // and each of its samples is kept between its neighbours across the seam.
        const size_t firstK = in_.closed ? 0 : 1, endK = in_.closed ? uc_.size() : uc_.size() - 1;
        // SplineFitOptions::averagedCorrections: Hoschek's intrinsic parametrization, each
        // sample's parameter moved by a Newton step toward its foot point (kept between its
        // neighbours'), the knots kept. The Newton step's evaluation also gives the sample's
        // distance at its parameter, so each correction measures the curve it corrects.
        double before = resume ? resume->error : std::numeric_limits<double>::infinity();
        // (The error the least squares may leave for the minimax rounds to bring within.)
        const double reach = opt_.minimaxRounds > 0 ? kMinimaxReach : 1.0;
        const int firstCorrection = resume  ? resume->done
                                    : start ? std::max(0, opt_.averagedCorrections - kEquidistributionCorrections)
                                            : 0;
        for (int k = firstCorrection; k < opt_.averagedCorrections; ++k) {
            const double e = correct(c, firstK, endK, nullptr);  // (the ends are P_0, P_n)
            if (opt_.averagedControlPoints > 0 && e > opt_.tolerance) {
                // A count that cannot fit is given up early (kCorrectionRejection). It reports
                // the error it has, not the optimistic projection: the caller's search predicts
                // the next count from it, and the corrections left would lower it by less
                // than the projection says (at 8 control points, 19.0 after one correction,
                // 16.4 after eight, projected 8.6).
                const double r = std::min(1.0, e / before);
                if (e * std::pow(r, opt_.averagedCorrections - k) > kCorrectionRejection * reach * opt_.tolerance) {
                    t.error = e;
                    return t;
                }
            }
            if (opt_.averagedControlPoints > 0 && opt_.averagedStopWhenWithin && e <= opt_.tolerance &&
                k + 1 < opt_.averagedCorrections) {
                // The count fits (every sample within the tolerance at its parameter, a curve
                // point). The state: the parameters just corrected, their solve not yet made.
                res_.correction = {uc_, k + 1, e, true};
                t.error = e;
                return t;
            }
            before = e;
            solve(c, X_, S_, uc_, opt_.fairing);
        }
        if (opt_.averagedControlPoints == 0) {
            t.error = measureAllPoints(c, in_, S_, uc_, opt_.tolerance);
            return t;
        }
        // The caller measures the result itself: only the samples, at their parameters, as a
        // quick bound for rejecting it.
        t.error = 0.0;
        for (size_t k = 0; k < uc_.size(); ++k) t.error = std::max(t.error, distanceAt(c, X_[S_[k]], uc_[k]));
        t.params = uc_;
        if (t.error > opt_.tolerance && t.error <= reach * opt_.tolerance) minimax(t, firstK, endK);
        return t;
    }

    // One Hoschek correction of uc_ on c: each sample's parameter (firstK..endK) a Newton step
    // toward its foot point, kept between its neighbours' (none when !step: a measure only).
    // Returns the samples' largest distance at their parameters before the step (the curve's, as
    // solved); `dist`, when given, receives each one.
    double correct(const Spline& c, size_t firstK, size_t endK, std::vector<double>* dist, bool step = true)
    {
        double e = 0.0;
        for (size_t k = firstK; k < endK; ++k) {
            Vec3 d[3];
            c.eval(uc_[k], d);
            const double dk = (d[0] - X_[S_[k]]).norm();
            e = std::max(e, dk);
            if (dist) (*dist)[k] = dk;
            if (!step) continue;
            const auto [lo, hi] = neighbourRange(uc_, k);
            footPointNewtonStep(d[0], d[1], d[2], X_[S_[k]], lo, hi, uc_[k]);
        }
        return e;
    }

    // SplineFitOptions::minimaxRounds: Lawson's algorithm (C. L. Lawson, 1961; the weights of a
    // least squares whose fixed point is the minimax fit) on t, whose samples at their parameters
    // uc_ miss the tolerance. Each round moves every sample's parameter a Newton step toward its
    // foot point (as a correction does), multiplies its weight by its distance and solves the
    // weighted least squares; the pass that makes the next round's steps measures the round's
    // curve (an open curve's end samples are its end points). t becomes the round's curve with
    // the smallest maximum distance.
    void minimax(Trial& t, size_t firstK, size_t endK)
    {
        thread_local std::vector<double> w, dist, before;
        w.assign(uc_.size(), 1.0);
        dist.assign(uc_.size(), 0.0);
        Spline c = t.curve;
        const double within = roundsTarget();
        for (int round = 0;; ++round) {
            // (The last round's curve is measured without moving the parameters: no round
            // follows to use them.)
            const bool last = round == opt_.minimaxRounds;
            before = uc_;  // (the parameters the round's curve is measured at, before its steps)
            const double err = correct(c, firstK, endK, &dist, !last);
            if (round > 0) {
                if (err < t.error) {
                    t.curve = c;
                    t.error = err;
                    std::swap(t.params, before);
                }
                if (opt_.minimaxWithin >= 0.0 && t.error <= within) break;
            }
            if (last) break;
            double sum = 0.0;
            for (size_t k = firstK; k < endK; ++k) sum += w[k] *= dist[k];
            if (!(sum > 0.0)) break;
            // Normalized to a mean of one (the fairing term's weight is relative to the samples'
            // count), and never below kMinimaxWeightFloor: a sample the curve passes through
            // would otherwise drop out of the least squares for good.
            const double scale = static_cast<double>(endK - firstK) / sum;
            for (size_t k = firstK; k < endK; ++k) w[k] = std::max(kMinimaxWeightFloor, w[k] * scale);
            solve(c, X_, S_, uc_, opt_.fairing, &w);
        }
    }

    // Each span's largest distance of the samples at a trial's parameters.
    std::vector<double> spanErrors(const Trial& t) const
    {
        const Spline& b = t.curve;
        std::vector<double> e(static_cast<size_t>(b.spanCount()), 0.0);
        for (size_t k = 0; k < t.params.size(); ++k) {
            const int j = b.spanOf(b.wrap(t.params[k]));
            e[j] = std::max(e[j], distanceAt(b, X_[S_[k]], t.params[k]));
        }
        return e;
    }

    // SplineFitOptions::seedBreaks: the trial of `nCtrl` on the breaks given (a curve of that count
    // fitted on other rows).
    Trial onSeedBreaks(int nCtrl)
    {
        const std::vector<double>& b = *opt_.seedBreaks;
        const size_t want = static_cast<size_t>(in_.closed ? nCtrl : nCtrl - 2);
        if (b.size() != want || b.front() != 0.0 || !std::is_sorted(b.begin(), b.end()) ||
            (!in_.closed && b.back() != 1.0) || (in_.closed && !(b.back() < 1.0)))
            throw GeometryError("averaged fit: the seed's breaks are not of this count");
        return trial(nCtrl, &b);
    }

    // SplineFitOptions::removalTrials: the seed of one control point more (AveragedTrialCache::seed)
    // less one break, from its parameters, in turn until a trial's samples come within what the
    // rounds aim for (the best kept). A curve that fits has its breaks where the shape needs them,
    // which averaged knots (the samples' density) and FITPACK's (each knot placed once, never moved)
    // need not be. The break removed first is the one between the two neighbouring spans whose
    // largest distances sum the least: the most room for the curve to widen them. (Ranked instead by
    // a least squares without each break, from the seed's parameters: fewer control points for as
    // many trials, more for as many instructions; see kRemovalTrials.)
    void removeFrom(int nCtrl, Trial& best)
    {
        const auto it = state_->seeds.find(nCtrl + 1);
        if (it == state_->seeds.end())
            throw GeometryError("averaged fit: no trial of one control point more to start from");
        const Trial seed = it->second;  // (a copy: the trials below may replace the map's entries)
        const Spline& b = seed.curve;
        const int spans = b.spanCount();
        const std::vector<double> e = spanErrors(seed);
        // Break r joins spans r - 1 and r: an open curve's interior breaks; a closed curve's every
        // break but b_0 = 0, its seam (removing it would move the parameters' origin).
        std::vector<std::pair<double, int>> rank;
        for (int r = 1; r < spans; ++r) rank.emplace_back(e[r - 1] + e[r], r);
        std::sort(rank.begin(), rank.end());
        const double within = roundsTarget();
        for (int t = 0; t < opt_.removalTrials && t < static_cast<int>(rank.size()) && !(best.error <= within); ++t) {
            std::vector<double> nb = b.breaks;
            nb.erase(nb.begin() + rank[t].second);
            Trial c = trial(nCtrl, &nb, &seed.params);
            if (c.error < best.error) best = std::move(c);
        }
        if (!std::isfinite(best.error)) throw GeometryError("averaged fit: no break to remove");
    }

    // SplineFitOptions::equidistributions (a fixed count whose trial misses): the breaks moved so
    // that every span carries the same share of the fourth root of its largest distance. A cubic's
    // error on a span of width h goes as h^4 |f''''| (de Boor, A Practical Guide to Splines, ch.
    // XII), so widths in proportion to (e_j)^(-1/4) h_j even the spans' errors out (de Boor's
    // equidistribution, here of the measured error rather than an estimated derivative: where the
    // noise is near the tolerance it is the error that matters). The breaks are the quantiles of
    // that mass, linear within a span; the trial with the smallest largest distance is kept.
    // (Until session 44 every round placed its breaks from the best trial's curve measured at the
    // parameters the last trial had left, a trial that was not kept included: on the development
    // strokes 56,731 control points; from the best trial at its own parameters, which repeats a
    // missed trial, 56,824; from each trial before, 56,706.)
    void equidistribute(int nCtrl, Trial& best)
    {
        const double within = roundsTarget();
        if (opt_.equidistributions <= 0 || opt_.averagedControlPoints <= 0 || !std::isfinite(best.error) ||
            best.error <= within || best.params.empty())
            return;
        // Each trial's breaks from the errors of the trial before (de Boor's iteration; from the
        // best one instead, a trial that misses would be made again the same).
        Trial last = best;
        for (int r = 0; r < opt_.equidistributions && best.error > within && !last.params.empty(); ++r) {
            const Spline& b = last.curve;
            const int spans = b.spanCount();
            const std::vector<double> e = spanErrors(last);
            double mean = 0.0;
            for (double v : e) mean += v / spans;
            if (!(mean > 0.0)) break;
            std::vector<double> mass(static_cast<size_t>(spans));
            double total = 0.0;
            for (int j = 0; j < spans; ++j)
                total += mass[j] = std::pow(std::max(e[j], kEquidistributionFloor * mean), 0.25);
            std::vector<double> nb = {0.0};
            double acc = 0.0;
            int j = 0;
            for (int i = 1; i < spans; ++i) {
                const double target = total * i / spans;
                while (j < spans - 1 && acc + mass[j] < target) acc += mass[j++];
                const double h = b.spanEnd(j) - b.breaks[j];
                const double knot = b.breaks[j] + h * std::clamp((target - acc) / mass[j], 0.0, 1.0);
                if (knot > nb.back() + 1e-12 && knot < 1.0 - 1e-12) nb.push_back(knot);
            }
            if (!in_.closed) nb.push_back(1.0);
            if (nb.size() != b.breaks.size()) break;
            // (trial copies the parameters before `last` is replaced.)
            last = trial(nCtrl, &nb, &last.params);
            if (last.error < best.error) best = last;
        }
    }

    const SplineFitInput& in_;
    const SplineFitOptions& opt_;
    const std::vector<Vec3>& X_;
    const std::vector<int> S_;
    const std::vector<double> u_;  // the samples' chord parameters
    std::vector<double> uc_;       // the parameters of the trial being made (corrected in it)
    SplineFitResult res_;
    AveragedTrialCache::State local_;             // (without SplineFitOptions::trialCache)
    AveragedTrialCache::State* state_ = &local_;  // this input's
};

}  // namespace

SplineFitResult fitAveraged(const SplineFitInput& in, const SplineFitOptions& opt, std::vector<int> S,
                            std::vector<double> u)
{
    return AveragedFit(in, opt, std::move(S), std::move(u)).run();
}

}  // namespace detail
}  // namespace sculptline::solvers::stroke
