#include "solvers/stroke/fit_reading.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/stroke/reading_fit.h"

#include <algorithm>
#include <cmath>

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

void ReadingFit::run()
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

// One measure: a worst sample beyond kOutlierSigmas * sigma is no outlier, so the count misses
// at once. (Measuring the maximum first, and the samples beyond the tolerance in a second
// measure only where the maximum left room for outliers, cost more over the 16 jittery
// flourishes of BM_StrokeFitSeeds/1: 138 against 132 M instructions, callgrind.)
// A curve within the tolerance of every sample must also stay near the stroke between them
// (measureStray): one that strays is measured as missing by its excess, never as fitting.
ReadingFit::Measured ReadingFit::deviation(const Curve3d& curve, SampleDeviation& dev)
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
StrayMeasure ReadingFit::strayOf(const Curve3d& curve, const SampleDeviation& dev, double stopAbove)
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
void ReadingFit::refine(int rounds)
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
void ReadingFit::search()
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

FitPass ReadingFit::solveTrial(int count, const std::vector<int>& rows)
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
        dense_.push_back(
            static_cast<int>(std::lround(static_cast<double>(k) * (cs_.size() - 1) / static_cast<double>(want - 1))));
    std::sort(dense_.begin(), dense_.end());
    dense_.erase(std::unique(dense_.begin(), dense_.end()), dense_.end());
    return fitConditioned(cs_, *trialPoints_, corners_, dense_, alt_, nullptr, &trialChain());
}

// A trial that cannot make a curve is a count that does not fit, not a failed stroke: a
// sparse loop's clamped piece whose averaged knots merge can leave fewer than the 4
// distinct points a closed cubic needs (teardrops of 16-24 samples), and the error-driven
// fit after the search still fits such a stroke.
FitPass ReadingFit::trial(int count, const std::vector<int>& rows)
{
    try {
        return solveTrial(count, rows);
    } catch (const GeometryError&) {
        FitPass none;
        none.maxError = std::numeric_limits<double>::infinity();
        return none;
    }
}

// (Whether a count's trial on `per` rows per control point adds no rows to the samples.)
bool ReadingFit::addsNoRows(int per, int count) const
{
    const size_t want =
        std::min(static_cast<size_t>(cs_.size()), static_cast<size_t>(per) * static_cast<size_t>(count));
    return samples_.size() >= want || want < 2;
}

FitPass ReadingFit::trialAt(int count)
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
void ReadingFit::finish(FitPass& a, int count, const std::vector<int>& rows)
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

// A count whose samples fit is taken when every kept raw sample is within the tolerance too.
// (A minimax trial, which replaces a fit already taken, is taken only with no noise outlier
// at all: every kept raw sample within the tolerance. Allowing as many as the fit it replaces
// made the choice hang on that fit's outliers, which round-off can decide: the sanitizer
// build's planar circle of Stroke3d.GivenPlanarStrokesTurnedIntoSpace_* took a count the
// same circle turned into space refused, 9 control points against 10.)
ReadingFit::Verdict ReadingFit::accept(FitPass& a, SampleDeviation& dev)
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
bool ReadingFit::takeOnRows(FitPass& a, int count)
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

bool ReadingFit::take(FitPass& a, int count)
{
    if (repeats(count) && firstRefused_.count(count) > 0) return false;
    const bool taken = takeOnRows(a, count);
    if (!taken && rowsPer_ == 0) firstRefused_.insert(count);
    return taken;
}

void ReadingFit::countUp()
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

namespace {

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
constexpr int kFirstCount = 8;
constexpr int kMaxClimbSteps = 3;
// A count that misses by no more than kNearMiss earns the climb another step, at most
// kNearMissClimbs times: the law then predicts the next count, and a stroke that close
// is not one the law keeps missing. A sparse real circle (30 samples, one corner where
// its ends meet) climbed 8, 10, 11, 12 on evenly spread rows and stopped at 12, 1.7 %
// over, for the error-driven fit's 17 control points; now 13 fits (12 after its seam
// is shared; FITPACK's splprep: 14; compare_splprep default mode 27 -> 28 of 28
// strokes, total 523 -> 518). The Fig. 4-3 hairpin keeps its count, and the benchmarks'
// strokes (BM_StrokeFit, -Jitter, -Loop, -Seeds) make the same trials, counted.
constexpr double kNearMiss = 1.05;
constexpr int kNearMissClimbs = 2;
// The search runs on the samples' own distances (cheap); only the count it ends at is
// measured on every raw sample, and if that misses, the next counts up (kVerifySteps).
constexpr int kVerifySteps = 3;

}  // namespace

void ReadingFit::searchPasses()
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
int ReadingFit::capOf(int per) const
{
    const int least = cs_.closed ? 5 : 4;
    return std::min(ceiling_, std::max(least, per > 0 ? cs_.size() / per : static_cast<int>(samples_.size())));
}

void ReadingFit::searchPass()
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
void ReadingFit::climb(FitPass& a, int& count, int& failed, int cap)
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
        const int predicted = std::isfinite(spans) && spans < cap ? extra + static_cast<int>(std::ceil(spans)) : cap;
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
void ReadingFit::bisectDown(FitPass& a, int& count, int& failed)
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

// Below the noise (a tolerance of a twentieth of a pixel on integer pixel samples) the
// dynamic threshold's subset leaves too few rows: the error-driven insertion runs out of
// room (one control point per point) before every sample is held. Every conditioned point
// then enters the least squares; an open stroke may also take averaged knots on every
// point (The NURBS Book eq. 9.69), which meet the Schoenberg-Whitney condition and so
// interpolate when nothing less does. The best of these is kept.
void ReadingFit::fallback()
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

void fitReading(const Prepared& p, const std::vector<int>& corners, Reading reading, FitResult& res, FitPass& fit,
                std::vector<int>& outliers, int ceiling)
{
    ReadingFit(p, corners, reading, res, fit, outliers, ceiling).run();
}

}  // namespace sculptline::solvers::stroke::detail
