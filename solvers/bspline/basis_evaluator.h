#pragma once
// Allocation-free B-spline basis evaluation (The NURBS Book, 2nd ed., A2.2 and A2.3) on stack arrays.
//
// One implementation of each algorithm: the runtime-degree forms of basis.h instantiate it with
// arrays for kMaxDegree, the fixed-degree forms here with arrays for their degree, which the
// compiler unrolls (like Eigen's Spline::BasisFunctionDerivatives, without its dynamic matrices).
// Solvers that evaluate one degree in an inner loop (the stroke fitter's cubics) use these forms.
#include "solvers/bspline/basis.h"

#include <algorithm>
#include <array>

namespace sculptline::solvers {
namespace detail {

/// A2.2's quotient: the plain division (the denominators of a non-empty span are positive).
struct DivideByDifference {
    double operator()(int /*index*/, double numerator, double difference) const { return numerator / difference; }
};

/// The NURBS Book A2.2 into out[0..p] (p <= MaxDegree). The p (p + 1) / 2 denominators are knot
/// differences independent of u; `quotient(k, numerator, difference)` divides by the k-th of them
/// (k counts the triangle row by row), so that a caller may supply precomputed reciprocals.
template <int MaxDegree, class Quotient = DivideByDifference>
inline void basisFunctionsA22(int span, double u, int p, const double* knots, double* out, Quotient quotient = {})
{
    double left[MaxDegree + 1], right[MaxDegree + 1];
    out[0] = 1.0;
    int k = 0;
    for (int j = 1; j <= p; ++j) {
        left[j] = u - knots[span + 1 - j];
        right[j] = knots[span + j] - u;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            const double temp = quotient(k++, out[r], right[r + 1] + left[j - r]);
            out[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        out[j] = saved;
    }
}

/// The NURBS Book A2.3: basis functions of degree p <= MaxDegree on `span` and their derivatives up
/// to order n; row(k) points to the p + 1 values of the k-th derivative (zero for k > p).
template <int MaxDegree, class Rows>
inline void basisDerivativesA23(int span, double u, int p, int n, const double* knots, Rows row)
{
    double ndu[MaxDegree + 1][MaxDegree + 1];
    double left[MaxDegree + 1], right[MaxDegree + 1];
    double a[2][MaxDegree + 1];
    // A2.3 reads only entries it has written, but GCC cannot see it in the unrolled fixed-degree
    // forms (-Wmaybe-uninitialized): zero the p + 1 entries used (the whole arrays would cost the
    // runtime form 500 bytes per call).
    std::fill(a[0], a[0] + p + 1, 0.0);
    std::fill(a[1], a[1] + p + 1, 0.0);
    ndu[0][0] = 1.0;
    for (int j = 1; j <= p; ++j) {
        left[j] = u - knots[span + 1 - j];
        right[j] = knots[span + j] - u;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            ndu[j][r] = right[r + 1] + left[j - r];  // lower triangle: knot differences
            const double temp = ndu[r][j - 1] / ndu[j][r];
            ndu[r][j] = saved + right[r + 1] * temp;  // upper triangle: basis functions
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
    for (int j = 0; j <= p; ++j) row(0)[j] = ndu[j][p];
    const int nd = std::min(n, p);
    for (int k = nd + 1; k <= n; ++k) std::fill(row(k), row(k) + p + 1, 0.0);
    for (int r = 0; r <= p; ++r) {
        int s1 = 0, s2 = 1;
        a[0][0] = 1.0;
        for (int k = 1; k <= nd; ++k) {
            double d = 0.0;
            const int rk = r - k, pk = p - k;
            if (r >= k) {
                a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
                d = a[s2][0] * ndu[rk][pk];
            }
            const int j1 = rk >= -1 ? 1 : -rk;
            const int j2 = (r - 1 <= pk) ? k - 1 : p - r;
            for (int j = j1; j <= j2; ++j) {
                a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
                d += a[s2][j] * ndu[rk + j][pk];
            }
            if (r <= pk) {
                a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
                d += a[s2][k] * ndu[r][pk];
            }
            row(k)[r] = d;
            std::swap(s1, s2);
        }
    }
    double factor = p;
    for (int k = 1; k <= nd; ++k) {
        for (int j = 0; j <= p; ++j) row(k)[j] *= factor;
        factor *= (p - k);
    }
}

}  // namespace detail

/// The basis functions of degree `Degree` non-zero on `span` and their derivatives up to `Order`:
/// d[k][j] = d^k/du^k N_{span-Degree+j, Degree}(u) (zero for k > Degree).
template <int Degree, int Order>
struct BasisDerivatives {
    static_assert(Degree >= 1 && Degree <= kMaxDegree, "degree out of the kernel's range");
    static_assert(Order >= 0, "derivative order must be non-negative");
    std::array<std::array<double, Degree + 1>, Order + 1> d;
    int span = 0;
};

/// The NURBS Book A2.3 for a degree and order known at compile time: fixed-size, no allocation.
/// @pre knots[span] < knots[span + 1] (a span from findSpan).
template <int Degree, int Order>
BasisDerivatives<Degree, Order> evaluateBasis(const KnotVector& knots, int span, double u)
{
    BasisDerivatives<Degree, Order> b;
    b.span = span;
    detail::basisDerivativesA23<Degree>(span, u, Degree, Order, knots.data(), [&b](int k) { return b.d[k].data(); });
    return b;
}

/// The same on the span holding u (findSpan).
template <int Degree, int Order>
BasisDerivatives<Degree, Order> evaluateBasis(const KnotVector& knots, double u)
{
    return evaluateBasis<Degree, Order>(knots, findSpan(Degree, knots, u), u);
}

/// The basis functions of one span for many parameters: A2.2's Degree (Degree + 1) / 2 denominators
/// are knot differences independent of u, so their reciprocals are computed once and each
/// evaluation is divisions-free (least squares evaluates many samples per span).
template <int Degree>
class SpanBasis {
    static_assert(Degree >= 1 && Degree <= kMaxDegree, "degree out of the kernel's range");

public:
    /// @pre knots[span] < knots[span + 1]: then every difference is positive.
    SpanBasis(const KnotVector& knots, int span) : knots_(knots.data()), span_(span)
    {
        int k = 0;
        for (int j = 1; j <= Degree; ++j)
            for (int r = 0; r < j; ++r) inverse_[k++] = 1.0 / (knots[span + r + 1] - knots[span + 1 - j + r]);
    }
    int span() const { return span_; }
    /// N_{span-Degree..span, Degree}(u) into out[0..Degree].
    void functions(double u, double* out) const
    {
        detail::basisFunctionsA22<Degree>(span_, u, Degree, knots_, out,
                                          [this](int k, double numerator, double) { return numerator * inverse_[k]; });
    }

private:
    const double* knots_;  // the knot vector outlives the evaluator (a stack object of one loop)
    int span_;
    std::array<double, Degree*(Degree + 1) / 2> inverse_;
};

}  // namespace sculptline::solvers
