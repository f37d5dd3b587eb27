#pragma once
// One reading of a conditioned stroke (fitStroke, stroke_fitter.cpp): the least squares with its
// knot search and minimax trials on the whole stroke, or piece by piece between its corners. Not
// part of the stroke library's interface.
#include "solvers/stroke/conditioned_fit.h"
#include "solvers/stroke/stroke_fitter.h"

#include <limits>
#include <vector>

namespace sculptline::solvers::stroke::detail {

// The constants fitStroke shares with a reading.
// Four rounds: each cuts the inner tolerance by the worst excess, so the error is cut by it too
// unless a sample is out of reach (noise beyond the tolerance), which more rounds would not fix.
constexpr int kMaxRefinements = 4;
// The polyline of measureSamples: points half a tolerance apart leave few samples for exact
// projection (those within ~tolerance / 30 of the maximum).
constexpr double kCheckSpacingShare = 0.5;
// How far a curve may bulge from the chord between two samples beyond the tolerance (measureStray):
// a sixth of the chord. A circular arc through two samples bulges from their chord by its sagitta,
// (c / 2) tan(t / 4) for a turn t between them: a sixth of the chord at t = 74 degrees, more than a
// hand turns between two samples of a smooth stroke (a corner is a sample of its own). Measured on
// the development strokes with the pieces searched (fitPiecesSearched): a quarter (t = 106
// degrees, the least-squares fit's own chord check, lsq_fit.cpp) let a sparse flourish's pieces
// bulge 3.48 from its dense fit, beyond FitTolerance.GivenSameStrokeAtThreeDensities' 3.33 (50,671
// control points); an eighth (56 degrees) refused minimax curves that were within it once taken
// (s04 medium 7 circle 40 -> 53; 51,049); a sixth 50,858, the circles 4,217 (4,155 before).
constexpr double kStrayChordShare = 1.0 / 6.0;

// What fitStroke has made of a stroke before the least squares: the raw stroke, the options, the
// conditioned stroke with the points the least squares fits, the dynamic threshold's rows, the
// raw samples kept (not dropped) and the conditioned points as drawn.
struct Prepared {
    const Stroke& stroke;
    const FitOptions& options;
    const ConditionedStroke& cs;
    const std::vector<Eigen::Vector3d>& fitPoints;
    const std::vector<int>& samples;
    const std::vector<char>& keep;
    /// The conditioned points before smoothing (one per conditioned point: the drawn samples, merged
    /// near-duplicates as their centroid), which the minimax trials fit (ReadingFit::minimaxTrials).
    const std::vector<Eigen::Vector3d>& drawn;
};

// How a reading looks for fewer control points than the error-driven fit's (where it looks:
// strokes without corners, loops with one, each piece of fitPiecesSearched).
enum class Reading {
    // The averaged-knot search on the dynamic threshold's rows, then the minimax trials below the
    // count it takes (the error-driven fit only where the search finds nothing).
    Searched,
    // The error-driven fit, then the minimax trials bisecting every count below its own and the
    // equidistributed descent (as where the count leaves few points per control point, kNoiseRowsPerPoint). For the
    // pieces between corners: the search cost more than it found there. On the development strokes
    // (unistroke-report --fit-dev, valgrind --tool=callgrind, the whole program, fitStroke 96 % of
    // it): the pieces searched 50,835 control points for 34.8 G instructions (105,391 search
    // trials, 29,706 minimax trials); descended 50,354 for 30.2 G (8,333 search trials, all of
    // whole strokes). Descended without the equidistributed descent: 50,672 for 28.6 G; with the
    // bisection only where the count follows the noise: 50,823; the search below the error-driven
    // count first, then the bisection: 50,220 for 37.7 G.
    Descended,
};

// Whether every kept raw sample the curve leaves beyond `tolerance` is the noise's outlier
// (FitResult::outliers): no farther than kOutlierSigmas * sigma from the curve, alone (the nearest
// kept sample on either side within the tolerance: a curve that misses a run of samples misses
// shape, and an end sample, which has one side, is not judged), and no more of them than
// kMaxOutlierShare of the kept samples. `dev` must be measured with exactAbove = tolerance, so that
// a bound beyond the tolerance is the sample's distance and one within it proves it. On true,
// `outliers` lists them (empty when nothing is beyond the tolerance); on false it is empty.
bool noiseOutliers(const SampleDeviation& dev, const std::vector<char>& keep, double tolerance, double sigma,
                   std::vector<int>& outliers);

// One reading of the stroke: the fit with these corners, into `fit`, `outliers` (the noise's
// outliers of the fit taken, noiseOutliers) and res's maxError, converged and refinements (res's
// tolerance is read). `reading`: how fewer control points are looked for where they are.
// `ceiling`: no count above it is searched for or tried by the minimax trials (a loop's other
// reading, which fitStroke takes only at no more control points than the first).
void fitReading(const Prepared& p, const std::vector<int>& corners, Reading reading, FitResult& res, FitPass& fit,
                std::vector<int>& outliers, int ceiling = std::numeric_limits<int>::max());

// The minimax trials piece by piece (fitReading without corners, Reading::Descended, on each piece
// of a stroke with corners, the corners kept: each piece a clamped cubic from corner to corner), the
// pieces joined with triple knots (C0 at the corners, as fitPieces joins the error-driven fit's).
// Each piece is a stroke of its own: the raw samples between its corners (a loop's last piece runs
// round its seam), its conditioned points, rows and keep flags. Returns false where a piece cannot
// be fitted within the tolerance (or its ends do not meet the next piece's); else the joined curve
// into `joined` (raw sample indices) and the pieces' noise outliers into `outliers`.
bool fitPiecesSearched(const Prepared& p, const std::vector<int>& corners, double tolerance, FitPass& joined,
                       std::vector<int>& outliers);

}  // namespace sculptline::solvers::stroke::detail
