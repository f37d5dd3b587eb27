#pragma once
// One least-squares fit of a conditioned stroke (fitStroke's trials, stroke_fitter.cpp): the chain of
// its points, rotated to start at a corner when it is a loop, cut into pieces at its corners, each
// piece a clamped cubic (lsq_fit.h), or one periodic cubic for a smooth loop. Not part of the stroke
// library's interface.
#include "solvers/bspline/bspline_curve.h"
#include "solvers/stroke/conditioning.h"
#include "solvers/stroke/lsq_fit.h"

#include <vector>

namespace sculptline::solvers::stroke::detail {

using Vec3 = Eigen::Vector3d;

// A chain of points (the conditioned stroke, rotated to start at a corner when closed) with its
// global chord parameter in [0, 1] and the pieces between consecutive break indices. An open stroke
// is its own chain: `points` and `source` then refer to the conditioned stroke's, not to a copy.
struct Chain {
    Chain() = default;
    Chain(const Chain&) = delete;  // `points` may point into this chain
    Chain& operator=(const Chain&) = delete;
    std::vector<Vec3> rotatedPoints;  // a loop's points from its start corner (empty when open)
    std::vector<int> rotatedSource;
    const std::vector<Vec3>* points = nullptr;
    const std::vector<int>* source = nullptr;  // raw index of each point
    std::vector<double> param;                 // global chord parameter, param[0] = 0, param.back() = 1
    std::vector<int> samples;                  // indices into points, increasing
    std::vector<int> breaks;                   // piece ends: 0, corners.., last
    // Each piece's own chord parameter on [0, 1] (empty for a piece that is the whole chain: its own
    // is `param`), and each conditioned point's index in the chain.
    std::vector<std::vector<double>> pieceChord;
    std::vector<int> position;
    std::vector<double> loopChord;  // a smooth loop's (fitted without a chain): arc length / length
    bool built = false;
};

// One least-squares fit of the conditioned stroke at `sopt.tolerance` (its samples and corners).
struct FitPass {
    Curve3d curve{1, {0.0, 0.0, 1.0, 1.0}, {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()}};
    std::vector<int> samples;  // raw indices
    double maxError = 0.0;     // the least squares' own measure over the conditioned points
    bool converged = false;
    AveragedCorrectionState correction;  // where a trial's corrections stopped (averagedStopWhenWithin)
};

// Appends one clamped cubic piece (knots on [d0, d1]) to a curve being joined from pieces: its
// knots mapped onto [g0, g0 + len] of the joined curve's parameter, the joint between two pieces a
// triple knot (C0), the shared corner point once. `first` / `last`: the piece's place.
void appendClampedPiece(const KnotVector& knots, const std::vector<Vec3>& points, double d0, double d1, double g0,
                        double len, bool first, bool last, KnotVector& outKnots, std::vector<Vec3>& outPoints);

// A clamped loop's knots and points (first point == last point) as a periodic curve: C0 at the seam
// (a triple knot), the period normalized to [0, 1].
Curve3d closeClampedLoop(const KnotVector& clamped, const std::vector<Vec3>& q);

// The data are `fitPoints` (one per conditioned point). The chord parameters of an open chain come
// from `paramPoints`: normally the smoothed cs.points, whose path length the digitizer's jitter does
// not inflate; the data themselves when the fit must interpolate them (parameters that disagree
// with the data's own spacing make an interpolant loop between samples).
// `chain`: the chain of earlier calls with the same stroke, points, corners and parameter points
// (the search's trials differ in their rows and options only), built by the first; its chord
// parameters were computed for every conditioned point on each call (a 1,000-sample stroke's trials
// each paid for 1,000 distances and two copies of 1,000 parameters).
FitPass fitConditioned(const ConditionedStroke& cs, const std::vector<Vec3>& fitPoints, const std::vector<int>& corners,
                       const std::vector<int>& samples, const SplineFitOptions& sopt,
                       const std::vector<Vec3>* paramPoints = nullptr, Chain* chain = nullptr);

}  // namespace sculptline::solvers::stroke::detail
