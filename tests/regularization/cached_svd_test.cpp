// CachedSvd: both backends reproduce A, agree on σ, and the null basis completes V. Given / When / Then.
#include "solvers/regularization/cached_svd.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers::regularization;

namespace {

constexpr double kReconstruction = 1e-12;  // relative to ‖A‖: backward-stable SVDs

Eigen::MatrixXd randomMatrix(int m, int n)
{
    std::srand(7);
    return Eigen::MatrixXd::Random(m, n);
}

void expectValid(const CachedSvd& svd, const Eigen::MatrixXd& a)
{
    const Eigen::MatrixXd back = svd.u() * svd.singularValues().asDiagonal() * svd.v().transpose();
    EXPECT_LT((back - a).norm(), kReconstruction * a.norm() * 10);
    const int p = static_cast<int>(svd.singularValues().size());
    EXPECT_LT((svd.u().transpose() * svd.u() - Eigen::MatrixXd::Identity(p, p)).norm(), 1e-12);
    EXPECT_LT((svd.v().transpose() * svd.v() - Eigen::MatrixXd::Identity(p, p)).norm(), 1e-12);
    for (int i = 1; i < p; ++i) EXPECT_GE(svd.singularValues()(i - 1), svd.singularValues()(i));
}

}  // namespace

TEST(CachedSvd, GivenTallAndWideMatrices_WhenFactoredByEachBackend_ThenTheyReproduceA)
{
    for (const auto& [m, n] : {std::pair{30, 12}, std::pair{12, 30}}) {
        const Eigen::MatrixXd a = randomMatrix(m, n);
        expectValid(CachedSvd(a, SvdBackend::Eigen), a);
        if (lapackAvailable()) {
            const CachedSvd l(a, SvdBackend::Lapack);
            expectValid(l, a);
            EXPECT_LT((l.singularValues() - CachedSvd(a, SvdBackend::Eigen).singularValues()).norm(), 1e-12);
        }
    }
}

TEST(CachedSvd, GivenRankTwoMatrix_WhenFactored_ThenRankIsTwo)
{
    const Eigen::MatrixXd a = randomMatrix(10, 2) * randomMatrix(2, 8);
    EXPECT_EQ(CachedSvd(a).rank(), 2);
    EXPECT_EQ(CachedSvd(Eigen::MatrixXd::Zero(3, 3)).rank(), 0);
}

TEST(CachedSvd, GivenWideMatrix_WhenNullBasisAsked_ThenVAndItAreOneOrthogonalMatrix)
{
    const Eigen::MatrixXd a = randomMatrix(5, 9);
    const CachedSvd svd(a);
    Eigen::MatrixXd full(9, 9);
    full << svd.v(), svd.nullBasis();
    EXPECT_LT((full.transpose() * full - Eigen::MatrixXd::Identity(9, 9)).norm(), 1e-12);
    EXPECT_LT((a * svd.nullBasis()).norm(), 1e-12);
}

TEST(CachedSvd, GivenNaNOrEmpty_WhenFactored_ThenRefused)
{
    Eigen::MatrixXd a = Eigen::MatrixXd::Ones(3, 3);
    a(1, 1) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(CachedSvd{a}, std::invalid_argument);
    EXPECT_THROW(CachedSvd{Eigen::MatrixXd(0, 3)}, std::invalid_argument);
}
