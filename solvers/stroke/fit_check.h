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

}  // namespace sculptline::solvers::stroke
