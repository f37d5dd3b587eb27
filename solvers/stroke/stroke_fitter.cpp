#include "solvers/stroke/stroke_fitter.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/stroke/conditioned_fit.h"
#include "solvers/stroke/fit_check.h"
#include "solvers/stroke/fit_reading.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace sculptline::solvers::stroke {
namespace {

using Vec3 = Eigen::Vector3d;
using detail::Chain;
using detail::fitConditioned;
using detail::FitPass;
using detail::fitPiecesSearched;
using detail::fitReading;
using detail::kCheckSpacingShare;
using detail::kMaxRefinements;
using detail::kStrayChordShare;
using detail::noiseOutliers;
using detail::Prepared;
using detail::Reading;

// A loop's two corners closer across the seam than 1 / kSeamPairShare of its conditioned points
// are where the hand closed it (see fitStroke's other reading).
constexpr int kSeamPairShare = 8;
// A corner with at most this many conditioned points between it and an open stroke's end is an end
// hook (FitOptions::endHookReading). On the 2,400 development strokes (unistroke-report --fit-dev)
// the reading without it took 24 control points fewer on 8 strokes at 5 (pigtails, question marks,
// two open circles, a check's lift: 45,964 -> 45,940), 19 on 6 at 3, the same 24 at 8. Counted as a
// share of the points instead, a quarter reached the corners of square brackets and arrows' heads
// (38 fewer, shapes a designer drew with corners) and a half those of carets, v's and checks.
constexpr int kEndHookPoints = 5;

}  // namespace

FitResult fitStroke(const Stroke& stroke, const FitOptions& options)
{
    FitResult res;
    const ConditioningOptions& copt = options.conditioning;
    // An absolute tolerance caps the merge distance at 0.4 * tolerance (minSpacing relative to the
    // stroke's extent, which conditioning computes anyway).
    ConditionedStroke cs = detail::conditionStrokeWithTolerance(stroke, copt, options.tolerance > 0.0 ? options.tolerance : 0.0);
    if (!(options.resolution >= 0.0) || !std::isfinite(options.resolution))
        throw GeometryError("resolution: must be zero or positive and finite");
    // The default tolerance respects the input's resolution (FitOptions::resolution,
    // kResolutionTolerance): below it the tolerance would hold the quantization's staircase.
    res.tolerance = options.tolerance > 0.0
                        ? options.tolerance
                        : std::max(options.relativeTolerance * cs.extent, kResolutionTolerance * options.resolution);
    if (!(res.tolerance > 0.0) || !std::isfinite(res.tolerance)) throw GeometryError("tolerance: must be positive and finite");

    std::vector<int> corners, samples;
    std::vector<Vec3> fitPoints, drawn;
    {
        // The features are freed before the least squares, which can then reuse their memory.
        // The features' arms are widened for the noise that is there (widenForNoise), so that jitter
        // turns the measured angles no more than on a clean stroke.
        // Where the noise calls for wider arms (widenForNoise's first test), the features on the
        // unwidened ones serve the arm count and the speed (their windows, FeatureSet::Windows),
        // and only where corners are found, localizeCorners (all of them).
        cs.noise = estimateNoise(cs.points, stroke.dimension);
        const bool noisy = noiseCallsForWiderArms(cs, cs.noise, options.features);
        StrokeFeatures f = computeFeatures(cs, options.features, noisy ? FeatureSet::Windows : FeatureSet::All);
        const FeatureOptions wide = widenForNoise(cs, cs.noise, f, options.features);
        if (wide.neighbourhood == options.features.neighbourhood) {
            if (noisy) f = computeFeatures(cs, options.features);  // a sparse stroke, not widened
            corners = detectCorners(cs, f, options.corners);
        } else {
            const StrokeFeatures wf = computeFeatures(cs, wide);
            corners = detectCorners(cs, wf, options.corners);
            if (!corners.empty()) {
                f = computeFeatures(cs, options.features);
                corners = localizeCorners(cs, f, wf, corners);
            }
        }
        // Smoothing by the noise that is there, within a share of the tolerance (ConditioningOptions::
        // smoothingShare, noiseMultiple): it removes jitter but never the shape the tolerance keeps.
        // The smoothed points serve the parameterization, the dynamic threshold and recognition
        // (cs.points, as before); the least squares gets them pulled back to within the budget of
        // the drawn points, and the minimax trials the drawn points themselves (Prepared::drawn).
        const double budget = std::min(copt.smoothingShare * res.tolerance, copt.noiseMultiple * cs.noise);
        drawn = cs.points;
        smoothPreservingCorners(cs, corners, copt.smoothingPasses);
        fitPoints = limitSmoothing(drawn, cs.points, budget, &cs.smoothingShift);
        if (options.dynamicSampling) {
            // The threshold reads the hand's speed on the smoothed path: measured on the drawn
            // points, jitter lengthens every window's path (a slow hand's most), and the jittery
            // flourishes took 196-208 rows against the clean ones' 161-176 (158-165 against
            // 152-157 now).
            measureSpeed(cs, f);
            samples = dynamicThresholdSamples(cs, f, corners, static_cast<int>(stroke.points.size()), options.sampling);
        } else {
            samples.reserve(static_cast<size_t>(cs.size()));
            for (int i = 0; i < cs.size(); ++i) samples.push_back(i);
        }
    }
    // The tolerance bounds the distance from the curve to every raw sample that is not dropped. The
    // least squares works on the smoothed points, which lie within smoothingShift of theirs: it gets
    // the rest of the tolerance. Merged near-duplicates (cluster centroids) and the rest are then
    // measured on the curve itself (measureSamples); where a sample still lies beyond the tolerance
    // the fit is repeated with the least squares' tolerance cut by the excess, which inserts knots
    // where those samples are, at most kMaxRefinements times.
    std::vector<char> keep(stroke.points.size(), 1);
    for (int i : cs.dropped) keep[static_cast<size_t>(i)] = 0;
    FitPass fit;
    std::vector<int> outliers;  // the noise's outliers (noiseOutliers) of the fit taken
    const Prepared prepared{stroke, options, cs, fitPoints, samples, keep, drawn};
    // A stroke with corners (other than a loop with one, which the search reads whole) gets the
    // minimax trials piece by piece, the corners kept (fitPiecesSearched), where every
    // piece fits: every kept raw sample within the tolerance (no more outliers than the pieces'),
    // and the curve near the stroke between samples. Else, and for every other stroke, one reading
    // with its corners (the error-driven fit of each piece where it has corners).
    bool byPieces = false;
    if (options.piecesSearched && options.fewerControlPoints && !corners.empty() &&
        !(cs.closed && corners.size() == 1)) {
        std::vector<int> pieceOutliers;
        if (fitPiecesSearched(prepared, corners, res.tolerance, fit, pieceOutliers)) {
            std::vector<char> kept = keep;
            for (int i : pieceOutliers) kept[static_cast<size_t>(i)] = 0;
            const SampleDeviation dev =
                measureSamples(fit.curve, stroke.points, kept, kCheckSpacingShare * res.tolerance);
            byPieces =
                dev.maxError <= res.tolerance &&
                (!options.boundStray || measureStray(fit.curve, stroke.points, kept, res.tolerance, kStrayChordShare,
                                                     kCheckSpacingShare * res.tolerance, &dev.foot, 1.0)
                                                .excess <= 1.0);
            if (byPieces) {
                outliers = std::move(pieceOutliers);
                res.maxError = dev.maxError;
                res.converged = true;
                res.refinements = 0;
            }
        }
    }
    if (!byPieces) fitReading(prepared, corners, Reading::Searched, res, fit, outliers);
    // A loop has two readings when it has at most one corner: periodic (C2 all round) and one
    // clamped piece from a point round to it (C0 there). Which needs fewer control points depends
    // on how the hand closed it, more than on whether a corner was detected: on the 2,400
    // development strokes (unistroke-report --fit-dev, both readings searched) the seam's clamped
    // piece took fewer on 30 of 58 smooth loops and the periodic curve on 19 of 37 loops with one
    // corner (224 control points fewer over the 95, 7.3 %), at all angles of the seam's turn: no
    // cheap test told them apart. So the other reading is fitted too and taken when it holds the
    // tolerance with fewer control points and no more outliers. (Loops with two corners keep
    // them: fitted periodic too, triangles and rectangles lose corners a designer expects, for 22
    // and 7 fewer control points over their 150 each in session 44; session 42 found the same.)
    // The other reading runs the search with its minimax trials, as the first does, no higher
    // than the first reading's count (fitReading's ceiling: it is taken at no more). Session 44,
    // on the development strokes (with the equidistributed breaks chained, averaged_fit.cpp):
    // circles 4,691 -> 4,610 control points (s02 fast 5 18 -> 12, s02 medium 10 16 -> 12, s03
    // medium 10 40 -> 35), the circles' fit time 193 -> 264 ms (unistroke-report --fit-dev).
    // (Before the minimax trials it was the error-driven fit alone: nearly all the gains were
    // that fit's then, the development loops 21,554 control points with it alone, 21,544 with the
    // search before it.) The detected corners (FitResult::corners, which recognition reads) stay
    // as found.
    // A loop with one corner away from its seam has a third reading: one clamped piece from the seam
    // (the first point kept) round to it, as a smooth loop's other reading. Where the hand closed a
    // loop its start and end often zigzag across each other (circle-s02f4 of the $1 logs: x 99,
    // 103, 101, 99 over the seam's four samples), and a corner detected a sample or two away leaves
    // that zigzag inside the clamped piece, for the curve to follow smoothly: 14 control points at
    // 1 px where the piece from the seam needs 8. On the 2,400 development strokes (unistroke-report
    // --fit-dev) 31 loops with one corner try it and 17 circles gain (s06 medium 9 48 -> 41, s03 slow
    // 1 53 -> 47, whose corner lies a third of the loop from the seam), 50,354 -> 50,306 control
    // points; the circles' fit time 564 -> 640 ms, the whole set's 2,211 -> 2,297 ms.
    // Two corners that meet across the seam, within 1 / kSeamPairShare of the loop's points, are where
    // the hand closed it (the pen's start and its lift, overlapping), not two corners of the
    // shape: such a loop's other reading is one clamped piece from the later corner round to it.
    // On the development strokes two circles have such a pair: s02 slow 1 31 -> 17 control points
    // (the fewer peer 24), s06 fast 8 25 -> 24; no triangle, rectangle or other gesture changes,
    // from an eighth to a quarter of the points. (From the earlier corner: 6 more control points
    // over the circles.)
    const bool seamPair = corners.size() == 2 && (corners[0] + cs.size() - corners[1]) * kSeamPairShare < cs.size();
    std::vector<std::vector<int>> others;
    if (cs.closed && (corners.size() <= 1 || seamPair) && options.bothLoopReadings) {
        others.push_back(seamPair          ? std::vector<int>{corners[1]}
                         : corners.empty() ? std::vector<int>{0}
                                           : std::vector<int>{});
        if (corners.size() == 1 && corners[0] != 0) others.push_back({0});
    }
    // An open stroke with a corner at most kEndHookPoints from an end (where the pen landed or
    // lifted with a hook) has another reading too: that corner left out, the hook fitted smoothly.
    // The corner is still reported (FitResult::corners); the curve is taken only where it holds the
    // tolerance with fewer control points, as a loop's other reading.
    if (!cs.closed && !corners.empty() && options.endHookReading) {
        std::vector<int> inner;
        for (int k : corners)
            if (k > kEndHookPoints && cs.size() - 1 - k > kEndHookPoints) inner.push_back(k);
        if (inner.size() < corners.size()) others.push_back(std::move(inner));
    }
    if (!others.empty() && options.fewerControlPoints && res.converged) {
        // Each other reading in turn, no higher than the best so far (counted as fitReading counts:
        // a loop's curves by its periodic reading's distinct points, a closed curve repeating 3).
        const int repeated = cs.closed ? 3 : 0;
        for (const std::vector<int>& other : others) {
            const int distinct = fit.curve.pointCount() - repeated;
            FitPass first = std::move(fit);
            std::vector<int> firstOutliers = std::move(outliers);
            const double firstError = res.maxError;
            const int firstRefinements = res.refinements;
            fit = FitPass{};
            outliers.clear();
            bool made = true;
            try {
                fitReading(prepared, other, Reading::Searched, res, fit, outliers, distinct);
            } catch (const GeometryError&) {  // (too few distinct points for the other reading's curve)
                made = false;
            }
            // (As many control points and closer to the drawn samples also takes it: a minimax curve,
            // below, can end at the other reading's count with a larger deviation.)
            const int otherDistinct = made ? fit.curve.pointCount() - repeated : 0;
            if (!made || !res.converged || otherDistinct > distinct ||
                (otherDistinct == distinct && !(res.maxError < firstError)) || outliers.size() > firstOutliers.size()) {
                fit = std::move(first);
                outliers = std::move(firstOutliers);
                res.maxError = firstError;
                res.converged = true;
                res.refinements = firstRefinements;
            }
        }
    }
    // Dropped samples the curve passes within the tolerance of (most of a loop's overshoot runs
    // along the loop's start) are not dropped after all. One measure, exact for every candidate
    // beyond the tolerance (measureSamples' exactAbove), settles which stay dropped; a second gives
    // the exact maximum of those kept, which joins max_error. (It was one measure per sample that
    // stayed dropped, each building the curve's polyline again: a loop's overshoot of 20 samples
    // cost 21 measures.)
    if (!cs.dropped.empty()) {
        std::vector<char> candidates(stroke.points.size(), 0);
        for (int i : cs.dropped) candidates[static_cast<size_t>(i)] = 1;
        const SampleDeviation dev = measureSamples(fit.curve, stroke.points, candidates, kCheckSpacingShare * res.tolerance, res.tolerance);
        bool kept = false;
        for (int i : cs.dropped) {
            if (dev.bound[static_cast<size_t>(i)] > res.tolerance) {
                res.dropped.push_back(i);
                candidates[static_cast<size_t>(i)] = 0;
            } else {
                kept = true;
            }
        }
        if (kept) {
            const double worst = res.dropped.empty() ? dev.maxError
                                                     : measureSamples(fit.curve, stroke.points, candidates, kCheckSpacingShare * res.tolerance).maxError;
            res.maxError = std::max(res.maxError, worst);
        }
    }
    res.dropped.insert(res.dropped.end(), outliers.begin(), outliers.end());
    std::sort(res.dropped.begin(), res.dropped.end());
    res.outliers = std::move(outliers);
    {
        // (Against the polyline the fit was accepted on: the conditioned stroke's samples less the
        // noise's outliers. A loop's overshoot the curve passes near, no longer dropped above, runs
        // back over the loop's start: in the polyline it would join the stroke's end to its start
        // across the overshoot.)
        std::vector<char> kept = keep;
        for (int i : res.outliers) kept[static_cast<size_t>(i)] = 0;
        res.stray = measureStray(fit.curve, stroke.points, kept, res.tolerance, kStrayChordShare,
                                 kCheckSpacingShare * res.tolerance);
    }
    res.curve = std::move(fit.curve);
    res.samples = std::move(fit.samples);
    res.corners.reserve(corners.size());
    for (int k : corners) res.corners.push_back(cs.source[k]);
    std::sort(res.corners.begin(), res.corners.end());
    res.warnings = cs.warnings;
    if (!res.converged) {
        res.warnings.push_back("fit: maximum deviation of a kept sample " + std::to_string(res.maxError) + " exceeds tolerance " +
                               std::to_string(res.tolerance));
    }
    if (res.stray.excess > 1.0) {
        res.warnings.push_back("fit: the curve strays " + std::to_string(res.stray.distance) +
                               " from the stroke after sample " + std::to_string(res.stray.after) +
                               ", beyond the tolerance and a sixth of the chord there");
    }
    res.conditioned = std::move(cs);
    return res;
}

}  // namespace sculptline::solvers::stroke
