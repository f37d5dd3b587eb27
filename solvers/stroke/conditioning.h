#pragma once
// Input conditioning (thesis §4.1; seed 003 §3.1 "input data filtering"): validation, removal of
// duplicate and near-coincident samples, timestamp repair, loop closure, and a mean filter that
// removes digitizer noise without moving corners.
#include "solvers/stroke/stroke.h"

#include <utility>

namespace sculptline::solvers::stroke {

/// Validates and de-duplicates a raw stroke, detects whether it closes on itself (trimming an
/// overshoot past the start), and fills the cumulative chord lengths. No smoothing yet: corners
/// must be found on the unsmoothed points first (see smoothPreservingCorners).
/// @throws GeometryError naming the field ("stroke.points", "stroke.times[4]", ...) for an empty
///         stroke, non-finite numbers, mismatched array sizes, or fewer than two distinct points.
/// @note Timestamps that decrease are not an error: they are ignored (speed is then estimated
///       from sample spacing) and a warning is recorded.
ConditionedStroke conditionStroke(const Stroke& stroke, const ConditioningOptions& options = {});

/// `passes` rounds of the 3-point mean filter p_i <- (p_{i-1} + p_i + p_{i+1}) / 3 over the
/// conditioned points (cyclically for a closed stroke). The points listed in `fixed` (corners)
/// and the ends of an open stroke keep their positions, so the filter rounds no corner off.
/// Recomputes the cumulative chord lengths.
void smoothPreservingCorners(ConditionedStroke& cs, const std::vector<int>& fixed, int passes);

/// The noise level of the points, model units: the standard deviation sigma of white noise that
/// would explain the fourth differences p_{i-2} - 4 p_{i-1} + 6 p_i - 4 p_{i+1} + p_{i+2} (their
/// per-coordinate variance is 70 sigma^2; a smooth curve sampled at spacing h contributes only
/// h^4 |C^(4)|, so curvature is not mistaken for noise, unlike second differences). The median of
/// their lengths is used (robust to corners and a few outliers): for a 2D Gaussian vector of
/// per-coordinate deviation s it is s sqrt(2 ln 2). 0 for fewer than five points.
double estimateNoise(const std::vector<Eigen::Vector3d>& points, int dimension = 2);

/// The smoothed points moved back onto the ball of radius `budget` (model units) around the drawn
/// ones: smoothing bounded so that it removes at most `budget` of shape or noise. *shift (if given)
/// receives the largest distance of a result from its drawn point. budget <= 0: the drawn points.
/// `drawn` is taken by value and becomes the result: move it in when it is not needed after.
std::vector<Eigen::Vector3d> limitSmoothing(std::vector<Eigen::Vector3d> drawn,
                                            const std::vector<Eigen::Vector3d>& smoothed, double budget,
                                            double* shift = nullptr);

/// The raw samples [first, last] left when a pen's light-pressure hooks at the stroke's ends are
/// left out (ConditioningOptions::hookPressure, maxHookLength): the range conditionStroke keeps.
/// The whole stroke without pressure, or with fewer than five samples. For strokes that are used
/// as drawn rather than fitted (over-sketch, lift, re-sketch in the window).
/// @throws GeometryError naming the field for mismatched or non-finite times or pressure.
std::pair<int, int> withoutPressureHooks(const Stroke& stroke, const ConditioningOptions& options = {});

/// Recomputes cs.arc from cs.points.
void updateArcLength(ConditionedStroke& cs);

namespace detail {
/// conditionStroke for fitStroke with an absolute tolerance > 0 (0: plain conditionStroke): the same
/// as conditionStroke with options.minSpacing lowered to min(minSpacing, 0.4 * tolerance / extent),
/// without computing the extent a second time.
ConditionedStroke conditionStrokeWithTolerance(const Stroke& stroke, const ConditioningOptions& options, double tolerance);
}  // namespace detail

/// The size every relative tolerance refers to: twice the largest distance from the centroid (0 for
/// fewer than two points). Unlike a bounding-box diagonal it does not change when the stroke is
/// rotated; for a segment it is its length, for a square its diagonal.
double strokeExtent(const std::vector<Eigen::Vector3d>& points);

}  // namespace sculptline::solvers::stroke
