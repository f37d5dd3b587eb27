#include "solvers/regularization/lcurve_corner.h"

#include "solvers/bspline/basis.h"
#include "solvers/bspline/knot_algorithms.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace sculptline::solvers::regularization {

CornerMethod defaultCornerMethod(bool mtsvd) { return mtsvd ? CornerMethod::AdaptivePruning : CornerMethod::KnotRemoval; }

std::string cornerMethodName(CornerMethod method)
{
    return method == CornerMethod::KnotRemoval ? "knot-removal" : "adaptive-pruning";
}

namespace {

// The usable points of the L-curve in log10-log10, with their k (1-based).
struct LogCurve {
    std::vector<int> k;
    std::vector<Eigen::Vector2d> p;
};

// A residual below this fraction of the largest is round-off (a consistent system solved to the last
// digit, e.g. k = n on a square matrix): its logarithm says nothing about the data and would stretch
// the curve by ten decades.
constexpr double kResidualRoundOff = 1e3 * std::numeric_limits<double>::epsilon();

// A singular value below this fraction of the largest is round-off too: its v_k is set by rounding
// errors, and dividing by it throws η up by ten decades in one step (heat at n = 64: σ_62 = 5e-15
// σ_1 survives the rank cut max(m, n) ε σ_1 by 1 %), a "vertical leg" of one point that hides the
// L-curve's real shape from both corner methods.
constexpr double kSigmaRoundOff = kResidualRoundOff;

LogCurve usablePoints(const LCurve& lc)
{
    LogCurve out;
    double rhoMax = 0.0;
    for (int i = 0; i < lc.rho.size(); ++i) {
        if (std::isfinite(lc.rho(i))) rhoMax = std::max(rhoMax, lc.rho(i));
    }
    const bool haveSigma = lc.sigma.size() == lc.rho.size() && lc.sigma.size() > 0;
    const double sigmaFloor = haveSigma ? kSigmaRoundOff * lc.sigma.maxCoeff() : 0.0;
    for (int i = 0; i < lc.rho.size(); ++i) {
        const double r = lc.rho(i), e = lc.eta(i);
        if (!(std::isfinite(r) && std::isfinite(e) && r > kResidualRoundOff * rhoMax && e > 0.0)) continue;
        if (haveSigma && !(lc.sigma(i) > sigmaFloor)) continue;
        const Eigen::Vector2d q(std::log10(r), std::log10(e));
        if (!out.p.empty() && q == out.p.back()) continue;  // a repeated point has no direction
        out.k.push_back(i + 1);
        out.p.push_back(q);
    }
    return out;
}

// The truncation when fewer than 3 usable points leave no corner: the first k that fits b exactly
// (ρ at round-off), else the last usable k, else the last k.
int withoutCorner(const LCurve& lc, const LogCurve& usable)
{
    double rhoMax = 0.0;
    for (int i = 0; i < lc.rho.size(); ++i) {
        if (std::isfinite(lc.rho(i))) rhoMax = std::max(rhoMax, lc.rho(i));
    }
    for (int i = 0; i < lc.rho.size(); ++i) {
        if (std::isfinite(lc.rho(i)) && lc.rho(i) <= kResidualRoundOff * rhoMax) return i + 1;
    }
    return usable.k.empty() ? static_cast<int>(lc.rho.size()) : usable.k.back();
}

void requirePoints(const LCurve& lc)
{
    if (lc.rho.size() == 0 || lc.rho.size() != lc.eta.size()) {
        throw std::invalid_argument("lcurve: needs at least one point and as many eta as rho values");
    }
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// ---- Seed 000 §4.2: knot removal on the C0 cubic through the points ------------------------------

constexpr int kDegree = 3;
// A knot whose two-sided turn is at least this (radians, clockwise) is a corner candidate.
constexpr double kMinCornerTurn = 10.0 * 3.14159265358979323846 / 180.0;
// |log10 ε_max − log10 ε_min| <= 1: the remaining knots' removal errors lie within one decade.
constexpr double kErrorSpreadDecades = 1.0;
// The half-width of the window over which a knot's turn is measured, as a fraction of the L-curve's
// chord length. Chosen on the tuning seeds of README "Which corner method" (0.02-0.2 pass within one
// case of each other there; 0.05 was the first value tried and kept).
constexpr double kTurnWindow = 0.05;

// The error that removing one copy of the knot u would cause (The NURBS Book A5.8, its first pass):
// the control points are solved from both ends of the affected range and their mismatch measured.
double removalError(const KnotVector& U, const ControlMatrix& P, double u)
{
    const int p = kDegree;
    const int s = knotMultiplicity(U, u);
    const int r = static_cast<int>(std::upper_bound(U.begin(), U.end(), u) - U.begin()) - 1;
    const int first = r - p, last = r - s, off = first - 1;
    ControlMatrix temp(2 * p + 1, P.cols());
    temp.row(0) = P.row(off);
    temp.row(last + 1 - off) = P.row(last + 1);
    int i = first, j = last, ii = 1, jj = last - off;
    while (j - i > 0) {
        const double ai = (u - U[i]) / (U[i + p + 1] - U[i]);
        const double aj = (u - U[j]) / (U[j + p + 1] - U[j]);
        temp.row(ii) = (P.row(i) - (1.0 - ai) * temp.row(ii - 1)) / ai;
        temp.row(jj) = (P.row(j) - aj * temp.row(jj + 1)) / (1.0 - aj);
        ++i, ++ii, --j, --jj;
    }
    if (j - i < 0) return (temp.row(ii - 1) - temp.row(jj + 1)).norm();
    const double ai = (u - U[i]) / (U[i + p + 1] - U[i]);
    return (P.row(i) - (ai * temp.row(ii + 1) + (1.0 - ai) * temp.row(ii - 1))).norm();
}

// The point of the cubic at u, from the left (side < 0) or the right, by de Boor.
Eigen::Vector2d evaluateAt(const KnotVector& U, const ControlMatrix& P, double u)
{
    const int span = findSpan(kDegree, U, u);
    double n[kDegree + 1];
    basisFunctions(span, u, kDegree, U, n);
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (int i = 0; i <= kDegree; ++i) c += n[i] * P.row(span - kDegree + i).transpose();
    return c;
}

}  // namespace

CornerResult cornerByKnotRemoval(const LCurve& lcurve)
{
    requirePoints(lcurve);
    const LogCurve lc = usablePoints(lcurve);
    const int np = static_cast<int>(lc.p.size());
    CornerResult result;
    if (np < 3) {
        result.k = withoutCorner(lcurve, lc);
        return result;
    }
    // Chord-length parameters on [0, 1].
    std::vector<double> t(np, 0.0);
    for (int i = 1; i < np; ++i) t[i] = t[i - 1] + (lc.p[i] - lc.p[i - 1]).norm();
    for (double& v : t) v /= t.back();
    t.back() = 1.0;
    // The polyline as a linear B-spline, elevated to a C0 cubic (every data point a triple knot).
    KnotVector knots;
    knots.push_back(0.0);
    for (double v : t) knots.push_back(v);
    knots.push_back(1.0);
    ControlMatrix points(np, 2);
    for (int i = 0; i < np; ++i) points.row(i) = lc.p[i].transpose();
    KnotsAndPoints cubic = elevateDegree(1, knots, points, kDegree - 1);
    KnotVector& U = cubic.knots;
    ControlMatrix& P = cubic.points;

    // Greedy ranking: remove the least significant knot copy (raising the threshold to its error)
    // until the remaining knots' errors span at most one decade. A removal changes control points and
    // knots only within about p + 1 indices of the removed knot, and a knot's error reads about p + 2
    // on either side, so only the errors of knots within kErrorStencil breakpoints of it are computed
    // again; the others are the same numbers (this makes the loop O(r) error evaluations, not O(r²)).
    constexpr int kErrorStencil = 2 * kDegree + 4;
    std::vector<double> breaks = interiorBreakpoints(kDegree, U), errors(breaks.size());
    for (size_t i = 0; i < breaks.size(); ++i) errors[i] = removalError(U, P, breaks[i]);
    double threshold = 0.0;  // the largest error spent on one removal
    while (!breaks.empty()) {
        const auto [lo, hi] = std::minmax_element(errors.begin(), errors.end());
        const double floor = std::numeric_limits<double>::min();
        if (std::log10(std::max(*hi, floor)) - std::log10(std::max(*lo, floor)) <= kErrorSpreadDecades) break;
        threshold = std::max(threshold, *lo);
        const long at = lo - errors.begin();
        removeKnot(kDegree, U, P, breaks[static_cast<size_t>(at)], 1, std::numeric_limits<double>::infinity(),
                   static_cast<int>(P.cols()));
        std::vector<double> next = interiorBreakpoints(kDegree, U);
        const bool vanished = next.size() < breaks.size();  // its last copy was removed
        std::vector<double> nextErrors(next.size());
        for (size_t j = 0; j < next.size(); ++j) {
            const size_t old = vanished && static_cast<long>(j) >= at ? j + 1 : j;
            nextErrors[j] = std::abs(static_cast<long>(j) - at) <= kErrorStencil ? removalError(U, P, next[j]) : errors[old];
        }
        breaks = std::move(next);
        errors = std::move(nextErrors);
    }

    // The turn at each remaining knot, measured over a window of kTurnWindow of the curve's chord
    // length on either side: a corner that the removal left as a cluster of nearby knots (seed 000
    // §4.2: "the corner consists of a cluster of rapidly varying values") turns as a whole, while
    // each knot of the cluster alone turns only a few degrees. A knot stands for the data points
    // within the threshold of its curve point; of those, the one of smallest η.
    std::vector<std::pair<double, int>> turns;  // (clockwise turn in radians, data index)
    for (size_t b = 0; b < breaks.size(); ++b) {
        const double u = breaks[b];
        const Eigen::Vector2d c = evaluateAt(U, P, u);
        const Eigen::Vector2d d1 = c - evaluateAt(U, P, std::max(0.0, u - kTurnWindow));
        const Eigen::Vector2d d2 = evaluateAt(U, P, std::min(1.0, u + kTurnWindow)) - c;
        const double turn = -std::atan2(cross(d1, d2), d1.dot(d2));  // > 0: clockwise
        int j = static_cast<int>(std::min_element(t.begin(), t.end(), [u](double a, double c2) {
                                     return std::abs(a - u) < std::abs(c2 - u);
                                 }) - t.begin());
        for (int i = 0; i < np; ++i) {
            if ((lc.p[i] - c).norm() <= threshold && lc.p[i].y() < lc.p[j].y()) j = i;
        }
        turns.emplace_back(turn, j);
    }
    // Corners: the knots turning at least kMinCornerTurn that turn most among their neighbours (a
    // window sees one corner from several knots); of several corners the one of smallest η (seed
    // 000 §4.2 after Hansen 1990).
    int best = -1;
    for (size_t b = 0; b < turns.size(); ++b) {
        const auto [turn, j] = turns[b];
        if (turn < kMinCornerTurn) continue;
        if (b > 0 && turns[b - 1].first > turn) continue;
        if (b + 1 < turns.size() && turns[b + 1].first >= turn) continue;
        result.candidates.push_back(lc.k[j]);
        if (best < 0 || lcurve.eta(lc.k[j] - 1) < lcurve.eta(lc.k[best] - 1)) best = j;
    }
    if (best < 0) {
        // No knot turns sharply: the one turning clockwise most, else the polyline's sharpest turn.
        double most = 0.0;
        for (const auto& [turn, j] : turns) {
            if (turn > most) most = turn, best = j;
        }
        const bool knotTurns = best >= 0;
        for (int i = 1; !knotTurns && i + 1 < np; ++i) {
            const Eigen::Vector2d d1 = lc.p[i] - lc.p[i - 1], d2 = lc.p[i + 1] - lc.p[i];
            const double turn = -std::atan2(cross(d1, d2), d1.dot(d2));
            if (turn > most) most = turn, best = i;
        }
        if (best < 0) best = np - 1;  // no turn at all: the least regularized solution
    }
    std::sort(result.candidates.begin(), result.candidates.end());
    result.candidates.erase(std::unique(result.candidates.begin(), result.candidates.end()), result.candidates.end());
    result.k = lc.k[best];
    return result;
}

// ---- Hansen, Jensen & Rodriguez 2007: adaptive pruning --------------------------------------------

namespace {

// The corner of a pruned L-curve (its segments `sel`, ascending) by the angle criterion: the point
// between the two consecutive segments with the most negative wedge product; -1 when none is < 0.
int angleCandidate(const std::vector<Eigen::Vector2d>& w, const std::vector<int>& sel)
{
    double most = 0.0;
    int at = -1;
    for (size_t i = 0; i + 1 < sel.size(); ++i) {
        const double wedge = cross(w[sel[i]], w[sel[i + 1]]);
        if (wedge < most) most = wedge, at = sel[i] + 1;
    }
    return at;
}

// The corner by the global behaviour: the flattest segment that comes before a steepest one describe
// the two legs; the point of the whole curve nearest their crossing is the candidate (-1: none).
int globalCandidate(const std::vector<Eigen::Vector2d>& pts, const std::vector<Eigen::Vector2d>& w,
                    const std::vector<int>& sel)
{
    const int ln = static_cast<int>(sel.size());
    std::vector<int> order(ln);  // positions in sel, flattest first
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return std::abs(w[sel[a]].y()) < std::abs(w[sel[b]].y()); });
    // Widen the flat and steep groups until one flat segment precedes one steep segment.
    int count = 0;
    int horizontal = -1, vertical = -1;
    for (count = 1; count <= ln && horizontal < 0; ++count) {
        for (int i = 0; i < count && horizontal < 0; ++i) {
            for (int j = ln - 1; j >= ln - count; --j) {
                if (order[i] < order[j]) {
                    horizontal = order[i], vertical = order[j];
                    break;
                }
            }
        }
    }
    if (horizontal < 0) return -1;
    const Eigen::Vector2d& a = pts[sel[vertical]];
    const Eigen::Vector2d& b = pts[sel[vertical] + 1];
    const double y = pts[sel[horizontal]].y();
    if (b.y() == a.y()) return -1;
    const Eigen::Vector2d origin(b.x() + (y - b.y()) / (b.y() - a.y()) * (b.x() - a.x()), y);
    int best = 0;
    for (int i = 1; i < static_cast<int>(pts.size()); ++i) {
        if ((pts[i] - origin).squaredNorm() < (pts[best] - origin).squaredNorm()) best = i;
    }
    return best;
}

}  // namespace

CornerResult cornerByAdaptivePruning(const LCurve& lcurve)
{
    requirePoints(lcurve);
    const LogCurve lc = usablePoints(lcurve);
    const int np = static_cast<int>(lc.p.size());
    CornerResult result;
    if (np < 3) {
        result.k = withoutCorner(lcurve, lc);
        return result;
    }
    const int nv = np - 1;
    std::vector<Eigen::Vector2d> w(nv);
    std::vector<double> len(nv);
    for (int i = 0; i < nv; ++i) {
        const Eigen::Vector2d v = lc.p[i + 1] - lc.p[i];
        len[i] = v.norm();
        w[i] = v / len[i];
    }
    std::vector<int> longest(nv);
    std::iota(longest.begin(), longest.end(), 0);
    std::stable_sort(longest.begin(), longest.end(), [&](int a, int b) { return len[a] > len[b]; });

    // Pruned L-curves of the 5, 10, 20, .. longest segments each propose up to two candidates.
    std::vector<int> candidates;
    bool convex = false;
    for (int p = std::min(5, nv); p < 2 * nv; p *= 2) {
        std::vector<int> sel(longest.begin(), longest.begin() + std::min(p, nv));
        std::sort(sel.begin(), sel.end());
        const int a = angleCandidate(w, sel);
        if (a >= 0) {
            convex = true;
            candidates.push_back(a);
        }
        const int g = globalCandidate(lc.p, w, sel);
        if (g >= 0) candidates.push_back(g);
    }
    if (!convex) {  // no corner anywhere: the least regularized solution
        result.k = lc.k.back();
        return result;
    }
    candidates.push_back(0);  // the rightmost point anchors the selection below
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    for (int c : candidates) result.candidates.push_back(lc.k[c]);

    // Select the first candidate after which the solution norm grows more than the residual falls,
    // where the curve turns convexly (clockwise); else the last such; else the leftmost candidate.
    const int nc = static_cast<int>(candidates.size());
    std::vector<int> steep;  // j: the step from candidates[j] to [j+1] is steep; j = 0 never counts
    for (int j = 1; j + 1 < nc; ++j) {
        const Eigen::Vector2d d = lc.p[candidates[j + 1]] - lc.p[candidates[j]];
        if (d.y() >= std::abs(d.x())) steep.push_back(j);
    }
    int index = candidates.back();
    if (!steep.empty()) {
        index = candidates[steep.back()];
        for (int j : steep) {
            const Eigen::Vector2d in = (lc.p[candidates[j]] - lc.p[candidates[j - 1]]).normalized();
            const Eigen::Vector2d out = (lc.p[candidates[j + 1]] - lc.p[candidates[j]]).normalized();
            if (cross(in, out) <= 0.0) {
                index = candidates[j];
                break;
            }
        }
    }
    result.k = lc.k[index];
    return result;
}

CornerResult lcurveCorner(const LCurve& lcurve, CornerMethod method)
{
    return method == CornerMethod::KnotRemoval ? cornerByKnotRemoval(lcurve) : cornerByAdaptivePruning(lcurve);
}

}  // namespace sculptline::solvers::regularization
