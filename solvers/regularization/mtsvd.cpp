#include "solvers/regularization/mtsvd.h"

#include <Eigen/Householder>
#include <Eigen/QR>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace sculptline::solvers::regularization {

namespace {

// A diagonal entry of R below this fraction of R's largest is taken as a rank deficiency of L V_{k+1}.
constexpr double kSingularRatio = 1e-10;

}  // namespace

Eigen::MatrixXd secondDifferences(int n)
{
    if (n < 3) throw std::invalid_argument("smoothing: second differences need n >= 3, got " + std::to_string(n));
    Eigen::MatrixXd l = Eigen::MatrixXd::Zero(n - 2, n);
    for (int i = 0; i < n - 2; ++i) {
        l(i, i) = 1.0;
        l(i, i + 1) = -2.0;
        l(i, i + 2) = 1.0;
    }
    return l;
}

MtsvdSolver::MtsvdSolver(const CachedSvd& svd, const Eigen::MatrixXd& l) : svd_(svd)
{
    if (l.cols() != svd.cols() || l.rows() < 1) {
        throw std::invalid_argument("smoothing: expected rows of " + std::to_string(svd.cols()) + " columns, got " +
                                    std::to_string(l.rows()) + "x" + std::to_string(l.cols()));
    }
    if (!l.allFinite()) throw std::invalid_argument("smoothing: contains a non-finite number");
    const Eigen::MatrixXd& nb = svd.nullBasis();
    vFull_.resize(svd.cols(), svd.cols());
    vFull_ << svd.v(), nb;
    lv_ = l * vFull_;
}

// γ_i = β_i/σ_i − α_i for i = 1..r: x_k − x0 = V_k γ_{1..k}.
Eigen::MatrixXd MtsvdSolver::gammaCoefficients(const ProjectedRhs& rhs) const
{
    const int r = svd_.rank();
    return svd_.singularValues().head(r).cwiseInverse().asDiagonal() * rhs.beta.topRows(r) - rhs.alpha.topRows(r);
}

Eigen::MatrixXd MtsvdSolver::solution(const ProjectedRhs& rhs, int k) const
{
    if (k < 1 || k > svd_.rank()) {
        throw std::invalid_argument("k: " + std::to_string(k) + " is outside 1.." + std::to_string(svd_.rank()));
    }
    const int n = svd_.cols();
    const Eigen::MatrixXd gamma = gammaCoefficients(rhs).topRows(k);
    Eigen::MatrixXd x = rhs.x0 + vFull_.leftCols(k) * gamma;  // x_k
    if (k < n) {
        const Eigen::MatrixXd c = lv_.leftCols(k) * gamma;  // L (x_k − x0)
        // The same rank cut as the sweep's: a direction of V_{k+1} that L hardly sees (an affine
        // motion under a thin-plate L, up to round-off) is left alone instead of amplified by 1/ε.
        Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod;
        cod.setThreshold(kSingularRatio);
        cod.compute(lv_.rightCols(n - k));
        x -= vFull_.rightCols(n - k) * cod.solve(c);
    }
    return x;
}

LCurve MtsvdSolver::lcurve(const ProjectedRhs& rhs) const
{
    const int r = svd_.rank(), n = svd_.cols(), p = static_cast<int>(lv_.rows());
    const int q = static_cast<int>(svd_.singularValues().size());
    const int d = static_cast<int>(rhs.beta.cols());
    const Eigen::VectorXd& s = svd_.singularValues();
    const Eigen::MatrixXd gamma = gammaCoefficients(rhs);
    LCurve lc;
    lc.rho.resize(r);
    lc.eta.resize(r);
    lc.sigma = s.head(r);
    fallbacks_ = 0;

    // ρ² from the coefficients g of x − x_k in V_{k+1}: rows k+1..q of Σ(α + g) − β, plus the outside part.
    auto rhoOf = [&](int k, const Eigen::MatrixXd& g) {
        double sq = rhs.outsideSq;
        for (int i = k; i < q; ++i) {
            const Eigen::RowVectorXd gi = i - k < g.rows() ? Eigen::RowVectorXd(g.row(i - k)) : Eigen::RowVectorXd::Zero(d);
            sq += (s(i) * (rhs.alpha.row(i) + gi) - rhs.beta.row(i)).squaredNorm();
        }
        return std::sqrt(sq);
    };

    const int kFirstQr = std::max(1, n - p);
    Eigen::MatrixXd qt;  // Qᵀ of the current QR, p×p
    Eigen::MatrixXd rr;  // R, p×c (c = n − k columns)
    bool haveQr = false;
    Eigen::MatrixXd c = Eigen::MatrixXd::Zero(p, d);  // L (x_k − x0)
    for (int k = 1; k <= r; ++k) {
        c += lv_.col(k - 1) * gamma.row(k - 1);
        const int cols = n - k;
        if (cols == 0) {  // V_{k+1} is empty: x = x_k
            lc.eta(k - 1) = c.norm();
            lc.rho(k - 1) = rhoOf(k, Eigen::MatrixXd(0, d));
            continue;
        }
        if (k >= kFirstQr) {
            if (!haveQr) {
                const Eigen::HouseholderQR<Eigen::MatrixXd> qr(lv_.rightCols(cols));
                qt = qr.householderQ().transpose() * Eigen::MatrixXd::Identity(p, p);
                rr = qr.matrixQR().triangularView<Eigen::Upper>();
                haveQr = true;
            } else {
                // Delete R's first column; the Hessenberg remainder is made triangular by Givens
                // rotations on rows (j, j+1), applied to Qᵀ as well.
                Eigen::MatrixXd h = rr.rightCols(cols);
                for (int j = 0; j < cols; ++j) {
                    Eigen::JacobiRotation<double> g;
                    g.makeGivens(h(j, j), h(j + 1, j));
                    h.applyOnTheLeft(j, j + 1, g.adjoint());
                    qt.applyOnTheLeft(j, j + 1, g.adjoint());
                    h(j + 1, j) = 0.0;
                }
                rr = std::move(h);
            }
            const Eigen::VectorXd diag = rr.topRows(cols).diagonal().cwiseAbs();
            if (diag.minCoeff() > kSingularRatio * std::max(diag.maxCoeff(), std::numeric_limits<double>::min())) {
                const Eigen::MatrixXd qc = qt * c;
                const Eigen::MatrixXd g =
                    -rr.topRows(cols).triangularView<Eigen::Upper>().solve(qc.topRows(cols));
                lc.eta(k - 1) = qc.bottomRows(p - cols).norm();
                lc.rho(k - 1) = rhoOf(k, g);
                continue;
            }
        }
        ++fallbacks_;
        const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(lv_.rightCols(cols));
        const Eigen::MatrixXd g = -cod.solve(c);
        lc.eta(k - 1) = (c + lv_.rightCols(cols) * g).norm();
        lc.rho(k - 1) = rhoOf(k, g);
    }
    return lc;
}

}  // namespace sculptline::solvers::regularization
