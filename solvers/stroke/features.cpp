#include "solvers/stroke/features.h"

#include <algorithm>
#include <Eigen/Geometry>
#include <cmath>

namespace sculptline::solvers::stroke {
namespace {

// The body of fastAtan2, inlined into the feature pass (three calls per sample: as an out-of-line
// call it took two fifths of computeFeatures).
inline double atan2Poly(double y, double x)
{
    const double ax = std::abs(x), ay = std::abs(y);
    const double mx = std::max(ax, ay), mn = std::min(ax, ay);
    if (mx == 0.0) return 0.0;
    const double a = mn / mx, s = a * a;
    double r = ((((-0.0117212 * s + 0.05265332) * s - 0.11643287) * s + 0.19354346) * s - 0.33262347) * s +
               0.99997726;
    r *= a;
    if (ay > ax) r = 1.57079632679489662 - r;
    if (x < 0.0) r = 3.14159265358979324 - r;
    return y < 0.0 ? -r : r;
}

}  // namespace

double fastAtan2(double y, double x) { return atan2Poly(y, x); }

namespace {

double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    // atan2 of |a x b| and a.b is accurate for small and for nearly opposite angles alike.
    return atan2Poly(a.cross(b).norm(), a.dot(b));
}

// Neighbourhood ends for every sample, with unwrapped indices (a closed stroke's may run below 0
// or past n - 1): lo[i] is the largest index <= i - minSteps whose chord to i is at least
// minLength, hi[i] the smallest >= i + minSteps likewise (the chord, not the path: jitter lengthens
// the path without moving the pen on). Both ends only move forward as i does, so two pointers find
// them all in O(n) (chord length is taken as monotone along the window, true up to jitter).
// An open stroke's ends clamp to 0 and n - 1; a closed stroke's window spans at most half the loop.
void windows(const ConditionedStroke& cs, int minSteps, double minLength, std::vector<int>& lo, std::vector<int>& hi)
{
    const int n = cs.size();
    const auto at = [&](int j) -> const Eigen::Vector3d& { return cs.points[j < 0 ? j + n : (j >= n ? j - n : j)]; };
    const int reachMax = cs.closed ? n / 2 : n;
    const double min2 = minLength * minLength;
    lo.assign(n, 0);
    hi.assign(n, 0);
    int a = cs.closed ? -reachMax : 0;
    int b = 0;
    for (int i = 0; i < n; ++i) {
        const int aMin = cs.closed ? i - reachMax : 0;
        const int aMax = cs.closed ? i - minSteps : std::max(0, i - minSteps);
        a = std::clamp(a, aMin, aMax);
        while (a + 1 <= aMax && (at(a + 1) - at(i)).squaredNorm() >= min2) ++a;
        lo[i] = a;
        const int bMax = cs.closed ? i + reachMax : n - 1;
        b = std::clamp(std::max(b, i + minSteps), i, bMax);
        while (b < bMax && (at(b) - at(i)).squaredNorm() < min2) ++b;
        hi[i] = b;
    }
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
    const double minLen = options.neighbourhood * cs.extent;
    const double duration = cs.time.back() - cs.time.front();
    f.averageSpeed = duration > 0.0 ? cs.arc.back() / duration : 0.0;
    std::vector<int> wideLo, wideHi;
    windows(cs, options.k, minLen, f.lo, f.hi);
    windows(cs, 2 * options.k, 2.0 * minLen, wideLo, wideHi);
    const double total = cs.length();
    // Unwrapped path position of index j (a closed stroke's seam gap counts as path). Window ends lie
    // within half a loop of their centre, so j is in (-n, 2n): one comparison instead of an integer
    // division (which took a fifth of this pass).
    const auto wrap = [&](int j) { return j < 0 ? j + n : (j >= n ? j - n : j); };
    const auto arcAt = [&](int j) { return cs.arc[wrap(j)] + (j < 0 ? -total : (j >= n ? total : 0.0)); };
    // The angles are measured between local means, not single samples: q_i is the mean of the
    // samples within chord distance `denoise` of sample i (at least sample i itself). Why: with
    // single samples the angle's noise is that of one sample (sigma / neighbourhood) however dense
    // the stroke, while every further sample on a bend is one more independent draw, so the chance
    // that one of them crosses the corner thresholds grew with the sampling rate (false corners on
    // the flourish's tightest bend: 1 in 60 strokes at 200 samples, 1 in 6 at 5,000). Averaging
    // over a fixed length of the curve makes each angle a property of that length: denser sampling
    // puts more samples into the same means (less noise) instead of adding independent trials, and
    // a stroke too sparse for the radius keeps its single samples, as before. The radius is a
    // fraction of the neighbourhood, both relative to the extent, so the test is also scale-free.
    // Cost: one two-pointer pass with a running sum, O(n) (each sample enters and leaves once).
    std::vector<Eigen::Vector3d> q(static_cast<size_t>(n));
    {
        const Eigen::Vector3d* p = cs.points.data();
        const auto at = [&](int j) -> const Eigen::Vector3d& { return p[wrap(j)]; };
        const double r2 = options.denoise * cs.extent * options.denoise * cs.extent;
        // The samples [s, e] around i (unwrapped on a loop) are those within the radius, taken as a
        // contiguous run (chord grows along the run, true up to jitter); both ends only move forward.
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        if (!cs.closed) {
            int s = 0, e = -1;
            for (int i = 0; i < n; ++i) {
                while (e < i) sum += p[++e];
                while (e + 1 < n && (p[e + 1] - p[i]).squaredNorm() < r2) sum += p[++e];
                while (s < i && (p[s] - p[i]).squaredNorm() >= r2) sum -= p[s++];
                q[i] = sum * (1.0 / double(e - s + 1));
            }
        } else {
            const int reach = n / 2;
            int s = -reach, e = s - 1;
            for (int i = 0; i < n; ++i) {
                while (e < i) sum += at(++e);
                while (e < i + reach && (at(e + 1) - p[i]).squaredNorm() < r2) sum += at(++e);
                while (s < i - reach) sum -= at(s++);
                while (s < i && (at(s) - p[i]).squaredNorm() >= r2) sum -= at(s++);
                q[i] = sum * (1.0 / double(e - s + 1));
            }
        }
    }
    for (int i = 0; i < n; ++i) {
        const int a = f.lo[i], b = f.hi[i];
        const Eigen::Vector3d& pa = q[wrap(a)];
        const Eigen::Vector3d& pb = q[wrap(b)];
        const Eigen::Vector3d chord = pb - pa;
        f.direction[i] = atan2Poly(chord.y(), chord.x());
        f.turning[i] = angleBetween(q[i] - pa, pb - q[i]);
        const double path = arcAt(b) - arcAt(a);
        f.curvature[i] = path > 0.0 ? f.turning[i] / path : 0.0;
        f.wideTurning[i] = angleBetween(q[i] - q[wrap(wideLo[i])], q[wrap(wideHi[i])] - q[i]);
        // Elapsed time over the neighbourhood; a window across a loop's seam, where time restarts,
        // gets the average speed.
        const double dt = (a >= 0 && b < n) ? cs.time[b] - cs.time[a] : 0.0;
        f.speed[i] = dt > 0.0 ? path / dt : f.averageSpeed;
        f.lo[i] = wrap(a);
        f.hi[i] = wrap(b);
    }
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
