// Basis functions: The NURBS Book Ex. 2.3/2.4 reference values, partition of unity, knot ranges.
#include "solvers/bspline/basis.h"
#include "solvers/bspline/geometry_error.h"
#include "test_curves.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using sculptline::solvers::testing::linspace;

namespace {
// Basis values are sums of a few products of O(1) numbers: exact to a few ulps.
constexpr double kBasisTolerance = 1e-14;
const KnotVector kEx23 = {0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5};
}  // namespace

TEST(Basis, NurbsBookExample23ValuesAtFiveHalves)
{
    // Given the knot vector of The NURBS Book Ex. 2.3 and u = 5/2
    const double u = 2.5;
    // When the span and the non-vanishing functions are computed
    const int span = findSpan(2, kEx23, u);
    double N[3];
    basisFunctions(span, u, 2, kEx23, N);
    // Then span 4 holds N_{2,2} = 1/8, N_{3,2} = 6/8, N_{4,2} = 1/8 (Ex. 2.3)
    EXPECT_EQ(span, 4);
    EXPECT_NEAR(N[0], 1.0 / 8, kBasisTolerance);
    EXPECT_NEAR(N[1], 6.0 / 8, kBasisTolerance);
    EXPECT_NEAR(N[2], 1.0 / 8, kBasisTolerance);
}

TEST(Basis, NurbsBookExample24Derivatives)
{
    // The NURBS Book Ex. 2.4: first derivatives -1/2, 0, 1/2 and second derivatives 1, -2, 1 at u = 5/2.
    const Eigen::MatrixXd d = basisDerivatives(4, 2.5, 2, 2, kEx23);
    EXPECT_NEAR(d(1, 0), -0.5, kBasisTolerance);
    EXPECT_NEAR(d(1, 1), 0.0, kBasisTolerance);
    EXPECT_NEAR(d(1, 2), 0.5, kBasisTolerance);
    EXPECT_NEAR(d(2, 0), 1.0, kBasisTolerance);
    EXPECT_NEAR(d(2, 1), -2.0, kBasisTolerance);
    EXPECT_NEAR(d(2, 2), 1.0, kBasisTolerance);
}

TEST(Basis, PartitionOfUnityOnNonUnitKnotRanges)
{
    // Given clamped and unclamped knot vectors on ranges other than [0, 1]
    const std::vector<std::pair<int, KnotVector>> cases = {
        {3, {-3.5, -3.5, -3.5, -3.5, -1, 0.25, 0.25, 4, 7.2, 7.2, 7.2, 7.2}},
        {2, {10, 11, 12, 13, 15, 18, 19, 23}},
        {1, {0, 0, 1e-3, 2e-3, 2e-3}},
    };
    for (const auto& [p, U] : cases) {
        const int n = static_cast<int>(U.size()) - p - 1;
        std::vector<double> us = linspace(U[p], U[n], 997);
        us.insert(us.end(), U.begin() + p, U.begin() + n + 1);  // exactly at every knot
        for (double u : us) {
            // When the basis and its derivatives are evaluated
            const int span = findSpan(p, U, u);
            const Eigen::MatrixXd d = basisDerivatives(span, u, p, p, U);
            // Then the functions sum to one, are non-negative, and their derivatives sum to zero
            EXPECT_NEAR(d.row(0).sum(), 1.0, kBasisTolerance) << "u = " << u;
            EXPECT_GE(d.row(0).minCoeff(), -kBasisTolerance);
            for (int k = 1; k <= p; ++k) EXPECT_NEAR(d.row(k).sum(), 0.0, 1e-9 * std::pow(1e3, k)) << "k = " << k;
            EXPECT_GE(u, U[span]);
            EXPECT_LE(u, U[span + 1]);
            EXPECT_LT(U[span], U[span + 1]);
        }
    }
}

TEST(Basis, SpanAtDomainEndsIsTheOuterNonEmptySpan)
{
    EXPECT_EQ(findSpan(2, kEx23, 0.0), 2);
    EXPECT_EQ(findSpan(2, kEx23, 5.0), 7);
    EXPECT_EQ(findSpan(2, kEx23, 4.0), 7);  // the double knot 4: the span [4, 5)
    EXPECT_EQ(findSpan(2, kEx23, 1.0), 3);
}

TEST(Basis, InvalidKnotVectorsAreRejectedWithTheField)
{
    auto message = [](int p, int n, const KnotVector& U) {
        try {
            validateKnots(p, n, U);
        } catch (const GeometryError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message(2, 8, {0, 0, 0, 1, 2, 3, 4, 5, 5, 5}).find("knots: expected 11 knots"), std::string::npos);
    EXPECT_NE(message(2, 8, {0, 0, 0, 1, 3, 2, 4, 4, 5, 5, 5}).find("knots[5]: knots must be non-decreasing"),
              std::string::npos);
    EXPECT_NE(message(2, 8, {0, 0, 0, 1, NAN, 3, 4, 4, 5, 5, 5}).find("knots[4]: not a finite number"), std::string::npos);
    EXPECT_NE(message(0, 3, {0, 1, 2}).find("degree"), std::string::npos);
    EXPECT_NE(message(2, 2, {0, 0, 0, 1, 1}).find("points: degree 2 needs at least 3"), std::string::npos);
    EXPECT_NE(message(2, 3, {0, 0, 0, 0, 1, 1}).find("domain"), std::string::npos);
    EXPECT_NE(message(1, 4, {0, 0, 1, 1, 1, 2}).find("multiplicity"), std::string::npos);
    EXPECT_EQ(message(2, 8, kEx23), "no error");
}
