// TSVD with a prior (seed 000 eqs. 3–4) against an independent pseudo-inverse, and the L-curve's
// ρ_k, η_k against direct computation. Given / When / Then.
#include "solvers/regularization/tsvd.h"

#include <Eigen/QR>
#include <gtest/gtest.h>

using namespace sculptline::solvers::regularization;

namespace {

constexpr double kAgreement = 1e-10;  // relative, the brief's bound for an independent computation

Eigen::MatrixXd random(int m, int n, unsigned seed)
{
    std::srand(seed);
    return Eigen::MatrixXd::Random(m, n);
}

double relative(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).norm() / b.norm(); }

}  // namespace

TEST(Tsvd, GivenFullRankSystem_WhenKIsTheRank_ThenTheSolutionIsThePseudoInverses)
{
    const Eigen::MatrixXd a = random(20, 8, 1), b = random(20, 3, 2);
    const TsvdSolver solver(a);
    TsvdSolver s = solver;
    s.setRhs(b);
    const Eigen::MatrixXd expected = a.completeOrthogonalDecomposition().solve(b);
    EXPECT_LT(relative(s.solution(8), expected), kAgreement);
}

TEST(Tsvd, GivenRankKTruncation_WhenSolved_ThenItIsThePseudoInverseOfTheRankKMatrix)
{
    const Eigen::MatrixXd a = random(15, 10, 3), b = random(15, 2, 4);
    TsvdSolver s(a);
    s.setRhs(b);
    const CachedSvd& svd = s.svd();
    for (int k = 1; k <= 10; ++k) {
        // A_k = U_k Σ_k V_kᵀ, then its minimum-norm least-squares solution by a different factorization.
        const Eigen::MatrixXd ak =
            svd.u().leftCols(k) * svd.singularValues().head(k).asDiagonal() * svd.v().leftCols(k).transpose();
        Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(ak);
        cod.setThreshold(1e-8);
        EXPECT_LT(relative(s.solution(k), cod.solve(b)), kAgreement) << "k = " << k;
    }
}

TEST(Tsvd, GivenPrior_WhenSolved_ThenTheFreePartIsThePriorsAndTheFitPartUnchanged)
{
    const Eigen::MatrixXd a = random(12, 9, 5), b = random(12, 1, 6), x0 = random(9, 1, 7);
    TsvdSolver s(a);
    s.setRhs(b, x0);
    const CachedSvd& svd = s.svd();
    const int k = 4;
    const Eigen::MatrixXd x = s.solution(k);
    const Eigen::MatrixXd vk = svd.v().leftCols(k), vr = svd.v().rightCols(9 - k);
    // V_kᵀ x = Σ_k⁻¹ U_kᵀ b and V_{k+1}ᵀ x = V_{k+1}ᵀ x0 (eq. 4 with f = V_{k+1}ᵀ x0).
    const Eigen::MatrixXd fit = svd.singularValues().head(k).cwiseInverse().asDiagonal() * svd.u().leftCols(k).transpose() * b;
    EXPECT_LT(relative(vk.transpose() * x, fit), kAgreement);
    EXPECT_LT(relative(vr.transpose() * x, vr.transpose() * x0), kAgreement);
    // And the same as the formula without a prior plus the projected prior.
    TsvdSolver plain(a);
    plain.setRhs(b);
    EXPECT_LT(relative(x, plain.solution(k) + vr * vr.transpose() * x0), kAgreement);
}

TEST(Tsvd, GivenTallWideAndMultipleRhs_WhenLCurveComputed_ThenRhoAndEtaMatchDirectNorms)
{
    for (const auto& [m, n] : {std::pair{25, 10}, std::pair{8, 14}}) {
        const Eigen::MatrixXd a = random(m, n, 11), b = random(m, 3, 12), x0 = random(n, 3, 13);
        TsvdSolver s(a);
        const LCurve& lc = s.setRhs(b, x0);
        ASSERT_EQ(lc.rho.size(), s.svd().rank());
        for (int k = 1; k <= s.svd().rank(); ++k) {
            const Eigen::MatrixXd x = s.solution(k);
            EXPECT_NEAR(lc.rho(k - 1), (a * x - b).norm(), kAgreement * b.norm()) << m << "x" << n << " k " << k;
            EXPECT_NEAR(lc.eta(k - 1), (x - x0).norm(), kAgreement * (x - x0).norm()) << m << "x" << n << " k " << k;
        }
    }
}

TEST(Tsvd, GivenANewRhs_WhenResolved_ThenNoRefactorizationAndTheSameAsAFreshSolver)
{
    const Eigen::MatrixXd a = random(10, 6, 21), b1 = random(10, 1, 22), b2 = random(10, 1, 23);
    TsvdSolver s(a);
    s.setRhs(b1);
    const Eigen::MatrixXd u0 = s.svd().u();
    s.setRhs(b2);
    EXPECT_EQ((s.svd().u() - u0).norm(), 0.0);
    TsvdSolver fresh(a);
    fresh.setRhs(b2);
    EXPECT_LT(relative(s.solution(3), fresh.solution(3)), 1e-14);
}

TEST(Tsvd, GivenBadSizesOrK_WhenSolved_ThenRefused)
{
    TsvdSolver s(random(6, 4, 31));
    EXPECT_THROW(s.setRhs(random(5, 1, 32)), std::invalid_argument);
    EXPECT_THROW(s.setRhs(random(6, 1, 32), random(3, 1, 33)), std::invalid_argument);
    s.setRhs(random(6, 1, 32));
    EXPECT_THROW(s.solution(0), std::invalid_argument);
    EXPECT_THROW(s.solution(5), std::invalid_argument);
}
