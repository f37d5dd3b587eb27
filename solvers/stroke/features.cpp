#include "solvers/stroke/features.h"

#include <algorithm>
#include <Eigen/Geometry>
#include <cmath>

namespace sculptline::solvers::stroke {
namespace {

constexpr double kPi = 3.14159265358979323846;

double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    const double na = a.norm(), nb = b.norm();
    if (na == 0.0 || nb == 0.0) return 0.0;
    // atan2 of |a x b| and a.b is accurate for small and for nearly opposite angles alike.
    return std::atan2(a.cross(b).norm(), a.dot(b));
}

// Walks index j by `step` (+1/-1), cyclically on a closed stroke; returns -1 past an open end.
int stepIndex(int j, int step, int n, bool closed)
{
    j += step;
    if (closed) return (j + n) % n;
    return (j < 0 || j >= n) ? -1 : j;
}

double segment(const ConditionedStroke& cs, int a, int b)  // length of the chord a -> b, adjacent samples
{
    return (cs.points[b] - cs.points[a]).norm();
}

// Moves from i by `step` at least `minSteps` samples and until the chord from i is at least
// `minLength` (the chord, not the path: jitter lengthens the path without moving the pen on).
// Returns the index reached and the path length; stops at an open end (index clamped there).
std::pair<int, double> reach(const ConditionedStroke& cs, int i, int step, int minSteps, double minLength)
{
    const int n = cs.size();
    int j = i;
    double len = 0.0;
    for (int s = 0; s < n / 2; ++s) {
        if (s >= minSteps && (cs.points[j] - cs.points[i]).norm() >= minLength) break;
        const int next = stepIndex(j, step, n, cs.closed);
        if (next < 0) break;
        len += segment(cs, j, next);
        j = next;
    }
    return {j, len};
}

}  // namespace

StrokeFeatures computeFeatures(const ConditionedStroke& cs, const FeatureOptions& options)
{
    const int n = cs.size();
    StrokeFeatures f;
    f.direction.resize(n);
    f.turning.resize(n);
    f.wideTurning.resize(n);
    f.curvature.resize(n);
    f.speed.resize(n);
    f.lo.resize(n);
    f.hi.resize(n);
    const double minLen = options.neighbourhood * cs.extent;
    const double duration = cs.time.back() - cs.time.front();
    f.averageSpeed = duration > 0.0 ? cs.arc.back() / duration : 0.0;

    for (int i = 0; i < n; ++i) {
        const auto [a, la] = reach(cs, i, -1, options.k, minLen);
        const auto [b, lb] = reach(cs, i, +1, options.k, minLen);
        f.lo[i] = a;
        f.hi[i] = b;
        const Eigen::Vector3d chord = cs.points[b] - cs.points[a];
        f.direction[i] = std::atan2(chord.y(), chord.x());
        f.turning[i] = angleBetween(cs.points[i] - cs.points[a], cs.points[b] - cs.points[i]);
        const double path = la + lb;
        f.curvature[i] = path > 0.0 ? f.turning[i] / path : 0.0;
        const auto [wa, wla] = reach(cs, i, -1, 2 * options.k, 2.0 * std::max(la, minLen));
        const auto [wb, wlb] = reach(cs, i, +1, 2 * options.k, 2.0 * std::max(lb, minLen));
        (void)wla;
        (void)wlb;
        f.wideTurning[i] = angleBetween(cs.points[i] - cs.points[wa], cs.points[wb] - cs.points[i]);
        // Elapsed time over the neighbourhood; on a closed stroke the window may wrap over the seam,
        // where time restarts: the wrapped part then counts one sample interval per sample.
        double dt = cs.time[b] - cs.time[a];
        if (cs.closed && (a > i || b < i)) dt = 0.0;
        f.speed[i] = dt > 0.0 ? path / dt : f.averageSpeed;
    }
    (void)kPi;
    return f;
}

std::vector<int> detectCorners(const ConditionedStroke& cs, const StrokeFeatures& f, const CornerOptions& o)
{
    const int n = cs.size();
    std::vector<char> candidate(n, 0);
    for (int i = 0; i < n; ++i) {
        if (!cs.closed && (i == 0 || i == n - 1 || f.lo[i] == 0 || f.hi[i] == n - 1)) continue;
        const double t = f.turning[i];
        const bool slow = f.averageSpeed > 0.0 && f.speed[i] < o.slowFraction * f.averageSpeed;
        const double ratio = f.wideTurning[i] > 0.0 ? t / f.wideTurning[i] : 1.0;
        candidate[i] = (t >= o.strongAngle && ratio >= o.sharpnessFast) ||
                       (slow && t >= o.slowAngle && ratio >= o.sharpness);
    }
    // Non-maximum suppression: keep a candidate only if no sample in its neighbourhood turns more
    // (ties broken towards the lower index so that a plateau yields one corner).
    std::vector<int> corners;
    for (int i = 0; i < n; ++i) {
        if (!candidate[i]) continue;
        bool best = true;
        for (int j = f.lo[i]; best && j != f.hi[i]; j = cs.closed ? (j + 1) % n : j + 1) {
            if (j == i) continue;
            const bool before = cs.closed ? ((i - j + n) % n) < n / 2 : j < i;
            if (f.turning[j] > f.turning[i] || (f.turning[j] == f.turning[i] && before && candidate[j])) best = false;
        }
        if (f.turning[f.hi[i]] > f.turning[i]) best = false;
        if (best) corners.push_back(i);
    }
    // Merge corners closer than mergeDistance along the path (cyclically on a loop).
    const double merge = o.mergeDistance * cs.extent;
    const double total = cs.length();
    auto gap = [&](int a, int b) {
        const double d = cs.arc[b] - cs.arc[a];
        return cs.closed ? std::min(d, total - d) : d;
    };
    bool changed = true;
    while (changed && corners.size() > 1) {
        changed = false;
        const size_t pairs = cs.closed ? corners.size() : corners.size() - 1;
        for (size_t k = 0; k < pairs; ++k) {
            const size_t next = (k + 1) % corners.size();
            if (std::abs(gap(corners[k], corners[next])) >= merge) continue;
            const size_t drop = f.turning[corners[k]] >= f.turning[corners[next]] ? next : k;
            corners.erase(corners.begin() + static_cast<long>(drop));
            changed = true;
            break;
        }
    }
    return corners;
}

}  // namespace sculptline::solvers::stroke
