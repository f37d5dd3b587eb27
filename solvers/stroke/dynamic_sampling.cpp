#include "solvers/stroke/dynamic_sampling.h"

#include <algorithm>
#include <cmath>

namespace sculptline::solvers::stroke {

double samplingThreshold(double speed, double averageSpeed, double unit, const SamplingOptions& o)
{
    if (!(averageSpeed > 0.0)) return unit;
    // r = S_i / S_avg; one digitizer tick covers r * unit of arc length.
    const double r = std::max(speed / averageSpeed, 1e-3);  // a stopped pen: at most 2000 ticks
    if (r < 1.0) return std::round(o.slowFactor / r + 0.5) * r * unit;  // eq. 4-2: round(2 S_avg/S_i + 0.5) ticks
    return o.fastFactor * unit;                                        // eq. 4-3: 7 S_avg/S_i ticks
}

std::vector<int> dynamicThresholdSamples(const ConditionedStroke& cs, const StrokeFeatures& f,
                                         const std::vector<int>& keep, int rawCount, const SamplingOptions& o)
{
    const int n = cs.size();
    std::vector<char> forced(n, 0);
    forced[0] = forced[n - 1] = 1;
    for (int k : keep) forced[k] = 1;
    const double unit = std::max(cs.length() / std::max(1, rawCount - 1), o.minUnit * cs.extent);

    std::vector<int> out;
    out.reserve(static_cast<size_t>(n));
    out.push_back(0);
    double since = 0.0;  // path length since the last sample taken
    for (int i = 1; i < n; ++i) {
        since += cs.arc[i] - cs.arc[i - 1];
        // The threshold matters only where no sample is forced.
        if (forced[i] || since >= samplingThreshold(f.speed[i], f.averageSpeed, unit, o)) {
            // A forced sample (a corner, the end) replaces a sample taken just before it if the two
            // would be closer than one unit: the corner matters more than the regular sample.
            if (forced[i] && !forced[out.back()] && since < unit && out.size() > 1) out.pop_back();
            out.push_back(i);
            since = 0.0;
        }
    }
    return out;
}

}  // namespace sculptline::solvers::stroke
