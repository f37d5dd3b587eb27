#include "solvers/incidence/smoothing_functionals.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/math_constants.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <utility>

namespace sculptline::solvers::incidence {

namespace {

// P_n(x) and P_n'(x) by the three-term recurrence.
std::pair<double, double> legendre(int n, double x)
{
    double pn = x, pm = 1.0;
    for (int k = 2; k <= n; ++k) {
        const double next = ((2.0 * k - 1.0) * x * pn - (k - 1.0) * pm) / k;
        pm = pn;
        pn = next;
    }
    if (n == 1) return {x, 1.0};
    return {pn, n * (x * pn - pm) / (x * x - 1.0)};
}

}  // namespace

void gaussLegendre(int n, Eigen::VectorXd& nodes, Eigen::VectorXd& weights)
{
    if (n < 1) throw GeometryError("quadrature: need at least one point");
    nodes.resize(n);
    weights.resize(n);
    // Newton on P_n from the estimate cos(pi (i + 3/4) / (n + 1/2)) of each root (Numerical
    // Recipes §4.6, gauleg); w = 2 / ((1 - x²) P_n'(x)²).
    for (int i = 0; i < (n + 1) / 2; ++i) {
        double x = std::cos(kPi * (i + 0.75) / (n + 0.5));
        for (int it = 0; it < 100; ++it) {
            const auto [p, dp] = legendre(n, x);
            const double step = p / dp;
            x -= step;
            if (std::abs(step) <= 1e-16) break;
        }
        if (n % 2 == 1 && i == n / 2) x = 0.0;
        const double dp = legendre(n, x).second;
        nodes[i] = -x;
        nodes[n - 1 - i] = x;
        weights[i] = weights[n - 1 - i] = 2.0 / ((1.0 - x * x) * dp * dp);
    }
}

Eigen::MatrixXd univariateGram(int degree, const KnotVector& knots, int derivative)
{
    const int count = static_cast<int>(knots.size()) - degree - 1;
    Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(count, count);
    if (derivative > degree) return gram;
    Eigen::VectorXd nodes, weights;
    gaussLegendre(degree + 1, nodes, weights);  // the integrand has degree 2 (degree - derivative)
    std::vector<double> ders(static_cast<size_t>((derivative + 1) * (degree + 1)));
    for (int span = degree; span < count; ++span) {
        const double a = knots[span], b = knots[span + 1];
        if (b <= a) continue;
        for (int g = 0; g < nodes.size(); ++g) {
            const double t = 0.5 * (a + b) + 0.5 * (b - a) * nodes[g];
            const double w = 0.5 * (b - a) * weights[g];
            basisDerivatives(span, t, degree, derivative, knots, ders.data());
            const double* d = ders.data() + static_cast<size_t>(derivative) * (degree + 1);
            for (int i = 0; i <= degree; ++i)
                for (int k = 0; k <= degree; ++k) gram(span - degree + i, span - degree + k) += w * d[i] * d[k];
        }
    }
    return gram;
}

namespace {

// coefficient * (gu ⊗ gv) added to `triplets`, index i * countV + j.
void addTensor(double coefficient, const Eigen::MatrixXd& gu, const Eigen::MatrixXd& gv,
               std::vector<Eigen::Triplet<double>>& triplets)
{
    if (coefficient == 0.0) return;
    const Eigen::Index nv = gv.rows();
    for (Eigen::Index i = 0; i < gu.rows(); ++i)
        for (Eigen::Index k = 0; k < gu.cols(); ++k) {
            if (gu(i, k) == 0.0) continue;
            for (Eigen::Index j = 0; j < nv; ++j)
                for (Eigen::Index l = 0; l < nv; ++l) {
                    if (gv(j, l) == 0.0) continue;
                    triplets.emplace_back(static_cast<int>(i * nv + j), static_cast<int>(k * nv + l),
                                          coefficient * gu(i, k) * gv(j, l));
                }
        }
}

}  // namespace

Eigen::SparseMatrix<double> smoothingGram(const SurfaceStructure& f, double a1, double a2, double a3)
{
    std::vector<Eigen::MatrixXd> gu, gv;
    for (int d = 0; d <= 3; ++d) {
        gu.push_back(univariateGram(f.degreeU, f.knotsU, d));
        gv.push_back(univariateGram(f.degreeV, f.knotsV, d));
    }
    std::vector<Eigen::Triplet<double>> triplets;
    addTensor(a1, gu[1], gv[0], triplets);  // S_u²
    addTensor(a1, gu[0], gv[1], triplets);  // S_v²
    addTensor(a2, gu[2], gv[0], triplets);  // S_uu²
    addTensor(2.0 * a2, gu[1], gv[1], triplets);  // 2 S_uv²
    addTensor(a2, gu[0], gv[2], triplets);  // S_vv²
    addTensor(a3, gu[3], gv[0], triplets);  // S_uuu²
    addTensor(3.0 * a3, gu[2], gv[1], triplets);  // 3 S_uuv²
    addTensor(3.0 * a3, gu[1], gv[2], triplets);  // 3 S_uvv²
    addTensor(a3, gu[0], gv[3], triplets);  // S_vvv²
    Eigen::SparseMatrix<double> gram(f.columnCount(), f.columnCount());
    gram.setFromTriplets(triplets.begin(), triplets.end());
    // Exactly symmetric (the sums above are, up to the order of additions).
    const Eigen::SparseMatrix<double> transposed = gram.transpose();
    return 0.5 * (gram + transposed);
}

Eigen::SparseMatrix<double> gramMatrix(const SurfaceStructure& f, Functional functional)
{
    switch (functional) {
    case Functional::Area: return smoothingGram(f, 1.0, 0.0, 0.0);
    case Functional::ThinPlate: return smoothingGram(f, 0.0, 1.0, 0.0);
    case Functional::CurvatureVariation: return smoothingGram(f, 0.0, 0.0, 1.0);
    }
    return {};
}

Eigen::MatrixXd gramFactor(const Eigen::MatrixXd& gram, FactorMethod method, double ridge)
{
    const double scale = gram.diagonal().cwiseAbs().maxCoeff();
    if ((gram - gram.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scale) throw GeometryError("gram: not symmetric");
    if (method == FactorMethod::CholeskyRidge) {
        const Eigen::MatrixXd shifted = gram + ridge * scale * Eigen::MatrixXd::Identity(gram.rows(), gram.cols());
        const Eigen::LLT<Eigen::MatrixXd> llt(shifted);
        if (llt.info() != Eigen::Success) throw GeometryError("gram: not positive semidefinite (Cholesky failed)");
        return llt.matrixU();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram);
    const Eigen::VectorXd& lambda = eigen.eigenvalues();  // ascending
    const double largest = lambda.cwiseAbs().maxCoeff();
    if (lambda.minCoeff() < -1e-10 * largest) throw GeometryError("gram: not positive semidefinite");
    constexpr double kNullRelative = 1e-13;
    std::vector<int> kept;
    for (int i = 0; i < lambda.size(); ++i)
        if (lambda[i] > kNullRelative * largest) kept.push_back(i);
    Eigen::MatrixXd l(static_cast<Eigen::Index>(kept.size()), gram.cols());
    for (size_t r = 0; r < kept.size(); ++r)
        l.row(static_cast<Eigen::Index>(r)) = std::sqrt(lambda[kept[r]]) * eigen.eigenvectors().col(kept[r]).transpose();
    return l;
}

}  // namespace sculptline::solvers::incidence
