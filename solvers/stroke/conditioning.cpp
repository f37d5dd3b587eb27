#include "solvers/stroke/conditioning.h"

#include "solvers/bspline/geometry_error.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace sculptline::solvers::stroke {
namespace {

std::string at(const std::string& field, size_t i) { return "stroke." + field + "[" + std::to_string(i) + "]"; }

void validate(const Stroke& s)
{
    if (s.points.empty()) throw GeometryError("stroke.points: empty stroke, at least two distinct points are needed");
    for (size_t i = 0; i < s.points.size(); ++i) {
        if (!s.points[i].allFinite()) throw GeometryError(at("points", i) + ": not a finite number");
    }
    if (!s.times.empty() && s.times.size() != s.points.size()) {
        throw GeometryError("stroke.times: " + std::to_string(s.times.size()) + " values for " +
                            std::to_string(s.points.size()) + " points");
    }
    for (size_t i = 0; i < s.times.size(); ++i) {
        if (!std::isfinite(s.times[i])) throw GeometryError(at("times", i) + ": not a finite number");
    }
    if (!s.pressure.empty() && s.pressure.size() != s.points.size()) {
        throw GeometryError("stroke.pressure: " + std::to_string(s.pressure.size()) + " values for " +
                            std::to_string(s.points.size()) + " points");
    }
    for (size_t i = 0; i < s.pressure.size(); ++i) {
        if (!std::isfinite(s.pressure[i])) throw GeometryError(at("pressure", i) + ": not a finite number");
    }
}

// Closest pair between the first and the last `window` points, searched with a stride that keeps
// the work bounded (at most ~400 x 400 distance evaluations).
struct EndPair {
    int head = 0;
    int tail = 0;
    double gap = std::numeric_limits<double>::infinity();
};

EndPair closestEnds(const ConditionedStroke& cs, double windowLength)
{
    const int n = cs.size();
    const double total = cs.arc.back();
    int headEnd = 0;
    while (headEnd + 1 < n && cs.arc[headEnd + 1] <= windowLength) ++headEnd;
    int tailStart = n - 1;
    while (tailStart - 1 > headEnd && total - cs.arc[tailStart - 1] <= windowLength) --tailStart;
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
// time, middle source index); the first and last samples are kept exactly.
void clusterSamples(const std::vector<Eigen::Vector3d>& pts, const std::vector<double>& times,
                    const std::vector<int>& sources, double minDist, ConditionedStroke& cs)
{
    cs.points.clear();
    cs.time.clear();
    cs.source.clear();
    const double minDist2 = minDist * minDist;
    const int last = static_cast<int>(pts.size()) - 1;
    auto keep = [&](int i) {
        cs.points.push_back(pts[i]);
        cs.source.push_back(sources[i]);
        cs.time.push_back(times[i]);
    };
    for (int i = 0; i <= last;) {
        int j = i + 1;
        while (j <= last && (pts[j] - pts[i]).squaredNorm() < minDist2) ++j;
        if (i == 0) {
            keep(0);
        } else if (j > last) {
            keep(last);
        } else {
            Eigen::Vector3d sum = Eigen::Vector3d::Zero();
            double t = 0.0;
            for (int k = i; k < j; ++k) {
                sum += pts[k];
                t += times[k];
            }
            cs.points.push_back(sum / (j - i));
            cs.source.push_back(sources[i + (j - 1 - i) / 2]);
            cs.time.push_back(t / (j - i));
        }
        i = j;
    }
    // The start cluster held every sample: keep the last one too when it is a distinct point.
    if (last > 0 && cs.source.back() != sources[last] && (pts[last] - pts[0]).squaredNorm() > 0.0) keep(last);
}

// [first, last] without the light-pressure hooks at the ends (ConditioningOptions::hookPressure).
std::pair<int, int> withoutHooks(const Stroke& s, const ConditioningOptions& o)
{
    const int last = static_cast<int>(s.points.size()) - 1;
    if (s.pressure.empty() || last < 4) return {0, last};
    std::vector<double> sorted = s.pressure;
    std::nth_element(sorted.begin(), sorted.begin() + last / 2, sorted.end());
    const double light = o.hookPressure * sorted[last / 2];
    if (!(light > 0.0)) return {0, last};
    double total = 0.0;
    for (int i = 1; i <= last; ++i) total += (s.points[i] - s.points[i - 1]).norm();
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
    v = std::vector<T>(v.begin() + first, v.begin() + last + 1);
}

}  // namespace

double ConditionedStroke::length() const
{
    if (points.empty()) return 0.0;
    return arc.back() + (closed ? (points.back() - points.front()).norm() : 0.0);
}

double strokeExtent(const std::vector<Eigen::Vector3d>& points)
{
    if (points.size() < 2) return 0.0;
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const auto& p : points) centroid += p;
    centroid /= static_cast<double>(points.size());
    double r = 0.0;
    for (const auto& p : points) r = std::max(r, (p - centroid).squaredNorm());
    return 2.0 * std::sqrt(r);
}

void updateArcLength(ConditionedStroke& cs)
{
    cs.arc.assign(cs.points.size(), 0.0);
    for (size_t i = 1; i < cs.points.size(); ++i) cs.arc[i] = cs.arc[i - 1] + (cs.points[i] - cs.points[i - 1]).norm();
}

ConditionedStroke conditionStroke(const Stroke& stroke, const ConditioningOptions& options)
{
    validate(stroke);
    ConditionedStroke cs;
    cs.extent = strokeExtent(stroke.points);
    // Exact duplicates differ by rounding only; a stroke whose extent is below this fraction of its
    // largest coordinate has no shape to fit.
    const double scale = stroke.points[0].cwiseAbs().maxCoeff() + cs.extent;
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
    const size_t stride = std::max<size_t>(1, stroke.points.size() / std::max(1, options.maxSamples));
    double rawLength = 0.0;
    for (size_t i = stride; i < stroke.points.size(); i += stride) {
        rawLength += (stroke.points[i] - stroke.points[i - stride]).norm();
    }
    double minDist = std::max(options.minSpacing * cs.extent, rawLength / std::max(16, options.maxSamples));
    const auto [first, last] = withoutHooks(stroke, options);
    if (first > 0) cs.warnings.push_back("stroke: light-pressure hook trimmed at the start (samples 0.." + std::to_string(first - 1) + ")");
    if (last + 1 < static_cast<int>(stroke.points.size())) {
        cs.warnings.push_back("stroke: light-pressure hook trimmed at the end (samples " + std::to_string(last + 1) + ".." +
                              std::to_string(stroke.points.size() - 1) + ")");
    }
    std::vector<double> times(static_cast<size_t>(last - first + 1));
    std::vector<int> sources(times.size());
    for (int i = first; i <= last; ++i) {
        times[i - first] = timed ? stroke.times[i] : static_cast<double>(i);
        sources[i - first] = i;
    }
    if (first == 0 && last + 1 == static_cast<int>(stroke.points.size())) {
        clusterSamples(stroke.points, times, sources, minDist, cs);
    } else {
        clusterSamples(std::vector<Eigen::Vector3d>(stroke.points.begin() + first, stroke.points.begin() + last + 1), times,
                       sources, minDist, cs);
    }
    // The strided length can still be inflated by jitter; the clusters are averaged and nearly
    // noise-free, so a second pass over them with their own length honours the bound.
    for (int pass = 0; pass < 2 && cs.size() > options.maxSamples; ++pass) {
        updateArcLength(cs);
        minDist = std::max(minDist, cs.arc.back() / options.maxSamples);
        const std::vector<Eigen::Vector3d> pts = cs.points;
        const std::vector<double> ts = cs.time;
        const std::vector<int> src = cs.source;
        clusterSamples(pts, ts, src, minDist, cs);
    }
    if (cs.points.size() < 2) {
        throw GeometryError("stroke.points: fewer than two distinct points after removing duplicates");
    }
    updateArcLength(cs);

    // Closure: the two ends meet (or overshoot) within closeGap of the length. An overshoot past
    // the start is trimmed at the closest pair of points between the head and the tail.
    if (options.closure != Closure::Open && cs.size() >= 6) {
        const double total = cs.arc.back();
        const EndPair c = closestEnds(cs, 0.15 * total);
        // A loop must also enclose area: a stroke drawn out and straight back has close ends but is
        // a doubled line. Vector area of the closed polygon (half the sum of p_i x p_{i+1}) against
        // minLoopArea * L^2 (a circle has L^2 / 4 pi = 0.08 L^2, a 10:1 rectangle 0.02 L^2).
        Eigen::Vector3d area = Eigen::Vector3d::Zero();
        for (int i = c.head; i < c.tail; ++i) area += cs.points[i].cross(cs.points[i + 1]);
        area += cs.points[c.tail].cross(cs.points[c.head]);
        const bool encloses = 0.5 * area.norm() >= options.minLoopArea * total * total;
        // The gap is measured against the perimeter of the stroke's extent (pi * extent, a circle's)
        // when that is shorter than the stroke: a long stroke (a spiral, a scribble) passing near
        // its start is not a loop because its length dwarfs the miss.
        const double perimeter = std::min(total, 3.14159265358979 * cs.extent);
        const bool meets =
            encloses && c.gap <= options.closeGap * perimeter && cs.arc[c.tail] - cs.arc[c.head] > 0.5 * total;
        if (meets || options.closure == Closure::Closed) {
            cs.closed = true;
            const EndPair cut = meets ? c : EndPair{0, cs.size() - 1, 0.0};
            if (cut.head > 0 || cut.tail < cs.size() - 1) {
                cs.warnings.push_back("stroke: loop overshoot trimmed to samples " + std::to_string(cs.source[cut.head]) +
                                      ".." + std::to_string(cs.source[cut.tail]));
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

void smoothPreservingCorners(ConditionedStroke& cs, const std::vector<int>& fixed, int passes)
{
    const int n = cs.size();
    if (n < 3 || passes <= 0) return;
    std::vector<char> hold(n, 0);
    for (int f : fixed) hold[f] = 1;
    if (!cs.closed) hold[0] = hold[n - 1] = 1;
    std::vector<Eigen::Vector3d> next(n);
    for (int pass = 0; pass < passes; ++pass) {
        for (int i = 0; i < n; ++i) {
            if (hold[i]) {
                next[i] = cs.points[i];
                continue;
            }
            const int a = i == 0 ? n - 1 : i - 1;
            const int b = i == n - 1 ? 0 : i + 1;
            next[i] = (cs.points[a] + cs.points[i] + cs.points[b]) / 3.0;
        }
        cs.points.swap(next);
    }
    updateArcLength(cs);
}

}  // namespace sculptline::solvers::stroke
