#include "solvers/stroke/composite.h"

#include "solvers/math_constants.h"

#include <algorithm>
#include <cmath>

namespace sculptline::solvers::stroke {
namespace {


// The current stroke's points in the previous stroke's plane coordinates.
std::vector<Point2> inFrameOf(const StrokeGeometry& frame, const StrokeGeometry& g)
{
    std::vector<Point2> out;
    for (const auto& p : g.points) {
        const Eigen::Vector3d x = g.origin + p.x() * g.axisU + p.y() * g.axisV;
        out.emplace_back((x - frame.origin).dot(frame.axisU), (x - frame.origin).dot(frame.axisV));
    }
    return out;
}

double cross(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }

bool segmentsCross(const Point2& a, const Point2& b, const Point2& c, const Point2& d)
{
    const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
}

// Whether the polylines cross other than at an open stroke's end: a crossing within `endZone` of
// an end of an open polyline is the pen landing on (or overshooting) the other stroke, which is
// touching, not overlapping (an edge drawn from a profile's corner crosses it by the jitter).
bool polylinesCross(const std::vector<Point2>& p, bool pClosed, const std::vector<Point2>& q, bool qClosed, double endZone)
{
    const size_t pe = pClosed ? p.size() : p.size() - 1, qe = qClosed ? q.size() : q.size() - 1;
    auto nearEnd = [&](const Point2& x) {
        const double z2 = endZone * endZone;
        return (!pClosed && ((x - p.front()).squaredNorm() <= z2 || (x - p.back()).squaredNorm() <= z2)) ||
               (!qClosed && ((x - q.front()).squaredNorm() <= z2 || (x - q.back()).squaredNorm() <= z2));
    };
    for (size_t i = 0; i < pe; ++i) {
        const Point2 &a = p[i], &b = p[(i + 1) % p.size()];
        for (size_t j = 0; j < qe; ++j) {
            const Point2 &c = q[j], &d = q[(j + 1) % q.size()];
            if (!segmentsCross(a, b, c, d)) continue;
            const double t = cross(c - a, d - c) / cross(b - a, d - c);  // a + t (b - a) on line cd
            if (!nearEnd(a + t * (b - a))) return true;
        }
    }
    return false;
}

// Crossing-number test (Jordan curve theorem) against the closed polygon of `poly`.
bool insidePolygon(const Point2& x, const std::vector<Point2>& poly)
{
    bool in = false;
    for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const Point2 &a = poly[i], &b = poly[j];
        if ((a.y() > x.y()) != (b.y() > x.y()) && x.x() < (b.x() - a.x()) * (x.y() - a.y()) / (b.y() - a.y()) + a.x()) {
            in = !in;
        }
    }
    return in;
}

double minDistance(const std::vector<Point2>& p, const std::vector<Point2>& q)
{
    double best = 1e300;
    for (const auto& a : p)
        for (const auto& b : q) best = std::min(best, (a - b).squaredNorm());
    return std::sqrt(best);
}

bool lineLike(const Recognition& r) { return r.kind == ShapeKind::Line; }

bool has(const std::vector<Relation>& rel, Relation r) { return std::find(rel.begin(), rel.end(), r) != rel.end(); }

bool polygonKind(ShapeKind k)
{
    return k == ShapeKind::Triangle || k == ShapeKind::Square || k == ShapeKind::Rectangle || k == ShapeKind::Diamond ||
           k == ShapeKind::Polyline;
}

Point2 centroid(const std::vector<Point2>& pts)
{
    Point2 c = Point2::Zero();
    for (const auto& p : pts) c += p;
    return c / static_cast<double>(std::max<size_t>(1, pts.size()));
}

}  // namespace

const char* relationName(Relation r)
{
    switch (r) {
    case Relation::Parallel: return "parallel";
    case Relation::Perpendicular: return "perpendicular";
    case Relation::Touching: return "touching";
    case Relation::Overlapping: return "overlapping";
    case Relation::Inside: return "inside";
    case Relation::Disjoint: return "disjoint";
    }
    return "disjoint";
}

const char* compositeName(CompositeKind k)
{
    switch (k) {
    case CompositeKind::None: return "none";
    case CompositeKind::Prism: return "prism";
    case CompositeKind::Cylinder: return "cylinder";
    case CompositeKind::Cone: return "cone";
    case CompositeKind::Extrusion: return "extrusion";
    case CompositeKind::Skinning: return "skinning";
    case CompositeKind::PolygonVolume: return "polygon_volume";
    }
    return "none";
}

std::vector<Relation> relate(const Recognition& previous, const Recognition& current, const RelationOptions& o)
{
    std::vector<Relation> rel;
    const StrokeGeometry& pg = previous.geometry;
    const std::vector<Point2> q = inFrameOf(pg, current.geometry);
    const Point2 pd = pg.points.back() - pg.points.front(), qd = q.back() - q.front();
    if (lineLike(previous) && lineLike(current) && pd.norm() > 0 && qd.norm() > 0) {
        const double c = std::abs(pd.normalized().dot(qd.normalized()));
        if (c >= std::cos(o.angle)) rel.push_back(Relation::Parallel);
        if (c <= std::sin(o.angle)) rel.push_back(Relation::Perpendicular);
    }
    const double touch = o.touch * std::min(pg.extent, current.geometry.extent);
    if (polylinesCross(pg.points, pg.closed, q, current.geometry.closed, touch)) {
        rel.push_back(Relation::Overlapping);
    } else if (pg.closed && std::all_of(q.begin(), q.end(), [&](const Point2& x) { return insidePolygon(x, pg.points); })) {
        rel.push_back(Relation::Inside);
    } else if (minDistance(pg.points, q) <= touch) {
        rel.push_back(Relation::Touching);
    } else {
        rel.push_back(Relation::Disjoint);
    }
    return rel;
}

CompositeKind composeShapes(const Recognition& previous, const Recognition& current, const std::vector<Relation>& rel)
{
    const ShapeKind p = previous.kind, c = current.kind;
    const bool round = p == ShapeKind::Circle || p == ShapeKind::Ellipse;
    const bool closedProfile = previous.geometry.closed;
    if (c == ShapeKind::Line) {
        if (p == ShapeKind::Triangle && has(rel, Relation::Overlapping)) return CompositeKind::Prism;
        if (round && has(rel, Relation::Inside)) return CompositeKind::Cone;
        if (round && (has(rel, Relation::Touching) || has(rel, Relation::Overlapping))) {
            // Fig. 3-4 (b) vs (c): the line starts on the circle and leaves it (cylinder) or starts
            // within it (cone: the apex line rises from inside the base).
            const std::vector<Point2> q = inFrameOf(previous.geometry, current.geometry);
            const double r0 = (q.front() - previous.circle.center).norm(), r1 = (q.back() - previous.circle.center).norm();
            const double rin = std::min(r0, r1), rad = previous.circle.radius;
            return rin < 0.7 * rad ? CompositeKind::Cone : CompositeKind::Cylinder;
        }
        if (closedProfile && (has(rel, Relation::Touching) || has(rel, Relation::Overlapping))) return CompositeKind::Extrusion;
    }
    const bool openCurves = !previous.geometry.closed && !current.geometry.closed && p != ShapeKind::Line &&
                            c != ShapeKind::Line;
    if (openCurves && has(rel, Relation::Disjoint)) {
        // Side by side: chord directions agree within 30 degrees (either drawing direction).
        const auto& a = previous.geometry;
        const std::vector<Point2> q = inFrameOf(a, current.geometry);
        const Point2 da = a.points.back() - a.points.front(), db = q.back() - q.front();
        if (da.norm() > 0 && db.norm() > 0 && std::abs(da.normalized().dot(db.normalized())) >= std::cos(kPi / 6)) {
            return CompositeKind::Skinning;
        }
    }
    return CompositeKind::None;
}

CompositeKind composeThree(const Recognition& first, const Recognition& second, const Recognition& third,
                           const VolumeOptions& o)
{
    const StrokeGeometry& base = first.geometry;
    if (!polygonKind(first.kind) || !base.closed || second.kind != ShapeKind::Line) return CompositeKind::None;
    // The edge, oriented from its end on the profile to its far end (in the profile's plane frame):
    // it must start on the profile (the pair's touching of Fig. 3-4) and leave it.
    const double touch = RelationOptions{}.touch * base.extent;
    const std::vector<Point2> edge = inFrameOf(base, second.geometry);
    Point2 from = edge.front(), to = edge.back();
    if (minDistance(base.points, {from}) > minDistance(base.points, {to})) std::swap(from, to);
    if (minDistance(base.points, {from}) > touch || minDistance(base.points, {to}) <= touch || insidePolygon(to, base.points)) {
        return CompositeKind::None;
    }
    if (polygonKind(third.kind) && third.geometry.closed) {
        // Top face: same kind of polygon, same size, where the edge carries the profile. Squares
        // and diamonds are one shape in two orientations (ShapeKind), so either matches the other.
        const auto squareLike = [](ShapeKind k) { return k == ShapeKind::Square || k == ShapeKind::Diamond; };
        const bool sameKind = third.kind == first.kind || (squareLike(third.kind) && squareLike(first.kind));
        const double size = std::abs(third.geometry.extent - base.extent) / base.extent;
        const Point2 expected = centroid(base.points) + (to - from);
        const Point2 top = centroid(inFrameOf(base, third.geometry));
        if (sameKind && size <= o.sizeMatch && (top - expected).norm() <= o.placement * base.extent) {
            return CompositeKind::PolygonVolume;
        }
        return CompositeKind::None;
    }
    if (third.kind == ShapeKind::Line) {
        // A second lateral edge: parallel to the first, from another point of the profile.
        const std::vector<Relation> toEdge = relate(second, third), toBase = relate(first, third);
        const std::vector<Point2> q = inFrameOf(base, third.geometry);
        const double apart = std::min((q.front() - from).norm(), (q.back() - from).norm());
        if (has(toEdge, Relation::Parallel) && (has(toBase, Relation::Touching) || has(toBase, Relation::Overlapping)) &&
            !has(toEdge, Relation::Touching) && !has(toEdge, Relation::Overlapping) && apart > touch) {
            return CompositeKind::PolygonVolume;
        }
    }
    return CompositeKind::None;
}

}  // namespace sculptline::solvers::stroke
