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
    /// point), exact for `worst`, for every sample whose bound reached maxError and for every one
    /// beyond measureSamples' exactAbove; 0 for a dropped one.
    std::vector<double> bound;
    /// With a finite exactAbove: the max distance over the kept samples within it (those beyond it
    /// left out), exact; else maxError.
    double maxWithin = 0.0;
};

/// Distances from the samples to a cubic curve (open or periodic). A polyline of the curve with
/// points at most `resolution` apart (in arc length, estimated per span) tracks the samples in
/// order, giving each an upper bound; samples whose bound could still be the maximum are then
/// projected exactly: every local minimum of the distance along the whole polyline that could beat
/// the best found is refined by safeguarded Newton steps on the curve's power form. So maxError is
/// the true max distance (to Newton's convergence), never a bound that may under- or over-report.
/// @param keep       per sample 1 = measured, 0 = dropped (empty: all kept)
/// @param resolution polyline spacing, model units (> 0); the tolerance / 2 keeps the candidates
///                   for exact projection to the few samples within ~tolerance / 30 of the maximum.
/// @param exactAbove every kept sample whose bound would exceed this is projected exactly too, so
///                   that `bound` > exactAbove holds exactly for the samples beyond it and no other
///                   (those at or below it are proven within it). Default: only the maximum's.
SampleDeviation measureSamples(const Curve3d& curve, const std::vector<Eigen::Vector3d>& samples,
                               const std::vector<char>& keep, double resolution,
                               double exactAbove = std::numeric_limits<double>::infinity());

}  // namespace sculptline::solvers::stroke
