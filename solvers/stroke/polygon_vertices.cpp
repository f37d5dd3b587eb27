// How a drawn polygon's vertices are found (shape_recognizer.cpp's recognizeShape): vertices
// inserted where the stroke leaves the polygon (refineVertices), sides fitted as lines
// (edgeLineVertices) and guessed vertices moved to where those sides meet (relocateVertices).
#include "solvers/stroke/polygon_vertices.h"

#include "solvers/math_constants.h"
#include "solvers/stroke/primitive_fit.h"

#include <algorithm>
#include <cmath>

namespace sculptline::solvers::stroke::detail {
namespace {

double segmentDistance(const Point2& p, const Point2& a, const Point2& b)
{
    const Point2 ab = b - a;
    const double l2 = ab.squaredNorm();
    const double t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
    return (a + t * ab - p).norm();
}

// Angle by which the path a -> k -> b turns at k (0 = straight on, pi = straight back).
double turnAt(const Point2& a, const Point2& k, const Point2& b)
{
    const Point2 u = k - a, v = b - k;
    return std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v));
}

// Angle by which the stroke turns at sample k of the edge from vertex `from` to vertex `to`, seen
// from the samples one `leg` of path length before and after it, or the edge's ends where they are
// nearer (round the seam of a loop): the turn of the edge itself there, not of its neighbours.
double localTurn(const std::vector<Point2>& pts, int k, int from, int to, double leg, bool closed)
{
    const int n = static_cast<int>(pts.size());
    const auto walk = [&](int step, int end) {
        double travelled = 0.0;
        int i = k;
        while (i != end && travelled < leg) {
            const int j = closed ? (i + step + n) % n : i + step;
            travelled += (pts[j] - pts[i]).norm();
            i = j;
        }
        return i;
    };
    return turnAt(pts[walk(-1, from)], pts[k], pts[walk(1, to)]);
}

}  // namespace

// Douglas-Peucker-like refinement of the vertex set (see RecognizeOptions::vertexInsertion): each
// point is measured against the edge between the vertices it lies between, in drawing order.
// Returns how many of the final vertices were inserted here (the corner detector did not find them).
int refineVertices(StrokeGeometry& g, double insertAbove, double minCornerTurn, double cornerLeg, double collinear,
                   double shortEdgeLength, int sameCorner, double straightLegs)
{
    auto& idx = g.vertexIndex;
    const std::vector<int> detected = idx;
    const int n = static_cast<int>(g.points.size());
    std::vector<std::pair<int, int>> curved;  // edges whose farthest point is a bend, not a corner
    for (int round = 0; round < 12; ++round) {
        if (g.closed && idx.size() < 2) {
            // Seeded seam-free: the sample farthest from the centroid, then the one farthest from
            // that (or from the one corner detected). A loop's seam is wherever the hand began,
            // often mid-side, and a vertex there makes the inserted ones miss the corners.
            Point2 from = Point2::Zero();
            if (idx.empty()) {
                for (const Point2& p : g.points) from += p;
                from /= static_cast<double>(n);
            } else {
                from = g.points[idx[0]];
            }
            int far = 0;
            for (int k = 1; k < n; ++k)
                if ((g.points[k] - from).squaredNorm() > (g.points[far] - from).squaredNorm()) far = k;
            // (Every sample at one point: the one halfway round, so that the two stay apart.)
            if (!idx.empty() && far == idx[0]) far = (idx[0] + n / 2) % n;
            idx.push_back(far);
            std::sort(idx.begin(), idx.end());
            continue;
        }
        double worst = insertAbove;
        int at = -1, from = -1, to = -1;
        const size_t edges = g.closed ? idx.size() : idx.size() - 1;
        for (size_t e = 0; e < edges; ++e) {
            const int a = idx[e], b = idx[(e + 1) % idx.size()];
            if (std::find(curved.begin(), curved.end(), std::make_pair(a, b)) != curved.end()) continue;
            for (int k = (a + 1) % n; k != b; k = (k + 1) % n) {
                const double d = segmentDistance(g.points[k], g.points[a], g.points[b]);
                if (d > worst) {
                    worst = d;
                    at = k;
                    from = a;
                    to = b;
                }
            }
        }
        if (at < 0) break;
        // A missed corner turns the pen sharply; the farthest point of a smoothly bent edge (a
        // brace's bulge, a circle's arc between two vertices) does not, and inserting it would
        // only approximate a curve by short chords. The turn is read from the edge's ends and
        // from one cornerLeg either side of the point (within the edge): seen from far edge ends
        // a rounded corner turns less than over its own legs (a square bracket's rounded corner,
        // RecognizeOptions::cornerLeg).
        const double fromEnds = turnAt(g.points[from], g.points[at], g.points[to]);
        const double fromLegs = cornerLeg > 0.0 ? localTurn(g.points, at, from, to, cornerLeg, g.closed) : 0.0;
        // A loop read as three vertices may still have missed a corner that turns less: the obtuse
        // corner of a hand's skewed or tapered rectangle turns 55-60 degrees seen from the two
        // corners beside it, as much as a circle's arc seen from its inscribed triangle's vertices.
        // It is taken as a corner where the edge is two straight sides meeting there: every sample
        // of either half within straightLegs of the insertion distance of the half's chord (an arc
        // of a third of a circle, halved, bows by 0.13 of the radius, 0.067 of the extent against
        // 0.03), both halves longer than twice the shortest edge kept (not a hook beside a
        // triangle's seam), and the turn at least 45 degrees (a circle seen from its inscribed
        // square's vertices).
        const auto straight = [&](int a, int b) {
            for (int k = (a + 1) % n; k != b; k = (k + 1) % n)
                if (segmentDistance(g.points[k], g.points[a], g.points[b]) > straightLegs * insertAbove) return false;
            return true;
        };
        const auto twoSides = [&] {
            const double shorter =
                std::min((g.points[at] - g.points[from]).norm(), (g.points[to] - g.points[at]).norm());
            return straightLegs > 0.0 && g.closed && idx.size() == 3u && std::max(fromEnds, fromLegs) >= kPi / 4 &&
                   shorter >= 2.0 * shortEdgeLength && straight(from, at) && straight(at, to);
        };
        if (std::max(fromEnds, fromLegs) < minCornerTurn && !twoSides()) {
            curved.emplace_back(from, to);
            continue;
        }
        idx.insert(std::upper_bound(idx.begin(), idx.end(), at), at);
    }
    // Drop the vertex that turns least while it is nearly collinear, or while it ends an edge
    // shorter than shortEdge (two detections of one corner, e.g. beside a loop's seam).
    for (bool removed = true; removed && idx.size() > (g.closed ? 3u : 2u);) {
        removed = false;
        const size_t m = idx.size();
        int weakest = -1;
        double weakestTurn = 1e300;
        bool mustGo = false;
        for (size_t v = g.closed ? 0 : 1; v < (g.closed ? m : m - 1); ++v) {
            const Point2 a = g.points[idx[v]] - g.points[idx[(v + m - 1) % m]];
            const Point2 b = g.points[idx[(v + 1) % m]] - g.points[idx[v]];
            const double turn = std::atan2(std::abs(a.x() * b.y() - a.y() * b.x()), a.dot(b));
            const bool shortEdge = std::min(a.norm(), b.norm()) < shortEdgeLength;
            if ((turn < collinear || shortEdge) && turn < weakestTurn) {
                weakest = static_cast<int>(v);
                weakestTurn = turn;
                mustGo = true;
            }
        }
        if (mustGo) {
            idx.erase(idx.begin() + weakest);
            removed = true;
        }
    }
    g.vertices.clear();
    for (int k : idx) g.vertices.push_back(g.points[k]);
    // A vertex within `sameCorner` samples of a detected corner is that corner, located at the
    // sample beside it (the farthest point and the sharpest turn of one rounded corner differ by a
    // sample or two, and which of them the detector or the refinement picks varies with noise).
    int inserted = 0;
    for (int k : idx) {
        bool near = false;
        for (int d : detected) {
            const int gap = std::abs(k - d);
            near = near || (g.closed ? std::min(gap, n - gap) : gap) <= sameCorner;
        }
        inserted += !near;
    }
    return inserted;
}

// The polygon's vertices as the intersections of straight lines fitted (total least squares) to the
// middle of each edge, the samples within `trim` of an edge's length from either end left out: a
// hand rounds a corner off, overshoots it or hooks at it, and the sample where it turned most lies
// inside or outside the corner the sides meet at. The sides are what the hand drew straight
// (Douglas and Peucker's split points are samples too; fitting the pieces is the usual second step,
// e.g. Sezgin et al. 2001 §3). An open stroke's ends are its end samples projected onto the end
// edges' lines. A vertex stays at its sample where the two lines are within `minAngle` of parallel
// or meet farther than `maxShift` from it.
std::vector<Point2> edgeLineVertices(const StrokeGeometry& g, double trim, double minAngle, double maxShift)
{
    const auto& idx = g.vertexIndex;
    const int n = static_cast<int>(g.points.size());
    const size_t m = idx.size();
    const size_t edges = g.closed ? m : m - 1;
    std::vector<LineFit> lines;
    for (size_t e = 0; e < edges; ++e) {
        const int a = idx[e], b = idx[(e + 1) % m];
        const int count = ((b - a) % n + n) % n;  // samples a..b along the stroke, cyclically
        const int skip = static_cast<int>(std::floor(trim * count));
        std::vector<Point2> mid;
        for (int k = skip; k <= count - skip; ++k) mid.push_back(g.points[(a + k) % n]);
        if (mid.size() < 2) mid = {g.points[a], g.points[b]};
        lines.push_back(fitLine(mid));
    }
    std::vector<Point2> v = g.vertices;
    const double sinMin = std::sin(minAngle);
    for (size_t i = 0; i < m; ++i) {
        const bool end = !g.closed && (i == 0 || i == m - 1);
        if (end) {
            const LineFit& l = lines[i == 0 ? 0 : edges - 1];
            v[i] = l.point + l.direction * (g.vertices[i] - l.point).dot(l.direction);
            continue;
        }
        const LineFit& l0 = lines[(i + edges - 1) % edges];
        const LineFit& l1 = lines[i % edges];
        const double cross = l0.direction.x() * l1.direction.y() - l0.direction.y() * l1.direction.x();
        if (std::abs(cross) < sinMin) continue;
        // l0.point + s d0 = l1.point + t d1
        const Point2 w = l1.point - l0.point;
        const double sParam = (w.x() * l1.direction.y() - w.y() * l1.direction.x()) / cross;
        const Point2 x = l0.point + sParam * l0.direction;
        if ((x - g.vertices[i]).norm() <= maxShift) v[i] = x;
    }
    return v;
}

// A loop's vertices moved to where its sides meet: each vertex goes to the sample nearest the
// intersection of the lines fitted to its two edges (edgeLineVertices), searched between its
// neighbours, and the lines are fitted again on the new edges, for at most `rounds` rounds or until
// no vertex moves. refineVertices places a vertex at the sample farthest from the chord between two
// others; on a corner the hand rounded off, that is where the arc's tangent is parallel to the
// chord, which lies toward the longer side when the chord is a rectangle's diagonal. The edge on
// either side then takes in part of the arc, its fitted line tilts, and the polygon comes out
// skewed (a rounded rectangle whose end ran on past its start read as an ellipse). Fitting the
// sides and splitting the samples between them in turn is the usual alternation of piecewise line
// fitting. A vertex whose lines are nearly parallel or meet farther than `maxShift` stays, and so
// does one within `sameCorner` samples of a corner the detector found (`detected`): the pen turned
// sharply there, and the polygon's tests count it as detected.
void relocateVertices(StrokeGeometry& g, int rounds, double trim, double minAngle, double maxShift,
                      const std::vector<int>& detected, int sameCorner)
{
    auto& idx = g.vertexIndex;
    const int n = static_cast<int>(g.points.size());
    const size_t m = idx.size();
    if (!g.closed || m < 3u || m > 4u || rounds <= 0) return;
    for (int round = 0; round < rounds; ++round) {
        const std::vector<Point2> meet = edgeLineVertices(g, trim, minAngle, maxShift);
        bool moved = false;
        for (size_t i = 0; i < m; ++i) {
            if (meet[i] == g.vertices[i]) continue;  // (kept at its sample)
            bool atCorner = false;
            for (int d : detected) {
                const int gap = std::abs(idx[i] - d);
                atCorner = atCorner || std::min(gap, n - gap) <= sameCorner;
            }
            if (atCorner) continue;
            const int lo = idx[(i + m - 1) % m], hi = idx[(i + 1) % m];
            int best = idx[i];
            for (int k = (lo + 1) % n; k != hi; k = (k + 1) % n)
                if ((g.points[k] - meet[i]).squaredNorm() < (g.points[best] - meet[i]).squaredNorm()) best = k;
            if (best != idx[i]) {
                idx[i] = best;
                g.vertices[i] = g.points[best];
                moved = true;
            }
        }
        if (!moved) break;
    }
    // A vertex moves only between its neighbours, so the cycle's order holds; one that crossed the
    // seam is now the lowest index: rotate it to the front, the indices ascending again.
    const long first = std::min_element(idx.begin(), idx.end()) - idx.begin();
    std::rotate(idx.begin(), idx.begin() + first, idx.end());
    std::rotate(g.vertices.begin(), g.vertices.begin() + first, g.vertices.end());
}

}  // namespace sculptline::solvers::stroke::detail
