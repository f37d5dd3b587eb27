#include "solvers/stroke/composite.h"

#include <algorithm>
#include <cmath>

namespace sculptline::solvers::stroke {
namespace {

constexpr double kPi = 3.14159265358979323846;

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

bool polylinesCross(const std::vector<Point2>& p, bool pClosed, const std::vector<Point2>& q, bool qClosed)
{
    const size_t pe = pClosed ? p.size() : p.size() - 1, qe = qClosed ? q.size() : q.size() - 1;
    for (size_t i = 0; i < pe; ++i)
        for (size_t j = 0; j < qe; ++j)
            if (segmentsCross(p[i], p[(i + 1) % p.size()], q[j], q[(j + 1) % q.size()])) return true;
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
    if (polylinesCross(pg.points, pg.closed, q, current.geometry.closed)) {
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

}  // namespace sculptline::solvers::stroke
