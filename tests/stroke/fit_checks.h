#pragma once
// Independent measurements of a fitted curve for the stroke tests.
#include "solvers/bspline/bspline_curve.h"
#include "solvers/bspline/tessellation.h"
#include "solvers/geometry/plane_fit.h"
#include "solvers/stroke/stroke_fitter.h"
#include "solvers/stroke/stroke_synthesis.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace sculptline::stroketest {

using Vec3 = Eigen::Vector3d;
using namespace solvers::stroke;

/// Max distance from `pts` to the curve, measured against a 20,000-segment polyline of it, its knots
/// among the vertices (the chord sagitta at that resolution is below 1e-7 of the curve's size): a measurement
/// independent of the fitter's own foot-point search and of the kernel's CurveProjector (which missed foot points
/// beside G0 triple knots until commit 39980b6). Each point's nearest segment is found exactly; blocks of segments
/// whose bounding box lies farther than the nearest found so far are skipped (they cannot hold a nearer one), which
/// makes it fast enough for the sanitizer build.
inline double maxDeviation(const solvers::Curve3d& c, const std::vector<Vec3>& pts)
{
    constexpr int kSteps = 20000;
    constexpr int kBlock = 50;  // segments per bounding box
    // Equal steps in parameter and every knot inside the domain: a G0 corner (a triple knot) is then
    // a vertex of the polyline, not cut by a segment (which put a corner sample 2e-3 from it).
    std::vector<double> t;
    t.reserve(kSteps + 1 + c.knots().size());
    for (int i = 0; i <= kSteps; ++i) t.push_back(c.domainStart() + (c.domainEnd() - c.domainStart()) * i / kSteps);
    for (double k : c.knots())
        if (k > c.domainStart() && k < c.domainEnd()) t.push_back(k);
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(), t.end()), t.end());
    const int kSegments = static_cast<int>(t.size()) - 1;
    std::vector<Vec3> dense;
    dense.reserve(t.size());
    for (double u : t) dense.push_back(c.evaluate(u));
    std::vector<Eigen::AlignedBox3d> boxes;
    for (int b = 0; b < kSegments; b += kBlock) {
        Eigen::AlignedBox3d box(dense[b]);
        for (int i = b + 1; i <= std::min(b + kBlock, kSegments); ++i) box.extend(dense[i]);
        boxes.push_back(box);
    }
    auto segment = [&](const Vec3& p, int i) { return solvers::distanceToSegment(p, dense[i], dense[i + 1]); };
    auto block = [&](const Vec3& p, int b, double best) {
        for (int i = b * kBlock; i < std::min((b + 1) * kBlock, kSegments); ++i) best = std::min(best, segment(p, i));
        return best;
    };
    double m = 0;
    int hint = 0;  // the previous point's nearest block: consecutive samples lie near each other
    for (const auto& p : pts) {
        double best = block(p, hint, std::numeric_limits<double>::infinity());
        for (int b = 0; b < static_cast<int>(boxes.size()); ++b) {
            if (b == hint || boxes[b].exteriorDistance(p) >= best) continue;
            const double d = block(p, b, best);
            if (d < best) {
                best = d;
                hint = b;
            }
        }
        m = std::max(m, best);
    }
    return m;
}

/// How far the curve strays from the polyline through `pts` (a loop's back to its first), measured
/// independently of the fitter's measureStray: at 8,000 points equally spaced in parameter, each
/// point's least ratio, over every segment, of its distance to the segment over that segment's
/// allowance tol + share * its length; the largest over the points (<= 1: every point lies
/// within some segment's allowance). Each point tries first the segments near the previous point's
/// best, and the whole polyline where those leave it beyond 1.
inline double strayExcess(const solvers::Curve3d& c, const std::vector<Vec3>& pts, bool closed, double tol,
                          double share)
{
    constexpr int kPoints = 8000;
    constexpr int kNear = 3;  // segments either side of the previous best tried first
    const int segments = static_cast<int>(pts.size()) - (closed ? 0 : 1);
    if (segments < 1) return 0.0;
    const auto ratio = [&](int q, const Vec3& x) {
        const Vec3& a = pts[static_cast<size_t>(q)];
        const Vec3& b = pts[static_cast<size_t>((q + 1) % static_cast<int>(pts.size()))];
        return solvers::distanceToSegment(x, a, b) / (tol + share * (b - a).norm());
    };
    double worst = 0.0;
    int hint = 0;
    for (int i = 0; i <= kPoints; ++i) {
        const Vec3 x = c.evaluate(c.domainStart() + (c.domainEnd() - c.domainStart()) * i / kPoints);
        double best = std::numeric_limits<double>::infinity();
        int at = hint;
        for (int q = std::max(0, hint - kNear); q <= std::min(segments - 1, hint + kNear); ++q) {
            const double r = ratio(q, x);
            if (r < best) best = r, at = q;
        }
        if (best > 1.0) {
            for (int q = 0; q < segments; ++q) {
                const double r = ratio(q, x);
                if (r < best) best = r, at = q;
            }
        }
        hint = at;
        worst = std::max(worst, best);
    }
    return worst;
}

/// Largest distance of the points from their best-fit plane: how far from planar a space curve is.
inline double distanceFromBestPlane(const std::vector<Vec3>& pts)
{
    const solvers::PlaneFit plane = solvers::bestFitPlane(pts);
    double d = 0.0;
    for (const Vec3& p : pts) d = std::max(d, std::abs((p - plane.centroid).dot(plane.normal)));
    return d;
}

/// maxDeviation's polyline (20,000 segments, equal steps in parameter) is off by up to its sagitta
/// and, where the parameter speed peaks (beside a G0 corner), by up to ~4e-3 units on 100-300-unit
/// strokes (measured); the fitter's projection is exact to Newton's convergence. Agreement within
/// this is "the same number".
constexpr double kMeasureAgreement = 1e-2;

/// The raw samples of `s` the fit kept (not in r.dropped): those its tolerance bounds.
inline std::vector<Vec3> keptSamples(const Stroke& s, const FitResult& r)
{
    std::vector<Vec3> out;
    for (size_t i = 0; i < s.points.size(); ++i)
        if (!std::binary_search(r.dropped.begin(), r.dropped.end(), static_cast<int>(i))) out.push_back(s.points[i]);
    return out;
}

/// The synthesized shapes of the tolerance and measure tests (fit_tolerance_test.cpp,
/// fit_measure_test.cpp): open, spiralling, wavy, a smooth loop and a loop with corners.
inline std::vector<std::pair<std::string, Shape>> toleranceShapes()
{
    return {{"s-curve", sCurveShape(200)},
            {"spiral", spiralShape(100, 2.5)},
            {"flourish", flourishShape(300)},
            {"circle", circleShape({10, 20, 0}, 80)},
            {"square", polygonShape({{0, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}}, true)}};
}

}  // namespace sculptline::stroketest
