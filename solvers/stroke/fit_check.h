#pragma once
// The tolerance check of a fitted stroke: the distance of every raw sample the fit keeps to the
// fitted curve, by point-to-curve projection (The NURBS Book §6.1, eq. 6.3), exact for the worst.
#include "solvers/bspline/bspline_curve.h"

#include <Eigen/Core>
#include <limits>
#include <vector>

namespace sculptline::solvers::stroke {

struct SampleDeviation {
    double maxError = 0.0;  ///< max over the kept samples of the distance to the curve, model units
    int worst = -1;         ///< index of the sample attaining it (-1: no kept sample)
    /// Per sample an upper bound on its distance to the curve (the distance to an actual curve
    /// point, the local minimum's where the samples run along the curve), exact for `worst`, for every sample whose
    /// bound reached maxError and for every one beyond measureSamples' exactAbove; 0 for a dropped one.
    std::vector<double> bound;
    /// With a finite exactAbove: the max distance over the kept samples within it (those beyond it
    /// left out), exact; else maxError.
    double maxWithin = 0.0;
    /// Per kept sample the parameter its tracked bound was measured at (its foot point as the
    /// samples run along the curve; 0 for a dropped one): measureStray's order along the curve.
    std::vector<double> foot;
};

/// Distances from the samples to a cubic curve (open or periodic). The samples are tracked in
/// order: each is projected by Newton's iteration from the foot predicted by the previous ones,
/// which gives it an upper bound (a curve point's distance, within ~resolution / 50 of the local
/// minimum's). Samples whose bound could still be the maximum are then projected exactly: every
/// span whose hull box comes nearer than the bound is sampled by a polyline with points at most
/// `resolution` apart (in arc length, estimated per span), and every local minimum of its distances
/// that could beat the best found is refined by safeguarded Newton steps on the curve's power form.
/// So maxError is the true max distance (to Newton's convergence), never a bound that may under- or
/// over-report.
/// @param keep       per sample 1 = measured, 0 = dropped (empty: all kept)
/// @param resolution polyline spacing of the exact projection, model units (> 0); the tolerance / 2
///                   is the fitter's.
/// @param exactAbove every kept sample whose bound would exceed this is projected exactly too, so
///                   that `bound` > exactAbove holds exactly for the samples beyond it and no other
///                   (those at or below it are proven within it). Default: only the maximum's.
SampleDeviation measureSamples(const Curve3d& curve, const std::vector<Eigen::Vector3d>& samples,
                               const std::vector<char>& keep, double resolution,
                               double exactAbove = std::numeric_limits<double>::infinity());

/// How far a curve strays from the stroke between its samples (measureStray).
struct StrayMeasure {
    double excess =
        0.0;  ///< max over the curve's points of the least distance / allowance over the segments (<= 1: within)
    double distance = 0.0;   ///< the distance from the stroke's polyline there, model units
    double parameter = 0.0;  ///< the curve parameter there
    int after = -1;          ///< the kept sample whose foot comes last before it (-1: none)
};

/// The other direction of the tolerance check: from the curve to the stroke. measureSamples bounds
/// each kept sample's distance to the curve, which says nothing of the curve between two samples:
/// a curve can pass within the tolerance of every sample and shoot far out between two of them.
/// Every point of the curve must lie within the allowance of some segment of the polyline through
/// the kept samples (a loop's closed), tolerance + chordShare * the segment's length: a smooth
/// curve through two samples bulges from their chord by its sagitta, which is the shape between
/// them, not a stray. The curve's points are its spans' polylines' (at most ~`resolution` apart),
/// each tried first on the segments at the two samples whose foot points bracket it, then on the
/// whole polyline (a curve may cut across to another part of the stroke).
/// @param feet      SampleDeviation::foot of the same curve and samples (null: tracked here)
/// @param stopAbove the measure stops once the excess exceeds it (a check that asks only whether
///                  the curve strays); `distance` is then that point's.
StrayMeasure measureStray(const Curve3d& curve, const std::vector<Eigen::Vector3d>& samples,
                          const std::vector<char>& keep, double tolerance, double chordShare, double resolution,
                          const std::vector<double>* feet = nullptr,
                          double stopAbove = std::numeric_limits<double>::infinity());

}  // namespace sculptline::solvers::stroke
