// Direct constrained manipulation (thesis §6.1, Fowler & Bartels 1993). Given / When / Then.
#include "solvers/editing/curve_manipulation.h"

#include "solvers/bspline/bspline_curve.h"

#include "solvers/bspline/geometry_error.h"

#include "tests/editing/editing_fixtures.h"

#include <Eigen/LU>
#include <Eigen/QR>
#include <gtest/gtest.h>
#include <cmath>

using namespace sculptline::solvers;
using namespace sculptline::solvers::editing;

namespace {

// Issue 4: constraints must hold to 1e-9 (model units; the curves here are ~10 units across).
constexpr double kConstraintTolerance = 1e-9;

Curve2d wavyOpen(int n)
{
    std::vector<Eigen::Vector2d> pts;
    for (int i = 0; i < n; ++i) pts.emplace_back(i, std::sin(0.7 * i) * 2.0);
    return makeClampedUniform<2>(3, pts);
}

Curve3d helixOpen(int n)
{
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < n; ++i) pts.emplace_back(std::cos(0.5 * i) * 3, std::sin(0.5 * i) * 3, 0.4 * i);
    return makeClampedUniform<3>(3, pts);
}

template <int Dim>
CurveConstraint<Dim> make(ConstraintType t, double u, Eigen::Matrix<double, Dim, 1> v, double u2 = 0.0)
{
    CurveConstraint<Dim> c;
    c.type = t;
    c.u = u;
    c.u2 = u2;
    c.value = v;
    return c;
}

}  // namespace

TEST(CurveManipulation, GivenPositionTangentDistance_WhenSolved_ThenAllHoldTo1e9)
{
    const Curve2d curve = wavyOpen(12);
    const Eigen::Vector2d p0 = curve.evaluate(0.3);
    const Eigen::Vector2d t0 = curve.derivatives(0.6, 1)[1];
    const std::vector<CurveConstraint<2>> cs = {
        make<2>(ConstraintType::Position, 0.3, p0 + Eigen::Vector2d(0.5, 1.0)),
        make<2>(ConstraintType::Tangent, 0.6, t0 + Eigen::Vector2d(0.0, 3.0)),
        make<2>(ConstraintType::Distance, 0.7, Eigen::Vector2d(1.2, 0.3), 0.8),
    };

    ManipulationReport report;
    const Curve2d out = constrainCurve(curve, cs, {}, &report);

    EXPECT_LT((out.evaluate(0.3) - cs[0].value).norm(), kConstraintTolerance);
    EXPECT_LT((out.derivatives(0.6, 1)[1] - cs[1].value).norm(), kConstraintTolerance);
    EXPECT_LT((out.evaluate(0.8) - out.evaluate(0.7) - cs[2].value).norm(), kConstraintTolerance);
    EXPECT_FALSE(report.compromise);
    EXPECT_FALSE(report.tooFewFreePoints);
    EXPECT_LT(report.maxResidual, kConstraintTolerance);
}

TEST(CurveManipulation, GivenCurvatureConstraintIn3D_WhenSolved_ThenSecondDerivativeHolds)
{
    const Curve3d curve = helixOpen(10);
    const Eigen::Vector3d target = curve.derivatives(0.5, 2)[2] * 0.25;

    const Curve3d out = constrainCurve(curve, {make<3>(ConstraintType::Curvature, 0.5, target)});

    EXPECT_LT((out.derivatives(0.5, 2)[2] - target).norm(), kConstraintTolerance * 100.0)
        << "second derivatives are ~1e3 here, so 1e-7 absolute is 1e-10 relative";
}

TEST(CurveManipulation, GivenBlockedPoints_WhenDragged_ThenTheyAreExactlyFixed)
{
    const Curve2d curve = wavyOpen(12);
    const std::vector<int> blocked = {0, 1, 5, 6, 11};
    CurveManipulationSolver<2> solver(curve, {make<2>(ConstraintType::Position, 0.45, Eigen::Vector2d::Zero())},
                                      blocked);

    const Curve2d out = solver.solve({curve.evaluate(0.45) + Eigen::Vector2d(0.0, 2.0)});

    for (int b : blocked) {
        EXPECT_EQ(out.points()[b], curve.points()[b]) << "blocked point " << b;
    }
    EXPECT_LT((out.evaluate(0.45) - curve.evaluate(0.45) - Eigen::Vector2d(0.0, 2.0)).norm(), kConstraintTolerance);
}

TEST(CurveManipulation, GivenThreeConstraints_WhenSolved_ThenChangeIsTheLeastNormOne)
{
    // Independent reference: Eigen's complete orthogonal decomposition gives the minimum-norm
    // solution of F d = b directly, without the QR-of-Fᵀ route the solver takes.
    const Curve3d curve = helixOpen(14);
    const std::vector<int> blocked = {0, 13};
    const std::vector<CurveConstraint<3>> cs = {
        make<3>(ConstraintType::Position, 0.2, curve.evaluate(0.2) + Eigen::Vector3d(1, -1, 0.5)),
        make<3>(ConstraintType::Tangent, 0.5, curve.derivatives(0.5, 1)[1] * 1.3),
        make<3>(ConstraintType::Distance, 0.6, Eigen::Vector3d(0.0, 2.0, 1.0), 0.9),
    };
    CurveManipulationSolver<3> solver(curve, cs, blocked);
    std::vector<Eigen::Vector3d> targets;
    for (const auto& c : cs) targets.push_back(c.value);

    CurveManipulationSolver<3>::Displacements d;
    solver.displacements(targets, d);

    Eigen::MatrixXd b(3, 3);
    for (int j = 0; j < 3; ++j) b.row(j) = (targets[j] - solver.currentValues()[j]).transpose();
    const Eigen::MatrixXd ref = solver.constraintMatrix().completeOrthogonalDecomposition().solve(b);
    EXPECT_LT((Eigen::MatrixXd(d) - ref).norm(), 1e-10 * ref.norm());
    // And a perturbation inside the null space of F only makes the change longer.
    Eigen::FullPivLU<Eigen::MatrixXd> lu(solver.constraintMatrix());
    const Eigen::MatrixXd z = lu.kernel().col(0) * Eigen::RowVector3d(0.1, 0.1, 0.1);
    EXPECT_GT((Eigen::MatrixXd(d) + z).norm(), Eigen::MatrixXd(d).norm());
}

TEST(CurveManipulation, GivenContradictoryConstraints_WhenSolved_ThenCompromiseAndResidualReported)
{
    const Curve2d curve = wavyOpen(10);
    const Eigen::Vector2d p = curve.evaluate(0.5);
    const std::vector<CurveConstraint<2>> cs = {
        make<2>(ConstraintType::Position, 0.5, p + Eigen::Vector2d(0, 1)),
        make<2>(ConstraintType::Position, 0.5, p - Eigen::Vector2d(0, 1)),
    };

    ManipulationReport report;
    const Curve2d out = constrainCurve(curve, cs, {}, &report);

    EXPECT_TRUE(report.compromise);
    EXPECT_EQ(report.rank, 1);
    // Least squares of two equal rows with targets ±1 is their mean: the point stays, residual 1 each.
    EXPECT_LT((out.evaluate(0.5) - p).norm(), kConstraintTolerance);
    EXPECT_NEAR(report.maxResidual, 1.0, kConstraintTolerance);
    EXPECT_FALSE(report.message.empty());
}

TEST(CurveManipulation, GivenTooFewFreePoints_WhenKnotsInserted_ThenConstraintsCanBeMet)
{
    // A single cubic Bezier (4 points) cannot take 5 position constraints sampled from a
    // non-polynomial displacement.
    const Curve2d curve = makeClampedUniform<2>(3, {{0, 0}, {1, 2}, {2, 2}, {3, 0}});
    std::vector<CurveConstraint<2>> cs;
    for (double u : {0.1, 0.3, 0.5, 0.7, 0.9}) {
        cs.push_back(make<2>(ConstraintType::Position, u, curve.evaluate(u) + Eigen::Vector2d(0, std::sin(7.0 * u))));
    }
    ManipulationReport before;
    constrainCurve(curve, cs, {}, &before);
    ASSERT_TRUE(before.tooFewFreePoints);
    EXPECT_GT(before.maxResidual, 1e-3);

    const Curve2d refined = insertKnotsNearConstraints(curve, cs, 2);
    ManipulationReport after;
    const Curve2d out = constrainCurve(refined, cs, {}, &after);

    EXPECT_FALSE(after.tooFewFreePoints);
    EXPECT_FALSE(after.compromise);
    for (const auto& c : cs) EXPECT_LT((out.evaluate(c.u) - c.value).norm(), kConstraintTolerance);
    for (double u : {0.0, 0.25, 0.55, 1.0}) {
        EXPECT_LT((refined.evaluate(u) - curve.evaluate(u)).norm(), 1e-12) << "knot insertion keeps the shape";
    }
}

TEST(CurveManipulation, GivenClosedCurve_WhenConstrainedAcrossSeam_ThenStaysClosedAndMeetsConstraint)
{
    std::vector<Eigen::Vector2d> loop;
    for (int i = 0; i < 8; ++i) loop.emplace_back(std::cos(i * M_PI / 4) * 4, std::sin(i * M_PI / 4) * 3);
    const Curve2d curve = makeClosedUniform<2>(3, loop);
    const double u = curve.domainStart() + 0.1;  // near the seam: wrapped basis functions involved
    const Eigen::Vector2d target = curve.evaluate(u) + Eigen::Vector2d(1.0, 0.5);

    const Curve2d out = constrainCurve(curve, {make<2>(ConstraintType::Position, u, target)});

    EXPECT_TRUE(out.isClosed());
    EXPECT_LT((out.evaluate(u) - target).norm(), kConstraintTolerance);
    const auto d0 = out.derivatives(out.domainStart(), 2);
    const auto d1 = out.derivatives(out.domainEnd(), 2);
    for (int k = 0; k < 3; ++k) EXPECT_LT((d0[k] - d1[k]).norm(), 1e-9) << "C2 across the seam, order " << k;
}

TEST(CurveManipulation, GivenDragSequence_WhenSolvedPerEvent_ThenEachEqualsTheOneOffSolve)
{
    const Curve2d curve = wavyOpen(50);
    std::vector<CurveConstraint<2>> cs = {
        make<2>(ConstraintType::Position, 0.4, curve.evaluate(0.4)),
        make<2>(ConstraintType::Tangent, 0.45, curve.derivatives(0.45, 1)[1]),
        make<2>(ConstraintType::Position, 0.6, curve.evaluate(0.6)),
    };
    CurveManipulationSolver<2> solver(curve, cs);
    for (int step = 1; step <= 5; ++step) {
        cs[0].value = curve.evaluate(0.4) + Eigen::Vector2d(0.1 * step, 0.2 * step);
        const Curve2d perEvent = solver.solve({cs[0].value, cs[1].value, cs[2].value});
        const Curve2d oneOff = constrainCurve(curve, cs);
        for (int i = 0; i < perEvent.pointCount(); ++i) {
            EXPECT_LT((perEvent.points()[i] - oneOff.points()[i]).norm(), 1e-12);
        }
        EXPECT_LT((perEvent.evaluate(0.4) - cs[0].value).norm(), kConstraintTolerance);
        EXPECT_LT((perEvent.evaluate(0.6) - curve.evaluate(0.6)).norm(), kConstraintTolerance);
    }
}

TEST(CurveManipulation, GivenBadInput_WhenConstructed_ThenGeometryErrorNotCrash)
{
    const Curve2d curve = wavyOpen(6);
    EXPECT_THROW(CurveManipulationSolver<2>(curve, {}, {7}), GeometryError);
    EXPECT_THROW(constrainCurve(curve, {make<2>(ConstraintType::Position, NAN, Eigen::Vector2d::Zero())}),
                 GeometryError);
    // All points blocked: nothing can move, the report says the constraint is not met.
    ManipulationReport r;
    constrainCurve(curve, {make<2>(ConstraintType::Position, 0.5, Eigen::Vector2d(100, 100))}, {0, 1, 2, 3, 4, 5}, &r);
    EXPECT_TRUE(r.tooFewFreePoints);
    EXPECT_GT(r.maxResidual, 50.0);
}

TEST(CurveManipulation, GivenFig63Setup_WhenPointDragged_ThenTangentAndDistanceKeptEveryEvent)
{
    // Thesis Fig. 6-3: one point moves while a tangent and a distance between two points are kept.
    const Curve3d curve = helixOpen(20);
    std::vector<CurveConstraint<3>> cs = {
        make<3>(ConstraintType::Position, 0.3, curve.evaluate(0.3)),
        make<3>(ConstraintType::Tangent, 0.6, curve.derivatives(0.6, 1)[1]),
        make<3>(ConstraintType::Distance, 0.6, curve.evaluate(0.7) - curve.evaluate(0.6), 0.7),
    };
    CurveManipulationSolver<3> solver(curve, cs, {0, 19});
    for (int step = 1; step <= 10; ++step) {
        const Eigen::Vector3d target = curve.evaluate(0.3) + 0.2 * step * Eigen::Vector3d(1, 0.5, -0.3);
        ManipulationReport report;
        const Curve3d out = solver.solve({target, cs[1].value, cs[2].value}, &report);
        EXPECT_LT((out.evaluate(0.3) - target).norm(), kConstraintTolerance);
        EXPECT_LT((out.derivatives(0.6, 1)[1] - cs[1].value).norm(), kConstraintTolerance * 10.0)
            << "derivatives are ~20 units per parameter here";
        EXPECT_LT((out.evaluate(0.7) - out.evaluate(0.6) - cs[2].value).norm(), kConstraintTolerance);
        EXPECT_EQ(out.points().front(), curve.points().front());
        EXPECT_EQ(out.points().back(), curve.points().back());
    }
}

namespace {

// A rational open cubic with weights 0.4 .. 2.2 (a NURBS whose shape the weights visibly pull).
Curve2d rationalOpen(int n)
{
    std::vector<Eigen::Vector2d> pts;
    std::vector<double> w;
    for (int i = 0; i < n; ++i) {
        pts.emplace_back(i, std::sin(0.7 * i) * 2.0);
        w.push_back(1.3 + 0.9 * std::sin(1.9 * i));
    }
    return makeClampedUniform<2>(3, pts, w);
}

}  // namespace

TEST(CurveManipulation, GivenRationalCurve_WhenRowsBuilt_ThenTheyReproduceTheKernelsDerivatives)
{
    // Given a rational cubic and one constraint of each order at several parameters
    const Curve2d curve = rationalOpen(12);
    for (double u : {0.0, 0.13, 0.5, 0.77, 1.0}) {
        const auto d = curve.derivatives(u, 2);  // The NURBS Book A4.2: independent of the rows
        for (int k = 0; k <= 2; ++k) {
            const ConstraintType t[] = {ConstraintType::Position, ConstraintType::Tangent, ConstraintType::Curvature};
            // When the row of F is applied to the control points
            const Eigen::VectorXd row = constraintRow(curve, make<2>(t[k], u, Eigen::Vector2d::Zero()));
            Eigen::Vector2d v = Eigen::Vector2d::Zero();
            for (int i = 0; i < curve.pointCount(); ++i) v += row[i] * curve.points()[i];
            // Then it is the k-th derivative of the rational curve (weights held fixed, C is linear in P)
            EXPECT_LT((v - d[k]).norm(), 1e-12 * std::max(1.0, d[k].norm())) << "u " << u << " order " << k;
        }
    }
}

TEST(CurveManipulation, GivenRationalCurve_WhenConstrained_ThenConstraintsHoldWeightsKeptLeastNorm)
{
    // Given a rational cubic, two blocked points and three constraints (position, tangent, distance)
    const Curve2d curve = rationalOpen(14);
    const std::vector<int> blocked = {0, 5};
    const std::vector<CurveConstraint<2>> cs = {
        make<2>(ConstraintType::Position, 0.25, curve.evaluate(0.25) + Eigen::Vector2d(0.4, -0.8)),
        make<2>(ConstraintType::Tangent, 0.55, curve.derivatives(0.55, 1)[1] * 1.2),
        make<2>(ConstraintType::Distance, 0.7, Eigen::Vector2d(1.5, 0.5), 0.85),
    };
    CurveManipulationSolver<2> solver(curve, cs, blocked);
    std::vector<Eigen::Vector2d> targets;
    for (const auto& c : cs) targets.push_back(c.value);

    // When solved
    ManipulationReport report;
    const Curve2d out = solver.solve(targets, &report);

    // Then the rational result (evaluated by the kernel) meets every constraint to 1e-9, keeps its
    // weights and its blocked points exactly, and the change is the least-norm one.
    ASSERT_TRUE(out.isRational());
    EXPECT_LT((out.evaluate(0.25) - cs[0].value).norm(), kConstraintTolerance);
    EXPECT_LT((out.derivatives(0.55, 1)[1] - cs[1].value).norm(), kConstraintTolerance);
    EXPECT_LT((out.evaluate(0.85) - out.evaluate(0.7) - cs[2].value).norm(), kConstraintTolerance);
    EXPECT_LT(report.maxResidual, kConstraintTolerance);
    EXPECT_EQ(out.weights(), curve.weights());
    for (int b : blocked) EXPECT_EQ(out.points()[b], curve.points()[b]);
    Eigen::MatrixXd b(3, 2);
    for (int j = 0; j < 3; ++j) b.row(j) = (targets[j] - solver.currentValues()[j]).transpose();
    const Eigen::MatrixXd ref = solver.constraintMatrix().completeOrthogonalDecomposition().solve(b);
    CurveManipulationSolver<2>::Displacements d;
    solver.displacements(targets, d);
    EXPECT_LT((Eigen::MatrixXd(d) - ref).norm(), 1e-10 * ref.norm());
}

TEST(CurveManipulation, GivenClosedRationalCurve_WhenCurvatureConstrainedAcrossSeam_ThenHoldsAndStaysClosed)
{
    // Given a closed rational cubic in 3D with uneven weights (1, 1.5, 2 repeating)
    std::vector<Eigen::Vector3d> pts;
    std::vector<double> w;
    for (int i = 0; i < 9; ++i) {
        pts.emplace_back(4 * std::cos(i * 2 * M_PI / 9), 3 * std::sin(i * 2 * M_PI / 9), 0.5 * std::sin(2.0 * i));
        w.push_back(1.0 + 0.5 * (i % 3));
    }
    const Curve3d curve = makeClosedUniform<3>(3, pts, w);
    const double seam = curve.domainStart();
    const std::vector<CurveConstraint<3>> cs = {
        make<3>(ConstraintType::Position, seam, curve.evaluate(seam) + Eigen::Vector3d(0, 0, 1)),
        make<3>(ConstraintType::Curvature, seam + 0.5, curve.derivatives(seam + 0.5, 2)[2] * 0.5),
    };

    // When constrained
    ManipulationReport report;
    const Curve3d out = constrainCurve(curve, cs, {}, &report);

    // Then both hold to 1e-9, the curve is closed with its weights, C2 across the seam
    ASSERT_TRUE(out.isClosed());
    EXPECT_EQ(out.weights(), curve.weights());
    EXPECT_LT((out.evaluate(seam) - cs[0].value).norm(), kConstraintTolerance);
    EXPECT_LT((out.derivatives(seam + 0.5, 2)[2] - cs[1].value).norm(), kConstraintTolerance);
    const auto a = out.derivatives(out.domainStart(), 2), e = out.derivatives(out.domainEnd(), 2);
    for (int k = 0; k <= 2; ++k) EXPECT_LT((a[k] - e[k]).norm(), 1e-9) << "order " << k;
}

TEST(CurveManipulation, GivenTheBenchmarkedDrag_WhenSolvedPerEvent_ThenConstraintsHoldAndEndsStayFixed)
{
    // Given bench/editing_bench.cpp's drag: 50-point helix, 3 constraints, both ends blocked
    const Curve3d curve = sculptline::editing_fixtures::helix(50);
    const auto cs = sculptline::editing_fixtures::dragConstraints(curve);
    const CurveManipulationSolver<3> solver(curve, cs, {0, 49});
    std::vector<Eigen::Vector3d> targets = {cs[0].value, cs[1].value, cs[2].value};

    for (int event = 1; event <= 50; ++event) {
        // When the point is dragged 0.05 further per event
        targets[0] = cs[0].value + Eigen::Vector3d(0.05 * event, 0.025 * event, 0.0);
        ManipulationReport report;
        const Curve3d out = solver.solve(targets, &report);

        // Then the moved point, the kept tangent and the kept distance hold to 1e-9 and the ends stay
        EXPECT_LT((out.evaluate(0.45) - targets[0]).norm(), kConstraintTolerance);
        EXPECT_LT((out.derivatives(0.5, 1)[1] - targets[1]).norm(), kConstraintTolerance * targets[1].norm());
        EXPECT_LT((out.evaluate(0.55) - out.evaluate(0.5) - targets[2]).norm(), kConstraintTolerance);
        EXPECT_EQ(out.points().front(), curve.points().front());
        EXPECT_EQ(out.points().back(), curve.points().back());
        EXPECT_FALSE(report.compromise);
    }
}
