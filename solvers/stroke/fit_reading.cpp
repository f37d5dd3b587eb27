#include "solvers/stroke/fit_reading.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/stroke/fit_check.h"
#include "solvers/stroke/fit_reading_tuning.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace sculptline::solvers::stroke::detail {

using Vec3 = Eigen::Vector3d;

bool noiseOutliers(const SampleDeviation& dev, const std::vector<char>& keep, double tolerance, double sigma,
                   std::vector<int>& outliers)
{
    outliers.clear();
    const double limit = kOutlierSigmas * sigma;
    const int n = static_cast<int>(dev.bound.size());
    const size_t kept = static_cast<size_t>(std::count(keep.begin(), keep.end(), 1));
    const size_t most = static_cast<size_t>(kMaxOutlierShare * static_cast<double>(kept));
    const auto beyond = [&](int i) { return dev.bound[static_cast<size_t>(i)] > tolerance; };
    for (int i = 0; i < n; ++i) {
        if (!keep[static_cast<size_t>(i)] || !beyond(i)) continue;
        int a = i - 1, b = i + 1;
        while (a >= 0 && !keep[static_cast<size_t>(a)]) --a;
        while (b < n && !keep[static_cast<size_t>(b)]) ++b;
        const bool alone = a >= 0 && b < n && !beyond(a) && !beyond(b);
        if (!alone || !(dev.bound[static_cast<size_t>(i)] <= limit) || outliers.size() >= most) {
            outliers.clear();
            return false;
        }
        outliers.push_back(i);
    }
    return true;
}

namespace {

// One reading of the stroke (fitReading): its steps share the stroke, the fit taken so far (the
// caller's res, fit and outliers) and the least squares' options and chain.
class ReadingFit {
public:
    ReadingFit(const Prepared& p, const std::vector<int>& corners, Reading reading, FitResult& res, FitPass& fit,
               std::vector<int>& outliers, int ceiling)
        : stroke_(p.stroke), options_(p.options), cs_(p.cs), fitPoints_(p.fitPoints), drawn_(p.drawn),
          samples_(p.samples), keep_(p.keep), corners_(corners), reading_(reading), res_(res), fit_(fit),
          outliers_(outliers), ceiling_(ceiling)
    {
        sopt_.tolerance = std::max(kMinInnerShare * res_.tolerance, res_.tolerance - cs_.smoothingShift);
    }

    void run()
    {
        if (search_) search();
        if (!found_ && !refined_ && !(search_ && scan_)) {
            // Where the search found nothing, the error-driven fit (its knots then removed as
            // SplineFitOptions::removal says: every knot by default since session 40; before, an open
            // stroke's fit here was switched to every knot alone, spiral 19 -> 18).
            refine(kMaxRefinements);
        }
        if (!res_.converged) fallback();
    }

private:
    // A curve's measure: `error`, its samples' largest distance (the noise's outliers left out),
    // or, where it holds every sample but strays between two (`strayed`), the straying's excess
    // in tolerances; `samples` is then the samples' largest distance alone.
    struct Measured {
        double error = 0.0;
        bool strayed = false;
        double samples = 0.0;
    };

    // One measure: a worst sample beyond kOutlierSigmas * sigma is no outlier, so the count misses
    // at once. (Measuring the maximum first, and the samples beyond the tolerance in a second
    // measure only where the maximum left room for outliers, cost more over the 16 jittery
    // flourishes of BM_StrokeFitSeeds/1: 138 against 132 M instructions, callgrind.)
    // A curve within the tolerance of every sample must also stay near the stroke between them
    // (measureStray): one that strays is measured as missing by its excess, never as fitting.
    Measured deviation(const Curve3d& curve, SampleDeviation& dev)
    {
        dev = measureSamples(curve, stroke_.points, keep_, kCheckSpacingShare * res_.tolerance, exactAbove_);
        suspects_.clear();
        double err = dev.maxError;
        if (!(dev.maxError <= res_.tolerance) && dev.maxError <= kOutlierSigmas * cs_.noise &&
            noiseOutliers(dev, keep_, res_.tolerance, cs_.noise, suspects_))
            err = dev.maxWithin;
        if (!(err <= res_.tolerance) || !options_.boundStray) return {err, false, err};
        const StrayMeasure stray = strayOf(curve, dev, 1.0);
        if (!(stray.excess > 1.0)) return {err, false, err};
        return {std::max(err, stray.excess * res_.tolerance), true, err};
    }

    // How far `curve` strays (measureStray) from the kept samples less the noise's outliers
    // (`suspects`), `dev` its samples' measure; stopping once beyond `stopAbove`.
    StrayMeasure strayOf(const Curve3d& curve, const SampleDeviation& dev, double stopAbove)
    {
        const std::vector<char>* kept = &keep_;
        if (!suspects_.empty()) {
            keepNow_ = keep_;
            for (int i : suspects_) keepNow_[static_cast<size_t>(i)] = 0;
            kept = &keepNow_;
        }
        return measureStray(curve, stroke_.points, *kept, res_.tolerance, kStrayChordShare,
                            kCheckSpacingShare * res_.tolerance, &dev.foot, stopAbove);
    }

    // Where the error-driven fit holds every sample but strays between two (a span the samples do
    // not hold), it is repeated with a firmer fairing term (kStrayFairingStep, kStrayFairingSteps),
    // the tolerance's refinements going on from there. If no fit then both holds the samples and
    // stays near the stroke, the one that held the samples and strayed least stands: FitResult::
    // stray reports (and a warning says) how far it strays.
    void refine(int rounds)
    {
        FitPass straying;  // the least straying fit that held every sample (strayBy: how much)
        std::vector<int> strayingOutliers;
        double strayBy = std::numeric_limits<double>::infinity(), strayingSamples = 0.0;
        int strayingRound = 0;
        for (;; ++round_) {
            fit_ = fitConditioned(cs_, fitPoints_, corners_, samples_, sopt_, nullptr, &chain_);
            SampleDeviation dev;
            const Measured m = deviation(fit_.curve, dev);
            const double err = m.error;
            const bool strayed = m.strayed;
            outliers_ = suspects_;
            res_.maxError = err;
            res_.converged = err <= res_.tolerance;
            res_.refinements = round_;
            if (res_.converged) break;
            const double by = strayed ? strayOf(fit_.curve, dev, std::numeric_limits<double>::infinity()).excess : 0.0;
            if (strayed && by < strayBy) {
                strayBy = by;
                straying = fit_;
                strayingOutliers = outliers_;
                strayingSamples = m.samples;
                strayingRound = round_;
            }
            if (strayed && firmer_ < kStrayFairingSteps) {
                ++firmer_;
                sopt_.fairing *= kStrayFairingStep;
                --round_;  // (not a refinement of the tolerance)
                continue;
            }
            if (strayed || round_ >= rounds || sopt_.tolerance <= kMinInnerShare * res_.tolerance) {
                if (std::isfinite(strayBy)) {
                    fit_ = std::move(straying);
                    outliers_ = std::move(strayingOutliers);
                    res_.maxError = strayingSamples;
                    res_.converged = true;
                    res_.refinements = strayingRound;
                }
                break;
            }
            sopt_.tolerance =
                std::max(kMinInnerShare * res_.tolerance, sopt_.tolerance * kRefineMargin * res_.tolerance / err);
        }
    }

    // The fewest control points with knots averaged over the samples' parameters (The NURBS
    // Book eq. 9.69) and the parameters corrected toward their foot points (Hoschek). A count
    // is taken only when every kept raw sample lies within the tolerance (measureSamples); the
    // samples' own distances reject it first, without that measure.
    void search()
    {
        alt_ = sopt_;
        alt_.knotPlacement = KnotPlacement::Averaged;
        alt_.averagedCorrections = kAveragedCorrections;
        alt_.tolerance = res_.tolerance;
        // (The minimax trials, after the search, end their rounds where the least squares' points,
        // smoothed by up to cs.smoothingShift, leave every drawn point within the tolerance.)
        alt_.minimaxWithin = std::max(kMinInnerShare * res_.tolerance, res_.tolerance - cs_.smoothingShift);
        alt_.averagedStopWhenWithin = true;  // (finish())
        if (scan_)
            countUp();
        else
            searchPasses();
        if (!found_ && !scan_) {
            refine(kMaxRefinements);  // (the error-driven fit, as below, before the minimax trials)
            refined_ = true;
        }
        if (res_.converged && options_.minimaxTrials) minimaxTrials();
    }

    FitPass solveTrial(int count, const std::vector<int>& rows)
    {
        highest_ = std::max(highest_, count);
        alt_.averagedControlPoints = count;
        const size_t want =
            std::min(static_cast<size_t>(cs_.size()), static_cast<size_t>(rowsPer_) * static_cast<size_t>(count));
        if (rows.size() >= want || want < 2)
            return fitConditioned(cs_, *trialPoints_, corners_, rows, alt_, nullptr, &trialChain());
        // The rows given and `want` conditioned points spread evenly over the stroke's indices.
        dense_ = rows;
        for (size_t k = 0; k < want; ++k)
            dense_.push_back(static_cast<int>(
                std::lround(static_cast<double>(k) * (cs_.size() - 1) / static_cast<double>(want - 1))));
        std::sort(dense_.begin(), dense_.end());
        dense_.erase(std::unique(dense_.begin(), dense_.end()), dense_.end());
        return fitConditioned(cs_, *trialPoints_, corners_, dense_, alt_, nullptr, &trialChain());
    }

    // The chain of the points the trials fit (a chain keeps the points it was built on).
    Chain& trialChain() { return trialPoints_ == &drawn_ ? drawnChain_ : chain_; }

    // A trial that cannot make a curve is a count that does not fit, not a failed stroke: a
    // sparse loop's clamped piece whose averaged knots merge can leave fewer than the 4
    // distinct points a closed cubic needs (teardrops of 16-24 samples), and the error-driven
    // fit after the search still fits such a stroke.
    FitPass trial(int count, const std::vector<int>& rows)
    {
        try {
            return solveTrial(count, rows);
        } catch (const GeometryError&) {
            FitPass none;
            none.maxError = std::numeric_limits<double>::infinity();
            return none;
        }
    }

    bool fits(const FitPass& a) const { return a.maxError <= res_.tolerance; }

    // (Whether a count's trial on `per` rows per control point adds no rows to the samples.)
    bool addsNoRows(int per, int count) const
    {
        const size_t want =
            std::min(static_cast<size_t>(cs_.size()), static_cast<size_t>(per) * static_cast<size_t>(count));
        return samples_.size() >= want || want < 2;
    }

    bool repeats(int count) const { return rowsPer_ > 0 && addsNoRows(rowsPer_, count); }

    FitPass trialAt(int count)
    {
        if (repeats(count)) {
            const auto it = firstTrials_.find(count);
            if (it != firstTrials_.end()) {
                highest_ = std::max(highest_, count);
                return it->second;
            }
        }
        FitPass a = trial(count, samples_);
        // (Kept only where the second pass can ask again: a count whose dense rows add some is
        // solved afresh there.)
        if (rowsPer_ == 0 && addsNoRows(kDenseRowsPerPoint, count)) firstTrials_.emplace(count, a);
        return a;
    }

    // A trial stops its corrections once its samples fit (averagedStopWhenWithin): the search
    // asks only whether a count fits. The count it ends at goes on from there to the last
    // correction before it is measured on the raw samples, so the curve taken is the one the
    // uninterrupted trial makes, to the bit. (Counts above the least that fits stop after 3-7 of
    // the 8 corrections: BM_StrokeFit/1000's 23 fits after 3.) Where the corrections are not
    // monotone a count stopped as fitting might have ended beyond the tolerance: that count is
    // then measured after finishing, and take() rejects it as any count that misses.
    void finish(FitPass& a, int count, const std::vector<int>& rows)
    {
        if (!a.correction.stopped) return;
        const AveragedCorrectionState state = std::move(a.correction);
        alt_.averagedStopWhenWithin = false;
        alt_.averagedResume = &state;
        // (A count judged to fit is finished by least squares alone: its curve is the one the
        // least squares' search would take. Its rows' distances, measured at their parameters,
        // can end above the tolerance while every raw sample's own distance is within it, and
        // minimax rounds from there lost such counts: a fast circle 12 -> 23 control points.)
        const int rounds = alt_.minimaxRounds;
        alt_.minimaxRounds = 0;
        a = trial(count, rows);
        alt_.minimaxRounds = rounds;
        alt_.averagedResume = nullptr;
        alt_.averagedStopWhenWithin = true;
    }

    // accept's verdict: taken, or refused, for straying between samples (every sample within
    // the tolerance) or for missing a sample.
    enum class Verdict { Taken, Missed, Strayed };

    // A count whose samples fit is taken when every kept raw sample is within the tolerance too.
    // (A minimax trial, which replaces a fit already taken, is taken only with no noise outlier
    // at all: every kept raw sample within the tolerance. Allowing as many as the fit it replaces
    // made the choice hang on that fit's outliers, which round-off can decide: the sanitizer
    // build's planar circle of Stroke3d.GivenPlanarStrokesTurnedIntoSpace_* took a count the
    // same circle turned into space refused, 9 control points against 10.)
    Verdict accept(FitPass& a, SampleDeviation& dev)
    {
        const Measured m = deviation(a.curve, dev);
        if (!(m.error <= res_.tolerance) || (replacing_ && !suspects_.empty()))
            return m.strayed ? Verdict::Strayed : Verdict::Missed;
        byMinimax_ = replacing_;
        fit_ = std::move(a);
        outliers_ = suspects_;
        res_.maxError = m.error;
        res_.refinements = 0;
        res_.converged = true;
        return Verdict::Taken;
    }

    // Where raw samples between the least squares' rows lie beyond the tolerance, the same count
    // is solved again with their conditioned points among the rows (kRowRounds, kRowShare), so
    // that the least squares answers for them: flourish-200 22 -> 21 control points, the
    // s-curve in the fewest-points mode 7 -> 6 (scripts/compare_splprep.py).
    bool takeOnRows(FitPass& a, int count)
    {
        finish(a, count, samples_);
        if (!fits(a)) return false;
        SampleDeviation dev;
        if (accept(a, dev) == Verdict::Taken) return true;
        std::vector<int> rows = samples_;
        for (int round = 0; round < kRowRounds; ++round) {
            const size_t before = rows.size();
            for (size_t i = 0; i < dev.bound.size(); ++i) {
                if (!keep_[i] || !(dev.bound[i] > kRowShare * res_.tolerance)) continue;
                // The conditioned point of raw sample i, or the next one when i was merged.
                const auto it = std::lower_bound(cs_.source.begin(), cs_.source.end(), static_cast<int>(i));
                rows.push_back(std::min(static_cast<int>(it - cs_.source.begin()), cs_.size() - 1));
            }
            std::sort(rows.begin(), rows.end());
            rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
            if (rows.size() == before) return false;
            FitPass b = trial(count, rows);
            finish(b, count, rows);
            if (!fits(b)) return false;
            if (accept(b, dev) == Verdict::Taken) return true;
        }
        return false;
    }

    bool take(FitPass& a, int count)
    {
        if (repeats(count) && firstRefused_.count(count) > 0) return false;
        const bool taken = takeOnRows(a, count);
        if (!taken && rowsPer_ == 0) firstRefused_.insert(count);
        return taken;
    }

    void countUp()
    {
        // Counting up from the smallest, below the error-driven count: never more than the
        // default's search (the error does not fall strictly with the count).
        refine(kMaxRefinements);
        const int errorDriven = fit_.curve.pointCount() - countOffset_;
        const int ceiling = errorDriven - (res_.converged ? 1 : 0);
        rowsPer_ = kDenseRowsPerPoint;
        for (int count = cs_.closed ? 5 : 4; count <= ceiling && !found_; ++count) {
            FitPass a = trial(count, samples_);
            found_ = take(a, count);
        }
    }

    // Predicted counts instead of a bisection: a cubic's least-squares error falls about
    // as the fourth power of the span (de Boor, ch. XII), so a count n - 3 spans missing
    // by e / tol needs about (n - 3) (e / tol)^(1/4) spans. From kFirstCount the counts
    // climb by that law until the samples fit, then step down while they still fit (the
    // law overshoots where the error falls faster), and the count reached is verified on
    // the raw samples. On the benchmark strokes the same counts as the bisection below the
    // error-driven count it replaces (flourish-200 22, flourish-1000 18, s-curve 7), with
    // 4-5 trials instead of 5-7 plus the error-driven fit. Where the law keeps missing
    // (more than kMaxClimbSteps predictions fall short: flourish-200 needs 3, the Fig. 4-3
    // hairpin climbs past the error-driven count, 22 against 16) averaged knots do not
    // suit the stroke and the error-driven fit is taken instead.
    // When the search on the dynamic threshold's rows finds nothing, it runs once more on
    // evenly spread rows, kDenseRowsPerPoint per control point (a sparse real pigtail 26 ->
    // 18 control points; the Fig. 4-3 hairpin still finds nothing and keeps its 14), before
    // the error-driven fit. Not first: on flourish-200 those rows cost a control point (24
    // against 21 with the climbs as they are, 22 with 5 climbs, which moved the hairpin to 20).
    static constexpr int kFirstCount = 8;
    static constexpr int kMaxClimbSteps = 3;
    // A count that misses by no more than kNearMiss earns the climb another step, at most
    // kNearMissClimbs times: the law then predicts the next count, and a stroke that close
    // is not one the law keeps missing. A sparse real circle (30 samples, one corner where
    // its ends meet) climbed 8, 10, 11, 12 on evenly spread rows and stopped at 12, 1.7 %
    // over, for the error-driven fit's 17 control points; now 13 fits (12 after its seam
    // is shared; FITPACK's splprep: 14; compare_splprep default mode 27 -> 28 of 28
    // strokes, total 523 -> 518). The Fig. 4-3 hairpin keeps its count, and the benchmarks'
    // strokes (BM_StrokeFit, -Jitter, -Loop, -Seeds) make the same trials, counted.
    static constexpr double kNearMiss = 1.05;
    static constexpr int kNearMissClimbs = 2;
    // The search runs on the samples' own distances (cheap); only the count it ends at is
    // measured on every raw sample, and if that misses, the next counts up (kVerifySteps).
    static constexpr int kVerifySteps = 3;

    void searchPasses()
    {
        for (int pass = 0; pass < 2 && !found_ && reading_ == Reading::Searched; ++pass) {
            rowsPer_ = pass == 0 ? 0 : kDenseRowsPerPoint;
            // The second pass replays the first trial for trial (the same counts on the same rows,
            // so the same answers) while kDenseRowsPerPoint rows per control point are no more than
            // the dynamic threshold's rows and neither pass's cap binds: then it is skipped. (Jittery
            // flourishes of 1,000 samples have ~205 rows and try at most 29 control points: the
            // replay was 30 % of their fit time.) One count of margin covers the verify loop's
            // test of the count after the last.
            if (pass == 1 &&
                static_cast<size_t>(kDenseRowsPerPoint) * static_cast<size_t>(highest_ + 1) <= samples_.size() &&
                highest_ + 1 < std::min(capOf(0), capOf(kDenseRowsPerPoint)))
                break;
            searchPass();
        }
    }

    // The largest count a pass on `per` rows per control point tries (0: the rows given).
    int capOf(int per) const
    {
        const int least = cs_.closed ? 5 : 4;
        return std::min(ceiling_, std::max(least, per > 0 ? cs_.size() / per : static_cast<int>(samples_.size())));
    }

    void searchPass()
    {
        highest_ = 0;
        // interpolation beyond
        const int cap = capOf(rowsPer_);
        // the largest count seen to miss (below the least a curve can have: 4 open, 5 closed;
        // a loop's clamped piece of 4 would leave 3 distinct points, too few for a periodic cubic)
        int count = std::min(kFirstCount, cap), failed = cs_.closed ? 4 : 3;
        FitPass a = trialAt(count);
        climb(a, count, failed, cap);
        bisectDown(a, count, failed);
        for (int step = 0; step <= kVerifySteps && (step > 0 || fits(a)) && !found_; ++step, ++count) {
            if (step > 0) {
                if (count > cap) break;
                a = trialAt(count);
            }
            found_ = take(a, count);
        }
    }

    // Up by the law from `count` (its trial `a`) while the samples miss; `failed` the largest count
    // seen to miss.
    void climb(FitPass& a, int& count, int& failed, int cap)
    {
        const auto climbing = [&](int climb) {
            return climb < kMaxClimbSteps ||
                   (climb < kMaxClimbSteps + kNearMissClimbs && a.maxError <= kNearMiss * res_.tolerance);
        };
        double missedBy = std::numeric_limits<double>::infinity();  // the last miss's error before `a`
        for (int climb = 0; !fits(a) && count < cap && climbing(climb); ++climb) {
            failed = count;
            missedBy = a.maxError;
            // (An open cubic has count - 3 spans, a closed one count.)
            const int extra = periodic_ ? 0 : 3;
            // (A trial that made no curve misses by an infinite error: the next count.)
            const double spans = (count - extra) * std::pow(a.maxError / res_.tolerance, 0.25);
            const int predicted =
                std::isfinite(spans) && spans < cap ? extra + static_cast<int>(std::ceil(spans)) : cap;
            count = std::min(cap, std::max(count + 1, predicted));
            a = trialAt(count);
        }
        // A climb whose last step missed by more than the step before (the error is not
        // monotone in the count, and a count given up early reports its error after fewer
        // corrections) has jumped past counts the law cannot judge: those between the last
        // two misses are tried in turn before the search gives up. Two of the 16 jittery
        // flourishes (BM_StrokeFitSeeds/1, seeds 3 and 15) climbed 20 (1.38 tolerances
        // after 6 corrections), 22 (2.44 after 2) and fell back to the error-driven fit, 30
        // and 32 control points in about 1 ms; 21 fits both, in about half that.
        if (!fits(a) && a.maxError > missedBy && count - failed > 1) {
            for (int k = failed + 1; k < count; ++k) {
                FitPass b = trialAt(k);
                if (!fits(b)) {
                    failed = k;  // (the bisection below starts above it)
                    continue;
                }
                a = std::move(b);
                count = k;
                break;
            }
        }
    }

    // Down by bisection between the largest count seen to miss and the count that fits:
    // a climb can land several counts above the least that fits (the law's prediction
    // from a large miss), and stepping down one count at a time took up to 6 trials on
    // the 32 flourishes of BM_StrokeFitSeeds (3-6 on 13 of them); the bisection takes
    // at most 3. (The error does not fall strictly with the count, so the two can end
    // at different counts: 16 clean flourishes 20.5 -> 19.9 control points on average,
    // 16 jittery 23.2 -> 23.6; scripts/compare_splprep.py unchanged, 518 and 496.)
    void bisectDown(FitPass& a, int& count, int& failed)
    {
        for (int fitsAt = count; fits(a) && fitsAt - 1 > failed;) {
            const int mid = failed + (fitsAt - failed) / 2;
            FitPass b = trialAt(mid);
            if (fits(b)) {
                a = std::move(b);
                count = fitsAt = mid;
            } else {
                failed = mid;
            }
        }
    }

    // Minimax trials below the count taken (SplineFitOptions::minimaxRounds, on every
    // conditioned point: the rows that hold the noise the least squares' rows skip): the
    // tolerance bounds the largest distance, which the least squares does not minimize. A
    // count is taken only when every kept raw sample is within the tolerance, with no more
    // noise outliers. Where the count leaves fewer than kNoiseRowsPerPoint points per control point
    // (the bisection's note above), a bisection between the least count and the one taken; then
    // down from the count reached, one at a time while the count below is taken; then, there, the
    // same descent with the breaks equidistributed. (The
    // counts do not fall monotonically: the bisection reaches counts far below that a descent
    // from the top stops short of.)
    // The trials fit the drawn points (Prepared::drawn), their rounds aiming at the tolerance
    // itself: it bounds the distance to what was drawn, which Lawson's rounds then minimize.
    // Then, down from the count reached, the same descent on the smoothed points the least
    // squares fits (their rounds aiming at the tolerance less the smoothing's shift), which fit
    // some strokes with fewer. Until session 51 the trials ran on the smoothed points alone: a
    // count whose curve came within 0.85 of them missed a drawn sample by 1.10 (question-s04m7 at
    // one pixel: 18 control points, OCCT 17; now 13). On the development strokes
    // (unistroke-report --fit-dev, fit ms the least of three runs): 50,233 control points in
    // 2,068-2,121 ms before; on the drawn points alone 46,775 in 1,729-1,796 ms, but 252 strokes
    // took more; the drawn points' pass and then the smoothed points' (without the bisection)
    // 45,964 in 2,492-2,561 ms, 1,653 strokes fewer and 16 more (both with the bisection, the
    // smoothed points' first: 46,026 in 2,710 ms). A trial on uniform breaks too (OCCT's) where
    // the others miss: 45,868-45,937 for 5-7 % more time, not kept. On a densely sampled stroke
    // the drawn points' pass gains nothing and costs a second pass on every point: the 1,000-sample
    // flourishes of BM_StrokeFitWarm kept their 21 / 19 control points for 328 -> 528 us clean;
    // where the count leaves kDrawnRowsPerPoint points per control point or more the smoothed
    // points' pass runs alone, as before (334 / 478 us; the development strokes' 45,964 alike).
    // (At kNoiseRowsPerPoint, 8, seven of the 750 development drawings of the peers' five gestures
    // took 1-2 more at one pixel, circle-s04m10 8 -> 10.)
    void minimaxTrials()
    {
        const int least = cs_.closed ? 5 : 4;
        all_.resize(static_cast<size_t>(cs_.size()));
        for (int i = 0; i < cs_.size(); ++i) all_[static_cast<size_t>(i)] = i;
        alt_.minimaxRounds = kMinimaxRounds;
        alt_.averagedCorrections = kMinimaxCorrections;
        // (The minimax trials all run on every conditioned point: they keep their insertion and
        // each count's trial for one another. The search's trials stop once within, and keep
        // nothing.)
        AveragedTrialCache trialCache;
        alt_.trialCache = &trialCache;
        alt_.averagedStopWhenWithin = false;
        replacing_ = true;
        // First on the drawn points, then down from the count reached on the smoothed ones (the
        // note above), where the count leaves fewer than kDrawnRowsPerPoint points per control
        // point (and in a Reading::Descended); elsewhere on the smoothed points alone.
        // (The counts the search missed were missed on the smoothed points.)
        const double smoothedWithin = alt_.minimaxWithin;
        const bool drawnFirst = leavesFewPerPoint(kDrawnRowsPerPoint);
        if (drawnFirst) {
            trialsOn(drawn_, res_.tolerance);
            minimaxPass(least, true);
            trialsOn(fitPoints_, smoothedWithin);
        }
        minimaxPass(least, !drawnFirst);
        if (byMinimax_) polish();
        alt_.trialCache = nullptr;  // (trialCache is this call's)
    }

    // The minimax trials from here on fit `points`, their rounds aiming at `within`; the counts
    // missed or refused so far were of other trials.
    void trialsOn(const std::vector<Vec3>& points, double within)
    {
        trialPoints_ = &points;
        alt_.minimaxWithin = within;
        missedBy_.clear();
        strayedAt_.clear();
    }

    // Whether the count taken leaves fewer than `perPoint` conditioned points per control point,
    // or the reading is a Reading::Descended.
    bool leavesFewPerPoint(int perPoint = kNoiseRowsPerPoint) const
    {
        return (fit_.curve.pointCount() - countOffset_) * perPoint >= cs_.size() || reading_ == Reading::Descended;
    }

    // One pass of the minimax trials on trialPoints_ (see minimaxTrials), without the bisection
    // unless `full`.
    void minimaxPass(int least, bool full)
    {
        // Bisect below the count, with FITPACK's knots tried too, where the count leaves fewer than
        // kNoiseRowsPerPoint conditioned points per control point, and always on a piece read by
        // descent (no search there): a count whose trial on averaged knots misses is tried on FITPACK's knots too
        // (SplineFitOptions::insertedTrials): they follow the error of the shape where averaged knots follow the
        // samples' density. On the development strokes 56,762 -> 56,474 control points (circles 4,610 -> 4,420), and
        // compare_splprep.py --dev circle 139 -> 144 of 150 circles meeting the fewer peer. For
        // 24 % more instructions there (callgrind, fitStroke over unistroke-report --fit-dev,
        // 7.43 -> 9.25 G), 0.7 % more on BM_StrokeRecorded/0 (423 -> 426 M). On every stroke
        // the minimax trials reach: 56,473 for 6 % more instructions on BM_StrokeRecorded/0;
        // in the search before them too: 56,470; FITPACK's knots alone in the minimax trials
        // (no averaged trial first): 56,563. (Those figures are of the rule before session 50,
        // where the count follows the noise.)
        const bool bisect = leavesFewPerPoint();
        alt_.insertedTrials = bisect;
        if (bisect && full) {
            // (A count refused for straying sends the bisection below it, as one taken: on the
            // development circles 4,217 -> 4,208 control points, circle-s02m6 23 -> 16, its
            // fewer peer 18; without this the bisection climbed past the counts below.)
            for (int lo = least - 1, hi = below(fit_.curve.pointCount() - countOffset_); hi - lo > 1;) {
                const int mid = lo + (hi - lo) / 2;
                if (takes(mid) || strayedAt_.count(mid) > 0)
                    hi = mid;
                else
                    lo = mid;
            }
        }
        descend(0);
        // Where the count still leaves fewer than kNoiseRowsPerPoint points per control point (and
        // in a Reading::Descended), the same descent with the trials' breaks moved to where the
        // error is (SplineFitOptions::equidistributions, kEquidistributions).
        if (leavesFewPerPoint()) {
            alt_.equidistributions = kEquidistributions;
            missedBy_.clear();  // (other trials)
            descend(kLookBelow);
            alt_.equidistributions = 0;
        }
    }

    // (No count above the ceiling is tried: the caller takes none.)
    int below(int count) const { return count > ceiling_ ? ceiling_ + 1 : count; }

    // Whether `count` is taken: its minimax trial (averaged knots, FITPACK's where it misses, and
    // in the equidistributed descent its breaks moved) and the removal trials (kRemovalTrials: the
    // breaks of one control point more less one). Where the count above has a seed (a count taken
    // in the trials, or its trial made for the purpose where the trials start from it), the
    // removal trials go first and the minimax trial follows where they are refused; otherwise the
    // minimax trial goes first. Where both are refused the minimax trial's verdict and largest
    // distance stand (missedBy_, strayedAt_: the bisection and the look below read them).
    bool takes(int count)
    {
        if (missedBy_.count(count) > 0) return false;
        AveragedTrialCache& cache = *alt_.trialCache;
        double error = 0.0;
        const bool removalFirst = cache.seeded(count + 1);
        bool taken = removalFirst && judge(count, true, error) == Verdict::Taken;
        Verdict verdict = Verdict::Taken;
        if (!taken) {
            verdict = judge(count, false, error);
            taken = verdict == Verdict::Taken;
        }
        if (!taken && !removalFirst && seedAbove(count)) {
            double removalError = 0.0;  // (the minimax trial's `error` stands where this is refused)
            taken = judge(count, true, removalError) == Verdict::Taken;
        }
        if (taken) {
            cache.seed(count);
            return true;
        }
        missedBy_[count] = error;
        if (verdict == Verdict::Strayed) strayedAt_.insert(count);
        return false;
    }

    // One trial of `count` (removal trials where `byRemoval`) and accept's verdict on it; `error`
    // receives its largest distance (its raw samples' where its samples fit).
    Verdict judge(int count, bool byRemoval, double& error)
    {
        alt_.removalTrials = byRemoval ? kRemovalTrials : 0;
        FitPass a = trial(count, all_);
        alt_.removalTrials = 0;
        SampleDeviation dev;
        const bool samplesFit = fits(a);
        const Verdict verdict = samplesFit ? accept(a, dev) : Verdict::Missed;
        error = samplesFit ? dev.maxError : a.maxError;
        if (verdict == Verdict::Taken) removedAt_ = byRemoval ? count : 0;
        return verdict;
    }

    // Whether count + 1 has a seed for the removal trials of `count`; where it has none and is the
    // count taken so far (the trials start from a count the search took, on other rows), its trial
    // is made on the trials' rows to be one.
    bool seedAbove(int count)
    {
        AveragedTrialCache& cache = *alt_.trialCache;
        if (!cache.seeded(count + 1) && count + 1 == fit_.curve.pointCount() - countOffset_) {
            trial(count + 1, all_);
            cache.seed(count + 1);
        }
        return cache.seeded(count + 1);
    }

    // Down one count at a time from the count taken while the count below is taken; where
    // the count that stops it missed by little (kLookMissShare), up to `look` counts below
    // it too, and on from one taken. (Looking below in this descent as well, before the
    // equidistributed one: 56,150-56,154 control points with 1-3 counts, for the same time.)
    void descend(int look)
    {
        const int least = cs_.closed ? 5 : 4;
        for (;;) {
            int k = below(fit_.curve.pointCount() - countOffset_) - 1;
            while (k >= least && takes(k)) --k;
            if (k < least || !(missedBy_.at(k) <= kLookMissShare * res_.tolerance)) return;
            bool taken = false;
            for (int j = k - 1; j >= least && j >= k - look && !taken; --j) taken = takes(j);
            if (!taken) return;
        }
    }

    // A count a minimax trial took is its curve once its rounds stop, anywhere within the
    // tolerance. Its rounds are then run to the end (kPolishRounds, the best kept): the
    // curve as close to the drawn samples as that count allows. A count the removal trials took
    // is polished from the same seed, and on averaged knots too (the closer kept): on
    // question-s06f3 at one pixel (compare_splprep.py --resolution 1) the removal trials' 11
    // control points polished came within 0.995, those on averaged knots within 0.914.
    void polish()
    {
        alt_.minimaxRounds = kPolishRounds;
        alt_.minimaxWithin = -1.0;
        const int count = fit_.curve.pointCount() - countOffset_;
        const bool removed = removedAt_ == count && alt_.trialCache->seeded(count + 1);
        for (const bool byRemoval : {true, false}) {
            if (byRemoval && !removed) continue;
            alt_.removalTrials = byRemoval ? kRemovalTrials : 0;
            FitPass a = trial(count, all_);
            alt_.removalTrials = 0;
            if (!std::isfinite(a.maxError)) continue;  // (no curve: trial's GeometryError)
            SampleDeviation dev;
            const double err = deviation(a.curve, dev).error;
            if (err < res_.maxError && suspects_.empty()) {
                fit_ = std::move(a);
                outliers_ = suspects_;
                res_.maxError = err;
            }
        }
    }

    // Below the noise (a tolerance of a twentieth of a pixel on integer pixel samples) the
    // dynamic threshold's subset leaves too few rows: the error-driven insertion runs out of
    // room (one control point per point) before every sample is held. Every conditioned point
    // then enters the least squares; an open stroke may also take averaged knots on every
    // point (The NURBS Book eq. 9.69), which meet the Schoenberg-Whitney condition and so
    // interpolate when nothing less does. The best of these is kept.
    void fallback()
    {
        std::vector<int> all(static_cast<size_t>(cs_.size()));
        for (int i = 0; i < cs_.size(); ++i) all[static_cast<size_t>(i)] = i;
        SplineFitOptions every = sopt_;
        every.tolerance = std::max(kMinInnerShare * res_.tolerance, res_.tolerance - cs_.smoothingShift);
        for (const KnotPlacement placement : {KnotPlacement::ErrorDriven, KnotPlacement::Averaged}) {
            if (res_.converged || (placement == KnotPlacement::Averaged && cs_.closed)) break;
            every.knotPlacement = placement;
            const bool interpolate = placement == KnotPlacement::Averaged;
            if (interpolate) every.fairing = 1e-10;
            FitPass alt = fitConditioned(cs_, fitPoints_, corners_, all, every, interpolate ? &fitPoints_ : nullptr);
            const SampleDeviation dev =
                measureSamples(alt.curve, stroke_.points, keep_, kCheckSpacingShare * res_.tolerance);
            if (dev.maxError < res_.maxError) {
                fit_ = std::move(alt);
                outliers_.clear();
                res_.maxError = dev.maxError;
                res_.converged = dev.maxError <= res_.tolerance;
            }
        }
    }

    // The prepared stroke and the caller's result (references to the caller's storage).
    const Stroke& stroke_;
    const FitOptions& options_;
    const ConditionedStroke& cs_;
    const std::vector<Vec3>& fitPoints_;
    const std::vector<Vec3>& drawn_;
    const std::vector<Vec3>* trialPoints_ = &fitPoints_;
    const std::vector<int>& samples_;
    const std::vector<char>& keep_;
    const std::vector<int>& corners_;
    const Reading reading_;
    FitResult& res_;
    FitPass& fit_;
    std::vector<int>& outliers_;
    const int ceiling_;
    SplineFitOptions sopt_ = options_.spline;
    // The averaged-knot search (FitOptions::fewerControlPoints) applies to strokes without corners
    // and to loops with one. By default it runs without the error-driven fit (which it replaced as
    // the first step: a quarter to a third of the time went into a fit that served only as the
    // search's ceiling); the error-driven fit runs only when the search finds nothing. The
    // fewest-points mode (FitOptions::countUp) counts up below the error-driven count instead.
    // A smooth loop is periodic; a loop with one corner is one clamped piece from the corner round
    // to it, fitted as an open curve whose ends meet (fitPieces, closeClampedLoop).
    const bool periodic_ = cs_.closed && corners_.empty();
    const bool search_ = (corners_.empty() || (cs_.closed && corners_.size() == 1)) && options_.fewerControlPoints;
    const bool scan_ = options_.countUp;
    // Where the noise can reach beyond the tolerance, every measure projects the samples beyond
    // it exactly (exactAbove); elsewhere the measures are as before.
    const double exactAbove_ = kOutlierSigmas * cs_.noise > res_.tolerance ? res_.tolerance
                                                                           : std::numeric_limits<double>::infinity();
    // The deviation of the kept samples from `curve`, the noise's outliers left out when every
    // sample beyond the tolerance is one (`suspects`; the maximum is then that of the samples within
    // the tolerance, SampleDeviation::maxWithin).
    std::vector<int> suspects_;
    std::vector<char> keepNow_;  // (strayOf's kept samples less the suspects)
    // The chain every fit below shares (the same points, corners and chord parameters; the rows
    // and options differ), built by the first.
    Chain chain_;
    Chain drawnChain_;
    int round_ = 0;
    int firmer_ = 0;  // fairing raised this many times
    bool found_ = false, refined_ = false;

    // The averaged-knot search's (search()) and the minimax trials' (minimaxTrials()).
    SplineFitOptions alt_;
    // The count a trial is asked for is the curve's points less this: a closed curve repeats 3
    // points, and a loop's one clamped piece has its seam point twice.
    const int countOffset_ = !cs_.closed ? 0 : periodic_ ? 3 : 2;
    int rowsPer_ = 0;  // 0: the rows given; else at least rowsPer * count (kDenseRowsPerPoint)
    std::vector<int> dense_;
    int highest_ = 0;  // the largest count tried in this pass
    // The first pass's answers by count (the trial on the dynamic threshold's rows, and whether
    // take() refused it). The second pass asks a count the same question when its
    // kDenseRowsPerPoint rows per control point are no more than those rows: solveTrial then
    // adds none, and the trial, its row rounds and their measures are the first pass's to the
    // bit. (On the 240 strokes people drew of BM_StrokeRecorded: 1,218 least-squares fits
    // against 1,283 and 559 raw-sample measures against 574, 331 against 340 M instructions.)
    std::map<int, FitPass> firstTrials_;
    std::set<int> firstRefused_;
    bool replacing_ = false, byMinimax_ = false;
    int removedAt_ = 0;  // the count taken by a removal trial (0: none)
    // The minimax trials' (on every conditioned point).
    std::vector<int> all_;
    // Each count that missed, and its largest distance then (its samples' or raw samples').
    std::map<int, double> missedBy_;
    // The counts refused only for straying between samples (every sample within the
    // tolerance): a curve of its own, not a sign that the count is too small.
    std::set<int> strayedAt_;
};

}  // namespace

void fitReading(const Prepared& p, const std::vector<int>& corners, Reading reading, FitResult& res, FitPass& fit,
                std::vector<int>& outliers, int ceiling)
{
    ReadingFit(p, corners, reading, res, fit, outliers, ceiling).run();
}

}  // namespace sculptline::solvers::stroke::detail
