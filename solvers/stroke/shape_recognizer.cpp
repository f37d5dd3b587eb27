#include "solvers/stroke/shape_recognizer.h"

#include "solvers/bspline/periodic.h"
#include "solvers/geometry/plane_fit.h"
#include "solvers/math_constants.h"
#include "solvers/stroke/features.h"
#include "solvers/stroke/polygon_vertices.h"
#include "solvers/stroke/quad_shapes.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace sculptline::solvers::stroke {
namespace {

using detail::angleOf;
using detail::classifyQuad;
using detail::detectedVertices;
using detail::edgeLineVertices;
using detail::QuadShape;
using detail::refineVertices;
using detail::regularDiamond;
using detail::regularRectangle;
using detail::relocateVertices;
using detail::roundedPolygonResidual;
using detail::roundedRectangleResidual;

constexpr double kQuarterTurn = kPi / 2;
// RecognizeOptions::looseQuad: the smallest interior angle of a quad read as a skewed rectangle.
constexpr double kLooseQuadAngle = kPi / 3;

Eigen::Vector3d lift(const StrokeGeometry& g, const Point2& p) { return g.origin + p.x() * g.axisU + p.y() * g.axisV; }

// A clamped curve whose last point repeats its first, as the equivalent closed (periodic) curve in the
// unwrapped convention of BSplineCurve: per period the knots are the clamped vector's start knot
// p times and its interior knots (N values for N distinct points), U_i = L[(i-1) mod N] + T
// floor((i-1)/N), and the first p points (and weights) repeat at the end. On each span the basis
// functions see the same knots U_1..U_2p as the clamped curve's, so the shape is unchanged; only the
// curve now says that it is closed (it wraps, and the JSON form carries "closed": true).
Curve3d closeLoop(const Curve3d& c)
{
    const int p = c.degree();
    const int n = c.pointCount() - 1;  // distinct points Q_0..Q_{n-1}
    const KnotVector& k = c.knots();
    const double period = c.domainEnd() - c.domainStart();
    const std::vector<double> per(k.begin() + 1, k.begin() + 1 + n);
    const KnotVector u = periodicKnots(p, per, period);
    std::vector<Eigen::Vector3d> pts(c.points().begin(), c.points().end() - 1);
    std::vector<double> w;
    if (c.isRational()) w.assign(c.weights().begin(), c.weights().end() - 1);
    for (int i = 0; i < p; ++i) {
        pts.push_back(pts[i % n]);
        if (c.isRational()) w.push_back(w[i % n]);
    }
    return Curve3d(p, u, pts, w, true);
}

// Degree-1 B-spline through the vertices, uniform knots on [0, 1]; closed: a periodic polygon.
Curve3d polylineCurve(const StrokeGeometry& g, std::vector<Point2> v, bool closed)
{
    if (closed) v.push_back(v.front());
    std::vector<Eigen::Vector3d> pts;
    for (const auto& p : v) pts.push_back(lift(g, p));
    KnotVector knots = {0.0};
    const int n = static_cast<int>(pts.size());
    for (int i = 0; i < n; ++i) knots.push_back(double(i) / (n - 1));
    knots.push_back(1.0);
    const Curve3d open(1, knots, pts);
    return closed ? closeLoop(open) : open;
}

// Unwrapped polar angles of the points around c: the total signed sweep.
double sweep(const std::vector<Point2>& pts, const Point2& c)
{
    double total = 0, prev = angleOf(pts.front() - c);
    for (const auto& p : pts) {
        const double a = angleOf(p - c);
        double d = a - prev;
        if (d > kPi) d -= 2 * kPi;
        if (d < -kPi) d += 2 * kPi;
        total += d;
        prev = a;
    }
    return total;
}

double score(double residual, double scale) { return std::exp(-(residual / scale) * (residual / scale)); }

// strokeExtent of the stroke as a curve rather than as samples: twice the largest distance of a
// point from the centroid of the polyline (each segment weighted by its length; a loop's closing gap
// included). The samples' centroid moves towards where the pen was slow or the device sampled
// densely, and with it every threshold relative to the extent: measured on the development
// strokes, resampling them at half or twice their spacing changed the sample extent by up to 10 %.
double curveExtent(const std::vector<Eigen::Vector3d>& p, bool closed)
{
    const size_t n = p.size();
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    double total = 0.0;
    for (size_t i = 0; i + 1 < n + (closed ? 1 : 0); ++i) {
        const Eigen::Vector3d& a = p[i];
        const Eigen::Vector3d& b = p[(i + 1) % n];
        const double l = (b - a).norm();
        c += 0.5 * l * (a + b);
        total += l;
    }
    if (!(total > 0.0)) return 0.0;
    c /= total;
    double r2 = 0.0;
    for (const auto& q : p) r2 = std::max(r2, (q - c).squaredNorm());
    return 2.0 * std::sqrt(r2);
}

// The conditioned stroke at uniform arc-length spacing (linear interpolation of position and time;
// a loop's closing gap is walked too, at the last sample's time). The recognizer reads shape at
// this one resolution, whatever the pen's sample density: see RecognizeOptions::sampleSpacing.
ConditionedStroke uniformResample(const ConditionedStroke& cs, double step)
{
    ConditionedStroke out;
    out.closed = cs.closed;
    out.timed = cs.timed;
    out.extent = curveExtent(cs.points, cs.closed);
    std::vector<Eigen::Vector3d> p = cs.points;
    std::vector<double> t = cs.time;
    std::vector<int> src = cs.source;
    if (cs.closed) {
        p.push_back(cs.points.front());
        t.push_back(cs.time.back());
        src.push_back(cs.source.back());
    }
    std::vector<double> arc(p.size(), 0.0);
    for (size_t i = 1; i < p.size(); ++i) arc[i] = arc[i - 1] + (p[i] - p[i - 1]).norm();
    const double total = arc.back();
    // At least 16 intervals (a stroke of a few samples keeps a shape to measure).
    const int m = std::max(16, static_cast<int>(std::lround(total / std::max(step, 1e-300))));
    const int count = cs.closed ? m : m + 1;  // a loop does not repeat its first sample
    size_t seg = 0;
    for (int k = 0; k < count; ++k) {
        const double a = total * k / m;
        while (seg + 2 < p.size() && arc[seg + 1] <= a) ++seg;
        const double len = arc[seg + 1] - arc[seg];
        const double u = len > 0.0 ? std::clamp((a - arc[seg]) / len, 0.0, 1.0) : 0.0;
        out.points.push_back((1 - u) * p[seg] + u * p[seg + 1]);
        out.time.push_back((1 - u) * t[seg] + u * t[seg + 1]);
        out.source.push_back(u < 0.5 ? src[seg] : src[seg + 1]);
        out.arc.push_back(k == 0 ? 0.0 : out.arc.back() + (out.points[k] - out.points[k - 1]).norm());
    }
    if (!cs.closed) {  // the ends exactly
        out.points.back() = p.back();
        out.time.back() = t.back();
    }
    return out;
}

}  // namespace

const char* shapeName(ShapeKind k)
{
    switch (k) {
    case ShapeKind::Line: return "line";
    case ShapeKind::Arc: return "arc";
    case ShapeKind::Circle: return "circle";
    case ShapeKind::Ellipse: return "ellipse";
    case ShapeKind::Triangle: return "triangle";
    case ShapeKind::Rectangle: return "rectangle";
    case ShapeKind::Square: return "square";
    case ShapeKind::Diamond: return "diamond";
    case ShapeKind::Polyline: return "polyline";
    case ShapeKind::Freeform: return "freeform";
    }
    return "freeform";
}

StrokeGeometry strokeGeometry(const FitResult& fit)
{
    const ConditionedStroke& cs = fit.conditioned;
    StrokeGeometry g;
    g.closed = fit.curve.isClosed();
    g.length = cs.length();
    g.extent = cs.extent;
    const double duration = cs.time.back() - cs.time.front();
    g.speed = duration > 0 ? cs.arc.back() / duration : 0.0;
    bool planarXY = true;
    for (const auto& p : cs.points) planarXY = planarXY && std::abs(p.z() - cs.points[0].z()) <= 1e-9 * (1 + g.extent);
    if (planarXY) {
        g.origin = Eigen::Vector3d(0, 0, cs.points[0].z());
    } else {
        const PlaneFit plane = bestFitPlane(cs.points);
        g.origin = plane.centroid;
        g.axisU = plane.axisU;
        g.axisV = plane.axisV;
    }
    for (const auto& p : cs.points) g.points.emplace_back((p - g.origin).dot(g.axisU), (p - g.origin).dot(g.axisV));
    std::vector<int> corner;
    for (int raw : fit.corners)
        for (int k = 0; k < cs.size(); ++k)
            if (cs.source[k] == raw) corner.push_back(k);
    std::sort(corner.begin(), corner.end());
    if (!g.closed) g.vertexIndex.push_back(0);
    for (int k : corner) g.vertexIndex.push_back(k);
    if (!g.closed) g.vertexIndex.push_back(static_cast<int>(g.points.size()) - 1);
    for (int k : g.vertexIndex) g.vertices.push_back(g.points[k]);
    return g;
}

Curve3d makeArc(const StrokeGeometry& g, const Point2& c, double r, double a0, double a1)
{
    // The NURBS Book A7.1: arcs of at most 90 degrees, middle weights cos(dtheta / 2).
    const double total = a1 - a0;
    const int arcs = std::max(1, static_cast<int>(std::ceil(std::abs(total) / kQuarterTurn - 1e-9)));
    const double d = total / arcs, w1 = std::cos(0.5 * d);
    std::vector<Eigen::Vector3d> pts;
    std::vector<double> weights;
    KnotVector knots = {0, 0, 0};
    auto on = [&](double a) { return Point2(c + r * Point2(std::cos(a), std::sin(a))); };
    pts.push_back(lift(g, on(a0)));
    weights.push_back(1.0);
    for (int i = 0; i < arcs; ++i) {
        const double mid = a0 + (i + 0.5) * d;
        pts.push_back(lift(g, Point2(c + (r / w1) * Point2(std::cos(mid), std::sin(mid)))));
        weights.push_back(w1);
        pts.push_back(lift(g, on(a0 + (i + 1) * d)));
        weights.push_back(1.0);
        if (i + 1 < arcs) knots.insert(knots.end(), 2, double(i + 1) / arcs);
    }
    knots.insert(knots.end(), 3, 1.0);
    if (arcs == 4 && std::abs(std::abs(total) - 2 * kPi) < 1e-12) {  // a full turn: exact closure, periodic
        pts.back() = pts.front();
        return closeLoop(Curve3d(2, knots, pts, weights));
    }
    return Curve3d(2, knots, pts, weights);
}

/// The regularized curve of `kind` for a recognized stroke (rec.polygon is set for polygon kinds).
/// `kind` must be one of rec's candidates: each candidate's fit (line, circle, ellipse, vertices)
/// was computed when it was scored.
static Curve3d regularize(Recognition& rec, const FitResult& fit, ShapeKind kind)
{
    const StrokeGeometry& g = rec.geometry;
    switch (kind) {
    case ShapeKind::Line: {
        const Point2 p = rec.line.point, d = rec.line.direction;
        rec.polygon = {p + d * (g.points.front() - p).dot(d), p + d * (g.points.back() - p).dot(d)};
        return polylineCurve(g, rec.polygon, false);
    }
    case ShapeKind::Arc: {
        const double a0 = angleOf(g.points.front() - rec.circle.center);
        return makeArc(g, rec.circle.center, rec.circle.radius, a0, a0 + sweep(g.points, rec.circle.center));
    }
    case ShapeKind::Circle: {
        const double a0 = angleOf(g.points.front() - rec.circle.center);
        const double dir = sweep(g.points, rec.circle.center) >= 0 ? 1.0 : -1.0;
        return makeArc(g, rec.circle.center, rec.circle.radius, a0, a0 + dir * 2 * kPi);
    }
    case ShapeKind::Ellipse: {
        // The unit circle mapped by the ellipse's affine frame: rational curves are affinely
        // invariant, so the result is an exact ellipse (The NURBS Book §7.3).
        StrokeGeometry unit;
        const Curve3d circle = makeArc(unit, Point2::Zero(), 1.0, 0.0, 2 * kPi);
        const Point2 ua(std::cos(rec.ellipse.angle), std::sin(rec.ellipse.angle)), ub(-ua.y(), ua.x());
        std::vector<Eigen::Vector3d> pts;
        for (const auto& p : circle.points()) {
            pts.push_back(lift(g, Point2(rec.ellipse.center + rec.ellipse.a * p.x() * ua + rec.ellipse.b * p.y() * ub)));
        }
        return Curve3d(2, circle.knots(), pts, circle.weights(), true);  // closed like the circle
    }
    case ShapeKind::Square:
    case ShapeKind::Rectangle:
        rec.polygon = regularRectangle(g.vertices, kind == ShapeKind::Square);
        return polylineCurve(g, rec.polygon, true);
    case ShapeKind::Diamond:
        rec.polygon = regularDiamond(g.vertices);
        return polylineCurve(g, rec.polygon, true);
    case ShapeKind::Triangle:
    case ShapeKind::Polyline:
        rec.polygon = g.vertices;
        return polylineCurve(g, rec.polygon, g.closed);
    case ShapeKind::Freeform:
        return fit.curve;
    }
    return fit.curve;
}

// G for recognition: the plane, length and speed of strokeGeometry(fit), with the points resampled at
// the spacing of RecognizeOptions::sampleSpacing and the corners detected again on them (thesis
// §4.1.1 features, default options), so that neither the points nor the corners depend on how
// densely the pen sampled. Returns the number of corners.
static int recognitionGeometry(const FitResult& fit, const RecognizeOptions& o, StrokeGeometry& g)
{
    g = strokeGeometry(fit);
    if (o.sampleSpacing <= 0.0) return static_cast<int>(fit.corners.size());
    const ConditionedStroke rs = uniformResample(fit.conditioned, o.sampleSpacing * curveExtent(fit.conditioned.points, g.closed));
    g.extent = rs.extent;
    const std::vector<int> corner = detectCorners(rs, computeFeatures(rs));
    g.points.clear();
    for (const auto& p : rs.points) g.points.emplace_back((p - g.origin).dot(g.axisU), (p - g.origin).dot(g.axisV));
    g.vertexIndex.clear();
    if (!g.closed) g.vertexIndex.push_back(0);
    for (int k : corner) g.vertexIndex.push_back(k);
    if (!g.closed) g.vertexIndex.push_back(static_cast<int>(g.points.size()) - 1);
    g.vertices.clear();
    for (int k : g.vertexIndex) g.vertices.push_back(g.points[k]);
    return static_cast<int>(corner.size());
}

Recognition recognizeShape(const FitResult& fit, const RecognizeOptions& o)
{
    Recognition rec;
    const int corners = recognitionGeometry(fit, o, rec.geometry);
    const StrokeGeometry& g = rec.geometry;
    const double sigma = o.residualScale * g.extent;
    auto add = [&](ShapeKind k, double s) { rec.candidates.push_back({k, std::clamp(s, 0.0, 1.0)}); };

    rec.line = fitLine(g.points);
    rec.circle = fitCircle(g.points);
    if (!g.closed && corners == 0) {
        const double chord = (g.points.back() - g.points.front()).norm();
        add(ShapeKind::Line, score(rec.line.maxResidual, sigma) * std::min(1.0, chord / std::max(g.length, 1e-300)));
        if (rec.circle.valid) {
            const double turn = std::abs(sweep(g.points, rec.circle.center));
            // Nearly straight arcs are lines; arcs past 330 degrees are circles not quite closed.
            const double bend = std::min(1.0, turn / (kPi / 4)) * (turn <= 330.0 / 180.0 * kPi ? 1.0 : 0.5);
            add(ShapeKind::Arc, score(rec.circle.maxResidual, sigma) * bend);
        }
    }
    if (g.closed) rec.ellipse = fitEllipse(g.points);
    // Every stroke's polygon is refined, an open one without corners too: a fast V or check whose
    // bottom the hand rounded off has no sharp corner, but its farthest point from the chord turns
    // it by far more than minCornerTurn, and the two sides fit it where no arc does.
    // The residual of a loop's polygon (infinite without one), for the round shapes' corner test.
    double loopPolygonResidual = std::numeric_limits<double>::infinity();
    double roundedLoopResidual = std::numeric_limits<double>::infinity();
    const std::vector<int> detectedCorners = g.closed ? g.vertexIndex : std::vector<int>{};
    const int sameCorner = o.sampleSpacing > 0.0 ? 2 : 0;
    const int inserted =
        refineVertices(rec.geometry, o.vertexInsertion * sigma, o.minCornerTurn, o.cornerLeg * g.extent,
                       o.collinearAngle, o.shortEdge * g.extent, sameCorner, o.straightLegs);
    relocateVertices(rec.geometry, o.relocateRounds, o.relocateTrim, o.collinearAngle, o.relocateShift * g.extent,
                     detectedCorners, sameCorner);
    if (g.vertices.size() >= 3u) {
        // The better of the polygon through the samples where the stroke turned and the polygon
        // whose sides are lines fitted to the edges (edgeLineVertices: rounded, overshot or hooked
        // corners); the recognized polygon has those vertices.
        const auto fitPolygon = [&](const StrokeGeometry& h, std::vector<Point2>& best) {
            const std::vector<Point2> lines = edgeLineVertices(h, o.edgeTrim, o.collinearAngle, o.shortEdge * h.extent);
            const double atSamples = polylineResidual(h.points, h.vertices, h.closed);
            const double atLines = polylineResidual(h.points, lines, h.closed);
            best = atLines < atSamples ? lines : h.vertices;
            return std::min(atSamples, atLines);
        };
        std::vector<Point2> polygon;
        double residual = fitPolygon(g, polygon);
        // The simplest polygon that fits: a loop's vertex goes while the polygon without it still
        // lies within vertexInsertion of every sample, the distance at which refineVertices would
        // have inserted a vertex (typically a second vertex beside the seam, where the hand stopped
        // short of the first corner or went on past it).
        for (bool dropped = true; dropped && g.closed && g.vertexIndex.size() > 3u;) {
            dropped = false;
            double bestResidual = o.vertexInsertion * sigma;
            StrokeGeometry best;
            std::vector<Point2> bestPolygon;
            for (size_t v = 0; v < g.vertexIndex.size(); ++v) {
                StrokeGeometry h = g;
                h.vertexIndex.erase(h.vertexIndex.begin() + static_cast<long>(v));
                h.vertices.erase(h.vertices.begin() + static_cast<long>(v));
                std::vector<Point2> hp;
                const double r = fitPolygon(h, hp);
                if (r <= bestResidual) {
                    bestResidual = r;
                    best = std::move(h);
                    bestPolygon = std::move(hp);
                    dropped = true;
                }
            }
            if (dropped) {
                rec.geometry = std::move(best);
                polygon = std::move(bestPolygon);
                residual = bestResidual;
            }
        }
        rec.geometry.vertices = polygon;
        // Vertices the corner detector did not see are the recognizer's guesses: one is expected on
        // a loop (its seam, and the vertex opposite when it has no corner), more mean the polygon
        // is being fitted to a curve (a brace's curls, a circle's arcs). Unless, on a loop, the
        // polygon lies closer to the stroke than the circle and the ellipse do: then the curve it
        // would be approximating is not there (a rectangle whose corners the hand, or the fitter's
        // smoothing, rounded off beyond the corner detector's sharpness test; a circle's inscribed
        // square misses it by 0.29 radius, a fitted circle by the pen's noise).
        double smooth = std::numeric_limits<double>::infinity();
        if (g.closed && rec.circle.valid) smooth = std::min(smooth, rec.circle.maxResidual);
        if (g.closed && rec.ellipse.valid) smooth = std::min(smooth, rec.ellipse.maxResidual);
        // The same on an open stroke against an arc that would be chosen over freeform (a bracket
        // whose corners the hand rounded off); a curve no arc fits (a pigtail, a question mark)
        // keeps its guessed vertices against it.
        bool arcCompetes = false;
        for (const ShapeCandidate& c : rec.candidates) arcCompetes = arcCompetes || (c.kind == ShapeKind::Arc && c.score >= o.freeformScore);
        if (!g.closed && arcCompetes) smooth = std::min(smooth, rec.circle.maxResidual);
        const bool polygonFitsBetter = (g.closed || arcCompetes) && residual < smooth;
        loopPolygonResidual = g.closed ? residual : loopPolygonResidual;
        const int guessed = polygonFitsBetter ? 0 : std::max(0, inserted - (g.closed ? 2 : 0));
        const double fitScore = score(residual, sigma) * std::pow(o.guessedVertex, guessed);
        if (g.closed && g.vertices.size() == 3) {
            add(ShapeKind::Triangle, fitScore);
        } else if (g.closed && g.vertices.size() == 4) {
            const QuadShape q = classifyQuad(g.vertices, o);
            // Each regular quadrilateral scores by how closely the stroke follows that shape itself
            // (the regularized polygon, the same residual scale): a hand's rectangle is a quad
            // whose angles stray by 7 degrees at the median and 15 at the 95th percentile
            // (development rectangles), and a few of them more; a yes/no test at a fixed angle
            // dropped those to "polyline" however well the rectangle fitted.
            const double guess = std::pow(o.guessedVertex, guessed);
            const auto ideal = [&](const std::vector<Point2>& shape) { return score(polylineResidual(g.points, shape, true), sigma) * guess; };
            // A rectangle or square whose rounded-corner form (cornerRounding) fits closer than the
            // round shapes do has no guessed vertices held against it: the curve its corners were
            // guessed on is its own rounded corners.
            const auto rectangular = [&](bool square) {
                const double sharp = ideal(regularRectangle(g.vertices, square));
                if (o.cornerRounding <= 0.0) return sharp;
                const double rounded = roundedRectangleResidual(g.points, g.vertices, square, o.cornerRounding);
                roundedLoopResidual = std::min(roundedLoopResidual, rounded);
                return std::max(sharp, score(rounded, sigma) * (rounded < smooth ? 1.0 : guess));
            };
            // The orientation rule of ShapeKind: square on its sides, diamond on a corner; a shape
            // with equal sides is reported as a square rather than a rectangle.
            add(ShapeKind::Square, rectangular(true) * (q.axisAligned || !q.right ? 1.0 : 0.5));
            // A skewed, sheared or tapered rectangle (looseQuad): the quad itself, scaled down.
            const double roundedQuad = o.cornerRounding > 0.0
                                           ? roundedPolygonResidual(g.points, g.vertices, o.cornerRounding)
                                           : std::numeric_limits<double>::infinity();
            roundedLoopResidual = std::min(roundedLoopResidual, roundedQuad);
            const bool loose =
                o.looseQuad > 0.0 && !q.equal && q.convex && q.smallestAngle >= kLooseQuadAngle &&
                (detectedVertices(g.vertexIndex, detectedCorners, static_cast<int>(g.points.size()), sameCorner) >= 3 ||
                 roundedQuad < o.roundedSides * smooth);
            const double looseScore = loose ? score(std::min(residual, roundedQuad), sigma) * o.looseQuad : 0.0;
            add(ShapeKind::Rectangle, std::max(rectangular(false) * (q.equal ? 0.7 : 1.0), looseScore));
            // A diamond is a rhombus (equal sides, QuadShape::equal): regularDiamond keeps only the
            // diagonals' directions and half-lengths, so a kite or trapezoid can lie close to it.
            add(ShapeKind::Diamond, ideal(regularDiamond(g.vertices)) * (q.axisAligned ? 0.5 : 1.0) * (q.equal ? 1.0 : 0.4));
            add(ShapeKind::Polyline, fitScore * 0.5);
        } else {
            add(ShapeKind::Polyline, fitScore);
        }
    }
    if (g.closed) {
        // Corners count against a round loop only where the polygon through them lies closer to
        // the stroke than the circle or ellipse does. The corner detector reads turning angles
        // over a few samples, and the pointer's pixel grid, coarse in plane units in a small
        // window, turns a drawn circle's samples by as much as a corner there: a circle whose
        // inscribed polygon misses it by more than its own fit does is a circle with a jittered
        // outline, whatever the window's size.
        const auto cornered = [&](double smoothResidual) {
            return (corners >= 2 && loopPolygonResidual < smoothResidual) ||
                           roundedLoopResidual < o.roundedSides * smoothResidual
                       ? 0.5
                       : 1.0;
        };
        const double roundness = rec.ellipse.valid ? rec.ellipse.a / std::max(rec.ellipse.b, 1e-300) : 1.0;
        if (rec.circle.valid) add(ShapeKind::Circle, score(rec.circle.maxResidual, sigma) * cornered(rec.circle.maxResidual));
        if (rec.ellipse.valid) {
            // A circle is an ellipse too; the ellipse is the better answer only when elongated.
            add(ShapeKind::Ellipse, score(rec.ellipse.maxResidual, sigma) * std::clamp((roundness - 1.0) / 0.2, 0.3, 1.0) *
                                        cornered(rec.ellipse.maxResidual));
        }
    }
    add(ShapeKind::Freeform, o.freeformScore);
    std::stable_sort(rec.candidates.begin(), rec.candidates.end(),
                     [](const ShapeCandidate& a, const ShapeCandidate& b) { return a.score > b.score; });
    rec.kind = rec.candidates.front().kind;

    if (!o.regularize) {
        rec.regularized = fit.curve;
        return rec;
    }
    rec.regularized = regularize(rec, fit, rec.kind);
    return rec;
}

}  // namespace sculptline::solvers::stroke

namespace sculptline::solvers::stroke {

namespace {

// RecognizeOptions::nearLoopTurn: an open stroke turning most of the way round whose end heads for
// its start, not far off (a figure the hand stopped short of closing on its last side).
bool nearlyClosed(const StrokeGeometry& g, double turn, const RecognizeOptions& o)
{
    const auto& q = g.points;
    const int n = static_cast<int>(q.size());
    if (o.nearLoopTurn <= 0.0 || turn < o.nearLoopTurn || turn >= o.maxLoopTurn || n < 3 || !(g.extent > 0.0)) return false;
    const Point2 gap = q.front() - q.back();
    if (gap.norm() > o.nearLoopGap * g.length) return false;
    int j = n - 1;  // the stroke's heading over the last tenth of its extent
    while (j > 0 && (q[j] - q[n - 1]).norm() < 0.1 * g.extent) --j;
    const Point2 heading = q[n - 1] - q[j];
    const double off = std::atan2(std::abs(heading.x() * gap.y() - heading.y() * gap.x()), heading.dot(gap));
    return off <= o.nearLoopHeading;
}

}  // namespace

StrokeRecognition recognizeStroke(const Stroke& stroke, const FitOptions& fitOptions, const RecognizeOptions& options)
{
    StrokeRecognition out{fitStroke(stroke, fitOptions), {}};
    const ConditionedStroke& cs = out.fit.conditioned;
    if (cs.closed && fitOptions.conditioning.closure == Closure::Auto && cs.size() > 1) {
        auto path = [&](int from, int to) {
            double l = 0;
            for (int i = from; i < to; ++i) l += (stroke.points[i + 1] - stroke.points[i]).norm();
            return l;
        };
        const int last = static_cast<int>(stroke.points.size()) - 1;
        const double trimmed = path(0, cs.source.front()) + path(cs.source.back(), last);
        // How far the trimmed ink at either end reaches from the loop that was kept.
        auto reach = [&](int from, int to) {
            double far = 0.0;
            for (int i = from; i <= to; ++i) {
                double near = std::numeric_limits<double>::infinity();
                for (int k = 0; k < cs.size(); ++k) {
                    const Eigen::Vector3d& a = cs.points[k];
                    const Eigen::Vector3d& b = cs.points[(k + 1) % cs.size()];
                    const Eigen::Vector3d ab = b - a;
                    const double t = ab.squaredNorm() > 0 ? std::clamp((stroke.points[i] - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
                    near = std::min(near, (a + t * ab - stroke.points[i]).norm());
                }
                far = std::max(far, near);
            }
            return far;
        };
        // The stroke's direction leaving the seam at its head and arriving at it at its tail (over a
        // twentieth of the extent): a loop overshot along itself arrives the way it left; a stroke
        // crossing itself meets its own path at an angle.
        auto direction = [&](int at, int step) {
            int j = at;
            while (j + step >= 0 && j + step <= last && (stroke.points[j] - stroke.points[at]).norm() < 0.05 * cs.extent) j += step;
            return Eigen::Vector3d(step * (stroke.points[j] - stroke.points[at]));
        };
        const Eigen::Vector3d leaves = direction(cs.source.front(), 1), arrives = direction(cs.source.back(), -1);
        const double meetAngle = std::atan2(leaves.cross(arrives).norm(), leaves.dot(arrives));
        const bool crossing = options.crossingTail > 0.0 && cs.source.front() > 0 && cs.source.back() < last && meetAngle > kPi / 4 &&
                              std::min(reach(0, cs.source.front() - 1), reach(cs.source.back() + 1, last)) > options.crossingTail * cs.extent;
        if (trimmed > options.maxOvershoot * cs.length() || crossing) {
            FitOptions open = fitOptions;
            open.conditioning.closure = Closure::Open;
            out.fit = fitStroke(stroke, open);
        }
    }
    out.recognition = recognizeShape(out.fit, options);
    const Recognition& r = out.recognition;
    if (!r.geometry.closed && fitOptions.conditioning.closure == Closure::Auto && r.circle.valid) {
        const double turn = std::abs(sweep(r.geometry.points, r.circle.center));
        if ((turn >= options.minLoopTurn && turn < options.maxLoopTurn) || nearlyClosed(r.geometry, turn, options)) {
            FitOptions closed = fitOptions;
            closed.conditioning.closure = Closure::Closed;
            StrokeRecognition loop{fitStroke(stroke, closed), {}};
            loop.recognition = recognizeShape(loop.fit, options);
            // A closing that explains nothing is undone: the open reading stays where the closed one
            // is freeform and the open one a shape. On the development subjects as drawn this changes
            // nothing; on their perturbed copies (unistroke-report --perturb-dev) it keeps sheared
            // arrows (98.7 -> 100 %) and overshot checks, x's and delete marks open, and costs one
            // question mark (s06 fast 9, a sparse hook read open as a three-vertex polyline) in two
            // of 33 perturbations. The rule closing the stroke is unchanged, so no option was re-chosen.
            if (!(loop.recognition.kind == ShapeKind::Freeform && r.kind != ShapeKind::Freeform)) out = std::move(loop);
        }
    }
    return out;
}

Curve3d regularizeAs(const Recognition& recognition, const FitResult& fit, ShapeKind kind)
{
    const bool candidate = std::any_of(recognition.candidates.begin(), recognition.candidates.end(),
                                       [kind](const ShapeCandidate& c) { return c.kind == kind; });
    if (!candidate) throw std::invalid_argument(std::string("shape: ") + shapeName(kind) + " is not a candidate of this stroke");
    Recognition copy = recognition;
    return regularize(copy, fit, kind);
}

}  // namespace sculptline::solvers::stroke
