// fitPiecesSearched (fit_reading.h): the minimax trials piece by piece between a stroke's corners,
// each piece a reading of its own (fitReading, Reading::Descended), joined with triple knots.
#include "solvers/bspline/geometry_error.h"
#include "solvers/stroke/fit_reading.h"

#include <algorithm>

namespace sculptline::solvers::stroke::detail {

using Vec3 = Eigen::Vector3d;

bool fitPiecesSearched(const Prepared& p, const std::vector<int>& corners, double tolerance, FitPass& joined,
                       std::vector<int>& outliers)
{
    const ConditionedStroke& cs = p.cs;
    const int n = cs.size();
    std::vector<int> sorted = corners;
    std::sort(sorted.begin(), sorted.end());
    // The chain: conditioned indices from the start (an open stroke's first point, a loop's first
    // corner) to the end (the last point, the loop's first corner again), and its breaks.
    const int start = cs.closed ? sorted.front() : 0;
    const int count = cs.closed ? n + 1 : n;
    const auto at = [&](int k) { return (start + k) % n; };
    std::vector<int> breaks = {0};
    for (int c : sorted) {
        const int k = ((c - start) % n + n) % n;
        if (k > 0 && k < count - 1) breaks.push_back(k);
    }
    breaks.push_back(count - 1);
    // Chord parameter along the chain (the smoothed points', as fitConditioned's).
    std::vector<double> g(static_cast<size_t>(count), 0.0);
    for (int k = 1; k < count; ++k) g[k] = g[k - 1] + (cs.points[at(k)] - cs.points[at(k - 1)]).norm();
    if (!(g.back() > 0.0)) return false;
    for (double& t : g) t /= g.back();
    std::vector<int> row(static_cast<size_t>(n), 0);
    for (int s : p.samples) row[static_cast<size_t>(s)] = 1;
    const int rawCount = static_cast<int>(p.stroke.points.size());
    KnotVector knots;
    std::vector<Vec3> points;
    outliers.clear();
    joined.samples.clear();
    for (size_t piece = 0; piece + 1 < breaks.size(); ++piece) {
        const int a = breaks[piece], b = breaks[piece + 1];
        // The raw samples from the first point's to the last's, round the seam where the piece
        // crosses it.
        std::vector<int> raw;
        for (int r = cs.source[at(a)];; r = (r + 1) % rawCount) {
            raw.push_back(r);
            if (r == cs.source[at(b)] || static_cast<int>(raw.size()) > rawCount) break;
        }
        Stroke sub;
        sub.dimension = p.stroke.dimension;
        std::vector<char> keep;
        for (int r : raw) {
            sub.points.push_back(p.stroke.points[static_cast<size_t>(r)]);
            keep.push_back(p.keep[static_cast<size_t>(r)]);
        }
        ConditionedStroke pc;
        pc.closed = false;
        pc.timed = false;
        pc.extent = cs.extent;
        pc.noise = cs.noise;
        pc.smoothingShift = cs.smoothingShift;
        std::vector<Vec3> fitPoints, drawn;
        std::vector<int> rows;
        for (int k = a, r = 0; k <= b; ++k) {
            const int i = at(k);
            while (raw[static_cast<size_t>(r)] != cs.source[i]) ++r;
            pc.source.push_back(r);
            pc.points.push_back(cs.points[i]);
            pc.time.push_back(static_cast<double>(r));
            pc.arc.push_back(k == a ? 0.0 : pc.arc.back() + (cs.points[i] - cs.points[at(k - 1)]).norm());
            fitPoints.push_back(p.fitPoints[i]);
            drawn.push_back(p.drawn[i]);
            if (row[i] || k == a || k == b) rows.push_back(k - a);
        }
        for (int d : cs.dropped) {
            const auto it = std::find(raw.begin(), raw.end(), d);
            if (it != raw.end()) pc.dropped.push_back(static_cast<int>(it - raw.begin()));
        }
        std::sort(pc.dropped.begin(), pc.dropped.end());
        if (pc.size() < 2) return false;
        const Prepared sp{sub, p.options, pc, fitPoints, rows, keep, drawn};
        FitResult r;
        r.tolerance = tolerance;
        FitPass fit;
        std::vector<int> pieceOutliers;
        try {
            fitReading(sp, {}, Reading::Descended, r, fit, pieceOutliers);
        } catch (const GeometryError&) {
            return false;
        }
        if (!r.converged || fit.curve.isClosed()) return false;
        for (int o : pieceOutliers) outliers.push_back(raw[static_cast<size_t>(o)]);
        for (int s : fit.samples) joined.samples.push_back(raw[static_cast<size_t>(s)]);
        // Onto the chain's parameter, as fitPieces joins; each later piece's first point must be the
        // corner the piece before ended at.
        const KnotVector& U = fit.curve.knots();
        const double d0 = fit.curve.domainStart(), d1 = fit.curve.domainEnd(), g0 = g[a], len = g[b] - g0;
        const std::vector<Vec3>& P = fit.curve.points();
        if (piece > 0 && !((P.front() - points.back()).norm() <= 1e-9 * std::max(1.0, cs.extent))) return false;
        detail::appendClampedPiece(U, P, d0, d1, g0, len, piece == 0, piece + 2 == breaks.size(), knots, points);
    }
    knots.front() = 0.0;
    std::sort(joined.samples.begin(), joined.samples.end());
    joined.samples.erase(std::unique(joined.samples.begin(), joined.samples.end()), joined.samples.end());
    std::sort(outliers.begin(), outliers.end());
    joined.curve = cs.closed ? detail::closeClampedLoop(knots, points) : Curve3d(3, knots, points);
    return true;
}

}  // namespace sculptline::solvers::stroke::detail
