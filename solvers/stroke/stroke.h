#pragma once
// A pen stroke as it arrives from a digitizer, and the conditioned form the fitting and
// recognition stages work on (thesis ch. 4 §4.1; seed 003 §3.1).
#include <Eigen/Core>
#include <string>
#include <vector>

namespace sculptline::solvers::stroke {

/// Raw samples between one pen-down and pen-up. The JSON form is
/// {"points": [[x,y] or [x,y,z], ..], "times": [seconds, ..], "pressure": [0..1, ..]}
/// (../shared/interfaces.md); 2D strokes are stored with z = 0 and `dimension` = 2.
struct Stroke {
    std::vector<Eigen::Vector3d> points;  ///< model units of the drawing plane
    std::vector<double> times;            ///< seconds, optional (empty or one per point)
    std::vector<double> pressure;         ///< 0..1, optional (empty or one per point)
    int dimension = 2;                    ///< 2 or 3
};

/// How the stroke's ends are treated.
enum class Closure { Auto, Open, Closed };

/// Parameters of input conditioning. Distances are fractions of the stroke's bounding-box
/// extent (strokeExtent: twice the largest distance from the centroid) so that the result does not depend on the drawing's scale.
struct ConditioningOptions {
    /// Consecutive samples closer than this (relative to the extent) are merged: they carry no
    /// shape at the default fitting tolerance (0.5 %), only digitizer jitter (seed 003 §3.1).
    double minSpacing = 0.002;
    /// A stroke whose ends come within this fraction of its length closes on itself. Hand-drawn
    /// loops typically miss or overshoot by a few per cent of their perimeter.
    double closeGap = 0.06;
    /// ... and enclose at least this area relative to L^2, L the shorter of the path length and
    /// pi x extent, which jitter does not inflate (a circle: 0.08, a 10:1 rectangle: 0.02).
    double minLoopArea = 0.01;
    Closure closure = Closure::Auto;
    /// Passes of the 3-point mean filter (seed 003 §3.1 "3x3 mean filter"); corners are held fixed.
    /// The smoothed points give the parameterization, the dynamic threshold and recognition; the
    /// least squares fits them pulled back toward the drawn points (smoothingShare, noiseMultiple),
    /// so smoothing never eats shape that the tolerance must keep.
    int smoothingPasses = 2;
    /// The filter moves no sample farther than this share of the fitting tolerance from where it
    /// was drawn. The fit then has the rest of the tolerance for the smoothed points (the smoothing
    /// shift is subtracted), so a quarter leaves three quarters: the control-point count of a cubic
    /// fit grows as tolerance^(-1/4), about 7 % more points for the guarantee on raw samples.
    double smoothingShare = 0.25;
    /// ...and no farther than this multiple of the estimated noise (estimateNoise): smoothing is
    /// for the noise that is there; a clean stroke is left almost as drawn. 3 sigma covers the
    /// excursions of Gaussian noise over a few hundred samples.
    double noiseMultiple = 3.0;
    /// Upper bound on the conditioned sample count; denser input is thinned first so that a
    /// million-sample stroke is handled in bounded time.
    int maxSamples = 20000;
    /// Pen-down and pen-up hooks (the digitizer artifacts of seed 003 §3.1): while the pressure builds
    /// up or falls off the tip skids, and the first or last few samples curl away from the stroke.
    /// End samples drawn with less than this fraction of the stroke's median pressure are trimmed...
    double hookPressure = 0.5;
    /// ...when the light run is at most this share of the stroke's path length (a hook is a few
    /// pixels; a longer light run was drawn on purpose and is kept). Strokes without pressure are
    /// not trimmed.
    double maxHookLength = 0.08;
};

/// The stroke after validation, de-duplication, closure detection and corner-preserving smoothing.
struct ConditionedStroke {
    std::vector<Eigen::Vector3d> points;  ///< smoothed positions
    std::vector<int> source;              ///< index of each point in the raw stroke
    std::vector<double> time;             ///< seconds, or the raw sample index when no usable times
    std::vector<double> arc;              ///< cumulative chord length, arc[0] = 0
    bool closed = false;                  ///< points form a loop; the seam gap is points.back() -> points[0]
    bool timed = false;                   ///< `time` holds real timestamps
    double extent = 0.0;                  ///< strokeExtent of the raw stroke (the scale of relative sizes)
    std::vector<std::string> warnings;    ///< repairs applied (ignored timestamps, trimmed overshoot)
    /// Raw-sample indices left out of the curve: light-pressure hooks and a loop's overshoot past its
    /// start (increasing). Merged near-duplicates are not dropped: the fit is measured against them.
    std::vector<int> dropped;
    double noise = 0.0;          ///< estimated noise sigma of the samples, model units (estimateNoise)
    /// Largest distance from a drawn point to the point the least squares fits (the smoothed point
    /// pulled back within ConditioningOptions::smoothingShare of the tolerance), model units.
    double smoothingShift = 0.0;

    int size() const { return static_cast<int>(points.size()); }
    /// Total length, including the closing gap of a closed stroke.
    double length() const;
};

}  // namespace sculptline::solvers::stroke
