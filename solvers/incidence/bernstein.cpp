#include "solvers/incidence/bernstein.h"

#include "solvers/bspline/basis.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sculptline::solvers::incidence {

Eigen::VectorXd bernsteinProduct(const Eigen::VectorXd& a, const Eigen::VectorXd& b)
{
    const int m = static_cast<int>(a.size()) - 1;
    const int n = static_cast<int>(b.size()) - 1;
    Eigen::VectorXd c = Eigen::VectorXd::Zero(m + n + 1);
    for (int i = 0; i <= m; ++i) {
        const double wi = binomial(m, i);
        for (int j = 0; j <= n; ++j) c[i + j] += wi * binomial(n, j) * a[i] * b[j];
    }
    for (int k = 0; k <= m + n; ++k) c[k] /= binomial(m + n, k);
    return c;
}

double bernsteinValue(const Eigen::VectorXd& c, double s)
{
    Eigen::VectorXd q = c;
    const int n = static_cast<int>(c.size()) - 1;
    for (int k = 1; k <= n; ++k)
        for (int i = 0; i <= n - k; ++i) q[i] = (1.0 - s) * q[i] + s * q[i + 1];
    return q[0];
}

void bernsteinSplit(const Eigen::VectorXd& c, double s, Eigen::VectorXd& left, Eigen::VectorXd& right)
{
    const int n = static_cast<int>(c.size()) - 1;
    Eigen::VectorXd q = c;
    left.resize(n + 1);
    right.resize(n + 1);
    left[0] = q[0];
    right[n] = q[n];
    for (int k = 1; k <= n; ++k) {
        for (int i = 0; i <= n - k; ++i) q[i] = (1.0 - s) * q[i] + s * q[i + 1];
        left[k] = q[0];
        right[n - k] = q[n - k];
    }
}

namespace {

int signChanges(const Eigen::VectorXd& c, double tol)
{
    int changes = 0;
    int last = 0;
    for (int i = 0; i < c.size(); ++i) {
        const int s = c[i] > tol ? 1 : (c[i] < -tol ? -1 : 0);
        if (s != 0 && last != 0 && s != last) ++changes;
        if (s != 0) last = s;
    }
    return changes;
}

// The one root of a piece whose end values have opposite signs and whose coefficients change sign
// once (Descartes' rule for the Bernstein basis: exactly one root), by bisection to round-off.
double bisect(const Eigen::VectorXd& c, double s0, double s1)
{
    double a = 0.0, b = 1.0;
    const bool risingAtA = c[0] < 0.0;
    for (int k = 0; k < 60 && b - a > 0.0; ++k) {
        const double m = 0.5 * (a + b);
        if (m <= a || m >= b) break;
        const double f = bernsteinValue(c, m);
        if (f == 0.0) return s0 + (s1 - s0) * m;
        ((f < 0.0) == risingAtA ? a : b) = m;
    }
    return s0 + (s1 - s0) * 0.5 * (a + b);
}

// Roots as intervals [first, second]: a point for a simple root, a range where the polynomial stays
// within the tolerance of zero (a touch, or close roots that no subdivision separates).
using Range = std::pair<double, double>;

void isolate(const Eigen::VectorXd& c, double s0, double s1, double tol, double width, int budget,
             std::vector<Range>& roots)
{
    const int n = static_cast<int>(c.size()) - 1;
    if (c.cwiseAbs().maxCoeff() <= tol) {  // the piece runs along the level: one root for all of it
        roots.emplace_back(s0, s1);
        return;
    }
    // A zero at an end of the piece is already reported (by the caller or the split that made
    // it): leave that coefficient out of the convex hull test, or the recursion would chase it.
    const int lo = std::abs(c[0]) <= tol ? 1 : 0;
    const int hi = std::abs(c[n]) <= tol ? n - 1 : n;
    if (lo > hi) return;
    const Eigen::VectorXd inner = c.segment(lo, hi - lo + 1);
    if (inner.minCoeff() > tol || inner.maxCoeff() < -tol) return;  // convex hull: no zero here
    if (lo == 0 && hi == n && c[0] * c[n] < 0.0 && signChanges(c, tol) == 1) {
        const double r = bisect(c, s0, s1);
        roots.emplace_back(r, r);
        return;
    }
    if (s1 - s0 <= width || budget == 0) {  // a root that no subdivision isolates, to `width`
        roots.emplace_back(s0, s1);
        return;
    }
    Eigen::VectorXd left, right;
    bernsteinSplit(c, 0.5, left, right);
    const double mid = 0.5 * (s0 + s1);
    if (std::abs(right[0]) <= tol) roots.emplace_back(mid, mid);
    isolate(left, s0, mid, tol, width, budget - 1, roots);
    isolate(right, mid, s1, tol, width, budget - 1, roots);
}

}  // namespace

std::vector<double> bernsteinRoots(const Eigen::VectorXd& c, double zeroTolerance, double width)
{
    std::vector<double> roots;
    if (c.size() == 0 || c.cwiseAbs().maxCoeff() <= zeroTolerance) return roots;
    const int n = static_cast<int>(c.size()) - 1;
    std::vector<Range> ranges;
    if (std::abs(c[0]) <= zeroTolerance) ranges.emplace_back(0.0, 0.0);
    if (std::abs(c[n]) <= zeroTolerance) ranges.emplace_back(1.0, 1.0);
    isolate(c, 0.0, 1.0, zeroTolerance, width, 64, ranges);
    std::sort(ranges.begin(), ranges.end());
    // Ranges that touch are one root (a touch found as several neighbouring pieces): its middle.
    for (size_t i = 0; i < ranges.size();) {
        Range merged = ranges[i];
        size_t j = i + 1;
        while (j < ranges.size() && ranges[j].first <= merged.second) merged.second = std::max(merged.second, ranges[j++].second);
        roots.push_back(merged.first == 0.0 ? 0.0 : (merged.second == 1.0 ? 1.0 : 0.5 * (merged.first + merged.second)));
        i = j;
    }
    return roots;
}

}  // namespace sculptline::solvers::incidence
