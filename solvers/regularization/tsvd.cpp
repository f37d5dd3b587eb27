#include "solvers/regularization/tsvd.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace sculptline::solvers::regularization {

ProjectedRhs projectRhs(const CachedSvd& svd, const Eigen::MatrixXd& b, const Eigen::MatrixXd& x0)
{
    if (b.rows() != svd.rows() || b.cols() < 1) {
        throw std::invalid_argument("rhs: expected " + std::to_string(svd.rows()) + " rows, got " +
                                    std::to_string(b.rows()));
    }
    const bool prior = x0.size() > 0;
    if (prior && (x0.rows() != svd.cols() || x0.cols() != b.cols())) {
        throw std::invalid_argument("prior: expected " + std::to_string(svd.cols()) + "x" + std::to_string(b.cols()) +
                                    ", got " + std::to_string(x0.rows()) + "x" + std::to_string(x0.cols()));
    }
    ProjectedRhs r;
    r.beta = svd.projectRhs(b);
    r.x0 = prior ? x0 : Eigen::MatrixXd::Zero(svd.cols(), b.cols());
    r.alpha = prior ? Eigen::MatrixXd(svd.v().transpose() * x0) : Eigen::MatrixXd::Zero(r.beta.rows(), b.cols());
    // Directly, not as ‖B‖² − ‖β‖²: that difference cancels when B is nearly in the range.
    r.outsideSq = (b - svd.u() * r.beta).squaredNorm();
    return r;
}

Eigen::MatrixXd tsvdSolution(const CachedSvd& svd, const ProjectedRhs& rhs, int k)
{
    if (k < 1 || k > svd.rank()) {
        throw std::invalid_argument("k: " + std::to_string(k) + " is outside 1.." + std::to_string(svd.rank()));
    }
    const Eigen::MatrixXd gamma = svd.singularValues().head(k).cwiseInverse().asDiagonal() * rhs.beta.topRows(k) -
                                  rhs.alpha.topRows(k);
    return rhs.x0 + svd.v().leftCols(k) * gamma;
}

LCurve tsvdLCurve(const CachedSvd& svd, const ProjectedRhs& rhs)
{
    const int r = svd.rank();
    const int p = static_cast<int>(svd.singularValues().size());
    const Eigen::VectorXd& s = svd.singularValues();
    LCurve lc;
    lc.rho.resize(r);
    lc.eta.resize(r);
    lc.sigma = s.head(r);
    // Residual terms of the columns beyond k, summed from the end (small terms first).
    Eigen::VectorXd tail(p + 1);
    tail(p) = rhs.outsideSq;
    for (int i = p - 1; i >= 0; --i) tail(i) = tail(i + 1) + (s(i) * rhs.alpha.row(i) - rhs.beta.row(i)).squaredNorm();
    double etaSq = 0.0;
    for (int k = 1; k <= r; ++k) {
        etaSq += (rhs.beta.row(k - 1) / s(k - 1) - rhs.alpha.row(k - 1)).squaredNorm();
        lc.eta(k - 1) = std::sqrt(etaSq);
        lc.rho(k - 1) = std::sqrt(tail(k));
    }
    return lc;
}

const LCurve& TsvdSolver::setRhs(const Eigen::MatrixXd& b, const Eigen::MatrixXd& x0)
{
    rhs_ = projectRhs(svd_, b, x0);
    lcurve_ = tsvdLCurve(svd_, rhs_);
    return lcurve_;
}

}  // namespace sculptline::solvers::regularization
