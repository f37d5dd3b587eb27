#pragma once
// B-spline basis functions on a knot vector (The NURBS Book, 2nd ed., ch. 2).
#include <Eigen/Core>
#include <string>
#include <vector>

namespace sculptline::solvers {

using KnotVector = std::vector<double>;

/// Highest supported degree: the basis evaluation keeps its triangle on the stack.
constexpr int kMaxDegree = 30;

/// Row-major matrix whose row i is control point i; rational geometry stores homogeneous rows
/// (w*x, w*y, [w*z,] w). The knot algorithms work on any number of columns, which lets a surface
/// reuse the curve algorithms on whole rows of its control net.
using ControlMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// Checks a knot vector for `pointCount` control points of `degree`: degree >= 1, pointCount >
/// degree, knots.size() == pointCount + degree + 1, all finite, non-decreasing, a non-empty domain
/// [knots[degree], knots[pointCount]], no multiplicity above degree + 1 and, inside the domain,
/// none above degree (the geometry stays connected).
/// @throws GeometryError naming `field` and the problem.
void validateKnots(int degree, int pointCount, const KnotVector& knots, const std::string& field = "knots");

/// Knot span index i with knots[i] <= u < knots[i+1], clamped to [degree, n] where n = pointCount-1;
/// u at the domain's right end maps to the last non-empty span. The NURBS Book, A2.1.
int findSpan(int degree, const KnotVector& knots, double u);

/// The degree+1 non-vanishing basis functions N_{span-degree..span, degree}(u). The NURBS Book, A2.2.
/// (basis_evaluator.h holds the algorithms, shared with the fixed-degree forms evaluateBasis<Degree,
/// Order> and SpanBasis<Degree>.)
void basisFunctions(int span, double u, int degree, const KnotVector& knots, double* out);

/// Basis functions and their derivatives up to order `n` (row k = k-th derivative, columns the
/// degree+1 functions of `span`); derivatives above the degree are zero. The NURBS Book, A2.3.
Eigen::MatrixXd basisDerivatives(int span, double u, int degree, int n, const KnotVector& knots);
/// The same into caller storage, without allocating: ders[k * (degree + 1) + j] for k = 0..n.
/// @note degree <= kMaxDegree; `ders` holds (n + 1) * (degree + 1) values.
void basisDerivatives(int span, double u, int degree, int n, const KnotVector& knots, double* ders);

/// Multiplicity of the knot value u (exact comparison; knots are data, not results of arithmetic).
int knotMultiplicity(const KnotVector& knots, double u);

/// The binomial coefficient C(n, k) as a double (exact for the small n of spline degrees).
inline double binomial(int n, int k)
{
    double b = 1.0;
    for (int i = 1; i <= k; ++i) b = b * (n - k + i) / i;
    return b;
}

/// Distinct knot values strictly inside (knots[degree], knots[size-degree-1]).
std::vector<double> interiorBreakpoints(int degree, const KnotVector& knots);

}  // namespace sculptline::solvers
