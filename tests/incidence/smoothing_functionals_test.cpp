// The smoothing functionals' Gram matrices (seed 000 §4.4): exact, symmetric, positive
// semidefinite, with the right null spaces, and factors L with L^T L = G.
#include "solvers/incidence/smoothing_functionals.h"

#include "tests/incidence/incidence_fixtures.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::incidence;
using namespace sculptline::incidence_test;

namespace {

constexpr double kRoundOff = 1e-12;
// Eigenvalues below this fraction of the largest are zeros (the null space).
constexpr double kNullRelative = 1e-11;

Eigen::VectorXd eigenvalues(const Eigen::SparseMatrix<double>& g)
{
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(g)).eigenvalues();
}

int nullity(const Eigen::VectorXd& lambda)
{
    return static_cast<int>((lambda.array().abs() <= kNullRelative * lambda.cwiseAbs().maxCoeff()).count());
}

// Greville abscissae: the control values that reproduce t (The NURBS Book eq. 9.7's averages).
Eigen::VectorXd greville(int degree, const KnotVector& knots, int count)
{
    Eigen::VectorXd x(count);
    for (int i = 0; i < count; ++i) {
        double sum = 0.0;
        for (int k = 1; k <= degree; ++k) sum += knots[i + k];
        x[i] = sum / degree;
    }
    return x;
}

// The energy of the surface by an independent, denser quadrature: 8 Gauss points on each quarter
// of every knot span, derivatives from the surface's own evaluator (The NURBS Book A3.6).
double denseEnergy(const Surface3d& f, double a1, double a2, double a3)
{
    Eigen::VectorXd nodes, weights;
    gaussLegendre(8, nodes, weights);
    auto pieces = [&](const KnotVector& k, int p, int n) {
        std::vector<std::pair<double, double>> out;
        for (int s = p; s < n; ++s)
            for (int q = 0; q < 4 && k[s + 1] > k[s]; ++q) {
                const double h = (k[s + 1] - k[s]) / 4.0;
                out.emplace_back(k[s] + q * h, k[s] + (q + 1) * h);
            }
        return out;
    };
    double energy = 0.0;
    for (const auto& [u0, u1] : pieces(f.knotsU(), f.degreeU(), f.countU()))
        for (const auto& [v0, v1] : pieces(f.knotsV(), f.degreeV(), f.countV()))
            for (int i = 0; i < nodes.size(); ++i)
                for (int j = 0; j < nodes.size(); ++j) {
                    const double u = 0.5 * (u0 + u1) + 0.5 * (u1 - u0) * nodes[i];
                    const double v = 0.5 * (v0 + v1) + 0.5 * (v1 - v0) * nodes[j];
                    const double w = 0.25 * (u1 - u0) * (v1 - v0) * weights[i] * weights[j];
                    const auto d = f.derivatives(u, v, 3);
                    const double area = d[1][0].squaredNorm() + d[0][1].squaredNorm();
                    const double plate = d[2][0].squaredNorm() + 2.0 * d[1][1].squaredNorm() + d[0][2].squaredNorm();
                    const double variation = d[3][0].squaredNorm() + 3.0 * d[2][1].squaredNorm() +
                                             3.0 * d[1][2].squaredNorm() + d[0][3].squaredNorm();
                    energy += w * (a1 * area + a2 * plate + a3 * variation);
                }
    return energy;
}

}  // namespace

TEST(IncidenceSmoothing, GaussLegendreIsExactToDegreeTwoNMinusOne)
{
    for (int n = 1; n <= 12; ++n) {
        Eigen::VectorXd x, w;
        gaussLegendre(n, x, w);
        for (int k = 0; k <= 2 * n - 1; ++k) {
            const double exact = k % 2 == 1 ? 0.0 : 2.0 / (k + 1);
            EXPECT_NEAR((w.array() * x.array().pow(k)).sum(), exact, 1e-14) << "n " << n << " k " << k;
        }
    }
}

TEST(IncidenceSmoothing, GramMatricesAreSymmetricSemidefiniteWithTheRightNullSpaces)
{
    // Given Fig. 4's 8x10 bicubic structure on uneven knots
    const Surface3d f = figureFourSurface();
    const SurfaceStructure s = SurfaceStructure::of(f);
    // Null spaces: constants (area), affine functions (thin plate), quadratics (curvature variation)
    const int expectedNullity[] = {1, 3, 6};
    const Functional functionals[] = {Functional::Area, Functional::ThinPlate, Functional::CurvatureVariation};
    for (int k = 0; k < 3; ++k) {
        const Eigen::SparseMatrix<double> g = gramMatrix(s, functionals[k]);
        const Eigen::MatrixXd dense(g);
        EXPECT_EQ((dense - dense.transpose()).cwiseAbs().maxCoeff(), 0.0);
        const Eigen::VectorXd lambda = eigenvalues(g);
        EXPECT_GE(lambda.minCoeff(), -kNullRelative * lambda.maxCoeff());
        EXPECT_EQ(nullity(lambda), expectedNullity[k]) << "functional " << k;
    }
    // Constants have no area energy; a planar affine net (control points at the Greville abscissae
    // under an affine map) has no thin plate energy
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(s.columnCount());
    EXPECT_LT((gramMatrix(s, Functional::Area) * ones).norm(), kRoundOff);
    const Eigen::VectorXd gu = greville(3, f.knotsU(), f.countU()), gv = greville(3, f.knotsV(), f.countV());
    Eigen::VectorXd affine(s.columnCount());
    for (int i = 0; i < f.countU(); ++i)
        for (int j = 0; j < f.countV(); ++j) affine[i * f.countV() + j] = 3.0 + 40.0 * gu[i] - 25.0 * gv[j];
    const Eigen::SparseMatrix<double> plate = gramMatrix(s, Functional::ThinPlate);
    EXPECT_LT(affine.dot(plate * affine), kRoundOff * affine.squaredNorm());
    // ... while the bilinear u v is not affine: it bends (S_uv = 1)
    Eigen::VectorXd bilinear(s.columnCount());
    for (int i = 0; i < f.countU(); ++i)
        for (int j = 0; j < f.countV(); ++j) bilinear[i * f.countV() + j] = gu[i] * gv[j];
    EXPECT_NEAR(bilinear.dot(plate * bilinear), 2.0, 1e-12);  // ∫∫ 2 * 1² over the unit square
}

TEST(IncidenceSmoothing, EnergiesMatchADenseQuadratureOfTheSurface)
{
    const Surface3d f = wavySurface(8, 10, 0.6);
    const SurfaceStructure s = SurfaceStructure::of(f);
    const ControlMatrix p = surfacePointRows(f);
    const double weights[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const auto& a : weights) {
        const Eigen::SparseMatrix<double> g = smoothingGram(s, a[0], a[1], a[2]);
        const double gram = (p.transpose() * (g * p)).trace();
        const double dense = denseEnergy(f, a[0], a[1], a[2]);
        EXPECT_NEAR(gram, dense, 1e-12 * dense) << a[0] << " " << a[1] << " " << a[2];
    }
    // The combination is the combination of the parts
    const double mix = (p.transpose() * (smoothingGram(s, 0.2, 0.5, 0.3) * p)).trace();
    EXPECT_NEAR(mix, denseEnergy(f, 0.2, 0.5, 0.3), 1e-12 * mix);
}

TEST(IncidenceSmoothing, FactorsReproduceTheGramMatrix)
{
    const SurfaceStructure s = SurfaceStructure::of(figureFourSurface());
    const Eigen::MatrixXd g(smoothingGram(s, 0.2, 0.5, 0.3));
    const double scale = g.cwiseAbs().maxCoeff();
    // The square root: L^T L = G, one row per non-zero eigenvalue (the mix's null space: constants)
    const Eigen::MatrixXd root = gramFactor(g, FactorMethod::SquareRoot);
    EXPECT_EQ(root.rows(), s.columnCount() - 1);
    EXPECT_LT((root.transpose() * root - g).cwiseAbs().maxCoeff(), kRoundOff * scale);
    EXPECT_LT((root * Eigen::VectorXd::Ones(s.columnCount())).norm(), 1e-10 * std::sqrt(scale));
    // Cholesky with a ridge: L^T L = G + ε I, upper triangular
    const Eigen::MatrixXd chol = gramFactor(g, FactorMethod::CholeskyRidge, 1e-12);
    const Eigen::MatrixXd shifted = g + 1e-12 * g.diagonal().maxCoeff() * Eigen::MatrixXd::Identity(g.rows(), g.cols());
    EXPECT_LT((chol.transpose() * chol - shifted).cwiseAbs().maxCoeff(), kRoundOff * scale);
    EXPECT_EQ(chol.triangularView<Eigen::StrictlyLower>().toDenseMatrix().cwiseAbs().maxCoeff(), 0.0);
}
