#pragma once
// Dynamic-threshold sampling (thesis §4.1.1, eqs. 4-2 and 4-3; seed 003 §3.2).
#include "solvers/stroke/features.h"

namespace sculptline::solvers::stroke {

/// Our reading of the garbled eqs. 4-2 and 4-3. The text defines: m is "the adaptive length
/// threshold for sampling ... to avoid picking too close points", m_i "the distance from the
/// (i-1)-th to the i-th [sampled] point", S_avg the average speed (arc length / duration), S_i the
/// speed at point i; eq. 4-3 serves the fast, non-corner parts and eq. 4-2 the slow corner regions.
/// The surviving glyphs are "m = round(2 x S/S + 0.5)" and "m_i = 7 x S/S", subscripts i and avg.
/// Spacing must grow with speed for the stated purpose (sparse where fast, dense where slow), so:
///   slow, S_i < S_avg:   m   = round(2 S_i / S_avg + 0.5) * u     (4-2)  in {1, 2, 3} * u
///   fast, S_i >= S_avg:  m_i = 7 S_i / S_avg * u                  (4-3)  >= 7 u
/// where u is the thesis's unit of length: there the tablet pixel, the distance a pen at average
/// speed travels per digitizer tick; here u = S_avg * (duration / (raw samples - 1)), i.e. the
/// stroke length over the raw sample count, which is the same quantity in model units. Rounding
/// up from 0.5 makes m >= u: no two samples closer than one average tick. In slow regions, where the
/// raw samples crowd together (their spacing is proportional to S_i), this thins them to 1-3 ticks;
/// in fast regions they are spaced ~7 raw samples apart. "Speed-only" sampling (thesis Fig. 4-2/4-3 a)
/// keeps every raw sample: its density follows 1/S_i and crowds the corners.
struct SamplingOptions {
    double slowFactor = 2.0;  ///< the 2 of eq. 4-2
    double fastFactor = 7.0;  ///< the 7 of eq. 4-3
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

/// The threshold of eqs. 4-2/4-3 at one point, in model units (exposed for tests).
double samplingThreshold(double speed, double averageSpeed, double unit, const SamplingOptions& options = {});

}  // namespace sculptline::solvers::stroke
