// Constraint-based surface deformation (thesis 002_d9515b9d07f9cfd1 §6.2, Table 6-1). Given / When / Then.
#include "solvers/deformation/surface_deformation.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/deformation/deformation_region.h"
#include "solvers/deformation/isocurve_deformation.h"
#include "solvers/math_constants.h"

#include "tests/deformation/deformation_fixtures.h"

#include <Eigen/Geometry>
#include <Eigen/QR>
#include <gtest/gtest.h>
#include <cmath>

using namespace sculptline::solvers;
using namespace sculptline::solvers::deformation;
using sculptline::deformtest::wavySurface;

namespace {

// Linear constraints hold to round-off; 1e-9 model units on nets ~10 units across leaves 1e5 × u.
constexpr double kConstraintTolerance = 1e-9;
// Normals and cross tangents: 1e-6 rad, the angle a person could not see even magnified 1000×.
constexpr double kAngleTolerance = 1e-6;
// Two computations of the same linear map (QR path vs Eigen's COD; factored vs one-shot): a few
// hundred round-offs of unit-sized control points.
constexpr double kSameSolutionTolerance = 1e-10;

SurfaceConstraint position(double u, double v, const Eigen::Vector3d& value)
{
    SurfaceConstraint c;
    c.type = SurfaceConstraintType::Position;
    c.uv = {u, v};
    c.value = value;
    return c;
}

SurfaceConstraint normal(double u, double v, const Eigen::Vector3d& value)
{
    SurfaceConstraint c = position(u, v, value);
    c.type = SurfaceConstraintType::Normal;
    return c;
}

BSplineCurve<3> line3(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    return BSplineCurve<3>(1, {0, 0, 1, 1}, {a, b});
}

BSplineCurve<2> line2(const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
    return BSplineCurve<2>(1, {0, 0, 1, 1}, {a, b});
}

double maxChange(const Surface3d& a, const Surface3d& b)
{
    double worst = 0.0;
    for (size_t i = 0; i < a.points().size(); ++i) worst = std::max(worst, (a.points()[i] - b.points()[i]).norm());
    return worst;
}


}  // namespace

TEST(SurfaceDeformation, GivenPositionConstraints_WhenDisplacementObjective_ThenMetAndEqualToPseudoInverse)
{
    // Given: two points to move on a 7 × 6 net.
    const Surface3d s = wavySurface(7, 6);
    const std::vector<SurfaceConstraint> cs = {position(0.3, 0.4, s.evaluate(0.3, 0.4) + Eigen::Vector3d(0.1, -0.2, 0.8)),
                                               position(0.7, 0.6, s.evaluate(0.7, 0.6) + Eigen::Vector3d(0, 0, -0.5))};
    DeformationOptions options;
    options.objective = Objective::Displacement;
    // When
    DeformationReport report;
    const Surface3d out = deformSurface(s, cs, options, &report);
    // Then: the points are met...
    for (const auto& c : cs) EXPECT_LT((out.evaluate(c.uv.x(), c.uv.y()) - c.value).norm(), kConstraintTolerance);
    EXPECT_LT(report.maxResidual, kConstraintTolerance);
    EXPECT_FALSE(report.compromise);
    // ...and the change is d = F⁺ b (eq. 6-9), computed independently: F from basisFunctions
    // (The NURBS Book A2.2), per coordinate, pseudo-inverse by Eigen's COD.
    const int n = s.countU() * s.countV();
    Eigen::MatrixXd F = Eigen::MatrixXd::Zero(2, n);
    Eigen::MatrixXd b(2, 3);
    for (int r = 0; r < 2; ++r) {
        const double u = cs[r].uv.x(), v = cs[r].uv.y();
        const int su = findSpan(3, s.knotsU(), u), sv = findSpan(3, s.knotsV(), v);
        double nu[4], nv[4];
        basisFunctions(su, u, 3, s.knotsU(), nu);
        basisFunctions(sv, v, 3, s.knotsV(), nv);
        for (int a = 0; a <= 3; ++a) {
            for (int c = 0; c <= 3; ++c) F(r, (su - 3 + a) * s.countV() + sv - 3 + c) = nu[a] * nv[c];
        }
        b.row(r) = (cs[r].value - s.evaluate(u, v)).transpose();
    }
    const Eigen::MatrixXd d = F.completeOrthogonalDecomposition().solve(b);
    for (int k = 0; k < n; ++k) {
        EXPECT_LT((out.points()[k] - s.points()[k] - d.row(k).transpose()).norm(), kSameSolutionTolerance) << k;
    }
}

TEST(SurfaceDeformation, GivenBlockedPointsAndABound_WhenDeformed_ThenThoseAreExactlyUnchanged)
{
    // Given: a 12 × 12 net, a bound square around the middle, two blocked points inside it.
    const Surface3d s = wavySurface(12, 12);
    DeformationOptions options;
    options.bound = {{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}};
    options.blocked = {{5, 5}, {6, 7}};
    const std::vector<SurfaceConstraint> cs = {position(0.5, 0.5, s.evaluate(0.5, 0.5) + Eigen::Vector3d(0, 0, 1))};
    for (Objective objective : {Objective::Force, Objective::Displacement}) {
        options.objective = objective;
        // When
        DeformationReport report;
        const Surface3d out = deformSurface(s, cs, options, &report);
        // Then: bitwise unchanged outside the bound and at the blocked points; the constraint met.
        const std::vector<bool> inside = insideBound(s, options.bound);
        int outside = 0;
        for (int i = 0; i < 12; ++i) {
            for (int j = 0; j < 12; ++j) {
                const bool blocked = (i == 5 && j == 5) || (i == 6 && j == 7);
                if (!inside[static_cast<size_t>(i * 12 + j)] || blocked) {
                    EXPECT_EQ(out.point(i, j), s.point(i, j)) << i << ", " << j;
                    ++outside;
                }
            }
        }
        EXPECT_GT(outside, 100);  // the bound really excludes most of the net
        EXPECT_LT(report.maxResidual, kConstraintTolerance);
        EXPECT_EQ(report.moved, 144 - outside);
    }
}

TEST(SurfaceDeformation, GivenANormalConstraint_WhenDeformed_ThenTheNormalIsParallelWithin1e6Rad)
{
    const Surface3d s = wavySurface(8, 8);
    const Eigen::Vector3d target = Eigen::Vector3d(0.3, -0.2, 1.0).normalized();
    DeformationReport report;
    const Surface3d out = deformSurface(s, {normal(0.35, 0.6, target)}, {}, &report);
    const double angle = std::acos(std::min(1.0, std::abs(out.normal(0.35, 0.6).dot(target))));
    EXPECT_LT(angle, kAngleTolerance);
    EXPECT_LT(report.maxResidual, kAngleTolerance);
    EXPECT_GT(maxChange(s, out), 0.01);  // it had to move: the normal there was not that before
}

TEST(SurfaceDeformation, GivenStiffness_WhenDeformed_ThenTheSurfaceMovesThatFractionOfTheWay)
{
    // Eq. 6-20: f_t = λ D_t. Linear constraints: the whole change scales with λ.
    const Surface3d s = wavySurface(9, 7);
    const std::vector<SurfaceConstraint> cs = {position(0.5, 0.5, s.evaluate(0.5, 0.5) + Eigen::Vector3d(0.2, 0, 1)),
                                               normal(0.2, 0.3, Eigen::Vector3d(0.1, 0.2, 1.0))};
    const Surface3d full = deformSurface(s, cs);
    for (double lambda : {0.25, 0.5, 0.8}) {
        DeformationOptions options;
        options.stiffness = lambda;
        DeformationReport report;
        const Surface3d part = deformSurface(s, cs, options, &report);
        for (size_t k = 0; k < s.points().size(); ++k) {
            const Eigen::Vector3d expected = s.points()[k] + lambda * (full.points()[k] - s.points()[k]);
            EXPECT_LT((part.points()[k] - expected).norm(), kSameSolutionTolerance);
        }
        const Eigen::Vector3d reached = part.evaluate(0.5, 0.5);
        EXPECT_LT((reached - (s.evaluate(0.5, 0.5) + lambda * Eigen::Vector3d(0.2, 0, 1))).norm(), kConstraintTolerance);
        EXPECT_LT(report.maxResidual, kConstraintTolerance);
    }
}

TEST(SurfaceDeformation, GivenASymmetricSurfaceAndConstraint_WhenDeformed_ThenTheResultIsSymmetric)
{
    // Given: the net is symmetric under i ↔ nu−1−i (x ↦ nu−1−x); the constraint sits on the mirror line.
    const Surface3d s = wavySurface(9, 8);
    const std::vector<SurfaceConstraint> cs = {position(0.5, 0.3, s.evaluate(0.5, 0.3) + Eigen::Vector3d(0, 0.1, 0.7))};
    for (Objective objective : {Objective::Force, Objective::Displacement}) {
        DeformationOptions options;
        options.objective = objective;
        const Surface3d out = deformSurface(s, cs, options);
        for (int i = 0; i < 9; ++i) {
            for (int j = 0; j < 8; ++j) {
                const Eigen::Vector3d a = out.point(i, j), b = out.point(8 - i, j);
                EXPECT_NEAR(a.x(), 8.0 - b.x(), kSameSolutionTolerance);
                EXPECT_NEAR(a.y(), b.y(), kSameSolutionTolerance);
                EXPECT_NEAR(a.z(), b.z(), kSameSolutionTolerance);
            }
        }
    }
}

TEST(SurfaceDeformation, GivenDegenerateInput_WhenFactored_ThenAnErrorNamesTheField)
{
    const Surface3d s = wavySurface(6, 6);
    auto message = [&](const std::vector<SurfaceConstraint>& cs, const DeformationOptions& o = {}) {
        try {
            deformSurface(s, cs, o);
        } catch (const GeometryError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message({position(1.5, 0.5, Eigen::Vector3d::Zero())}).find("constraints[0].uv"), std::string::npos);
    EXPECT_NE(message({position(std::nan(""), 0.5, Eigen::Vector3d::Zero())}).find("constraints[0].uv"), std::string::npos);
    EXPECT_NE(message({position(0.5, 0.5, Eigen::Vector3d(std::nan(""), 0, 0))}).find("constraints[0].value"),
              std::string::npos);
    EXPECT_NE(message({normal(0.5, 0.5, Eigen::Vector3d::Zero())}).find("constraints[0].value"), std::string::npos);
    DeformationOptions badBlock;
    badBlock.blocked = {{6, 0}};
    EXPECT_NE(message({}, badBlock).find("blocked[0]"), std::string::npos);
    DeformationOptions badStiffness;
    badStiffness.stiffness = 1.5;
    EXPECT_NE(message({}, badStiffness).find("stiffness"), std::string::npos);
}

TEST(SurfaceDeformation, GivenADrag_WhenFactoredOnceAndSolvedPerEvent_ThenEachEqualsTheOneShotSolve)
{
    // Given: a point, a normal and a curve constraint, factored once as at the start of a drag.
    const Surface3d s = wavySurface(10, 9);
    SurfaceConstraint curve;
    curve.type = SurfaceConstraintType::Curve;
    curve.domain = line2({0.2, 0.8}, {0.8, 0.8});
    std::vector<SurfaceConstraint> cs = {position(0.4, 0.4, s.evaluate(0.4, 0.4)), normal(0.7, 0.3, s.normal(0.7, 0.3)),
                                         curve};
    cs[2].target = line3(s.evaluate(0.2, 0.8), s.evaluate(0.8, 0.8));
    SurfaceDeformationSolver solver;
    solver.factor(s, cs);
    // When: the dragged point and the target curve move over 20 events.
    for (int e = 1; e <= 20; ++e) {
        const double t = 0.05 * e;
        cs[0].value = s.evaluate(0.4, 0.4) + Eigen::Vector3d(0.1 * t, 0, t);
        cs[2].target = line3(s.evaluate(0.2, 0.8) + Eigen::Vector3d(0, 0, t), s.evaluate(0.8, 0.8) + Eigen::Vector3d(0, 0, -t));
        DeformationReport dragged, fresh;
        const Surface3d a = solver.solve(cs, &dragged);
        const Surface3d b = deformSurface(s, cs, {}, &fresh);
        // Then
        EXPECT_LT(maxChange(a, b), kSameSolutionTolerance) << "event " << e;
        EXPECT_LT(dragged.maxResidual, kConstraintTolerance);
        EXPECT_EQ(dragged.keyPoints.size(), fresh.keyPoints.size());
    }
}

TEST(SurfaceDeformation, GivenADistanceConstraint_WhenDeformed_ThenTheTwoPointsAreThatFarApart)
{
    const Surface3d s = wavySurface(8, 8);
    SurfaceConstraint c;
    c.type = SurfaceConstraintType::Distance;
    c.uv = {0.2, 0.5};
    c.uv2 = {0.8, 0.5};
    c.distance = 6.0;  // currently 4.2 apart (x from 1.4 to 5.6): a large non-linear stretch
    DeformationReport report;
    const Surface3d out = deformSurface(s, {c}, {}, &report);
    EXPECT_NEAR((out.evaluate(0.8, 0.5) - out.evaluate(0.2, 0.5)).norm(), 6.0, kConstraintTolerance);
    EXPECT_LT(report.maxResidual, kConstraintTolerance);
    EXPECT_LE(report.gaussNewtonSteps, 20);
}

TEST(SurfaceDeformation, GivenATargetCurveWithoutDomain_WhenDeformed_ThenKeyPointsFollowEq624AndAreMet)
{
    // Given: a target 0.6 above the surface along v = 0.5, projected onto the surface (its feet).
    const Surface3d s = wavySurface(12, 8);
    SurfaceConstraint c;
    c.type = SurfaceConstraintType::Curve;
    c.target = line3(Eigen::Vector3d(2.0, 3.5, 1.2), Eigen::Vector3d(9.0, 3.5, 1.2));
    DeformationReport report;
    SurfaceDeformationSolver solver;
    solver.factor(s, {c});
    const Surface3d out = solver.solve({c}, &report);
    // Then: eq. 6-24 — the feet run along U over the spans between them (no bends: no extra).
    const auto& feet = solver.keyPointLocations()[0];
    const int spans = std::abs(findSpan(3, s.knotsU(), feet.back().x()) - findSpan(3, s.knotsU(), feet.front().x())) + 1;
    EXPECT_EQ(static_cast<int>(feet.size()), spans);
    EXPECT_GE(spans, 5);
    ASSERT_EQ(report.keyPoints.size(), feet.size());
    for (size_t k = 0; k < feet.size(); ++k) {
        EXPECT_LT((out.evaluate(feet[k].x(), feet[k].y()) - report.keyPoints[k]).norm(), kConstraintTolerance);
    }
    EXPECT_LT(report.maxResidual, kConstraintTolerance);
}

// The key points of a target without a domain are evenly spaced along its length, so the same
// shape parametrized at another speed (a stroke fitted with other control points) gives the same
// key points and the same sculpt.
TEST(SurfaceDeformation, GivenOneTargetAtTwoSpeeds_WhenKeyPointsPlaced_ThenTheSameKeyPointsEvenlyAlongIt)
{
    const Surface3d s = wavySurface(12, 8);
    const Eigen::Vector3d a(2.0, 3.5, 1.2), b(9.0, 3.5, 1.2);
    SurfaceConstraint even, uneven;
    even.type = uneven.type = SurfaceConstraintType::Curve;
    even.target = line3(a, b);
    // The same segment, its control points bunched at the start: its speed varies ~10x
    uneven.target = BSplineCurve<3>(3, {0, 0, 0, 0, 1, 1, 1, 1}, {a, a + 0.02 * (b - a), a + 0.1 * (b - a), b});
    const KeyPoints ke = curveKeyPoints(s, even), ku = curveKeyPoints(s, uneven);
    ASSERT_EQ(ke.t.size(), ku.t.size());
    ASSERT_GE(ke.t.size(), 3u);
    const double step = (b - a).norm() / static_cast<double>(ke.t.size() - 1);
    for (size_t k = 0; k < ke.t.size(); ++k) {
        const Eigen::Vector3d pe = even.target->evaluate(ke.t[k]), pu = uneven.target->evaluate(ku.t[k]);
        EXPECT_NEAR((pe - a).norm(), step * static_cast<double>(k), 1e-3) << k;
        EXPECT_NEAR((pu - pe).norm(), 0.0, 1e-3) << k;
        EXPECT_NEAR((ke.uv[k] - ku.uv[k]).norm(), 0.0, 1e-3) << k;
    }
}

TEST(SurfaceDeformation, GivenACurveTangentConstraint_WhenDeformed_ThenTheCrossTangentPointsAlongValue)
{
    const Surface3d s = wavySurface(10, 10);
    SurfaceConstraint c;
    c.type = SurfaceConstraintType::CurveTangent;
    c.domain = line2({0.2, 0.3}, {0.8, 0.3});
    c.value = Eigen::Vector3d(0, 1, 0.5);
    DeformationReport report;
    const Surface3d out = deformSurface(s, {c}, {}, &report);
    EXPECT_LT(report.maxResidual, kAngleTolerance);
    // Checked between the key points too? No: only the key points are constrained (eq. 6-24);
    // at one of them by hand.
    const Eigen::Vector3d sv = out.derivatives(0.2, 0.3, 1)[0][1];
    EXPECT_LT(std::atan2(sv.cross(c.value).norm(), std::abs(sv.dot(c.value))), kAngleTolerance);
}

TEST(SurfaceDeformation, GivenContradictoryConstraints_WhenDeformed_ThenALeastSquaresCompromiseIsFlagged)
{
    const Surface3d s = wavySurface(6, 6);
    const Eigen::Vector3d p = s.evaluate(0.5, 0.5);
    DeformationReport report;
    deformSurface(s, {position(0.5, 0.5, p + Eigen::Vector3d(0, 0, 1)), position(0.5, 0.5, p - Eigen::Vector3d(0, 0, 1))},
                  {}, &report);
    EXPECT_TRUE(report.compromise);
    EXPECT_FALSE(report.message.empty());
    EXPECT_NEAR(report.residuals[0], 1.0, kConstraintTolerance);  // the midpoint: 1 from each
    EXPECT_NEAR(report.residuals[1], 1.0, kConstraintTolerance);
}

TEST(SurfaceDeformation, GivenOnePulledPoint_WhenForceObjective_ThenTheChangeIsSmootherThanLeastDisplacement)
{
    // The default objective's reason: both meet the constraint exactly; the force objective's
    // change has a smaller external-force change ‖K d‖ (no spike at the dragged points).
    const Surface3d s = wavySurface(20, 20);
    const std::vector<SurfaceConstraint> cs = {position(0.5, 0.5, s.evaluate(0.5, 0.5) + Eigen::Vector3d(0, 0, 1))};
    DeformationOptions displacement;
    displacement.objective = Objective::Displacement;
    DeformationReport a, b;
    const Surface3d byDisplacement = deformSurface(s, cs, displacement, &a);
    const Surface3d byForce = deformSurface(s, cs, {}, &b);
    EXPECT_LT(a.maxResidual, kConstraintTolerance);
    EXPECT_LT(b.maxResidual, kConstraintTolerance);
    EXPECT_LT(forceChange(s, byForce), 0.5 * forceChange(s, byDisplacement));
}

TEST(IsocurveDeformation, GivenOnePoint_WhenIsocurves_ThenEqualToTheGlobalLeastDisplacement)
{
    // The tensor-product row N_i(u)N_j(v) has pseudo-inverse N_i N_j / (ΣN_i² ΣN_j²): the U-curve
    // step (eq. 6-17) then the V-curve steps (eq. 6-18) produce exactly that.
    const Surface3d s = wavySurface(9, 7);
    const std::vector<SurfaceConstraint> cs = {position(0.42, 0.63, s.evaluate(0.42, 0.63) + Eigen::Vector3d(0.3, -0.1, 1))};
    DeformationOptions displacement;
    displacement.objective = Objective::Displacement;
    DeformationReport report;
    const Surface3d byIsocurves = deformByIsocurves(s, cs, {}, &report);
    EXPECT_LT(maxChange(byIsocurves, deformSurface(s, cs, displacement)), kSameSolutionTolerance);
    EXPECT_LT(report.maxResidual, kConstraintTolerance);
}

TEST(IsocurveDeformation, GivenPointsAndACurve_WhenIsocurves_ThenAllMetAndBlockedPointsStay)
{
    const Surface3d s = wavySurface(14, 12);
    SurfaceConstraint curve;
    curve.type = SurfaceConstraintType::Curve;
    curve.domain = line2({0.2, 0.75}, {0.8, 0.75});
    curve.target = line3(s.evaluate(0.2, 0.75) + Eigen::Vector3d(0, 0, 0.5), s.evaluate(0.8, 0.75) + Eigen::Vector3d(0, 0, 0.5));
    const std::vector<SurfaceConstraint> cs = {position(0.3, 0.3, s.evaluate(0.3, 0.3) + Eigen::Vector3d(0, 0, 1)),
                                               position(0.6, 0.35, s.evaluate(0.6, 0.35) + Eigen::Vector3d(0, 0.2, -0.5)),
                                               curve};
    DeformationOptions options;
    options.blocked = {{0, 0}, {13, 11}};
    DeformationReport report;
    const Surface3d out = deformByIsocurves(s, cs, options, &report);
    EXPECT_LT(report.maxResidual, kConstraintTolerance);
    EXPECT_FALSE(report.compromise);
    EXPECT_EQ(out.point(0, 0), s.point(0, 0));
    EXPECT_EQ(out.point(13, 11), s.point(13, 11));
    EXPECT_GE(report.keyPoints.size(), 2u);
}

TEST(IsocurveDeformation, GivenANormalConstraint_WhenIsocurves_ThenAnErrorNamesIt)
{
    const Surface3d s = wavySurface(6, 6);
    EXPECT_THROW(deformByIsocurves(s, {normal(0.5, 0.5, Eigen::Vector3d::UnitZ())}), GeometryError);
}

TEST(SurfaceDeformation, GivenABound_WhenForceObjective_ThenTheChangeFadesTowardsIt)
{
    // §6.2.4: the fixed nodes' force rows keep the change and its slope small at the bound, so the
    // inside points next to it move far less than the middle (least displacement has no such fade:
    // there only the constraint's support moves at all).
    const Surface3d s = wavySurface(20, 20);
    DeformationOptions options;
    options.bound = {{0.2, 0.2}, {0.8, 0.2}, {0.8, 0.8}, {0.2, 0.8}};
    const Surface3d out =
        deformSurface(s, {position(0.5, 0.5, s.evaluate(0.5, 0.5) + Eigen::Vector3d(0, 0, 1))}, options);
    const std::vector<bool> inside = insideBound(s, options.bound);
    double rim = 0.0, all = 0.0;
    for (int i = 1; i + 1 < 20; ++i) {
        for (int j = 1; j + 1 < 20; ++j) {
            if (!inside[static_cast<size_t>(i * 20 + j)]) continue;
            const double moved = (out.point(i, j) - s.point(i, j)).norm();
            all = std::max(all, moved);
            const bool nextToOutside = !inside[static_cast<size_t>((i - 1) * 20 + j)] || !inside[static_cast<size_t>((i + 1) * 20 + j)] ||
                                       !inside[static_cast<size_t>(i * 20 + j - 1)] || !inside[static_cast<size_t>(i * 20 + j + 1)];
            if (nextToOutside) rim = std::max(rim, moved);
        }
    }
    // The rim is one bar in from the bound, ~6 bars from the middle; measured ratio 0.13 (0.15
    // leaves room for round-off and nothing more: a regression in the fade shows up here).
    EXPECT_LT(rim, 0.15 * all);
    EXPECT_GT(rim, 0.0);  // but it does move: the fade is spread, not a step
}

TEST(SurfaceDeformation, GivenANormalInTheSurfacesPlaneAtACorner_WhenDeformed_ThenNotMetIsReported)
{
    // S_u·n = S_v·n = 0 with n along the corner's own S_u: the least change collapses S_u, the rows
    // hold and the normal is undefined — a compromise, said so, not a silent success.
    const Surface3d s = wavySurface(6, 6, 0.0);
    DeformationReport report;
    deformSurface(s, {normal(0.0, 0.0, Eigen::Vector3d::UnitX())}, {}, &report);
    EXPECT_TRUE(report.compromise);
    EXPECT_NE(report.message.find("constraints[0]"), std::string::npos);
}

TEST(SurfaceDeformation, GivenACurveTangentAndStiffness_WhenDeformed_ThenItsRowsMoveThatFractionAndAreMet)
{
    const Surface3d s = wavySurface(10, 10);
    SurfaceConstraint c;
    c.type = SurfaceConstraintType::CurveTangent;
    c.domain = line2({0.2, 0.3}, {0.8, 0.3});
    c.value = Eigen::Vector3d(0, 1, 0.5);
    const Surface3d full = deformSurface(s, {c});
    DeformationOptions half;
    half.stiffness = 0.5;
    DeformationReport report;
    const Surface3d out = deformSurface(s, {c}, half, &report);
    EXPECT_FALSE(report.compromise) << report.message;
    EXPECT_LT(report.maxResidual, kConstraintTolerance);
    for (size_t k = 0; k < s.points().size(); ++k) {
        EXPECT_LT((out.points()[k] - (s.points()[k] + 0.5 * (full.points()[k] - s.points()[k]))).norm(), kSameSolutionTolerance);
    }
}

TEST(SurfaceDeformation, GivenABentTarget_WhenKeyPointsAreCounted_ThenMoreThanForAStraightOne)
{
    // Eq. 6-24 counts the spans crossed; a target that turns gets one more key point per π/8.
    const Surface3d s = wavySurface(12, 12);
    const BSplineCurve<3> straight = line3(Eigen::Vector3d(2, 5, 1), Eigen::Vector3d(9, 5, 1));
    const BSplineCurve<3> bent(2, {0, 0, 0, 1, 1, 1},
                               {Eigen::Vector3d(2, 5, 1), Eigen::Vector3d(5.5, 10, 1), Eigen::Vector3d(9, 5, 1)});
    const Eigen::Vector2d a(2.0 / 11, 5.0 / 11), b(9.0 / 11, 5.0 / 11);
    const int plain = keyPointCount(s, straight, a, b);
    const int more = keyPointCount(s, bent, a, b);
    EXPECT_GE(plain, 5);
    // The parabola turns ~110° (four more by π/8), but the count stops at the spans crossed + the
    // degree − 2: one more than the straight line's
    EXPECT_EQ(more, plain + 1);
}

TEST(SurfaceDeformation, GivenAFinOverAFineNet_WhenDeformed_ThenTheNetMovesAboutTheFinsHeight)
{
    // A flat 30 x 17 bicubic sheet (x from -59 to 40 mm, y from -16 to 16, integer knots) and a
    // 13 mm bump over its middle line, as the stroke fitter made it from a drawn fin (the replay
    // data/sessions/fish_fins.json's case). Eq. 6-24 alone asked for 19 key points on the 18 basis
    // functions under the feet: met "exactly", with control points moved by 4.6e6 mm.
    const int nu = 30, nv = 17;
    KnotVector ku{0, 0, 0}, kv{0, 0, 0};
    for (int k = 0; k <= nu - 3; ++k) ku.push_back(k);
    for (int k = 0; k <= nv - 3; ++k) kv.push_back(k);
    ku.insert(ku.end(), {27.0, 27.0, 27.0});
    kv.insert(kv.end(), {14.0, 14.0, 14.0});
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < nu; ++i) {
        for (int j = 0; j < nv; ++j) pts.emplace_back(-59.0 + 99.0 * i / (nu - 1), -16.0 + 2.0 * j, 0.0);
    }
    const Surface3d sheet(3, 3, ku, kv, nu, nv, pts);
    SurfaceConstraint fin;
    fin.type = SurfaceConstraintType::Curve;
    fin.target = BSplineCurve<3>(3, {0, 0, 0, 0, 0.488641, 1, 1, 1, 1},
                                 {Eigen::Vector3d(-44, 0, 1), Eigen::Vector3d(-37.4552, 0, 6.1901), Eigen::Vector3d(-19.1961, 0, 19.4846),
                                  Eigen::Vector3d(-0.9871, 0, 6.5974), Eigen::Vector3d(6, 0, 1)});
    DeformationReport report;
    const Surface3d out = deformSurface(sheet, {fin}, {}, &report);
    EXPECT_FALSE(report.compromise) << report.message;
    EXPECT_LT(report.maxResidual, kConstraintTolerance);
    double moved = 0.0;
    for (size_t k = 0; k < pts.size(); ++k) moved = std::max(moved, (out.points()[k] - pts[k]).norm());
    EXPECT_LT(moved, 20.0);  // measured 13.1
}

TEST(SurfaceDeformation, GivenADragWithADistance_WhenSolvedPerEvent_ThenEachEqualsTheOneShotSolve)
{
    // The distance rows' chord-Newton steps reuse the factorization: a drag stays back-substitution.
    const Surface3d s = wavySurface(9, 9);
    SurfaceConstraint distance;
    distance.type = SurfaceConstraintType::Distance;
    distance.uv = {0.2, 0.5};
    distance.uv2 = {0.8, 0.5};
    std::vector<SurfaceConstraint> cs = {position(0.5, 0.2, s.evaluate(0.5, 0.2)), distance};
    cs[1].distance = (s.evaluate(0.8, 0.5) - s.evaluate(0.2, 0.5)).norm();
    SurfaceDeformationSolver solver;
    solver.factor(s, cs);
    for (int e = 1; e <= 10; ++e) {
        cs[0].value = s.evaluate(0.5, 0.2) + Eigen::Vector3d(0, 0, 0.1 * e);
        cs[1].distance += 0.1;
        DeformationReport report;
        const Surface3d a = solver.solve(cs, &report);
        EXPECT_LT(maxChange(a, deformSurface(s, cs)), kSameSolutionTolerance) << "event " << e;
        EXPECT_LT(report.maxResidual, kConstraintTolerance);
    }
}

TEST(SurfaceDeformation, GivenABoundAndLeastDisplacement_WhenAPointNearItIsPulled_ThenTheRimMovesLeast)
{
    // The relaxation weights (3/r)² make a point r rings in from the bound move ∝ r²/9 of what the
    // plain least displacement would give it: the rim (r = 1) gets at most 1/9 of its share.
    const Surface3d s = wavySurface(16, 16);
    DeformationOptions options;
    options.objective = Objective::Displacement;
    options.bound = {{0.2, 0.2}, {0.8, 0.2}, {0.8, 0.8}, {0.2, 0.8}};
    const Eigen::Vector2d uv(0.3, 0.5);  // its support reaches the bound's rim on the U side
    DeformationReport report;
    const Surface3d out =
        deformSurface(s, {position(uv.x(), uv.y(), s.evaluate(uv.x(), uv.y()) + Eigen::Vector3d(0, 0, 1))}, options, &report);
    EXPECT_LT(report.maxResidual, kConstraintTolerance);
    const std::vector<bool> inside = insideBound(s, options.bound);
    double rim = 0.0, all = 0.0;
    for (int i = 0; i < 16; ++i) {
        for (int j = 0; j < 16; ++j) {
            const double moved = (out.point(i, j) - s.point(i, j)).norm();
            all = std::max(all, moved);
            if (inside[static_cast<size_t>(i * 16 + j)] && i > 0 && !inside[static_cast<size_t>((i - 1) * 16 + j)]) {
                rim = std::max(rim, moved);
            }
        }
    }
    EXPECT_GT(rim, 0.0);
    EXPECT_LT(rim, 0.25 * all);
}

TEST(SurfaceDeformation, GivenTangentValues_WhenDeformed_ThenSuAndSvAreMetAndATurnNeedsNoNewFactorization)
{
    // Given: a point handle's tangent plane turned by R about the point (Tangents = R S_u°, R S_v°).
    const Surface3d s = wavySurface(9, 9);
    const Eigen::Vector2d uv(0.5, 0.5);
    const auto der = s.derivatives(uv.x(), uv.y(), 1);
    auto handle = [&](double angle) {
        const Eigen::Matrix3d r = Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, 0).normalized()).toRotationMatrix();
        SurfaceConstraint p = position(uv.x(), uv.y(), s.evaluate(uv.x(), uv.y()) + Eigen::Vector3d(0, 0, angle));
        SurfaceConstraint t = p;
        t.type = SurfaceConstraintType::Tangents;
        t.value = r * der[1][0];
        t.value2 = r * der[0][1];
        return std::vector<SurfaceConstraint>{p, t};
    };
    SurfaceDeformationSolver solver;
    solver.factor(s, handle(0.0));
    for (double angle : {0.1, 0.25, 0.4}) {
        // When: solved per event with the factorization of the unturned handle
        const std::vector<SurfaceConstraint> cs = handle(angle);
        DeformationReport report;
        const Surface3d out = solver.solve(cs, &report);
        // Then: S_u and S_v are the turned ones, the normal turned by R, and it equals a one-shot solve
        const auto now = out.derivatives(uv.x(), uv.y(), 1);
        EXPECT_LT((now[1][0] - cs[1].value).norm(), kConstraintTolerance);
        EXPECT_LT((now[0][1] - cs[1].value2).norm(), kConstraintTolerance);
        const Eigen::Vector3d turned = Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, 0).normalized()) * s.normal(uv.x(), uv.y());
        EXPECT_LT(std::acos(std::clamp(out.normal(uv.x(), uv.y()).dot(turned), -1.0, 1.0)), kAngleTolerance);
        EXPECT_LT(report.maxResidual, kConstraintTolerance);
        EXPECT_LT(maxChange(out, deformSurface(s, cs)), kSameSolutionTolerance);
    }
}

TEST(SurfaceDeformation, GivenABoundAndTargets_WhenFactored_ThenEachIsClassifiedOverUnderOrWell)
{
    // Given: a 16 × 16 net, a bound around the middle, three straight targets 0.5 above the surface:
    // one across the middle inside the bound, one crossing the bound, one in a corner outside it.
    const Surface3d s = wavySurface(16, 16, 0.0);
    DeformationOptions options;
    options.bound = {{0.2, 0.2}, {0.8, 0.2}, {0.8, 0.8}, {0.2, 0.8}};
    auto target = [&](double u0, double u1, double v) {
        SurfaceConstraint c;
        c.type = SurfaceConstraintType::Curve;
        c.target = line3(s.evaluate(u0, v) + Eigen::Vector3d(0, 0, 0.5), s.evaluate(u1, v) + Eigen::Vector3d(0, 0, 0.5));
        return c;
    };
    const std::vector<SurfaceConstraint> cs = {target(0.4, 0.6, 0.5), target(0.05, 0.6, 0.4), target(0.02, 0.1, 0.05)};
    // When
    DeformationReport report;
    const Surface3d out = deformSurface(s, cs, options, &report);
    // Then: well, under and over; the over one adds nothing (residual 0), the others are met
    ASSERT_EQ(report.boundCases.size(), 3u);
    EXPECT_EQ(report.boundCases[0], BoundCase::Well);
    EXPECT_EQ(report.boundCases[1], BoundCase::Under);
    EXPECT_EQ(report.boundCases[2], BoundCase::Over);
    EXPECT_LT(report.maxResidual, kConstraintTolerance);
    EXPECT_NE(report.message.find("constraints[2] lies outside the bound"), std::string::npos) << report.message;
    // And a lone target outside the bound leaves the surface exactly as it was (§6.3)
    DeformationReport alone;
    EXPECT_EQ(deformSurface(s, {cs[2]}, options, &alone).points(), s.points());
    EXPECT_EQ(alone.moved, 0);
    EXPECT_GT(maxChange(out, s), 0.4);
}

TEST(SurfaceDeformation, GivenAnAngleConstraint_WhenDeformed_ThenTheNormalMakesThatAngleWithTheDirection)
{
    // Given: the normal near the middle of a gentle bump (almost vertical there), asked to make 30°
    // with z and then 60° (tilted in the plane of z and the present normal), a point held beside.
    const Surface3d s = wavySurface(9, 9);
    for (double degrees : {30.0, 60.0}) {
        SurfaceConstraint angle;
        angle.type = SurfaceConstraintType::Angle;
        angle.uv = {0.45, 0.5};
        angle.value = Eigen::Vector3d::UnitZ();
        angle.angle = degrees * kPi / 180.0;
        const std::vector<SurfaceConstraint> cs = {angle, position(0.2, 0.2, s.evaluate(0.2, 0.2))};
        // When
        DeformationReport report;
        const Surface3d out = deformSurface(s, cs, {}, &report);
        // Then
        const double reached = std::acos(std::clamp(out.normal(0.45, 0.5).dot(Eigen::Vector3d::UnitZ()), -1.0, 1.0));
        EXPECT_NEAR(reached, angle.angle, kAngleTolerance) << degrees;
        EXPECT_LT(report.maxResidual, kAngleTolerance) << report.message;
        EXPECT_LT((out.evaluate(0.2, 0.2) - s.evaluate(0.2, 0.2)).norm(), kConstraintTolerance);
    }
    // An angle outside [0, π] is refused, naming the field
    SurfaceConstraint bad;
    bad.type = SurfaceConstraintType::Angle;
    bad.uv = {0.5, 0.5};
    bad.value = Eigen::Vector3d::UnitZ();
    bad.angle = 4.0;
    try {
        deformSurface(s, {bad});
        ADD_FAILURE() << "accepted";
    } catch (const GeometryError& e) {
        EXPECT_NE(std::string(e.what()).find("constraints[0].angle"), std::string::npos) << e.what();
    }
}
