#include "solvers/stroke/quad_shapes.h"

#include "solvers/math_constants.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sculptline::solvers::stroke::detail {
namespace {

constexpr double kQuarterTurn = kPi / 2;

}  // namespace

// Orientation of a quadrilateral's edges modulo 90 degrees (average of 4 * edge angle, so that
// opposite and adjacent edges reinforce).
double quadOrientation(const std::vector<Point2>& v)
{
    Point2 acc = Point2::Zero();
    for (size_t i = 0; i < v.size(); ++i) {
        const Point2 e = v[(i + 1) % v.size()] - v[i];
        const double a = 4.0 * angleOf(e);
        acc += e.norm() * Point2(std::cos(a), std::sin(a));
    }
    return angleOf(acc) / 4.0;
}

QuadShape classifyQuad(const std::vector<Point2>& v, const RecognizeOptions& o)
{
    QuadShape q;
    double smin = 1e300, smax = 0, ssum = 0, worstAngle = 0;
    int turns = 0;  // the sign of every vertex's turn, while they agree
    q.convex = true;
    for (size_t i = 0; i < 4; ++i) {
        const Point2 a = v[(i + 3) % 4] - v[i], b = v[(i + 1) % 4] - v[i];
        const double s = b.norm();
        smin = std::min(smin, s);
        smax = std::max(smax, s);
        ssum += s;
        const double ang = std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
        worstAngle = std::max(worstAngle, std::abs(ang - kQuarterTurn));
        q.smallestAngle = std::min(q.smallestAngle, ang);
        const double cross = a.x() * b.y() - a.y() * b.x();
        const int turn = cross > 0 ? 1 : (cross < 0 ? -1 : 0);
        if (turn == 0 || (turns != 0 && turn != turns)) q.convex = false;
        turns = turn;
    }
    q.right = worstAngle <= o.rightAngle;
    q.equal = (smax - smin) / (ssum / 4) <= o.equalSides;
    // The one orientation-dependent test of the recognizer (ShapeKind): square vs diamond is decided
    // by the sides' angle to the plane's axes, modulo 90 degrees. 0 = axis-aligned, pi/4 = on a corner.
    const double orient = std::abs(quadOrientation(v));
    q.axisAligned = orient < kPi / 8;
    return q;
}

// How many of a quad's vertices (sample indices `at`) lie within `sameCorner` samples of a corner
// the detector found (`detected`) on a loop of `n` samples (RecognizeOptions::looseQuad).
int detectedVertices(const std::vector<int>& at, const std::vector<int>& detected, int n, int sameCorner)
{
    int found = 0;
    for (int k : at) {
        bool near = false;
        for (int d : detected) {
            const int gap = std::abs(k - d);
            near = near || std::min(gap, n - gap) <= sameCorner;
        }
        found += near;
    }
    return found;
}

namespace {

// The rectangle (or square) a quad stands for: the quad's orientation, centred on its vertices'
// centroid, half-sides the vertices' mean distances from the centre along each axis.
struct RectangleFrame {
    Point2 c, ux, uy;
    double hx = 0.0, hy = 0.0;
};

RectangleFrame rectangleFrame(const std::vector<Point2>& v, bool square)
{
    const double th = quadOrientation(v);
    RectangleFrame f;
    f.ux = Point2(std::cos(th), std::sin(th));
    f.uy = Point2(-f.ux.y(), f.ux.x());
    f.c = Point2::Zero();
    for (const auto& p : v) f.c += p / 4.0;
    for (const auto& p : v) {
        f.hx += std::abs((p - f.c).dot(f.ux)) / 4.0;
        f.hy += std::abs((p - f.c).dot(f.uy)) / 4.0;
    }
    if (square) f.hx = f.hy = 0.5 * (f.hx + f.hy);
    return f;
}

}  // namespace

// Rectangle (or square) of rectangleFrame, one corner per vertex.
std::vector<Point2> regularRectangle(const std::vector<Point2>& v, bool square)
{
    const auto [c, ux, uy, hx, hy] = rectangleFrame(v, square);
    std::vector<Point2> out;
    for (const auto& p : v) {  // each vertex snaps to the corner in its quadrant: drawing order kept
        const double sx = (p - c).dot(ux) >= 0 ? 1 : -1, sy = (p - c).dot(uy) >= 0 ? 1 : -1;
        out.push_back(c + sx * hx * ux + sy * hy * uy);
    }
    return out;
}

// The largest distance of the points from the rectangle (square) of regularRectangle with its corners
// rounded by the radius, among f * its shorter half-side for f = 0, 0.05, .. maxShare, that fits
// closest (RecognizeOptions::cornerRounding). The rounded rectangle is the Minkowski sum of the
// rectangle shrunk by the radius and a disc of that radius; distances are those to its outline.
double roundedRectangleResidual(const std::vector<Point2>& pts, const std::vector<Point2>& v, bool square,
                                double maxShare)
{
    const auto [c, ux, uy, hx, hy] = rectangleFrame(v, square);
    double best = std::numeric_limits<double>::infinity();
    const int steps = static_cast<int>(std::floor(maxShare / 0.05 + 1e-9));
    for (int i = 0; i <= steps; ++i) {
        const double r = 0.05 * i * std::min(hx, hy);
        double worst = 0.0;
        for (const auto& p : pts) {
            const double qx = std::abs((p - c).dot(ux)) - (hx - r), qy = std::abs((p - c).dot(uy)) - (hy - r);
            const double outside = std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) + std::min(std::max(qx, qy), 0.0);
            worst = std::max(worst, std::abs(outside - r));
            if (worst >= best) break;
        }
        best = std::min(best, worst);
    }
    return best;
}

double roundedPolygonResidual(const std::vector<Point2>& pts, const std::vector<Point2>& v, double maxShare)
{
    const size_t m = v.size();
    if (m < 3) return std::numeric_limits<double>::infinity();
    const auto cross = [](const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); };
    double area = 0.0;
    for (size_t i = 0; i < m; ++i) area += cross(v[i], v[(i + 1) % m]);
    const double orient = area >= 0.0 ? 1.0 : -1.0;
    // Inward unit normals of the sides; a side of zero length or a reflex vertex: not convex.
    std::vector<Point2> normal(m);
    for (size_t i = 0; i < m; ++i) {
        const Point2 e = v[(i + 1) % m] - v[i];
        if (!(e.norm() > 0.0) || orient * cross(e, v[(i + 2) % m] - v[(i + 1) % m]) <= 0.0)
            return std::numeric_limits<double>::infinity();
        normal[i] = orient * Point2(-e.y(), e.x()) / e.norm();
    }
    double width = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < m; ++i) {
        double reach = 0.0;
        for (const Point2& q : v) reach = std::max(reach, (q - v[i]).dot(normal[i]));
        width = std::min(width, reach);
    }
    double best = std::numeric_limits<double>::infinity();
    const int steps = static_cast<int>(std::floor(maxShare / 0.05 + 1e-9));
    std::vector<Point2> inner(m);
    size_t far = 0;
    for (int s = 0; s <= steps; ++s) {
        const double r = 0.05 * s * 0.5 * width;
        // The polygon moved inward by r: vertex i where the offset lines of sides i-1 and i meet.
        bool valid = true;
        for (size_t i = 0; i < m && valid; ++i) {
            const size_t h = (i + m - 1) % m;
            const Point2 a = v[i] + r * normal[h], b = v[i] + r * normal[i];
            const Point2 d0 = v[i] - v[h], d1 = v[(i + 1) % m] - v[i];
            const double den = cross(d0, d1);
            if (std::abs(den) <= 1e-12 * d0.norm() * d1.norm()) {
                valid = false;
                break;
            }
            inner[i] = a + d0 * (cross(b - a, d1) / den);
        }
        // A side the offset reversed: the rounded shape is no longer this polygon's.
        for (size_t i = 0; i < m && valid; ++i)
            valid = (inner[(i + 1) % m] - inner[i]).dot(v[(i + 1) % m] - v[i]) > 0.0;
        if (!valid) break;
        // The rounded polygon is the inner one grown by r: a point's distance from its outline is
        // |signed distance from the inner polygon - r|.
        const auto distance = [&](const Point2& p) {
            double edge = std::numeric_limits<double>::infinity();
            bool inside = true;
            for (size_t i = 0; i < m; ++i) {
                const Point2 a = inner[i], ab = inner[(i + 1) % m] - a;
                const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
                edge = std::min(edge, (p - a - t * ab).norm());
                inside = inside && (p - a).dot(normal[i]) >= 0.0;
            }
            return std::abs((inside ? -edge : edge) - r);
        };
        // The point farthest at the last radius first: a radius that does not beat the best so
        // far is usually refused by it at once.
        double worst = pts.empty() ? 0.0 : distance(pts[far]);
        for (size_t k = 0; k < pts.size() && worst < best; ++k) {
            const double d = distance(pts[k]);
            if (d > worst) {
                worst = d;
                far = k;
            }
        }
        best = std::min(best, worst);
    }
    return best;
}

// Rhombus: diagonals through the centroid, perpendicular, with the measured half-lengths.
std::vector<Point2> regularDiamond(const std::vector<Point2>& v)
{
    Point2 c = Point2::Zero();
    for (const auto& p : v) c += p / 4.0;
    const Point2 d1 = (v[0] - v[2]).normalized(), d2(-d1.y(), d1.x());
    const double p = 0.5 * (v[0] - v[2]).norm(), q = 0.5 * std::abs((v[1] - v[3]).dot(d2));
    const double s = (v[1] - c).dot(d2) >= 0 ? 1 : -1;
    return {c + p * d1, c + s * q * d2, c - p * d1, c - s * q * d2};
}

}  // namespace sculptline::solvers::stroke::detail
