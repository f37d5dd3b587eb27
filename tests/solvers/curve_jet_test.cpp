// The kernel's curve jet (curve_jet.h) against BSplineCurve::derivatives, and the foot-point Newton
// step (projection.h).
#include "solvers/bspline/curve_jet.h"
#include "solvers/bspline/projection.h"
#include "test_curves.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::testing;

namespace {

template <int Dim>
void expectJetMatchesDerivatives(const BSplineCurve<Dim>& c)
{
    const CurveJet<Dim> jet(c);
    std::vector<double> us = linspace(c.domainStart(), c.domainEnd(), 97);
    us.insert(us.end(), c.knots().begin() + c.degree(), c.knots().begin() + c.pointCount() + 1);  // at the knots
    for (double u : us) {
        // A closed curve's domain end: the jet's left-hand limits, derivatives()' wrap to the start.
        if (c.isClosed() && u == c.domainEnd()) continue;
        typename CurveJet<Dim>::Point x, d1, d2;
        jet.evaluate(u, x, d1, d2);
        const auto ref = c.derivatives(u, 2);
        const double scale = 1.0 + ref[0].norm() + ref[1].norm() + ref[2].norm();
        EXPECT_LT((x - ref[0]).norm(), kExact * scale) << u;
        EXPECT_LT((d1 - ref[1]).norm(), kExact * scale) << u;
        EXPECT_LT((d2 - ref[2]).norm(), kExact * scale) << u;
        EXPECT_LT((jet.derivative(u) - ref[1]).norm(), kExact * scale) << u;
    }
}

}  // namespace

TEST(CurveJet, GivenPolynomialRationalClosedAnd2dCurves_WhenEvaluated_ThenMatchesDerivatives)
{
    expectJetMatchesDerivatives(nurbsBookEx23Curve());
    expectJetMatchesDerivatives(nurbsBookEx51Curve());
    expectJetMatchesDerivatives(unitCircle());
    expectJetMatchesDerivatives(rationalCubic());
    expectJetMatchesDerivatives(closedCubic());
    expectJetMatchesDerivatives(Curve3d(1, {0, 0, 1, 1}, {{0, 0, 0}, {1, 2, 3}}));
    expectJetMatchesDerivatives(makeClosedUniform<2>(2, {{0, 0}, {3, -1}, {4, 2}, {1, 4}, {-1, 2}}, {1, 3, 0.5, 2, 1}));
}

TEST(CurveJet, GivenClosedCurve_WhenEvaluatedAtTheDomainEnd_ThenLeftLimitsNotTheStart)
{
    // A periodic quadratic is C1 at its seam: the position and tangent at the end are the start's,
    // the second derivative is the last span's.
    const Curve2d c = makeClosedUniform<2>(2, {{0, 0}, {3, -1}, {4, 2}, {1, 4}, {-1, 2}});
    const CurveJet2d jet(c);
    Eigen::Vector2d x, d1, d2;
    jet.evaluate(c.domainEnd(), x, d1, d2);
    const auto start = c.derivatives(c.domainStart(), 2);
    EXPECT_LT((x - start[0]).norm(), kExact);
    EXPECT_LT((d1 - start[1]).norm(), kExact);
    // Last span [4, 5] of the uniform quadratic: C'' = P_4 - 2 P_5 + P_6 with P_5, P_6 = P_0, P_1.
    const Eigen::Vector2d expected = c.points()[4] - 2 * c.points()[5] + c.points()[6];
    EXPECT_LT((d2 - expected).norm(), kExact);
}

TEST(CurveJet, GivenNonRationalCurve_ThenSameBitsAsDerivatives)
{
    // Without weights the jet skips the quotient rule: the same sums as derivatives().
    const Curve3d c = nurbsBookEx51Curve();
    const CurveJet3d jet(c);
    for (double u : linspace(0.0, 5.0, 53)) {
        Eigen::Vector3d x, d1, d2;
        jet.evaluate(u, x, d1, d2);
        const auto ref = c.derivatives(u, 2);
        EXPECT_EQ(x, ref[0]);
        EXPECT_EQ(d1, ref[1]);
        EXPECT_EQ(d2, ref[2]);
    }
}

TEST(FootPointNewtonStep, GivenLine_ThenOneStepReachesTheFootPoint)
{
    // f is linear on a line: Newton is exact in one step.
    const Eigen::Vector2d c(0.9, 0.0), d1(1.0, 0.0), d2(0.0, 0.0), x(0.3, 1.0);
    double u = 0.9;
    EXPECT_TRUE(footPointNewtonStep(c, d1, d2, x, 0.0, 1.0, u));
    EXPECT_NEAR(u, 0.3, 1e-15);
    // Clamped to the interval.
    u = 0.9;
    EXPECT_TRUE(footPointNewtonStep(c, d1, d2, x, 0.5, 1.0, u));
    EXPECT_EQ(u, 0.5);
}

TEST(FootPointNewtonStep, GivenPointBeyondTheCentreOfCurvature_ThenNoStep)
{
    // C(u) = (u, u^2) at u = 0, x = (0, 10): f' = C''·(C - x) + |C'|^2 = -20 + 1 < 0.
    double u = 0.0;
    EXPECT_FALSE(footPointNewtonStep(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 2),
                                     Eigen::Vector2d(0, 10), -1.0, 1.0, u));
    EXPECT_EQ(u, 0.0);
}

TEST(FootPointNewtonStep, GivenJetOfACircle_WhenIterated_ThenConvergesToTheProjection)
{
    const Curve3d circle = unitCircle();
    const CurveJet3d jet(circle);
    const Eigen::Vector3d x(2.0, 1.5, 0.3);
    double u = 0.05;
    for (int it = 0; it < 20; ++it) {
        Eigen::Vector3d c, d1, d2;
        jet.evaluate(u, c, d1, d2);
        if (!footPointNewtonStep(c, d1, d2, x, 0.0, 1.0, u)) break;
    }
    const CurveProjection<3> ref = projectToCurve(circle, x);
    EXPECT_NEAR(u, ref.u, 1e-12);
    EXPECT_NEAR((circle.evaluate(u) - x).norm(), ref.distance, 1e-12);
}
