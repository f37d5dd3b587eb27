// MTSVD (Hansen, Sekii & Shibahashi 1992; seed 000 eq. 5). Given / When / Then.
#include "solvers/regularization/mtsvd.h"
#include "solvers/regularization/test_problems.h"

#include <Eigen/QR>
#include <gtest/gtest.h>

using namespace sculptline::solvers::regularization;

namespace {

constexpr double kAgreement = 1e-9;

Eigen::MatrixXd random(int m, int n, unsigned seed)
{
    std::srand(seed);
    return Eigen::MatrixXd::Random(m, n);
}

}  // namespace

TEST(Mtsvd, GivenTsvdSolution_WhenModified_ThenTheFitInTheFirstKDirectionsIsUnchangedAndLxSmaller)
{
    const TestProblem p = shaw(32);
    const Eigen::VectorXd b = withNoise(p.b, 1e-3, 1);
    const CachedSvd svd(p.a);
    const Eigen::MatrixXd x0 = Eigen::VectorXd::Constant(32, 0.3);
    const ProjectedRhs rhs = projectRhs(svd, b, x0);
    const Eigen::MatrixXd l = secondDifferences(32);
    const MtsvdSolver m(svd, l);
    for (int k = 2; k <= 8; ++k) {
        const Eigen::MatrixXd xt = tsvdSolution(svd, rhs, k), xm = m.solution(rhs, k);
        const Eigen::MatrixXd uk = svd.u().leftCols(k);
        EXPECT_LT((uk.transpose() * p.a * (xm - xt)).norm(), kAgreement * (p.a * xt).norm()) << k;
        EXPECT_LE((l * (xm - x0)).norm(), (l * (xt - x0)).norm() * (1 + 1e-12)) << k;
    }
}

TEST(Mtsvd, GivenTheUpdatedQr_WhenLCurveSwept_ThenRhoAndEtaMatchTheDirectSolutions)
{
    for (const auto& [m, n] : {std::pair{30, 16}, std::pair{10, 16}}) {
        const Eigen::MatrixXd a = random(m, n, 3), b = random(m, 2, 4), x0 = random(n, 2, 5);
        const CachedSvd svd(a);
        const ProjectedRhs rhs = projectRhs(svd, b, x0);
        const Eigen::MatrixXd l = secondDifferences(n);
        const MtsvdSolver solver(svd, l);
        const LCurve lc = solver.lcurve(rhs);
        ASSERT_EQ(lc.rho.size(), svd.rank());
        for (int k = 1; k <= svd.rank(); ++k) {
            const Eigen::MatrixXd x = solver.solution(rhs, k);
            EXPECT_NEAR(lc.rho(k - 1), (a * x - b).norm(), kAgreement * b.norm()) << m << "x" << n << " k " << k;
            EXPECT_NEAR(lc.eta(k - 1), (l * (x - x0)).norm(), kAgreement * (1 + lc.eta(k - 1))) << m << "x" << n << " k " << k;
        }
        // Second differences (n − 2 rows): only k = 1 has more columns than rows and needs a fresh solve.
        EXPECT_LE(solver.fallbackCount(), 1) << m << "x" << n;
    }
}

TEST(Mtsvd, GivenSolution_WhenComparedWithTheDefinition_ThenItMinimizesLxOverTheFreeSpace)
{
    const Eigen::MatrixXd a = random(20, 12, 7), b = random(20, 1, 8);
    const CachedSvd svd(a);
    const ProjectedRhs rhs = projectRhs(svd, b);
    const Eigen::MatrixXd l = secondDifferences(12);
    const int k = 5;
    const Eigen::MatrixXd xk = tsvdSolution(svd, rhs, k), vr = svd.v().rightCols(12 - k);
    // x_k − V_{k+1} (L V_{k+1})⁺ L x_k by an independent pseudo-inverse.
    const Eigen::MatrixXd lv = l * vr;
    const Eigen::MatrixXd pinv = lv.completeOrthogonalDecomposition().pseudoInverse();
    const Eigen::MatrixXd expected = xk - vr * pinv * l * xk;
    EXPECT_LT((MtsvdSolver(svd, l).solution(rhs, k) - expected).norm(), 1e-10 * expected.norm());
}

TEST(Mtsvd, GivenSmoothingOfWrongWidth_WhenConstructed_ThenRefused)
{
    const CachedSvd svd(random(6, 5, 9));
    EXPECT_THROW(MtsvdSolver(svd, Eigen::MatrixXd::Ones(2, 4)), std::invalid_argument);
    EXPECT_THROW(secondDifferences(2), std::invalid_argument);
}
