#pragma once
// Per-sample stroke features and corner detection (thesis §4.1.1, eq. 4-1; seed 003 §3.2).
#include "solvers/stroke/stroke.h"

namespace sculptline::solvers::stroke {

/// Eq. 4-1 as we read it (the formula is lost in the thesis text; the prose defines its terms):
///   d_n = phi(angle of P_{n+k} - P_{n-k})                      direction, phi wraps to (-pi, pi]
///   C_n = phi(angle(P_n - P_{n-k}, P_{n+k} - P_n)) / D(n-k, n+k)  curvature = turning / path length
/// with D(n-k, n+k) the path length between the neighbours. The thesis fixes k = 2 for tablet
/// samples a pixel or two apart; our samples are thinned to >= 0.2 % of the extent apart, and a
/// jitter of that order over only two samples would turn the direction by tens of degrees, so k
/// starts at 2 and grows until each side of the neighbourhood is `neighbourhood` long.
struct FeatureOptions {
    int k = 2;                     ///< minimum neighbourhood in samples (thesis: 2)
    double neighbourhood = 0.015;  ///< minimum one-sided neighbourhood length / stroke extent (strokeExtent)
    /// Angles are taken between the means of the samples within this chord distance (/ extent) of
    /// each point, not between single samples (computeFeatures says why); 0 = single samples.
    double denoise = 0.005;
    /// fitStroke measures its features with the neighbourhood and denoise widened for the noise it
    /// estimates (widenForNoise) until the turning's noise is at most this (radians; 0 = never
    /// widen), by at most maxWidening. 0.07 rad (4 degrees) lies above the 3.3 degrees of the clean
    /// benchmark flourish (noise 0.25 on 300 units, 1,000 samples), which therefore keeps its arms.
    double maxTurningNoise = 0.07;
    double maxWidening = 3.0;
};

struct StrokeFeatures {
    std::vector<double> direction;  ///< d_n, radians in (-pi, pi], in the xy-plane
    std::vector<double> turning;    ///< turning angle over the neighbourhood, radians in [0, pi]
    std::vector<double> wideTurning;///< the same over a neighbourhood twice as long (sharpness test)
    std::vector<double> curvature;  ///< C_n, 1 / model unit
    std::vector<double> speed;      ///< S_n = D(n-k, n+k) / elapsed time (model units per second or per sample)
    std::vector<int> lo, hi;        ///< neighbourhood ends n-k, n+k (indices; cyclic for closed strokes)
    double averageSpeed = 0.0;      ///< S_avg = length / duration (thesis §4.1.1)
};

/// What computeFeatures measures. `Windows`: only the neighbourhoods' ends lo and hi (the rest
/// stays empty): what fitStroke needs of the features on the unwidened arms of a stroke it measures
/// again on widened ones (widenForNoise's arm count, and the speed, which it measures on the
/// smoothed path anyway; only a stroke with corners needs their turning too, for localizeCorners).
/// One two-pointer pass (BM_StrokeFeatures/1, the jittery benchmark flourish: 73 us for two full
/// passes, 47 us for the windows and one full pass on the widened arms).
enum class FeatureSet { All, Windows };

StrokeFeatures computeFeatures(const ConditionedStroke& cs, const FeatureOptions& options = {},
                               FeatureSet set = FeatureSet::All);

/// f.speed and f.averageSpeed measured again on cs's path as it is now (cs.arc: after smoothing),
/// over f's windows (f.lo, f.hi); a window across a loop's seam gets the average speed, as in
/// computeFeatures.
void measureSpeed(const ConditionedStroke& cs, StrokeFeatures& f);

/// The turning angle's standard deviation (radians) that white noise of `noise` (per coordinate,
/// model units; estimateNoise) puts on computeFeatures' turning with these options:
///   sqrt(6) sigma_m / L,
/// the second difference (q_b - 2 q_i + q_a) across the two arms of length L = max(neighbourhood *
/// extent, k * mean spacing) of the means q, each of m = 1 + 2 denoise * extent / spacing samples
/// (sigma_m = noise / sqrt(m)). An estimate (mean spacing, straight arms), for choosing the arms.
double turningNoise(const ConditionedStroke& cs, double noise, const FeatureOptions& options);

/// The options with the neighbourhood and the denoising radius widened together, by the smallest
/// factor (up to options.maxWidening) that brings turningNoise down to options.maxTurningNoise; unchanged when it
/// is already there. Sensor jitter then turns the measured angle no more than the pen's own
/// drawing does on a clean stroke: the fixed arms of 1.5 % of the extent let a slow hand's jitter
/// (noise 0.5 on a 300-unit flourish: 9 degrees) lift a smooth bend past the 55-degree corner
/// threshold on 6 strokes in 8 (bench's jittery flourish). A corner keeps its turning on longer
/// arms (its sides are straight), a smooth bend's grows and its sharpness ratio stays that of an arc.
/// Only a dense stroke is widened (the median arm of `f`, the features on `options`, at least 3
/// samples): on a sparse one estimateNoise's fourth differences take the curve's own bending
/// (h^4 C^(4)) for noise, and the longer arms made a flourish's tight bend a corner at 200 samples.
/// widenForNoise's first test: the noise turns the angles on `options`' arms by more than
/// options.maxTurningNoise (and that is not 0), so the arms are widened where the stroke is dense.
bool noiseCallsForWiderArms(const ConditionedStroke& cs, double noise, const FeatureOptions& options);

FeatureOptions widenForNoise(const ConditionedStroke& cs, double noise, const StrokeFeatures& f, const FeatureOptions& options);

/// Corner detection combining the three cues of thesis §4.1.1 (curvature, direction change,
/// slowing down; cf. Sezgin et al. 2001 "Sketch based interfaces"):
/// a sample is a corner candidate when its turning angle is at least `strongAngle` and the turn is
/// sharp (concentrated: turning / wideTurning >= `sharpnessFast`; a smooth bend doubles its turning
/// when the window doubles, a corner does not), or when it turns at least `slowAngle` with
/// turning / wideTurning >= `sharpness` while the pen moved slower than `slowFraction` of the
/// average speed. Candidates are thinned to the local maxima
/// of turning within their neighbourhood. Ends of an open stroke are never corners.
struct CornerOptions {
    double strongAngle = 0.96;   ///< 55 degrees
    double slowAngle = 0.75;     ///< 43 degrees, accepted only where the hand slowed down (below
                                 ///< ~40 degrees the slow-down around a true vertex, with jitter,
                                 ///< produced false corners a few samples beside it)
    double slowFraction = 0.55;  ///< "slow" = speed below this fraction of S_avg
    /// Corners closer than this (path length / extent) are one corner: the one turning most stays.
    double mergeDistance = 0.05;
    double sharpness = 0.62;     ///< turning / wideTurning; 0.5 for a circular arc, 1 for a corner
    /// Without the slow-down cue the turn must be sharper still: a fast, tight bend of a flourish
    /// reaches 55 degrees with a ratio near 0.75, drawn vertices measured 0.84 and above.
    double sharpnessFast = 0.85;
};

/// atan2(y, x) within 1e-5 rad (checked against std::atan2 in stroke_numerics_test): the widely
/// used odd degree-11 minimax polynomial for atan on [0, 1] with octant reduction. Corner
/// thresholds are tenths of a radian, and libm's atan2 took a third of the feature pass.
double fastAtan2(double y, double x);

/// Corners found on widened features (widenForNoise) moved to where the narrow features `f` turn
/// most within the wide neighbourhood `wide.lo[c]..wide.hi[c]`: long arms see the whole turn from
/// every sample within an arm of the vertex, so their maximum is a noisy pick along that plateau,
/// and the curve's G0 joint belongs at the vertex. Increasing, without duplicates.
std::vector<int> localizeCorners(const ConditionedStroke& cs, const StrokeFeatures& f, const StrokeFeatures& wide,
                                 const std::vector<int>& corners);

/// Indices of the corner samples, increasing.
std::vector<int> detectCorners(const ConditionedStroke& cs, const StrokeFeatures& f, const CornerOptions& options = {});

}  // namespace sculptline::solvers::stroke
