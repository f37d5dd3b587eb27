// ReadingFit's minimax trials (reading_fit.h): below the count the search or the error-driven fit
// took, each count's trial on every conditioned point, its largest distance minimized (Lawson's
// rounds), and the removal trials from the breaks of the count above.
#include "solvers/stroke/reading_fit.h"

#include <algorithm>
#include <cmath>

namespace sculptline::solvers::stroke::detail {

// Minimax trials below the count taken (SplineFitOptions::minimaxRounds, on every
// conditioned point: the rows that hold the noise the least squares' rows skip): the
// tolerance bounds the largest distance, which the least squares does not minimize. A
// count is taken only when every kept raw sample is within the tolerance, with no more
// noise outliers. Where the count leaves fewer than kNoiseRowsPerPoint points per control point
// (minimaxPass), a bisection between the least count and the one taken; then
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
void ReadingFit::minimaxTrials()
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
    firmDescent();
    if (byMinimax_) polish();
    alt_.trialCache = nullptr;  // (trialCache is this call's)
}

// The minimax trials from here on fit `points`, their rounds aiming at `within`; the counts
// missed or refused so far were of other trials.
void ReadingFit::trialsOn(const std::vector<Vec3>& points, double within)
{
    trialPoints_ = &points;
    alt_.minimaxWithin = within;
    missedBy_.clear();
    strayedAt_.clear();
}

// Whether the count taken leaves fewer than `perPoint` conditioned points per control point,
// or the reading is a Reading::Descended.
bool ReadingFit::leavesFewPerPoint(int perPoint) const
{
    return (fit_.curve.pointCount() - countOffset_) * perPoint >= cs_.size() || reading_ == Reading::Descended;
}

// One pass of the minimax trials on trialPoints_ (see minimaxTrials), without the bisection
// unless `full`.
void ReadingFit::minimaxPass(int least, bool full)
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

// Whether `count` is taken: its minimax trial (averaged knots, FITPACK's where it misses, and
// in the equidistributed descent its breaks moved) and the removal trials (kRemovalTrials: the
// breaks of one control point more less one). Where the count above has a seed (a count taken
// in the trials, or its trial made for the purpose where the trials start from it), the
// removal trials go first and the minimax trial follows where they are refused; otherwise the
// minimax trial goes first. In the last descent (firmDescent), where all are refused and one held
// every sample but strayed between two, it is made again with a firmer fairing term (judge's
// `firmer`), as the error-driven fit is (refine). Where every trial is
// refused the minimax trial's verdict and largest distance stand (missedBy_, strayedAt_: the
// bisection and the look below read them).
bool ReadingFit::takes(int count)
{
    if (missedBy_.count(count) > 0) return false;
    AveragedTrialCache& cache = *alt_.trialCache;
    double error = 0.0;
    bool strayed[2] = {false, false};  // (a trial refused for straying: [byRemoval])
    const auto tried = [&](bool byRemoval, double& err) {
        const Verdict v = judge(count, byRemoval, err);
        strayed[byRemoval] = strayed[byRemoval] || v == Verdict::Strayed;
        return v;
    };
    const bool removalFirst = cache.seeded(count + 1);
    bool taken = removalFirst && tried(true, error) == Verdict::Taken;
    Verdict verdict = Verdict::Taken;
    if (!taken) {
        verdict = tried(false, error);
        taken = verdict == Verdict::Taken;
    }
    // (The minimax trial's `error` stands where the removal trials are refused.)
    double removalError = 0.0;
    for (const bool searched : {false, true})
        if (!taken && !removalFirst && seedAbove(count, searched)) taken = tried(true, removalError) == Verdict::Taken;
    if (!taken && (strayed[0] || strayed[1])) strayedAny_.insert(count);
    for (int firmer = 1; firm_ && firmer <= kStrayFairingSteps && !taken && (strayed[0] || strayed[1]); ++firmer) {
        for (const bool byRemoval : {true, false}) {
            if (taken || !strayed[byRemoval]) continue;
            const Verdict v = judge(count, byRemoval, removalError, firmer);
            taken = v == Verdict::Taken;
            strayed[byRemoval] = v == Verdict::Strayed;
        }
    }
    if (taken) {
        cache.seed(count);
        return true;
    }
    missedBy_[count] = error;
    if (verdict == Verdict::Strayed) strayedAt_.insert(count);
    return false;
}

// One trial of `count` (removal trials where `byRemoval`; the fairing term's weight raised
// kStrayFairingStep times `firmer` times) and accept's verdict on it; `error` receives its largest
// distance (its raw samples' where its samples fit).
ReadingFit::Verdict ReadingFit::judge(int count, bool byRemoval, double& error, int firmer)
{
    alt_.removalTrials = byRemoval ? kRemovalTrials : 0;
    const double fairing = alt_.fairing;
    alt_.fairing = fairing * std::pow(kStrayFairingStep, firmer);
    FitPass a = trial(count, all_);
    alt_.fairing = fairing;
    alt_.removalTrials = 0;
    SampleDeviation dev;
    const bool samplesFit = fits(a);
    const Verdict verdict = samplesFit ? accept(a, dev) : Verdict::Missed;
    error = samplesFit ? dev.maxError : a.maxError;
    if (verdict == Verdict::Taken) removedAt_ = byRemoval ? count : 0;
    return verdict;
}

namespace {

// The distinct knots of `c` over its domain (an open curve's both ends, a closed one's start alone)
// where that domain is [0, 1], as the averaged fit's breaks are; else none.
std::vector<double> breaksOf(const Curve3d& c)
{
    std::vector<double> b;
    if (c.domainStart() != 0.0 || c.domainEnd() != 1.0) return b;
    for (const double k : c.knots())
        if (k >= 0.0 && (k < 1.0 || (k == 1.0 && !c.isClosed())) && (b.empty() || k > b.back())) b.push_back(k);
    return b;
}

}  // namespace

// Whether count + 1 has a seed for the removal trials of `count`. Where it has none and is the
// count taken so far (the trials start from a count the search took, on other rows), its trial on
// the trials' rows is made to be one. Where that seed's removal trials are refused, `searched`
// asks for a second: the trial of count + 1 on the breaks of the curve taken before the trials
// (the search's, or the error-driven fit's where the search found none or the reading is
// Reading::Descended; SplineFitOptions::seedBreaks): a curve that fits, where the averaged trial of
// its count may not. (The size is checked here so that a curve whose breaks are not of the count,
// a loop's clamped piece say, is passed over without onSeedBreaks' GeometryError.)
bool ReadingFit::seedAbove(int count, bool searched)
{
    AveragedTrialCache& cache = *alt_.trialCache;
    const bool taken = count + 1 == fit_.curve.pointCount() - countOffset_;
    if (!searched) {
        if (!cache.seeded(count + 1) && taken) {
            trial(count + 1, all_);
            cache.seed(count + 1);
        }
        return cache.seeded(count + 1);
    }
    if (!taken || byMinimax_ || !corners_.empty() || searchSeeded_.count(count + 1) > 0) return false;
    searchSeeded_.insert(count + 1);
    const std::vector<double> breaks = breaksOf(fit_.curve);
    if (breaks.size() != static_cast<size_t>(periodic_ ? count + 1 : count - 1)) return false;
    alt_.seedBreaks = &breaks;
    const FitPass seed = trial(count + 1, all_);
    alt_.seedBreaks = nullptr;
    if (!std::isfinite(seed.maxError)) return false;  // (no curve on those breaks: trial's GeometryError)
    cache.seed(count + 1);
    return true;
}

// Last, where the count below the one taken was refused and one of its trials held every sample
// but strayed between two: the descent once more (on the same points, the breaks equidistributed
// as in the last), each count's trials refused for straying made again with a firmer fairing
// term (takes). Not earlier: a count taken so changes the seeds of the removal trials below it,
// and the passes after it started from there (on the development strokes 41,107 control points
// against 41,076, but 36 strokes took more, by up to 12). Not on the pieces between corners
// (Reading::Descended): on dense jittery polygons (CornerDetection.GivenJitteryPolygons_*, 1,000
// and 2,000 samples) it made the fit 3.6x slower (21.9 s against 6.1 s for the test) and the
// sanitizer build's run of that test went past its 900 s; the development strokes take 41,469
// control points without it there, 41,394 with.
void ReadingFit::firmDescent()
{
    const int count = fit_.curve.pointCount() - countOffset_;
    if (strayedAny_.count(count - 1) == 0 || reading_ == Reading::Descended) return;
    firm_ = true;
    missedBy_.clear();  // (asked again, firmer)
    alt_.equidistributions = leavesFewPerPoint() ? kEquidistributions : 0;
    descend(0);
    alt_.equidistributions = 0;
    firm_ = false;
}

// Down one count at a time from the count taken while the count below is taken; where
// the count that stops it missed by little (kLookMissShare), up to `look` counts below
// it too, and on from one taken. (Looking below in this descent as well, before the
// equidistributed one: 56,150-56,154 control points with 1-3 counts, for the same time.)
void ReadingFit::descend(int look)
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
void ReadingFit::polish()
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

}  // namespace sculptline::solvers::stroke::detail
