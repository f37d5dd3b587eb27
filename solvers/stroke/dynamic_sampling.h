#pragma once
// Dynamic-threshold sampling (thesis §4.1.1, eqs. 4-2 and 4-3; seed 003 §3.2).
#include "solvers/stroke/features.h"

namespace sculptline::solvers::stroke {

/// Our reading of the garbled eqs. 4-2 and 4-3. The text defines: m is "the adaptive length
/// threshold for sampling ... to avoid picking too close points", m_i "the distance from the
/// (i-1)-th to the i-th [sampled] point", S_avg the average speed (arc length / duration), S_i the
/// speed at point i; eq. 4-3 serves the fast, non-corner parts and eq. 4-2 the slow corner regions.
/// The surviving glyphs are "m = round(2 x S/S + 0.5)" and "m_i = 7 x S/S", subscripts i and avg,
/// and the stated aim is to "balance the distribution of all the sampling points" that speed-only
/// sampling crowds into the slow corners. We read both as steps counted in digitizer samples with
/// the speed ratio S_avg / S_i, which divides the speed out of the raw spacing (S_i per tick):
///   slow, S_i < S_avg:   m   = round(2 S_avg / S_i + 0.5) ticks  ->  (2..3) u of arc length  (4-2)
///   fast, S_i >= S_avg:  m_i = 7 S_avg / S_i ticks               ->  7 u of arc length       (4-3)
/// where u = S_avg * tick is the arc length an average-speed pen covers per digitizer tick (the
/// thesis's pixel; here the stroke length over the raw sample count). The result is dense (2-3 u)
/// in slow regions, sparse (7 u) in fast ones, and within each regime independent of how the hand's
/// speed varied: a slow bend no longer contributes dozens of near-identical least-squares rows.
/// The other reading (S_i / S_avg, spacing in u) was implemented first: it makes fast parts sparser
/// still and the imbalance worse; on the Fig. 4-3 stroke it needed more control points than this
/// one (bench BM_StrokeFig43). "Speed-only" sampling (thesis Fig. 4-2/4-3 a) keeps every
/// conditioned sample: its density follows 1/S_i and crowds the corners.
struct SamplingOptions {
    double slowFactor = 2.0;  ///< the 2 of eq. 4-2 (ticks at average speed)
    double fastFactor = 7.0;  ///< the 7 of eq. 4-3 (ticks at average speed)
    /// Lower bound on u as a fraction of the stroke extent (strokeExtent): very dense input must not yield
    /// samples closer than the noise the conditioning already removed.
    double minUnit = 0.002;
};

/// Indices (into the conditioned stroke) of the dynamic-threshold samples, increasing. Always
/// includes the first and last points and every index in `keep` (the corners). `rawCount` is
/// the number of samples the digitizer delivered (before de-duplication).
std::vector<int> dynamicThresholdSamples(const ConditionedStroke& cs, const StrokeFeatures& f,
                                         const std::vector<int>& keep, int rawCount,
                                         const SamplingOptions& options = {});

/// The threshold of eqs. 4-2/4-3 at one point as arc length in model units: the tick count m times
/// the raw spacing (speed / averageSpeed) * unit (exposed for tests).
double samplingThreshold(double speed, double averageSpeed, double unit, const SamplingOptions& options = {});

}  // namespace sculptline::solvers::stroke
