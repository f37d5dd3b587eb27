#include "solvers/incidence/curve_crossings.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/knot_algorithms.h"
#include "solvers/incidence/bernstein.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace sculptline::solvers::incidence {

namespace {

// Subdivision stops when both boxes are this small (relative to the curves' size): Newton does the rest.
constexpr double kBoxRelative = 1e-7;
// Newton's result is a crossing when the curves are this close there (relative to their size).
constexpr double kMeetRelative = 1e-10;
// A touch Newton cannot converge on is still kept when the candidate is this close.
constexpr double kTouchRelative = 1e-8;
constexpr double kMergeRelative = 1e-7;
constexpr size_t kMaxCandidates = 1000;

struct Piece {
    Eigen::VectorXd x, y;
    double t0, t1;
    Eigen::AlignedBox2d box() const
    {
        Eigen::AlignedBox2d b;
        b.extend(Eigen::Vector2d(x.minCoeff(), y.minCoeff()));
        b.extend(Eigen::Vector2d(x.maxCoeff(), y.maxCoeff()));
        return b;
    }
    std::pair<Piece, Piece> split() const
    {
        Piece l, r;
        bernsteinSplit(x, 0.5, l.x, r.x);
        bernsteinSplit(y, 0.5, l.y, r.y);
        const double m = 0.5 * (t0 + t1);
        l.t0 = t0;
        l.t1 = m;
        r.t0 = m;
        r.t1 = t1;
        return {l, r};
    }
};

std::vector<Piece> bezierPieces(const Curve2d& g)
{
    if (g.isRational()) throw GeometryError("domain curve: must be non-rational");
    ControlMatrix rows(g.pointCount(), 2);
    for (int i = 0; i < g.pointCount(); ++i) rows.row(i) = g.points()[i].transpose();
    std::vector<double> bounds{g.domainStart()};
    for (double t : interiorBreakpoints(g.degree(), g.knots())) bounds.push_back(t);
    bounds.push_back(g.domainEnd());
    std::vector<Piece> pieces;
    for (size_t s = 0; s + 1 < bounds.size(); ++s) {
        const ControlMatrix b = extractSegment(g.degree(), g.knots(), rows, bounds[s], bounds[s + 1]).points;
        pieces.push_back({b.col(0), b.col(1), bounds[s], bounds[s + 1]});
    }
    return pieces;
}

void subdivide(const Piece& a, const Piece& b, double small, int depth, std::vector<Eigen::Vector2d>& candidates)
{
    if (candidates.size() >= kMaxCandidates) return;
    const Eigen::AlignedBox2d ba = a.box(), bb = b.box();
    if (!ba.intersects(bb)) return;
    const double da = ba.diagonal().norm(), db = bb.diagonal().norm();
    if ((da <= small && db <= small) || depth >= 60) {
        candidates.emplace_back(0.5 * (a.t0 + a.t1), 0.5 * (b.t0 + b.t1));
        return;
    }
    if (da >= db) {
        const auto [l, r] = a.split();
        subdivide(l, b, small, depth + 1, candidates);
        subdivide(r, b, small, depth + 1, candidates);
    } else {
        const auto [l, r] = b.split();
        subdivide(a, l, small, depth + 1, candidates);
        subdivide(a, r, small, depth + 1, candidates);
    }
}

}  // namespace

std::vector<Crossing> curveCrossings(const Curve2d& first, const Curve2d& second)
{
    const std::vector<Piece> pa = bezierPieces(first), pb = bezierPieces(second);
    const double size = std::max({first.controlSize(), second.controlSize(), 1e-300});
    std::vector<Eigen::Vector2d> candidates;
    for (const Piece& a : pa)
        for (const Piece& b : pb) subdivide(a, b, kBoxRelative * size, 0, candidates);

    std::vector<Crossing> found;
    for (const Eigen::Vector2d& start : candidates) {
        double t1 = start.x(), t2 = start.y();
        for (int it = 0; it < 30; ++it) {
            const auto d1 = first.derivatives(t1, 1);
            const auto d2 = second.derivatives(t2, 1);
            const Eigen::Vector2d f = d1[0] - d2[0];
            if (f.norm() <= 1e-15 * size) break;
            Eigen::Matrix2d j;
            j.col(0) = d1[1];
            j.col(1) = -d2[1];
            if (std::abs(j.determinant()) <= 1e-14 * j.squaredNorm()) break;  // tangential: keep the candidate
            const Eigen::Vector2d step = j.partialPivLu().solve(f);
            t1 = std::clamp(t1 - step.x(), first.domainStart(), first.domainEnd());
            t2 = std::clamp(t2 - step.y(), second.domainStart(), second.domainEnd());
        }
        double gap = (first.evaluate(t1) - second.evaluate(t2)).norm();
        if (gap > kMeetRelative * size) {
            // Newton did not converge (a touch): fall back to the subdivision's candidate.
            t1 = start.x();
            t2 = start.y();
            gap = (first.evaluate(t1) - second.evaluate(t2)).norm();
            if (gap > kTouchRelative * size) continue;
        }
        found.push_back({t1, t2, 0.5 * (first.evaluate(t1) + second.evaluate(t2))});
    }
    std::sort(found.begin(), found.end(), [](const Crossing& a, const Crossing& b) { return a.t1 < b.t1; });
    const double m1 = kMergeRelative * (first.domainEnd() - first.domainStart());
    const double m2 = kMergeRelative * (second.domainEnd() - second.domainStart());
    std::vector<Crossing> out;
    for (const Crossing& c : found) {
        const bool duplicate = std::any_of(out.begin(), out.end(), [&](const Crossing& o) {
            return std::abs(o.t1 - c.t1) <= m1 && std::abs(o.t2 - c.t2) <= m2;
        });
        if (!duplicate) out.push_back(c);
    }
    return out;
}

}  // namespace sculptline::solvers::incidence
