#include "solvers/bspline/basis.h"

#include "solvers/bspline/basis_evaluator.h"

#include "solvers/bspline/geometry_error.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sculptline::solvers {

void validateKnots(int degree, int pointCount, const KnotVector& knots, const std::string& field)
{
    if (degree < 1) {
        throw GeometryError("degree: must be at least 1, got " + std::to_string(degree));
    }
    if (degree > kMaxDegree) {
        throw GeometryError("degree: at most " + std::to_string(kMaxDegree) + " is supported, got " + std::to_string(degree));
    }
    if (pointCount < degree + 1) {
        std::ostringstream msg;
        msg << "points: degree " << degree << " needs at least " << degree + 1 << " control points, got " << pointCount;
        throw GeometryError(msg.str());
    }
    const size_t expected = static_cast<size_t>(pointCount + degree + 1);
    if (knots.size() != expected) {
        std::ostringstream msg;
        msg << field << ": expected " << expected << " knots (points + degree + 1 = " << pointCount << " + " << degree
            << " + 1), got " << knots.size();
        throw GeometryError(msg.str());
    }
    for (size_t i = 0; i < knots.size(); ++i) {
        if (!std::isfinite(knots[i])) {
            throw GeometryError(field + "[" + std::to_string(i) + "]: not a finite number");
        }
        if (i > 0 && knots[i] < knots[i - 1]) {
            std::ostringstream msg;
            msg << field << "[" << i << "]: knots must be non-decreasing, but " << knots[i] << " < " << knots[i - 1];
            throw GeometryError(msg.str());
        }
    }
    if (!(knots[degree] < knots[pointCount])) {
        throw GeometryError(field + ": the parameter domain [knots[degree], knots[points]] is empty");
    }
    for (size_t i = 0; i < knots.size();) {
        size_t j = i;
        while (j < knots.size() && knots[j] == knots[i]) ++j;
        if (static_cast<int>(j - i) > degree + 1) {
            std::ostringstream msg;
            msg << field << ": knot " << knots[i] << " has multiplicity " << j - i << ", more than degree + 1 = " << degree + 1;
            throw GeometryError(msg.str());
        }
        // Inside the domain a knot of multiplicity degree + 1 cuts the geometry in two pieces that
        // need not meet (C^-1: by The NURBS Book P2.5 the basis is C^(p-k) at a knot of multiplicity k).
        // Every algorithm of the kernel presumes at most degree inside the domain (Boehm's
        // insertion A5.1 and refinement A5.4, knot removal A5.8, clamping and extraction index
        // past a span of p + 1 equal knots), and a modeler's curve is connected: refuse it here.
        const double u = knots[i];
        if (static_cast<int>(j - i) > degree && u > knots[degree] && u < knots[pointCount]) {
            std::ostringstream msg;
            msg << field << ": interior knot " << u << " has multiplicity " << j - i << ", more than the degree " << degree
                << " (the curve would break apart there)";
            throw GeometryError(msg.str());
        }
        i = j;
    }
}

int findSpan(int degree, const KnotVector& knots, double u)
{
    const int n = static_cast<int>(knots.size()) - degree - 2;  // index of the last control point
    if (u >= knots[n + 1]) {
        // Right end of the domain (and beyond): the last non-empty span.
        int span = n;
        while (span > degree && knots[span] == knots[span + 1]) --span;
        return span;
    }
    if (u <= knots[degree]) {
        int span = degree;
        while (span < n && knots[span] == knots[span + 1]) ++span;
        return span;
    }
    // Binary search, A2.1: the largest i in [degree, n] with knots[i] <= u.
    const auto first = knots.begin() + degree;
    const auto last = knots.begin() + n + 1;
    const auto it = std::upper_bound(first, last, u);
    return static_cast<int>(it - knots.begin()) - 1;
}

void basisFunctions(int span, double u, int degree, const KnotVector& knots, double* out)
{
    detail::basisFunctionsA22<kMaxDegree>(span, u, degree, knots.data(), out);
}

void basisDerivatives(int span, double u, int p, int n, const KnotVector& knots, double* ders)
{
    // Fixed-size arrays (degree <= kMaxDegree): no allocation, so that per-sample evaluations in
    // inner loops (frames along a path, curve jets) can call it.
    const int cols = p + 1;
    detail::basisDerivativesA23<kMaxDegree>(span, u, p, n, knots.data(),
                                            [ders, cols](int k) { return ders + k * cols; });
}

Eigen::MatrixXd basisDerivatives(int span, double u, int p, int n, const KnotVector& knots)
{
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> ders(n + 1, p + 1);
    basisDerivatives(span, u, p, n, knots, ders.data());
    return ders;
}

int knotMultiplicity(const KnotVector& knots, double u)
{
    return static_cast<int>(std::count(knots.begin(), knots.end(), u));
}

std::vector<double> interiorBreakpoints(int degree, const KnotVector& knots)
{
    std::vector<double> out;
    const double a = knots[degree];
    const double b = knots[knots.size() - degree - 1];
    for (double k : knots) {
        if (k > a && k < b && (out.empty() || out.back() != k)) out.push_back(k);
    }
    return out;
}

}  // namespace sculptline::solvers
