// Curve evaluation and derivatives: reference values (The NURBS Book), rational circles, closed
// curves, evaluation at knots and both ends, and validation at construction.
#include "solvers/bspline/bspline_curve.h"
#include "solvers/bspline/geometry_error.h"
#include "test_curves.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::testing;

namespace {

// Finite-difference step and the accuracy it gives for a central difference (h^2 * |C'''| ~ 1e-8).
constexpr double kFdStep = 1e-5;
constexpr double kFdTolerance = 1e-6;

Eigen::Vector3d centralDifference(const Curve3d& c, double u, int order)
{
    if (order == 1) return (c.evaluate(u + kFdStep) - c.evaluate(u - kFdStep)) / (2 * kFdStep);
    return (c.derivatives(u + kFdStep, order - 1)[order - 1] - c.derivatives(u - kFdStep, order - 1)[order - 1]) /
           (2 * kFdStep);
}

}  // namespace

TEST(Curve, EndsInterpolateTheEndPointsOfAClampedCurve)
{
    const Curve3d c = nurbsBookEx23Curve();
    EXPECT_EQ(c.evaluate(0.0), c.points().front());
    EXPECT_EQ(c.evaluate(5.0), c.points().back());
    // The NURBS Book eq. 3.7: C'(0) = p / u_{p+1} (P1 - P0), C'(1) = p / (1 - u_{m-p-1}) (Pn - Pn-1).
    const auto d0 = c.derivatives(0.0, 1);
    const auto d1 = c.derivatives(5.0, 1);
    EXPECT_LT((d0[1] - 2.0 / 1.0 * (c.points()[1] - c.points()[0])).norm(), kExact);
    EXPECT_LT((d1[1] - 2.0 / (5.0 - 4.0) * (c.points()[7] - c.points()[6])).norm(), kExact);
}

TEST(Curve, PointAtFiveHalvesIsTheBasisCombinationOfExample23)
{
    // The NURBS Book Ex. 2.3: C(5/2) = 1/8 P2 + 6/8 P3 + 1/8 P4.
    const Curve3d c = nurbsBookEx23Curve();
    const auto& P = c.points();
    const Eigen::Vector3d expected = P[2] / 8 + P[3] * 6 / 8 + P[4] / 8;
    EXPECT_LT((c.evaluate(2.5) - expected).norm(), kExact);
}

TEST(Curve, DerivativesAgreeWithFiniteDifferencesIncludingAtKnots)
{
    for (const Curve3d& c : {nurbsBookEx51Curve(), rationalCubic(), unitCircle()}) {
        const double a = c.domainStart(), b = c.domainEnd();
        for (double u : linspace(a + 0.01 * (b - a), b - 0.01 * (b - a), 37)) {
            const auto d = c.derivatives(u, 2);
            EXPECT_LT((d[0] - c.evaluate(u)).norm(), kExact);
            EXPECT_LT((d[1] - centralDifference(c, u, 1)).norm(), kFdTolerance * (1 + d[1].norm())) << u;
            EXPECT_LT((d[2] - centralDifference(c, u, 2)).norm(), 1e-4 * (1 + d[2].norm())) << u;
        }
    }
}

TEST(Curve, DerivativesAboveTheDegreeVanishForPolynomialCurves)
{
    const Curve3d c = nurbsBookEx51Curve();
    const auto d = c.derivatives(1.3, 5);
    EXPECT_EQ(d[4], Eigen::Vector3d::Zero());
    EXPECT_EQ(d[5], Eigen::Vector3d::Zero());
    EXPECT_GT(d[3].norm(), 0.0);
}

TEST(Curve, RationalCircleHasUnitRadiusAndKnownTangent)
{
    // The NURBS Book §7.5: the 9-point rational quadratic is the exact unit circle.
    const Curve3d c = unitCircle();
    for (double u : linspace(0, 1, 1000)) EXPECT_NEAR(c.evaluate(u).norm(), 1.0, kExact);
    EXPECT_LT((c.evaluate(0.5) - Eigen::Vector3d(-1, 0, 0)).norm(), kExact);
    // Rational end derivative (The NURBS Book eq. 4.9): C'(0) = p/u_{p+1} (w1/w0) (P1 - P0) = 8 sqrt(2)/2 (0,1,0).
    const auto d = c.derivatives(0.0, 1);
    EXPECT_LT((d[1] - Eigen::Vector3d(0, 8 * std::sqrt(0.5), 0)).norm(), kExact);
}

TEST(Curve, ClosedCurveIsPeriodicAndSmoothAcrossTheSeam)
{
    const Curve3d c = closedCubic();
    const double a = c.domainStart(), T = c.domainEnd() - a;
    for (double u : linspace(a, a + T, 50)) {
        EXPECT_LT((c.evaluate(u) - c.evaluate(u + T)).norm(), kExact);
        EXPECT_LT((c.evaluate(u) - c.evaluate(u - 3 * T)).norm(), 1e-11);
    }
    // C2 at the seam: left and right limits of the first two derivatives agree.
    const double eps = 1e-9;
    const auto left = c.derivatives(a + T - eps, 2), right = c.derivatives(a + eps, 2);
    EXPECT_LT((left[0] - right[0]).norm(), 1e-7);
    EXPECT_LT((left[1] - right[1]).norm(), 1e-6);
    EXPECT_LT((left[2] - right[2]).norm(), 1e-5);
}

TEST(Curve, TwoDimensionalCurvesEvaluate)
{
    const std::vector<Eigen::Vector2d> pts = {{0, 0}, {1, 1}, {2, 0}};
    const Curve2d c(2, {0, 0, 0, 1, 1, 1}, pts);
    // Quadratic Bezier at 1/2: (P0 + 2 P1 + P2) / 4.
    EXPECT_LT((c.evaluate(0.5) - Eigen::Vector2d(1, 0.5)).norm(), kExact);
}

TEST(Curve, InvalidGeometryIsRejectedAtConstruction)
{
    const std::vector<Eigen::Vector3d> pts(4, Eigen::Vector3d::Zero());
    auto message = [&](auto&& make) {
        try {
            make();
        } catch (const GeometryError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message([&] { Curve3d(3, {0, 0, 0, 1, 1, 1, 1}, pts); }).find("knots: expected 8"), std::string::npos);
    EXPECT_NE(message([&] { Curve3d(3, {0, 0, 0, 0, 1, 1, 1, 1}, pts, {1, 1, -1, 1}); }).find("weights[2]: must be positive"),
              std::string::npos);
    EXPECT_NE(message([&] { Curve3d(3, {0, 0, 0, 0, 1, 1, 1, 1}, pts, {1, 1, 0, 1}); }).find("weights[2]"),
              std::string::npos);
    EXPECT_NE(message([&] { Curve3d(3, {0, 0, 0, 0, 1, 1, 1, 1}, pts, {1, 1}); }).find("weights: expected one per point"),
              std::string::npos);
    auto bad = pts;
    bad[1].y() = std::numeric_limits<double>::infinity();
    EXPECT_NE(message([&] { Curve3d(3, {0, 0, 0, 0, 1, 1, 1, 1}, bad); }).find("points[1]: not a finite"),
              std::string::npos);
    EXPECT_NE(message([&] { Curve3d(3, {0, 0, 0, 0, 1, 1, 1, 1}, pts, {}, true); }).find("closed"), std::string::npos);
    EXPECT_NE(message([&] { Curve3d(0, {0, 1, 2, 3}, pts); }).find("degree"), std::string::npos);
    // A closed curve whose wrapped points do not repeat.
    const Curve3d good = closedCubic();
    auto open = good.points();
    open.back() += Eigen::Vector3d(1, 0, 0);
    EXPECT_NE(message([&] { Curve3d(3, good.knots(), open, {}, true); }).find("must repeat"), std::string::npos);
    EXPECT_EQ(message([&] { Curve3d(3, good.knots(), good.points(), {}, true); }), "no error");
}

TEST(Curve, NonFiniteParameterIsAnErrorNotGarbage)
{
    const Curve3d c = nurbsBookEx23Curve();
    EXPECT_THROW(c.evaluate(std::nan("")), GeometryError);
    // Outside the domain an open curve clamps (documented), it does not extrapolate.
    EXPECT_EQ(c.evaluate(-7.0), c.evaluate(0.0));
}

TEST(Curve, InteriorKnotOfMultiplicityDegreePlusOneIsRefusedNamingTheKnots)
{
    // Two cubic pieces that need not meet (C^-1 at 0.5, The NURBS Book P2.5): the kernel's
    // algorithms (A5.1, A5.4, A5.8, clamping, compatible layouts) presume multiplicity <= degree.
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < 8; ++i) pts.emplace_back(i, i % 3, 0);
    const KnotVector knots{0, 0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1, 1, 1};
    try {
        Curve3d(3, knots, pts);
        FAIL() << "a curve broken at an interior knot was accepted";
    } catch (const GeometryError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("knots: interior knot 0.5 has multiplicity 4", 0), 0u) << e.what();
    }
}

TEST(Curve, InteriorKnotOfMultiplicityDegreeIsAValidC0Curve)
{
    // Multiplicity = degree: a C0 corner, the curve passes through the shared control point.
    const std::vector<Eigen::Vector3d> pts{{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0}, {4, 1, 0}, {5, 1, 0}, {6, 0, 0}};
    const Curve3d c(3, {0, 0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1, 1}, pts);
    EXPECT_EQ(c.evaluate(0.5), pts[3]);
}
