#include "solvers/bspline/periodic.h"

#include "solvers/bspline/geometry_error.h"

#include <algorithm>
#include <cmath>

namespace sculptline::solvers {
namespace {

// floor(a / b) for b > 0 (integer division truncates toward zero).
int floorDiv(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

}  // namespace

KnotVector periodicKnots(int degree, const std::vector<double>& L, double period)
{
    const int N = static_cast<int>(L.size());
    if (N < 1 || !(period > 0.0)) throw GeometryError("knots: a period needs at least one knot and a positive length");
    int m = 1;
    while (m < N && L[static_cast<size_t>(m)] == L[0]) ++m;
    if (m > degree) throw GeometryError("knots: the period's start knot has multiplicity above the degree");
    const int o = degree + 1 - m;
    KnotVector U(static_cast<size_t>(N + 2 * degree + 1));
    for (int i = 0; i < static_cast<int>(U.size()); ++i) {
        const int q = floorDiv(i - o, N);
        U[static_cast<size_t>(i)] = L[static_cast<size_t>(i - o - q * N)] + q * period;
    }
    return U;
}

KnotVector periodicUniformKnots(int degree, int spans, double start, double period)
{
    if (spans < 1 || !(period > 0.0)) {
        throw GeometryError("knots: a period needs at least one span and a positive length");
    }
    KnotVector U(static_cast<size_t>(spans + 2 * degree + 1));
    for (int i = 0; i < static_cast<int>(U.size()); ++i) {
        U[static_cast<size_t>(i)] = start + period * (i - degree) / spans;
    }
    return U;
}

PeriodicWindow periodicExtension(int p, const KnotVector& t, const ControlMatrix& P, int periods)
{
    const int n = static_cast<int>(P.rows()) - 1;
    const int N = n + 1 - p;  // control points per period
    PeriodicWindow w;
    w.start = t[p];
    w.period = t[n + 1] - t[p];
    auto knotAt = [&](int i) {
        const int j = i - p;
        const int q = floorDiv(j, N);
        return t[p + (j - q * N)] + q * w.period;
    };
    const int iMin = -periods * N;
    const int iMax = (periods + 1) * N + p - 1;
    w.points.resize(iMax - iMin + 1, P.cols());
    for (int i = iMin; i <= iMax; ++i) {
        const int q = floorDiv(i, N);
        w.points.row(i - iMin) = P.row(i - q * N);
    }
    w.knots.resize(static_cast<size_t>(iMax - iMin + 1 + p + 1));
    for (int i = iMin; i <= iMax + p + 1; ++i) w.knots[i - iMin] = knotAt(i);
    return w;
}

KnotsAndPoints periodicFromWindow(int p, const KnotVector& K, const ControlMatrix& Q, double start, double period)
{
    // Knots within this distance of a period boundary are that boundary: the window's copies of the
    // start knot are computed as start + q*T and may differ from it in the last bits.
    const double eps = 1e-12 * std::max(1.0, std::abs(start) + std::abs(period));
    // The closed curve's domain starts at the first knot at or after `start` (start itself may have
    // been removed); the parameterization is unchanged, only the seam moves.
    const auto lo = std::lower_bound(K.begin(), K.end(), start - eps);
    if (lo == K.end()) throw GeometryError("closed: internal error, periodic window too small");
    start = *lo;
    const auto hi = std::lower_bound(K.begin(), K.end(), start + period - eps);
    const int idx = static_cast<int>(lo - K.begin());
    const int perPeriod = static_cast<int>(hi - lo);
    if (idx - p < 0 || idx + perPeriod + p >= static_cast<int>(K.size()) || perPeriod < 1) {
        throw GeometryError("closed: internal error, periodic window too small");
    }
    KnotsAndPoints out;
    out.knots.assign(K.begin() + idx - p, K.begin() + idx + perPeriod + p + 1);
    // Make the wrapped knots exactly periodic copies of the domain knots.
    out.knots[p] = start;
    for (int i = 0; i < p; ++i) out.knots[i] = out.knots[i + perPeriod] - period;
    for (int i = p + perPeriod; i < static_cast<int>(out.knots.size()); ++i)
        out.knots[i] = out.knots[i - perPeriod] + period;
    out.points = Q.middleRows(idx - p, perPeriod + p);
    for (int i = 0; i < p; ++i) out.points.row(perPeriod + i) = out.points.row(i);
    return out;
}

}  // namespace sculptline::solvers
