#pragma once
// Error-driven least-squares cubic B-spline approximation (thesis §4.1.2, eqs. 4-4..4-22; de Boor,
// A Practical Guide to Splines, ch. XIV; The NURBS Book §9.4.1 for the end-point constrained form).
#include "solvers/bspline/basis.h"

#include <Eigen/Core>
#include <memory>
#include <vector>

namespace sculptline::solvers::stroke {

/// Where knots go: inserted where the error is (default), or averaged over the sample parameters
/// with the fewest control points that reach the tolerance (The NURBS Book §9.4.1; the thesis's
/// de Boor approximation, where the sampling alone decides the knot density: thesis Fig. 4-3).
enum class KnotPlacement { ErrorDriven, Averaged };

enum class KnotRemoval { None, LastRound, AllKnots };

struct SplineFitOptions {
    KnotPlacement knotPlacement = KnotPlacement::ErrorDriven;
    double tolerance = 0.0;  ///< maximum allowed deviation, model units (> 0)
    /// Weight of the control-polygon second-difference term sum |P_{i-1} - 2 P_i + P_{i+1}|^2,
    /// relative to the average number of samples per control point. It only has to make the normal
    /// matrix definite when a knot span holds no sample (Schoenberg-Whitney condition violated);
    /// 1e-6 keeps its pull on the fit far below any tolerance while leaving the pivots well above
    /// round-off (condition number <= ~1e8 in double precision).
    double fairing = 1e-6;
    int maxIterations = 64;
    /// Each round splits only the spans whose error exceeds the tolerance by at least this share
    /// of the round's worst excess over it, E_worst - tol (0: every span above the tolerance:
    /// fewer rounds, more control points). A span deviating by E is cut into about (E/tol)^(1/4)
    /// pieces (2 to 4), the least-squares error of a cubic falling as the fourth power of the span.
    /// Measured against splitting every span deviating by more than share * E_worst in two: the
    /// 1,000-sample flourish fitted in one piece 30 -> 24 control points, the others equal or fewer
    /// (scripts/compare_splprep.py).
    double insertionShare = 0.5;
    /// After convergence, which knots to try removing again (each kept out when the refit stays
    /// within tolerance at every point and chord). LastRound undoes the overshoot of the final
    /// insertion round at little cost. AllKnots ranks every interior break of an open curve by its
    /// knot-removal distance (The NURBS Book A5.8: how far the control points must move to drop
    /// it), tries them cheapest first, re-ranking after each removal; a trial re-solves only the
    /// least-squares sums of the six spans around the break and re-measures only the points whose
    /// bound (last distance plus the curve's change on their span) exceeds the tolerance. The
    /// default since session 40: on the 2,400 development strokes of the $1 logs 38,645 control
    /// points against 40,651 with LastRound (-4.9 %; the pieces of strokes with corners, which
    /// the averaged-knot search does not reach, gain most), for 10.9 % more instructions on the 240
    /// strokes people drew (BM_StrokeRecorded/0, callgrind: 346.4 against 312.4 M). A closed
    /// curve tries each break in turn, each trial solved and measured in full.
    KnotRemoval removal = KnotRemoval::AllKnots;
    /// Parameter correction (Hoschek 1988, "Intrinsic parametrization for approximation"): one
    /// Newton step per sample and iteration moves its parameter toward the foot point on the curve.
    /// Measured on synthesized strokes it does not pay here: with the error-driven knot insertion
    /// it lets samples bunch up in parameter, leaving spans the data no longer hold (loops between
    /// samples) and twice the control points (spiral: 49 vs 23). Off by default.
    bool correctParameters = false;
    /// Once the samples fit but the check of every point fails (an open piece), the samples'
    /// parameters are moved once to their foot points (one Hoschek correction, on a curve that
    /// already has the shape, so the bunching above cannot happen) and the same knots are solved
    /// again, with the points the check found worst among the rows, before a knot is added. On the
    /// benchmark strokes: arc 5 -> 4 and flourish-200 22 -> 20 control points, the others
    /// unchanged (scripts/compare_splprep.py).
    bool polishParameters = true;
    /// Measure a sample's deviation at its Newton-improved foot point (closer to the true distance)
    /// rather than at its chord parameter; the parameter itself is kept.
    bool measureAtFootPoint = true;
    /// KnotPlacement::Averaged only: Hoschek parameter corrections per trial count (each one
    /// Newton step per sample toward its foot point, then the same knots solved again).
    int averagedCorrections = 0;
    /// KnotPlacement::Averaged only: this many control points (> 0; no search), else the fewest
    /// within tolerance found by bisection.
    int averagedControlPoints = 0;
    /// KnotPlacement::Averaged with averagedControlPoints: rounds of Lawson's algorithm after the
    /// corrections when the samples still miss the tolerance (by at most kMinimaxReach): the least
    /// squares reweighted toward the smallest maximum distance (each sample's weight times its
    /// distance, normalized), one Hoschek correction per round; the round whose curve has the
    /// smallest maximum distance is kept, the first within the tolerance ends them. The tolerance
    /// bounds the largest distance, which least squares does not minimize: on strokes whose noise is
    /// near the tolerance a minimax curve needs fewer control points. 0: least squares only.
    int minimaxRounds = 0;
    /// KnotPlacement::Averaged with averagedControlPoints: when the trial misses (its rounds end
    /// above minimaxWithin), this many more trials with the breaks moved to equidistribute the
    /// fourth root of each span's largest distance (averaged_fit.cpp); the best trial is kept.
    int equidistributions = 0;
    /// KnotPlacement::Averaged with averagedControlPoints (neither stopping once within nor
    /// resuming): when the trial on averaged knots misses, one more on the knots of FITPACK's
    /// insertion (averaged_fit.cpp); the better is kept.
    bool insertedTrials = false;
    /// KnotPlacement::Averaged with averagedControlPoints and a trialCache: instead of the trial on
    /// averaged knots, up to this many trials on the breaks of the seed of one control point more
    /// (AveragedTrialCache::seed), less one break each, until one comes within (averaged_fit.cpp);
    /// the best is returned. Throws GeometryError where there is no such seed.
    int removalTrials = 0;
    /// KnotPlacement::Averaged with averagedControlPoints: the trial on these breaks instead of
    /// averaged ones (distinct; open: 0 = b_0 < .. < b_s = 1 with s + 3 = the count; closed: 0 = b_0
    /// < .. < b_{N-1} < 1 with N = the count; else GeometryError): the breaks of a curve of that
    /// count fitted on other rows.
    const std::vector<double>* seedBreaks = nullptr;
    /// The minimax rounds end once every sample is within this (0: the tolerance).
    double minimaxWithin = 0.0;
    /// KnotPlacement::Averaged with averagedControlPoints: stop the corrections as soon as every
    /// sample lies within the tolerance at its parameter (the count is then known to fit, which is
    /// all a search's trial asks), leaving the corrections' state in SplineFitResult::correction.
    bool averagedStopWhenWithin = false;
    /// KnotPlacement::Averaged with averagedControlPoints: go on from the state a stopped fit of the
    /// same input and count left (SplineFitResult::correction): the result is the uninterrupted
    /// fit's, to the bit.
    const struct AveragedCorrectionState* averagedResume = nullptr;
    /// KnotPlacement::Averaged with averagedControlPoints: what the trials on one input keep for
    /// the trials after them (AveragedTrialCache; null: each trial starts afresh).
    class AveragedTrialCache* trialCache = nullptr;
};

/// What the fixed-count averaged-knot trials on one input (the same rows, parameters and points)
/// keep for the trials after them: the knots FITPACK's insertion placed, in the order inserted, and
/// each count's best trial before its equidistributions, which a trial of the same count and
/// options takes instead of solving it again (averaged_fit.cpp; the result is the same to the bit).
/// A trial on another input starts it afresh. The caller's, passed to every trial that may share it.
class AveragedTrialCache {
public:
    AveragedTrialCache();
    ~AveragedTrialCache();
    AveragedTrialCache(const AveragedTrialCache&) = delete;
    AveragedTrialCache& operator=(const AveragedTrialCache&) = delete;

    /// The last trial of `count` control points on this input becomes the seed the removal trials
    /// of count - 1 start from (SplineFitOptions::removalTrials). Seeds carry over to another input
    /// on the same rows (the drawn points' seeds start the smoothed points' trials).
    void seed(int count);
    /// Whether `count` has a seed.
    bool seeded(int count) const;

    struct State;
    std::unique_ptr<State> state;
};

/// Where a fit with averagedStopWhenWithin stopped: the parameters after `done` corrections (the
/// next least-squares solve not yet made) and the samples' largest distance last measured.
struct AveragedCorrectionState {
    std::vector<double> parameters;
    int done = 0;
    double error = 0.0;
    bool stopped = false;  ///< false: the fit ran every correction, nothing to resume
};

/// Data for one piece: ordered points with chord-length parameters normalized to [0, 1]
/// (closed: chord[0] = 0 and chord.back() < 1, the rest of [0, 1) being the seam gap).
struct SplineFitInput {
    const std::vector<Eigen::Vector3d>* points = nullptr;  ///< every conditioned point (the check set)
    /// One parameter per point, increasing (the caller's storage: a search's trials share one).
    const std::vector<double>* chord = nullptr;
    std::vector<int> samples;                               ///< indices used by the least squares, increasing,
                                                            ///< containing 0 (and the last point when open)
    bool closed = false;
};

struct SplineFitResult {
    KnotVector knots;                      ///< open: clamped on [0, 1]; closed: periodic, domain [0, 1]
    std::vector<Eigen::Vector3d> points;   ///< open: n+1 points; closed: unwrapped (last 3 repeat first 3)
    std::vector<int> samples;              ///< the samples finally used (the input set plus any added)
    double maxError = 0.0;                 ///< max distance from a point to its (corrected) curve point
    bool converged = false;                ///< maxError <= tolerance
    int iterations = 0;
    AveragedCorrectionState correction;  ///< averagedStopWhenWithin: where the corrections stopped
};

/// Open curves interpolate the first and last points and approximate the others; closed curves are
/// periodic C2 cubics. Starting from one span (open) or five (closed), the loop solves the least
/// squares, corrects parameters, and inserts a knot into every span whose samples deviate by more
/// than the tolerance, at the error-weighted median of those samples (so knots go where the shape
/// needs them). When all samples are within tolerance the whole check set is verified and the
/// worst offending points are added as samples. Normal equations are band (open, half-bandwidth 3,
/// banded Cholesky) or cyclic band (closed, sparse LDL^T): O(samples + control points) per solve.
SplineFitResult fitCubicSpline(const SplineFitInput& input, const SplineFitOptions& options);

}  // namespace sculptline::solvers::stroke
