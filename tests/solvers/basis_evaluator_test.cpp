// The fixed-size basis evaluator (basis_evaluator.h) against The NURBS Book's reference values and
// the runtime-degree form; the periodic knot builders (periodic.h) against known vectors.
#include "solvers/bspline/basis_evaluator.h"
#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/periodic.h"
#include "test_curves.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using sculptline::solvers::testing::kExact;
using sculptline::solvers::testing::linspace;

namespace {
// Basis values are sums of a few products of O(1) numbers: exact to a few ulps.
constexpr double kBasisTolerance = 1e-14;
const KnotVector kEx23 = {0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5};

// Parameters across the domain of (p, U), and every knot of the domain exactly.
std::vector<double> sampleParameters(int p, const KnotVector& U)
{
    const int n = static_cast<int>(U.size()) - p - 1;
    std::vector<double> us = linspace(U[p], U[n], 211);
    us.insert(us.end(), U.begin() + p, U.begin() + n + 1);
    return us;
}

// The fixed form of degree P and order 2 against the runtime form, row by row.
template <int P>
void expectFixedMatchesDynamic(const KnotVector& U)
{
    for (double u : sampleParameters(P, U)) {
        const int span = findSpan(P, U, u);
        const BasisDerivatives<P, 2> fixed = evaluateBasis<P, 2>(U, span, u);
        const Eigen::MatrixXd dynamic = basisDerivatives(span, u, P, 2, U);
        EXPECT_EQ(fixed.span, span);
        for (int k = 0; k <= 2; ++k)
            for (int j = 0; j <= P; ++j)
                EXPECT_NEAR(fixed.d[k][j], dynamic(k, j), kBasisTolerance * (1.0 + std::abs(dynamic(k, j))))
                    << "p = " << P << ", u = " << u << ", k = " << k << ", j = " << j;
        // Partition of unity; the derivatives of a constant vanish.
        double sum[3] = {0.0, 0.0, 0.0}, scale[3] = {0.0, 0.0, 0.0};
        for (int k = 0; k <= 2; ++k)
            for (int j = 0; j <= P; ++j) {
                sum[k] += fixed.d[k][j];
                scale[k] += std::abs(fixed.d[k][j]);
            }
        EXPECT_NEAR(sum[0], 1.0, kBasisTolerance) << u;
        EXPECT_NEAR(sum[1], 0.0, kBasisTolerance * (1.0 + scale[1])) << u;
        EXPECT_NEAR(sum[2], 0.0, kBasisTolerance * (1.0 + scale[2])) << u;
    }
}

}  // namespace

TEST(BasisEvaluator, GivenNurbsBookExample23_WhenEvaluatedAtFiveHalves_ThenExample23And24Values)
{
    // Given U = {0,0,0,1,2,3,4,4,5,5,5}, p = 2, u = 5/2 (The NURBS Book Ex. 2.3 and 2.4)
    // When the fixed-size evaluator computes the functions and two derivatives on the span of u
    const BasisDerivatives<2, 2> b = evaluateBasis<2, 2>(kEx23, 2.5);
    // Then span 4 holds N_{2,2} = 1/8, N_{3,2} = 6/8, N_{4,2} = 1/8, first derivatives -1/2, 0, 1/2
    // and second derivatives 1, -2, 1
    EXPECT_EQ(b.span, 4);
    const double expected[3][3] = {{1.0 / 8, 6.0 / 8, 1.0 / 8}, {-0.5, 0.0, 0.5}, {1.0, -2.0, 1.0}};
    for (int k = 0; k <= 2; ++k)
        for (int j = 0; j <= 2; ++j) EXPECT_NEAR(b.d[k][j], expected[k][j], kBasisTolerance) << k << ", " << j;
}

TEST(BasisEvaluator, GivenClampedUnclampedAndRepeatedKnots_ThenFixedFormMatchesRuntimeForm)
{
    expectFixedMatchesDynamic<1>({0, 0, 1e-3, 2e-3, 2e-3});
    expectFixedMatchesDynamic<2>(kEx23);
    expectFixedMatchesDynamic<2>({10, 11, 12, 13, 15, 18, 19, 23});
    expectFixedMatchesDynamic<3>({0, 0, 0, 0, 0.1, 0.35, 0.35, 0.35, 0.6, 1, 1, 1, 1});
    expectFixedMatchesDynamic<3>({-3.5, -3.5, -3.5, -3.5, -1, 0.25, 0.25, 4, 7.2, 7.2, 7.2, 7.2});
    expectFixedMatchesDynamic<5>({0, 0, 0, 0, 0, 0, 0.5, 1.5, 1.5, 3, 3, 3, 3, 3, 3});
}

TEST(BasisEvaluator, GivenOrderAboveDegree_ThenHigherRowsAreZero)
{
    const BasisDerivatives<2, 4> b = evaluateBasis<2, 4>(kEx23, 3.3);
    for (int k = 3; k <= 4; ++k)
        for (int j = 0; j <= 2; ++j) EXPECT_EQ(b.d[k][j], 0.0);
    // The second derivative of a quadratic is piecewise constant: on [3, 4) the Ex. 2.3 knots give
    // 2 / ((4-2)(4-3)), -(that + 2/((5-3)(4-3))), ... ; check against the runtime form instead.
    const Eigen::MatrixXd ref = basisDerivatives(b.span, 3.3, 2, 2, kEx23);
    for (int j = 0; j <= 2; ++j) EXPECT_NEAR(b.d[2][j], ref(2, j), kBasisTolerance);
}

TEST(BasisEvaluator, GivenPrecomputedReciprocals_ThenSpanBasisMatchesA22)
{
    // Clamped ends and a triple interior knot: every span from findSpan is non-empty.
    const KnotVector U = {0, 0, 0, 0, 0.1, 0.35, 0.35, 0.35, 0.6, 1, 1, 1, 1};
    for (double u : sampleParameters(3, U)) {
        const int span = findSpan(3, U, u);
        const SpanBasis<3> basis(U, span);
        double n[4], ref[4];
        basis.functions(u, n);
        basisFunctions(span, u, 3, U, ref);
        EXPECT_EQ(basis.span(), span);
        for (int j = 0; j <= 3; ++j) EXPECT_NEAR(n[j], ref[j], kBasisTolerance) << u;
    }
}

TEST(BasisEvaluator, GivenCallerStorage_ThenSameAsTheAllocatingForm)
{
    const KnotVector U = {-3.5, -3.5, -3.5, -3.5, -1, 0.25, 0.25, 4, 7.2, 7.2, 7.2, 7.2};
    for (double u : sampleParameters(3, U)) {
        const int span = findSpan(3, U, u);
        double ders[5 * 4];
        basisDerivatives(span, u, 3, 4, U, ders);
        const Eigen::MatrixXd ref = basisDerivatives(span, u, 3, 4, U);
        for (int k = 0; k <= 4; ++k)
            for (int j = 0; j <= 3; ++j) EXPECT_EQ(ders[k * 4 + j], ref(k, j));
    }
}

TEST(PeriodicKnots, GivenSimpleBreaks_ThenUnwrappedVectorWithDomainStartAtIndexDegree)
{
    // Given one period's breaks 0, 0.25, 0.5, 0.8 (period 1) of a closed cubic
    const KnotVector U = periodicKnots(3, {0, 0.25, 0.5, 0.8}, 1.0);
    // Then U_i = b_{(i-3) mod 4} + floor((i-3)/4)
    const KnotVector expected = {-0.75, -0.5, -0.2, 0, 0.25, 0.5, 0.8, 1, 1.25, 1.5, 1.8};
    ASSERT_EQ(U.size(), expected.size());
    for (size_t i = 0; i < U.size(); ++i) EXPECT_DOUBLE_EQ(U[i], expected[i]) << i;
}

TEST(PeriodicKnots, GivenClampedLoop_ThenClosedCurveHasTheSameShape)
{
    // Given a clamped cubic loop (first point == last point) on [0, 2]
    const std::vector<Eigen::Vector3d> q = {{0, 0, 0}, {4, -1, 1}, {6, 5, 0}, {1, 6, -1}, {0, 0, 0}};
    const Curve3d open(3, {0, 0, 0, 0, 1, 2, 2, 2, 2}, q);
    // When its period's knots (the start knot 3 times, then the interior knot) become periodic
    const KnotVector U = periodicKnots(3, {0, 0, 0, 1}, 2.0);
    const KnotVector expected = {-1, 0, 0, 0, 1, 2, 2, 2, 3, 4, 4};
    ASSERT_EQ(U.size(), expected.size());
    for (size_t i = 0; i < U.size(); ++i) EXPECT_DOUBLE_EQ(U[i], expected[i]) << i;
    std::vector<Eigen::Vector3d> pts(q.begin(), q.end() - 1);
    for (int i = 0; i < 3; ++i) pts.push_back(q[static_cast<size_t>(i) % 4]);
    const Curve3d closed(3, U, pts, {}, true);
    // Then the closed curve is the clamped one on its domain
    EXPECT_TRUE(closed.isClosed());
    EXPECT_LT(sculptline::solvers::testing::maxDistance(open, closed, linspace(0.0, 2.0, 200)), kExact);
}

TEST(PeriodicKnots, GivenUniformSpans_ThenKnotsOfMakeClosedUniformAndOfAUnitPeriod)
{
    const KnotVector unit = periodicUniformKnots(3, 4);
    const KnotVector expected = {-0.75, -0.5, -0.25, 0, 0.25, 0.5, 0.75, 1, 1.25, 1.5, 1.75};
    ASSERT_EQ(unit.size(), expected.size());
    for (size_t i = 0; i < unit.size(); ++i) EXPECT_EQ(unit[i], expected[i]) << i;
    const KnotVector integers = periodicUniformKnots(2, 5, 0.0, 5.0);
    ASSERT_EQ(integers.size(), 10u);
    for (size_t i = 0; i < integers.size(); ++i) EXPECT_EQ(integers[i], static_cast<double>(i) - 2.0);
    EXPECT_EQ(makeClosedUniform<3>(3, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 1}}).knots(),
              periodicUniformKnots(3, 4, 0.0, 4.0));
}

TEST(PeriodicKnots, GivenInvalidPeriods_ThenGeometryError)
{
    EXPECT_THROW(periodicKnots(2, {}, 1.0), GeometryError);
    EXPECT_THROW(periodicKnots(2, {0, 0.5}, 0.0), GeometryError);
    EXPECT_THROW(periodicKnots(2, {0, 0, 0, 0.5}, 1.0), GeometryError);  // start knot above the degree
    EXPECT_THROW(periodicUniformKnots(3, 0), GeometryError);
}
