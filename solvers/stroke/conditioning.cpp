#include "solvers/stroke/conditioning.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/math_constants.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace sculptline::solvers::stroke {
namespace {

std::string at(const std::string& field, size_t i) { return "stroke." + field + "[" + std::to_string(i) + "]"; }

using Vec3 = Eigen::Vector3d;

// Throws for the first non-finite point (nothing if a sum of finite points merely overflowed).
void checkFinitePoints(const std::vector<Vec3>& points)
{
    for (size_t i = 0; i < points.size(); ++i) {
        if (!points[i].allFinite()) throw GeometryError(at("points", i) + ": not a finite number");
    }
}

// A sum is finite only if every term is (infinities and NaN propagate), so a finite sum proves
// every value finite in one add per value; a non-finite sum is followed by the exact scan.
double sequentialSum(const std::vector<double>& v)
{
    double sum = 0.0;
    for (double x : v) sum += x;
    return sum;
}

// Validation of times and pressure (the points are checked by the caller, in one pass with the
// centroid sum); the same messages in the same order as a field-by-field check.
void validateTimesAndPressure(const Stroke& s)
{
    if (!s.times.empty() && s.times.size() != s.points.size()) {
        throw GeometryError("stroke.times: " + std::to_string(s.times.size()) + " values for " +
                            std::to_string(s.points.size()) + " points");
    }
    if (!std::isfinite(sequentialSum(s.times))) {
        for (size_t i = 0; i < s.times.size(); ++i) {
            if (!std::isfinite(s.times[i])) throw GeometryError(at("times", i) + ": not a finite number");
        }
    }
    if (!s.pressure.empty() && s.pressure.size() != s.points.size()) {
        throw GeometryError("stroke.pressure: " + std::to_string(s.pressure.size()) + " values for " +
                            std::to_string(s.points.size()) + " points");
    }
    if (!std::isfinite(sequentialSum(s.pressure))) {
        for (size_t i = 0; i < s.pressure.size(); ++i) {
            if (!std::isfinite(s.pressure[i])) throw GeometryError(at("pressure", i) + ": not a finite number");
        }
    }
}

// Sum of the points in order (the centroid numerator of strokeExtent).
Vec3 pointSum(const std::vector<Vec3>& points)
{
    Vec3 sum = Vec3::Zero();
    for (const auto& p : points) sum += p;
    return sum;
}

// Largest squared distance from the centroid (strokeExtent = 2 sqrt of it).
double maxSquaredRadius(const std::vector<Vec3>& points, const Vec3& centroid)
{
    double r = 0.0;
    for (const auto& p : points) r = std::max(r, (p - centroid).squaredNorm());
    return r;
}

// Closest pair between the first and the last `window` points, searched with a stride that keeps
// the work bounded (at most ~400 x 400 distance evaluations).
struct EndPair {
    int head = 0;
    int tail = 0;
    double gap = std::numeric_limits<double>::infinity();
};

// The head [0, headEnd] and the tail [tailStart, n - 1] searched by closestEnds.
struct EndWindows {
    int headEnd = 0;
    int tailStart = 0;
};

EndWindows endWindows(const ConditionedStroke& cs, double windowLength)
{
    const int n = cs.size();
    const double total = cs.arc.back();
    int headEnd = 0;
    while (headEnd + 1 < n && cs.arc[headEnd + 1] <= windowLength) ++headEnd;
    int tailStart = n - 1;
    while (tailStart - 1 > headEnd && total - cs.arc[tailStart - 1] <= windowLength) --tailStart;
    return {headEnd, tailStart};
}

// A lower bound on the distance of any head point to any tail point: the gap between the two
// windows' bounding boxes.
double windowGapBound(const ConditionedStroke& cs, const EndWindows& w)
{
    Eigen::Array3d hlo = cs.points[0].array(), hhi = hlo;
    for (int i = 1; i <= w.headEnd; ++i) {
        hlo = hlo.min(cs.points[i].array());
        hhi = hhi.max(cs.points[i].array());
    }
    const int n = cs.size();
    Eigen::Array3d tlo = cs.points[n - 1].array(), thi = tlo;
    for (int j = w.tailStart; j < n - 1; ++j) {
        tlo = tlo.min(cs.points[j].array());
        thi = thi.max(cs.points[j].array());
    }
    const Eigen::Array3d d = (tlo - hhi).max(hlo - thi).max(0.0);
    return d.matrix().norm();
}

EndPair closestEnds(const ConditionedStroke& cs, const EndWindows& w)
{
    const int n = cs.size();
    const int headEnd = w.headEnd;
    const int tailStart = w.tailStart;
    // Coarse pass with at most ~64 x 64 pairs, then the exact pairs around the coarse winner.
    const int strideH = std::max(1, (headEnd + 1) / 64);
    const int strideT = std::max(1, (n - tailStart) / 64);
    EndPair best;
    auto consider = [&](int i, int j) {
        const double d = (cs.points[i] - cs.points[j]).squaredNorm();
        if (d < best.gap) best = {i, j, d};
    };
    for (int i = 0; i <= headEnd; i += strideH)
        for (int j = n - 1; j >= tailStart; j -= strideT) consider(i, j);
    const EndPair coarse = best;
    for (int i = std::max(0, coarse.head - strideH); i <= std::min(headEnd, coarse.head + strideH); ++i)
        for (int j = std::max(tailStart, coarse.tail - strideT); j <= std::min(n - 1, coarse.tail + strideT); ++j)
            consider(i, j);
    best.gap = std::sqrt(best.gap);
    return best;
}

// Consecutive samples within minDist of a cluster's first sample become their centroid (mean
// time, middle source index); the first and last samples are kept exactly. The input is
// pts[0..count), with the time and the raw index of sample k given by timeAt(k) and sourceAt(k).
// Fills cs.points, cs.time, cs.source and cs.arc (the cumulative chord lengths, as updateArcLength).
template <typename TimeAt, typename SourceAt>
void clusterSamples(const Vec3* pts, int count, TimeAt timeAt, SourceAt sourceAt, double minDist, int maxSamples,
                    ConditionedStroke& cs)
{
    // Appended to room reserved for every sample of an ordinary stroke (a very dense one is
    // thinned to ~maxSamples). Reserved, not resized: only the entries written touch memory, so a
    // process's first fit faults in the pages of the clusters it keeps, not of every raw sample
    // (resize zero-filled the times and lengths for all of them: 4 fresh pages of 8 on a
    // 1,000-sample stroke that keeps 664). No staging buffers either.
    const size_t cap = static_cast<size_t>(std::max(2, std::min(count + 1, 2 * std::max(16, std::min(maxSamples, 1 << 24)))));
    cs.points.clear();
    cs.time.clear();
    cs.arc.clear();
    cs.source.clear();
    cs.points.reserve(cap);
    cs.time.reserve(cap);
    cs.arc.reserve(cap);
    cs.source.reserve(cap);
    auto emit = [&](const Vec3& p, int src, double t) {
        cs.arc.push_back(cs.points.empty() ? 0.0 : cs.arc.back() + (p - cs.points.back()).norm());
        cs.points.push_back(p);
        cs.source.push_back(src);
        cs.time.push_back(t);
    };
    const double minDist2 = minDist * minDist;
    const int last = count - 1;
    for (int i = 0; i <= last;) {
        int j = i + 1;
        while (j <= last && (pts[j] - pts[i]).squaredNorm() < minDist2) ++j;
        if (i == 0) {
            emit(pts[0], sourceAt(0), timeAt(0));
        } else if (j > last) {
            emit(pts[last], sourceAt(last), timeAt(last));
        } else if (j == i + 1) {
            // A cluster of one: its mean is the sample itself (0 + x, as the sum below starts at
            // zero: -0 becomes +0; the division by one is exact).
            const Vec3& p = pts[i];
            emit(Vec3(0.0 + p.x(), 0.0 + p.y(), 0.0 + p.z()), sourceAt(i), 0.0 + timeAt(i));
        } else {
            Vec3 sum = Vec3::Zero();
            double t = 0.0;
            for (int m = i; m < j; ++m) {
                sum += pts[m];
                t += timeAt(m);
            }
            emit(sum / (j - i), sourceAt(i + (j - 1 - i) / 2), t / (j - i));
        }
        i = j;
    }
    // The start cluster held every sample: keep the last one too when it is a distinct point.
    if (last > 0 && cs.source.back() != sourceAt(last) && (pts[last] - pts[0]).squaredNorm() > 0.0) {
        emit(pts[last], sourceAt(last), timeAt(last));
    }
}

// [first, last] without the light-pressure hooks at the ends (ConditioningOptions::hookPressure).
// `pathLength` is the sum of all sample-to-sample distances if already known (negative if not).
std::pair<int, int> withoutHooks(const Stroke& s, const ConditioningOptions& o, double pathLength)
{
    const int last = static_cast<int>(s.points.size()) - 1;
    if (s.pressure.empty() || last < 4) return {0, last};
    std::vector<double> sorted = s.pressure;
    std::nth_element(sorted.begin(), sorted.begin() + last / 2, sorted.end());
    const double light = o.hookPressure * sorted[last / 2];
    if (!(light > 0.0)) return {0, last};
    double total = pathLength;
    if (total < 0.0) {
        total = 0.0;
        for (int i = 1; i <= last; ++i) total += (s.points[i] - s.points[i - 1]).norm();
    }
    const double maxLength = o.maxHookLength * total;
    int a = 0, b = last;
    double len = 0.0;
    while (a < last && s.pressure[a] < light) len += (s.points[a + 1] - s.points[a]).norm(), ++a;
    if (len > maxLength) a = 0;
    len = 0.0;
    while (b > a && s.pressure[b] < light) len += (s.points[b] - s.points[b - 1]).norm(), --b;
    if (len > maxLength) b = last;
    if (b - a < 1) return {0, last};  // all light: nothing to tell hook from stroke
    return {a, b};
}

template <typename T>
void keepRange(std::vector<T>& v, int first, int last)
{
    v.erase(v.begin() + last + 1, v.end());
    v.erase(v.begin(), v.begin() + first);
}

}  // namespace

std::pair<int, int> withoutPressureHooks(const Stroke& stroke, const ConditioningOptions& options)
{
    validateTimesAndPressure(stroke);
    return withoutHooks(stroke, options, -1.0);
}

double ConditionedStroke::length() const
{
    if (points.empty()) return 0.0;
    return arc.back() + (closed ? (points.back() - points.front()).norm() : 0.0);
}

double strokeExtent(const std::vector<Eigen::Vector3d>& points)
{
    if (points.size() < 2) return 0.0;
    const Vec3 centroid = pointSum(points) / static_cast<double>(points.size());
    return 2.0 * std::sqrt(maxSquaredRadius(points, centroid));
}

void updateArcLength(ConditionedStroke& cs)
{
    const size_t n = cs.points.size();
    cs.arc.resize(n);
    if (n == 0) return;
    double* arc = cs.arc.data();
    const Vec3* p = cs.points.data();
    double acc = 0.0;
    arc[0] = 0.0;
    for (size_t i = 1; i < n; ++i) arc[i] = acc = acc + (p[i] - p[i - 1]).norm();
}

ConditionedStroke conditionStroke(const Stroke& stroke, const ConditioningOptions& options)
{
    return detail::conditionStrokeWithTolerance(stroke, options, 0.0);
}

ConditionedStroke detail::conditionStrokeWithTolerance(const Stroke& stroke, const ConditioningOptions& options,
                                                       double tolerance)
{
    const std::vector<Vec3>& points = stroke.points;
    const size_t count = points.size();
    if (points.empty()) throw GeometryError("stroke.points: empty stroke, at least two distinct points are needed");
    // Validation and the centroid in one pass: a sum of points is finite only if every point is.
    const Vec3 sum = pointSum(points);
    if (!sum.allFinite()) checkFinitePoints(points);
    validateTimesAndPressure(stroke);

    // The strided path length (see below); with stride 1 it is summed in the extent's pass.
    const size_t stride = std::max<size_t>(1, count / std::max(1, options.maxSamples));
    double rawLength = 0.0;
    double r = 0.0;  // largest squared distance from the centroid
    const Vec3 centroid = sum / static_cast<double>(count);
    if (count >= 2) {
        if (stride == 1) {
            r = std::max(0.0, (points[0] - centroid).squaredNorm());
            for (size_t i = 1; i < count; ++i) {
                r = std::max(r, (points[i] - centroid).squaredNorm());
                rawLength += (points[i] - points[i - 1]).norm();
            }
        } else {
            r = maxSquaredRadius(points, centroid);
            for (size_t i = stride; i < count; i += stride) rawLength += (points[i] - points[i - stride]).norm();
        }
    }

    ConditionedStroke cs;
    cs.extent = count < 2 ? 0.0 : 2.0 * std::sqrt(r);
    // Exact duplicates differ by rounding only; a stroke whose extent is below this fraction of its
    // largest coordinate has no shape to fit.
    const double scale = points[0].cwiseAbs().maxCoeff() + cs.extent;
    if (!(cs.extent > 1e-12 * scale) || cs.extent == 0.0) {
        throw GeometryError("stroke.points: all points coincide, a curve needs at least two distinct points");
    }

    bool timed = !stroke.times.empty();
    for (size_t i = 1; timed && i < stroke.times.size(); ++i) {
        if (stroke.times[i] < stroke.times[i - 1]) {
            timed = false;
            cs.warnings.push_back("stroke.times: decreasing at index " + std::to_string(i) +
                                  ", timestamps ignored and speed estimated from sample spacing");
        }
    }
    if (timed && !(stroke.times.back() > stroke.times.front())) timed = false;
    cs.timed = timed;

    // Duplicate and near-coincident samples (seed 003 §3.1: duplicates are removed, and data "within
    // some small distance of each other" are mean-filtered): consecutive samples within minDist of
    // a cluster's first sample become their centroid, which averages the jitter of a slow or densely
    // sampled pen instead of keeping one noisy sample of it. The stroke's first and last samples
    // are kept exactly (the fit interpolates them). minDist is at least length / maxSamples, so the
    // conditioned count is bounded by ~maxSamples for any input size, in one linear pass.
    // The path length is taken over every stride-th sample: summed over every sample of a very
    // dense stroke, jitter would inflate it many times over (1e6 samples with 0.1 noise: 150x),
    // and the merge distance with it.
    // fitStroke's absolute tolerance caps the merge distance (see the header); the extent is the same
    // number fitStroke would get from strokeExtent.
    const double minSpacing =
        tolerance > 0.0 ? std::min(options.minSpacing, 0.4 * tolerance / cs.extent) : options.minSpacing;
    double minDist = std::max(minSpacing * cs.extent, rawLength / std::max(16, options.maxSamples));
    const auto [first, last] = withoutHooks(stroke, options, stride == 1 ? rawLength : -1.0);
    for (int i = 0; i < first; ++i) cs.dropped.push_back(i);
    for (int i = last + 1; i < static_cast<int>(count); ++i) cs.dropped.push_back(i);
    if (first > 0) cs.warnings.push_back("stroke: light-pressure hook trimmed at the start (samples 0.." + std::to_string(first - 1) + ")");
    if (last + 1 < static_cast<int>(count)) {
        cs.warnings.push_back("stroke: light-pressure hook trimmed at the end (samples " + std::to_string(last + 1) + ".." +
                              std::to_string(count - 1) + ")");
    }
    {
        const int kept = last - first + 1;
        auto sourceAt = [first = first](int k) { return first + k; };
        if (timed) {
            const double* t = stroke.times.data() + first;
            clusterSamples(points.data() + first, kept, [t](int k) { return t[k]; }, sourceAt, minDist, options.maxSamples, cs);
        } else {
            clusterSamples(points.data() + first, kept, [first = first](int k) { return static_cast<double>(first + k); },
                           sourceAt, minDist, options.maxSamples, cs);
        }
    }
    // The strided length can still be inflated by jitter; the clusters are averaged and nearly
    // noise-free, so a second pass over them with their own length honours the bound.
    for (int pass = 0; pass < 2 && cs.size() > options.maxSamples; ++pass) {
        minDist = std::max(minDist, cs.arc.back() / options.maxSamples);
        std::vector<Vec3> pts;
        std::vector<double> ts;
        std::vector<int> src;
        pts.swap(cs.points);
        ts.swap(cs.time);
        src.swap(cs.source);
        clusterSamples(pts.data(), static_cast<int>(pts.size()), [&ts](int k) { return ts[k]; },
                       [&src](int k) { return src[k]; }, minDist, options.maxSamples, cs);
    }
    if (cs.points.size() < 2) {
        throw GeometryError("stroke.points: fewer than two distinct points after removing duplicates");
    }
    // cs.arc is up to date (clusterSamples).

    // Closure: the two ends meet (or overshoot) within closeGap of the length. An overshoot past
    // the start is trimmed at the closest pair of points between the head and the tail.
    if (options.closure != Closure::Open && cs.size() >= 6) {
        const double total = cs.arc.back();
        // The gap is measured against the perimeter of the stroke's extent (pi * extent, a circle's)
        // when that is shorter than the stroke: a long stroke (a spiral, a scribble) passing near
        // its start is not a loop because its length dwarfs the miss.
        const double perimeter = std::min(total, kPi * cs.extent);
        const double maxGap = options.closeGap * perimeter;
        const EndWindows w = endWindows(cs, 0.15 * total);
        // Ends whose windows lie farther apart than maxGap cannot meet, whatever the closest pair
        // (the margin covers the rounding of the bound): the search below is then skipped.
        const bool farApart = windowGapBound(cs, w) > maxGap * (1.0 + 1e-9) + 1e-300;
        bool meets = false;
        EndPair c;
        if (!farApart) {
            c = closestEnds(cs, w);
            // A loop must also enclose area: a stroke drawn out and straight back has close ends but is
            // a doubled line. Vector area of the closed polygon (half the sum of p_i x p_{i+1}) against
            // minLoopArea * L^2 (a circle has L^2 / 4 pi = 0.08 L^2, a 10:1 rectangle 0.02 L^2), L the
            // perimeter above: the path length itself grows with the digitizer's jitter as the
            // sampling gets denser (a pentagon drawn with 10,000 samples: path 3.9x its perimeter),
            // which would make every dense loop "enclose" too little.
            Vec3 area = Vec3::Zero();
            for (int i = c.head; i < c.tail; ++i) area += cs.points[i].cross(cs.points[i + 1]);
            area += cs.points[c.tail].cross(cs.points[c.head]);
            const bool encloses = 0.5 * area.norm() >= options.minLoopArea * perimeter * perimeter;
            meets = encloses && c.gap <= maxGap && cs.arc[c.tail] - cs.arc[c.head] > 0.5 * total;
        }
        if (meets || options.closure == Closure::Closed) {
            cs.closed = true;
            const EndPair cut = meets ? c : EndPair{0, cs.size() - 1, 0.0};
            if (cut.head > 0 || cut.tail < cs.size() - 1) {
                cs.warnings.push_back("stroke: loop overshoot trimmed to samples " + std::to_string(cs.source[cut.head]) +
                                      ".." + std::to_string(cs.source[cut.tail]));
                // The raw samples before the head's and after the tail's are the overshoot.
                for (int i = first; i < cs.source[cut.head]; ++i) cs.dropped.push_back(i);
                for (int i = cs.source[cut.tail] + 1; i <= last; ++i) cs.dropped.push_back(i);
                std::sort(cs.dropped.begin(), cs.dropped.end());
                keepRange(cs.points, cut.head, cut.tail);
                keepRange(cs.source, cut.head, cut.tail);
                keepRange(cs.time, cut.head, cut.tail);
            }
            // The two ends of a loop are one place; keep one of them if they nearly coincide.
            if (cs.size() > 3 && (cs.points.back() - cs.points.front()).norm() < minDist) {
                cs.points.pop_back();
                cs.source.pop_back();
                cs.time.pop_back();
            }
            updateArcLength(cs);
        }
    } else if (options.closure == Closure::Closed) {
        cs.closed = true;
    }
    return cs;
}

double estimateNoise(const std::vector<Eigen::Vector3d>& p, int dimension)
{
    const int n = static_cast<int>(p.size());
    if (n < 5) return 0.0;
    std::vector<double> len(static_cast<size_t>(n - 4));
    for (int i = 2; i + 2 < n; ++i) len[i - 2] = (p[i - 2] - 4.0 * p[i - 1] + 6.0 * p[i] - 4.0 * p[i + 1] + p[i + 2]).norm();
    const size_t mid = len.size() / 2;
    std::nth_element(len.begin(), len.begin() + static_cast<long>(mid), len.end());
    // Median of the length of a Gaussian vector with unit per-coordinate deviation: sqrt(2 ln 2)
    // in 2D (Rayleigh), 1.5382 in 3D (Maxwell); the fourth difference scales it by sqrt(70).
    const double chiMedian = dimension == 3 ? 1.5382 : 1.1774;
    return len[mid] / (chiMedian * std::sqrt(70.0));
}

std::vector<Eigen::Vector3d> limitSmoothing(std::vector<Eigen::Vector3d> drawn, const std::vector<Eigen::Vector3d>& smoothed,
                                            double budget, double* shift)
{
    // In place: the drawn points become the result (a caller that moves them in saves a copy of
    // the stroke, and the fresh heap pages it would take on a process's first fit).
    double moved = 0.0;
    if (budget > 0.0) {
        for (size_t i = 0; i < drawn.size(); ++i) {
            const Vec3 d = smoothed[i] - drawn[i];
            const double len = d.norm();
            drawn[i] = len > budget ? (drawn[i] + d * (budget / len)).eval() : smoothed[i];
            moved = std::max(moved, std::min(len, budget));
        }
    }
    if (shift) *shift = moved;
    return drawn;
}

void smoothPreservingCorners(ConditionedStroke& cs, const std::vector<int>& fixed, int passes)
{
    const int n = cs.size();
    if (n < 3 || passes <= 0) return;
    std::vector<char> hold(n, 0);
    for (int f : fixed) hold[f] = 1;
    if (!cs.closed) hold[0] = hold[n - 1] = 1;
    Vec3* p = cs.points.data();
    for (int pass = 0; pass < passes; ++pass) {
        // In place: `before` is the previous point's value before this pass, `start` the first's.
        const Vec3 start = p[0];
        Vec3 before = p[n - 1];
        for (int i = 0; i < n - 1; ++i) {
            const Vec3 here = p[i];
            if (!hold[i]) p[i] = (before + here + p[i + 1]) / 3.0;
            before = here;
        }
        if (!hold[n - 1]) p[n - 1] = (before + p[n - 1] + start) / 3.0;
    }
    updateArcLength(cs);
}

}  // namespace sculptline::solvers::stroke
