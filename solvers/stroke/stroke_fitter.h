#pragma once
// From raw pen samples to a fair cubic B-spline (thesis ch. 4 §4.1; seed 003 §3): conditioning,
// features and corners, dynamic-threshold sampling, and error-driven least-squares approximation.
#include "solvers/bspline/bspline_curve.h"
#include "solvers/stroke/conditioning.h"
#include "solvers/stroke/dynamic_sampling.h"
#include "solvers/stroke/features.h"
#include "solvers/stroke/fit_check.h"
#include "solvers/stroke/lsq_fit.h"

namespace sculptline::solvers::stroke {

/// Default fitting tolerance as a fraction of the stroke's extent (strokeExtent): 0.5 % is about
/// one pixel on a 200-pixel sketch, below what a designer perceives as a change of shape.
constexpr double kDefaultRelativeTolerance = 0.005;
/// The default tolerance is never below this many input resolutions (FitOptions::resolution). A
/// sample quantized to a grid of pitch q (whole pixels) is only known to within +-q/2 per axis, so
/// up to q/sqrt(2) (~0.71 q) from where the pen was; a tolerance below that asks the curve to
/// follow the quantization's staircase, not the drawing. One pitch (one pixel, the intent of
/// kDefaultRelativeTolerance) leaves the smooth curve through the true positions inside it with a
/// margin the least squares needs (it does not find the minimax curve).
constexpr double kResolutionTolerance = 1.0;

/// A raw sample the curve leaves beyond the tolerance may be the noise's outlier only when it lies
/// within this many noise sigmas (estimateNoise, per coordinate) of the curve. A sample's offset
/// across the pen's path is N(0, sigma): beyond 4 sigma with probability 6e-5 (one sample in
/// 16,000), so a sample farther off is taken for shape and held. Where 4 sigma is within the
/// tolerance nothing is an outlier (the development subjects' real strokes: none). Measured on the
/// 16 jittery flourishes of BM_StrokeFitSeeds/1 (noise 0.5, tolerance 1.51; callgrind instructions
/// in fitStroke, control points' mean, outliers of all 16): off 439 M, 29.5, 0; 3 sigma 254 M,
/// 26.1, 25; 3.5 sigma 149 M, 23.4, 48; 4 sigma 129 M, 23.2, 65; 5 sigma 123 M, 23.1, 74 (the clean
/// flourishes: 71 M, 20.5). Beyond 4 the gain is small and the outliers keep growing.
constexpr double kOutlierSigmas = 4.0;
/// At most this share of a stroke's kept samples may be outliers. Gaussian noise puts 0.27 % of
/// the samples beyond 3 sigma; a curve that misses more is missing shape, or the tolerance is
/// below the noise, and is refitted instead.
constexpr double kMaxOutlierShare = 0.01;

struct FitOptions {
    double tolerance = 0.0;  ///< max deviation in model units; <= 0 means relativeTolerance * extent
    double relativeTolerance = kDefaultRelativeTolerance;
    /// The input's resolution, model units: the pitch its samples are quantized to (the window's
    /// pointer: one pixel's footprint on the sketch plane, manipulators::pixelFootprint). With
    /// tolerance <= 0 the tolerance used is max(relativeTolerance * extent, kResolutionTolerance *
    /// resolution). 0 = unknown (the relative tolerance alone). Ignored when tolerance > 0.
    double resolution = 0.0;
    /// false: every conditioned sample enters the least squares ("speed-only" sampling of thesis
    /// Fig. 4-3 a, whose density follows the hand's slowness); true: eqs. 4-2/4-3.
    bool dynamicSampling = true;
    /// After the error-driven fit of an open stroke without corners, look for fewer control points
    /// with averaged knots and corrected parameters (stroke_fitter.cpp); kept only when every kept
    /// raw sample stays within the tolerance. Smooth loops search with periodic averaged knots;
    /// strokes with corners keep the error-driven fit.
    bool fewerControlPoints = true;
    /// The search counts up from the least count a curve can have (below the error-driven count)
    /// instead of predicting the count from the error (stroke_fitter.cpp): the fewest control
    /// points the averaged knots allow, for up to 3x the time on long strokes
    /// (`"minimize_control_points": true`; BM_StrokeFitFewest).
    bool countUp = false;
    /// A loop with at most one corner is fitted both periodic and as one clamped piece (from its
    /// corner, or from its seam), and the reading with fewer control points is taken
    /// (stroke_fitter.cpp). false: the detected corners alone decide (before session 42).
    bool bothLoopReadings = true;
    /// An open stroke with a corner a few points from an end (a hook where the pen landed or
    /// lifted) is fitted without that corner too, and that reading taken where it needs fewer
    /// control points; the corner is still reported (stroke_fitter.cpp, kEndHookPoints). false:
    /// the detected corners alone decide (before session 52).
    bool endHookReading = true;
    /// After the search, counts below the one taken are tried with minimax trials (Lawson's
    /// reweighted least squares, SplineFitOptions::minimaxRounds): the tolerance bounds the
    /// largest distance, which least squares does not minimize, and on strokes whose noise is near
    /// the tolerance a minimax curve needs fewer control points (stroke_fitter.cpp). A count is
    /// taken only when every kept raw sample is within the tolerance. false: least squares alone
    /// (before session 43).
    bool minimaxTrials = true;
    /// A curve is taken only when it also stays near the stroke between the samples (measureStray,
    /// fit_check.h): within the tolerance plus a sixth of the chord between two samples. false:
    /// the samples' distances alone (before session 47), and FitResult::stray only reports.
    bool boundStray = true;
    /// A stroke with corners (other than a loop with one) gets the search and minimax trials piece
    /// by piece between its corners, the corners kept (stroke_fitter.cpp, fitPiecesSearched), where
    /// every piece fits; else the error-driven fit of its pieces. false: the error-driven fit alone
    /// (before session 47).
    bool piecesSearched = true;
    ConditioningOptions conditioning;
    FeatureOptions features;
    CornerOptions corners;
    SamplingOptions sampling;
    SplineFitOptions spline;
};

struct FitResult {
    /// Cubic; closed (periodic) for a closed stroke. (Initialized to a placeholder segment: curves
    /// have no empty state.)
    Curve3d curve{1, {0.0, 0.0, 1.0, 1.0}, {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()}};
    std::vector<int> corners;            ///< raw-sample indices of the corners (G0 joints of the curve)
    std::vector<int> samples;            ///< raw-sample indices used by the least squares
    /// Raw-sample indices left out of the fit and of maxError (ConditionedStroke::dropped: hooks,
    /// a loop's overshoot; and `outliers`), increasing.
    std::vector<int> dropped;
    /// The raw samples among `dropped` that the digitizer's noise put beyond the tolerance: each
    /// alone between neighbours within it, and no farther from the curve than the measured noise
    /// explains (kOutlierSigmas), at most kMaxOutlierShare of the samples. Increasing.
    std::vector<int> outliers;
    double maxError = 0.0;               ///< max distance of a raw sample not dropped to the curve
                                         ///< (projected: measureSamples), model units
    /// How far the curve strays from the stroke between the kept samples (measureStray): excess
    /// <= 1 when it stays within the tolerance plus a sixth of the chord between two samples.
    StrayMeasure stray;
    int refinements = 0;                 ///< refits needed to bring every kept sample within tolerance
    double tolerance = 0.0;              ///< the tolerance used, model units
    bool converged = false;              ///< maxError <= tolerance (every kept raw sample within it)
    std::vector<std::string> warnings;   ///< repairs made to the input
    ConditionedStroke conditioned;       ///< the smoothed input (for tests and recognition)
};

/// Fits one stroke. The curve is C2 except at the detected corners, where three coincident knots
/// make it G0 (the corner sample is interpolated); the stroke's ends are interpolated; a stroke that
/// closes on itself gives a closed curve (periodic C2, or C0 at its corners).
/// @throws GeometryError for an empty stroke, a single or all-identical points, NaN or infinite
///         input, or mismatched times/pressure arrays (the message names the field).
FitResult fitStroke(const Stroke& stroke, const FitOptions& options = {});

}  // namespace sculptline::solvers::stroke
