#pragma once
// The class behind fitReading (fit_reading.h): one reading of a conditioned stroke. Its error-driven
// fit and averaged-knot search are in fit_reading.cpp, its minimax trials in fit_minimax.cpp. Not
// part of the stroke library's interface.
#include "solvers/stroke/fit_check.h"
#include "solvers/stroke/fit_reading.h"
#include "solvers/stroke/fit_reading_tuning.h"

#include <map>
#include <set>
#include <vector>

namespace sculptline::solvers::stroke::detail {

// One reading of the stroke (fitReading): its steps share the stroke, the fit taken so far (the
// caller's res, fit and outliers) and the least squares' options and chain.
class ReadingFit {
    using Vec3 = Eigen::Vector3d;

public:
    ReadingFit(const Prepared& p, const std::vector<int>& corners, Reading reading, FitResult& res, FitPass& fit,
               std::vector<int>& outliers, int ceiling)
        : stroke_(p.stroke), options_(p.options), cs_(p.cs), fitPoints_(p.fitPoints), drawn_(p.drawn),
          samples_(p.samples), keep_(p.keep), corners_(corners), reading_(reading), res_(res), fit_(fit),
          outliers_(outliers), ceiling_(ceiling)
    {
        sopt_.tolerance = std::max(kMinInnerShare * res_.tolerance, res_.tolerance - cs_.smoothingShift);
    }

    // The reading: the search or the error-driven fit, the minimax trials, the fallback.
    void run();

private:
    // A curve's measure: `error`, its samples' largest distance (the noise's outliers left out),
    // or, where it holds every sample but strays between two (`strayed`), the straying's excess
    // in tolerances; `samples` is then the samples' largest distance alone.
    struct Measured {
        double error = 0.0;
        bool strayed = false;
        double samples = 0.0;
    };

    // The error-driven fit and the averaged-knot search (fit_reading.cpp; each documented there).
    Measured deviation(const Curve3d& curve, SampleDeviation& dev);
    StrayMeasure strayOf(const Curve3d& curve, const SampleDeviation& dev, double stopAbove);
    void refine(int rounds);
    void search();
    FitPass solveTrial(int count, const std::vector<int>& rows);
    // The chain of the points the trials fit (a chain keeps the points it was built on).
    Chain& trialChain() { return trialPoints_ == &drawn_ ? drawnChain_ : chain_; }
    FitPass trial(int count, const std::vector<int>& rows);
    bool fits(const FitPass& a) const { return a.maxError <= res_.tolerance; }
    bool addsNoRows(int per, int count) const;
    bool repeats(int count) const { return rowsPer_ > 0 && addsNoRows(rowsPer_, count); }
    FitPass trialAt(int count);
    void finish(FitPass& a, int count, const std::vector<int>& rows);
    // accept's verdict: taken, or refused, for straying between samples (every sample within
    // the tolerance) or for missing a sample.
    enum class Verdict { Taken, Missed, Strayed };
    Verdict accept(FitPass& a, SampleDeviation& dev);
    bool takeOnRows(FitPass& a, int count);
    bool take(FitPass& a, int count);
    void countUp();
    void searchPasses();
    int capOf(int per) const;
    void searchPass();
    void climb(FitPass& a, int& count, int& failed, int cap);
    void bisectDown(FitPass& a, int& count, int& failed);
    void fallback();

    // The minimax trials below the count taken (fit_minimax.cpp; each documented there).
    void minimaxTrials();
    void trialsOn(const std::vector<Vec3>& points, double within);
    bool leavesFewPerPoint(int perPoint = kNoiseRowsPerPoint) const;
    void minimaxPass(int least, bool full);
    // (No count above the ceiling is tried: the caller takes none.)
    int below(int count) const { return count > ceiling_ ? ceiling_ + 1 : count; }
    bool takes(int count);
    Verdict judge(int count, bool byRemoval, double& error, int firmer = 0);
    bool seedAbove(int count, bool searched);
    void descend(int look);
    void firmDescent();
    void polish();

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
    std::set<int> strayedAny_;    // the counts refused where a trial strayed (firmDescent)
    bool firm_ = false;           // (firmDescent: the trials refused for straying made again, firmer)
    std::set<int> searchSeeded_;  // the counts seeded from the search's curve (seedAbove)
    int removedAt_ = 0;  // the count taken by a removal trial (0: none)
    // The minimax trials' (on every conditioned point).
    std::vector<int> all_;
    // Each count that missed, and its largest distance then (its samples' or raw samples').
    std::map<int, double> missedBy_;
    // The counts refused only for straying between samples (every sample within the
    // tolerance): a curve of its own, not a sign that the count is too small.
    std::set<int> strayedAt_;
};

}  // namespace sculptline::solvers::stroke::detail
