#include "solvers/stroke/features.h"

#include "solvers/math_constants.h"

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
    if (x < 0.0) r = kPi - r;
    return y < 0.0 ? -r : r;
}

}  // namespace

double fastAtan2(double y, double x) { return atan2Poly(y, x); }

namespace {

// The angle between u - o and v - w, in scalars: the same operations in the same order as Eigen's
// (a - b).cross(c - d).norm() and .dot() evaluate them (sums left to right: (x + y) + z), so the
// results are bit-identical, without the packet shuffles and, above all, without the out-of-line
// call GCC chose for the Eigen form.
// atan2 of |a x b| and a.b is accurate for small and for nearly opposite angles alike.
[[gnu::always_inline]] inline double angleBetween(const Eigen::Vector3d& o, const Eigen::Vector3d& u,
                                                  const Eigen::Vector3d& v, const Eigen::Vector3d& w)
{
    const double ax = o.x() - u.x(), ay = o.y() - u.y(), az = o.z() - u.z();
    const double bx = v.x() - w.x(), by = v.y() - w.y(), bz = v.z() - w.z();
    const double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
    const double cross = std::sqrt((cx * cx + cy * cy) + cz * cz);
    const double dot = (ax * bx + ay * by) + az * bz;
    return atan2Poly(cross, dot);
}

// (a - b).squaredNorm() as Eigen evaluates it for a Vector3d: (x^2 + y^2) + z^2.
// Planar: z is zero throughout, and (x^2 + y^2) + 0 is x^2 + y^2.
template <bool Planar = false>
[[gnu::always_inline]] inline double dist2(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    const double dx = a.x() - b.x(), dy = a.y() - b.y();
    if constexpr (Planar) return dx * dx + dy * dy;
    const double dz = a.z() - b.z();
    return (dx * dx + dy * dy) + dz * dz;
}

// Neighbourhood ends for every sample, with unwrapped indices (a closed stroke's may run below 0
// or past n - 1): lo[i] is the largest index <= i - minSteps whose chord to i is at least
// minLength, hi[i] the smallest >= i + minSteps likewise (the chord, not the path: jitter lengthens
// the path without moving the pen on). Both ends only move forward as i does, so two pointers find
// them all in O(n) (chord length is taken as monotone along the window, true up to jitter).
// An open stroke's ends clamp to 0 and n - 1; a closed stroke's window spans at most half the loop.
// The open case is the struct OpenWindow below, advanced inside the feature pass; this general form
// serves closed strokes.
void windows(const ConditionedStroke& cs, int minSteps, double minLength, std::vector<int>& lo, std::vector<int>& hi)
{
    const int n = cs.size();
    const auto at = [&](int j) -> const Eigen::Vector3d& { return cs.points[j < 0 ? j + n : (j >= n ? j - n : j)]; };
    const int reachMax = cs.closed ? n / 2 : n;
    // On a closed stroke of fewer than 2 minSteps samples the half-loop bound wins; without this
    // the clamp below had lo > hi (undefined; _GLIBCXX_ASSERTIONS aborts).
    const int steps = cs.closed ? std::min(minSteps, reachMax) : minSteps;
    const double min2 = minLength * minLength;
    lo.resize(n);
    hi.resize(n);
    int a = cs.closed ? -reachMax : 0;
    int b = 0;
    for (int i = 0; i < n; ++i) {
        const int aMin = cs.closed ? i - reachMax : 0;
        const int aMax = cs.closed ? i - steps : std::max(0, i - minSteps);
        a = std::clamp(a, aMin, aMax);
        while (a + 1 <= aMax && (at(a + 1) - at(i)).squaredNorm() >= min2) ++a;
        lo[i] = a;
        const int bMax = cs.closed ? i + reachMax : n - 1;
        b = std::clamp(std::max(b, i + steps), i, bMax);
        while (b < bMax && (at(b) - at(i)).squaredNorm() < min2) ++b;
        hi[i] = b;
    }
}

// `windows` for an open stroke, one sample at a time (no wrapping, no stored arrays): the feature
// pass advances the narrow and the wide window together. Same ends as `windows` gives: there the
// clamp of lo is a no-op on an open stroke (lo never exceeds the previous, smaller bound), and the
// clamp of hi is max(hi, i + minSteps, i) capped at n - 1.
template <bool Planar>
struct OpenWindow {
    int minSteps, stepsAhead, last;
    double min2;
    int a = 0, b = 0;
    OpenWindow(int steps, double minLength, int n)
        : minSteps(steps), stepsAhead(std::max(steps, 0)), last(n - 1), min2(minLength * minLength) {}
    void advance(const Eigen::Vector3d* p, int i)
    {
        const Eigen::Vector3d& pi = p[i];
        const int aMax = std::max(0, i - minSteps);
        while (a < aMax && dist2<Planar>(p[a + 1], pi) >= min2) ++a;
        b = std::min(std::max(b, i + stepsAhead), last);
        while (b < last && dist2<Planar>(p[b], pi) < min2) ++b;
    }
};

// computeFeatures for an open stroke: the window ends are indices as they are (no wrapping), and
// the narrow and the wide window advance together in the feature pass instead of in two passes
// through stored arrays. Planar: the points' z are all zero (see computeFeatures).
template <bool Planar>
void openFeatures(const ConditionedStroke& cs, const FeatureOptions& options, double minLen, StrokeFeatures& f)
{
    const int n = cs.size();
    const Eigen::Vector3d* p = cs.points.data();
    // Local means (computeFeatures says why), kept as separate coordinate arrays.
    std::vector<double> qbuf(static_cast<size_t>(Planar ? 2 * n : 3 * n));
    double* qx = qbuf.data();
    double* qy = qx + n;
    double* qz = Planar ? nullptr : qy + n;
    {
        const double r2 = options.denoise * cs.extent * options.denoise * cs.extent;
        double sx = 0.0, sy = 0.0, sz = 0.0;
        const auto add = [&](const Eigen::Vector3d& v) {
            sx += v.x();
            sy += v.y();
            if constexpr (!Planar) sz += v.z();
        };
        const auto sub = [&](const Eigen::Vector3d& v) {
            sx -= v.x();
            sy -= v.y();
            if constexpr (!Planar) sz -= v.z();
        };
        int s = 0, e = -1;
        for (int i = 0; i < n; ++i) {
            const Eigen::Vector3d& pi = p[i];
            while (e < i) add(p[++e]);
            while (e + 1 < n && dist2<Planar>(p[e + 1], pi) < r2) add(p[++e]);
            while (s < i && dist2<Planar>(p[s], pi) >= r2) sub(p[s++]);
            const double inv = 1.0 / double(e - s + 1);
            qx[i] = sx * inv;
            qy[i] = sy * inv;
            if constexpr (!Planar) qz[i] = sz * inv;
        }
    }
    // The angle between q_o - q_u and q_v - q_w (angleBetween's arithmetic).
    const auto angle = [&](int o, int u, int v, int w) {
        const double ax = qx[o] - qx[u], ay = qy[o] - qy[u];
        const double bx = qx[v] - qx[w], by = qy[v] - qy[w];
        if constexpr (Planar) {
            const double cz = ax * by - ay * bx;
            return atan2Poly(std::sqrt(cz * cz), ax * bx + ay * by);
        } else {
            const double az = qz[o] - qz[u], bz = qz[v] - qz[w];
            const double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
            return atan2Poly(std::sqrt((cx * cx + cy * cy) + cz * cz), (ax * bx + ay * by) + az * bz);
        }
    };
    f.lo.resize(n);
    f.hi.resize(n);
    OpenWindow<Planar> narrow(options.k, minLen, n), wide(2 * options.k, 2.0 * minLen, n);
    const double* arc = cs.arc.data();
    double* direction = f.direction.data();
    double* turningOut = f.turning.data();
    double* wideTurning = f.wideTurning.data();
    double* curvature = f.curvature.data();
    int* lo = f.lo.data();
    int* hi = f.hi.data();
    for (int i = 0; i < n; ++i) {
        narrow.advance(p, i);
        wide.advance(p, i);
        const int a = narrow.a, b = narrow.b;
        direction[i] = atan2Poly(qy[b] - qy[a], qx[b] - qx[a]);
        const double turning = angle(i, a, b, i);
        turningOut[i] = turning;
        const double path = arc[b] - arc[a];
        curvature[i] = path > 0.0 ? turning / path : 0.0;
        wideTurning[i] = angle(i, wide.a, wide.b, i);
        lo[i] = a;
        hi[i] = b;
    }
}

}  // namespace

StrokeFeatures computeFeatures(const ConditionedStroke& cs, const FeatureOptions& options, FeatureSet set)
{
    const int n = cs.size();
    StrokeFeatures f;
    const double minLen = options.neighbourhood * cs.extent;
    const double total = cs.length();
    // Unwrapped path position of index j (a closed stroke's seam gap counts as path). Window ends lie
    // within half a loop of their centre, so j is in (-n, 2n): one comparison instead of an integer
    // division (which took a fifth of this pass).
    const auto wrap = [&](int j) { return j < 0 ? j + n : (j >= n ? j - n : j); };
    const auto arcAt = [&](int j) { return cs.arc[wrap(j)] + (j < 0 ? -total : (j >= n ? total : 0.0)); };
    if (set == FeatureSet::Windows) {  // the ends the full pass gives, as it finds them
        if (cs.closed) {
            windows(cs, options.k, minLen, f.lo, f.hi);
            for (int i = 0; i < n; ++i) {
                f.lo[i] = wrap(f.lo[i]);
                f.hi[i] = wrap(f.hi[i]);
            }
        } else {
            f.lo.resize(n);
            f.hi.resize(n);
            OpenWindow<false> w(options.k, minLen, n);
            for (int i = 0; i < n; ++i) {
                w.advance(cs.points.data(), i);
                f.lo[i] = w.a;
                f.hi[i] = w.b;
            }
        }
        return f;
    }
    f.direction.resize(n);
    f.turning.resize(n);
    f.wideTurning.resize(n);
    f.curvature.resize(n);
    if (!cs.closed) {
        // Planar strokes (every z zero, as 2D input is stored) take the same arithmetic without the
        // z terms, which are exact zeros there: (x^2 + y^2) + 0 is x^2 + y^2, and the cross product's
        // x and y components are zeros whose squares add nothing; the dot product can at most
        // change the sign of a zero, which atan2Poly maps to the same angle.
        const bool planar = std::all_of(cs.points.begin(), cs.points.end(), [](const Eigen::Vector3d& p) { return p.z() == 0.0; });
        if (planar) openFeatures<true>(cs, options, minLen, f);
        else openFeatures<false>(cs, options, minLen, f);
        measureSpeed(cs, f);
        return f;
    }
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
        {
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
    f.lo.resize(n);
    f.hi.resize(n);
    const Eigen::Vector3d* qd = q.data();
    std::vector<int> wideLo, wideHi;
    windows(cs, options.k, minLen, f.lo, f.hi);
    windows(cs, 2 * options.k, 2.0 * minLen, wideLo, wideHi);
    for (int i = 0; i < n; ++i) {
        const int a = f.lo[i], b = f.hi[i];
        const Eigen::Vector3d& pa = qd[wrap(a)];
        const Eigen::Vector3d& pb = qd[wrap(b)];
        const Eigen::Vector3d chord = pb - pa;
        f.direction[i] = atan2Poly(chord.y(), chord.x());
        const double turning = angleBetween(qd[i], pa, pb, qd[i]);
        f.turning[i] = turning;
        const double path = arcAt(b) - arcAt(a);
        f.curvature[i] = path > 0.0 ? turning / path : 0.0;
        f.wideTurning[i] = angleBetween(qd[i], qd[wrap(wideLo[i])], qd[wrap(wideHi[i])], qd[i]);
        f.lo[i] = wrap(a);
        f.hi[i] = wrap(b);
    }
    measureSpeed(cs, f);
    return f;
}

// Elapsed time over each window; a window across a loop's seam (its wrapped ends out of order),
// where time restarts, gets the average speed.
void measureSpeed(const ConditionedStroke& cs, StrokeFeatures& f)
{
    const int n = cs.size();
    if (n == 0 || static_cast<int>(f.lo.size()) != n || static_cast<int>(f.hi.size()) != n) return;
    const double duration = cs.time.back() - cs.time.front();
    f.averageSpeed = duration > 0.0 ? cs.arc.back() / duration : 0.0;
    f.speed.resize(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        const int a = f.lo[i], b = f.hi[i];
        const double dt = a < b ? cs.time[b] - cs.time[a] : 0.0;
        f.speed[i] = dt > 0.0 ? (cs.arc[b] - cs.arc[a]) / dt : f.averageSpeed;
    }
}

double turningNoise(const ConditionedStroke& cs, double noise, const FeatureOptions& o)
{
    const int n = cs.size();
    if (n < 3 || !(noise > 0.0) || !(cs.extent > 0.0)) return 0.0;
    const double spacing = cs.length() / double(n - 1);
    if (!(spacing > 0.0)) return 0.0;
    const double m = 1.0 + 2.0 * o.denoise * cs.extent / spacing;
    const double arm = std::max(o.neighbourhood * cs.extent, double(std::max(o.k, 1)) * spacing);
    return std::sqrt(6.0 / m) * noise / arm;
}

bool noiseCallsForWiderArms(const ConditionedStroke& cs, double noise, const FeatureOptions& options)
{
    return options.maxTurningNoise > 0.0 && turningNoise(cs, noise, options) > options.maxTurningNoise;
}

FeatureOptions widenForNoise(const ConditionedStroke& cs, double noise, const StrokeFeatures& f, const FeatureOptions& options)
{
    FeatureOptions o = options;
    const double maxTurningNoise = options.maxTurningNoise;
    if (!noiseCallsForWiderArms(cs, noise, options)) return o;
    // Dense enough: the median arm of f (options' own windows) holds kMinArmSamples samples. Counted
    // in samples, not as length over the mean spacing: jitter lengthens the path, and a jittery
    // zigzag's mean spacing (0.9 units, three times its chord spacing) called it sparse.
    constexpr int kMinArmSamples = 3;
    const int n = cs.size();
    if (n < 2 * kMinArmSamples + 1 || static_cast<int>(f.hi.size()) != n) return o;
    std::vector<int> arm(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) arm[static_cast<size_t>(i)] = cs.closed ? (f.hi[i] - i + n) % n : f.hi[i] - i;
    std::nth_element(arm.begin(), arm.begin() + n / 2, arm.end());
    if (arm[static_cast<size_t>(n / 2)] < kMinArmSamples) return o;
    // turningNoise falls monotonically with the widening (both the arm and m grow): steps of 10 %
    // (finer than the estimate's accuracy), at most 11 under maxWidening 3 (2.85x); if even that
    // leaves the noise above the target, the widest is used.
    constexpr double kStep = 1.1;
    for (double g = kStep; g <= options.maxWidening * (1.0 + 1e-12); g *= kStep) {
        o.neighbourhood = options.neighbourhood * g;
        o.denoise = options.denoise * g;
        if (turningNoise(cs, noise, o) <= maxTurningNoise) break;
    }
    return o;
}

std::vector<int> localizeCorners(const ConditionedStroke& cs, const StrokeFeatures& f, const StrokeFeatures& wide,
                                 const std::vector<int>& corners)
{
    const int n = cs.size();
    std::vector<int> out;
    out.reserve(corners.size());
    for (int c : corners) {
        int best = c;
        for (int j = wide.lo[c];; j = cs.closed ? (j + 1) % n : j + 1) {
            if (f.turning[j] > f.turning[best]) best = j;
            if (j == wide.hi[c] || j >= n - 1) break;
        }
        out.push_back(best);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

std::vector<int> detectCorners(const ConditionedStroke& cs, const StrokeFeatures& f, const CornerOptions& o)
{
    const int n = cs.size();
    std::vector<char> candidate(n, 0);
    // Both cues need t >= min(strongAngle, slowAngle) (false for NaN either way): most samples stop
    // at that one comparison. Loop invariants in locals (the char stores may alias anything).
    const double minAngle = std::min(o.strongAngle, o.slowAngle);
    const double strongAngle = o.strongAngle, slowAngle = o.slowAngle;
    const double sharpnessFast = o.sharpnessFast, sharpness = o.sharpness;
    const double averageSpeed = f.averageSpeed, slowSpeed = o.slowFraction * f.averageSpeed;
    const double* turning = f.turning.data();
    const double* wideTurning = f.wideTurning.data();
    const double* speed = f.speed.data();
    const int* lo = f.lo.data();
    const int* hi = f.hi.data();
    const bool closed = cs.closed;
    for (int i = 0; i < n; ++i) {
        const double t = turning[i];
        if (t < minAngle) continue;
        if (!closed && (i == 0 || i == n - 1 || lo[i] == 0 || hi[i] == n - 1)) continue;
        const bool slow = averageSpeed > 0.0 && speed[i] < slowSpeed;
        const double ratio = wideTurning[i] > 0.0 ? t / wideTurning[i] : 1.0;
        candidate[i] = (t >= strongAngle && ratio >= sharpnessFast) || (slow && t >= slowAngle && ratio >= sharpness);
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
