#include "solvers/incidence/compatibility.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/knot_algorithms.h"

#include <algorithm>
#include <cmath>

namespace sculptline::solvers::incidence {

namespace {

constexpr double kDomainRelative = 1e-12;
constexpr double kSnapRelative = 1e-9;

}  // namespace

SparseRows compatibilityMatrix(int degree, const KnotVector& knots, const CompositionSpace& target)
{
    const int count = static_cast<int>(knots.size()) - degree - 1;
    validateKnots(degree, count, knots, "request knots");
    if (degree > target.degree) {
        throw GeometryError("request degree: " + std::to_string(degree) + " exceeds the surface curve's " +
                            std::to_string(target.degree));
    }
    const double t0 = target.start(), t1 = target.end(), length = t1 - t0;
    KnotsAndPoints cur = clampEnds(degree, knots, ControlMatrix::Identity(count, count));
    if (std::abs(cur.knots.front() - t0) > kDomainRelative * length ||
        std::abs(cur.knots.back() - t1) > kDomainRelative * length) {
        throw GeometryError("request knots: the domain differs from the domain curve's [" + std::to_string(t0) + ", " +
                            std::to_string(t1) + "]");
    }
    const double a = cur.knots[degree], b = cur.knots[cur.knots.size() - degree - 1];
    for (double& t : cur.knots) {
        if (t <= a || t >= b) {
            t = t < 0.5 * (t0 + t1) ? t0 : t1;
            continue;
        }
        const auto near = std::min_element(target.breakpoints.begin(), target.breakpoints.end(),
                                           [t](double a, double b) { return std::abs(a - t) < std::abs(b - t); });
        if (near == target.breakpoints.end() || std::abs(*near - t) > kSnapRelative * length) {
            throw GeometryError("request knots: " + std::to_string(t) +
                                " is not a breakpoint of the surface curve (compose with it as an extra breakpoint)");
        }
        t = *near;
    }
    cur = elevateDegree(degree, cur.knots, cur.points, target.degree - degree);
    // The knots of the target missing from the elevated curve, with their multiplicities.
    std::vector<double> missing;
    for (size_t i = 0; i < target.knots.size();) {
        const double t = target.knots[i];
        size_t j = i;
        while (j < target.knots.size() && target.knots[j] == t) ++j;
        const int have = knotMultiplicity(cur.knots, t);
        const int want = static_cast<int>(j - i);
        if (have > want) throw GeometryError("request knots: multiplicity above the surface curve's at " + std::to_string(t));
        missing.insert(missing.end(), static_cast<size_t>(want - have), t);
        i = j;
    }
    if (!missing.empty()) cur = refineKnots(target.degree, cur.knots, cur.points, missing);
    if (cur.knots != target.knots) throw GeometryError("request knots: not compatible with the surface curve's space");
    SparseRows c = cur.points.sparseView(0.0, 0.0);
    return c;
}

Curve3d bringIntoSpace(const Curve3d& request, const CompositionSpace& target)
{
    if (request.isRational()) throw GeometryError("request curve: must be non-rational");
    const Curve3d open = request.isClosed() ? request.clamped() : request;
    const SparseRows c = compatibilityMatrix(open.degree(), open.knots(), target);
    ControlMatrix p(open.pointCount(), 3);
    for (int i = 0; i < open.pointCount(); ++i) p.row(i) = open.points()[i].transpose();
    const ControlMatrix brought = c * p;
    std::vector<Curve3d::Point> points(static_cast<size_t>(brought.rows()));
    for (Eigen::Index i = 0; i < brought.rows(); ++i) points[static_cast<size_t>(i)] = brought.row(i).transpose();
    return Curve3d(target.degree, target.knots, std::move(points));
}

}  // namespace sculptline::solvers::incidence
