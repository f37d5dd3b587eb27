#include "solvers/regularization/cached_svd.h"

#include <Eigen/Householder>
#include <Eigen/SVD>

#include <limits>
#include <stdexcept>
#include <vector>

#ifdef SCULPTLINE_HAVE_LAPACKE
#include <lapacke.h>
#endif

namespace sculptline::solvers::regularization {

bool lapackAvailable()
{
#ifdef SCULPTLINE_HAVE_LAPACKE
    return true;
#else
    return false;
#endif
}

SvdBackend defaultSvdBackend()
{
    // Measured on 1000×500 (README "Regularization"): dgesdd through OpenBLAS is the faster one.
    return lapackAvailable() ? SvdBackend::Lapack : SvdBackend::Eigen;
}

std::string svdBackendName(SvdBackend backend)
{
    switch (backend) {
    case SvdBackend::Default: return "default (" + svdBackendName(defaultSvdBackend()) + ")";
    case SvdBackend::Eigen: return "eigen-bdcsvd";
    case SvdBackend::Lapack: return "lapack-dgesdd";
    }
    return "?";
}

namespace {

#ifdef SCULPTLINE_HAVE_LAPACKE
// dgesdd with jobz = 'S' (thin U and Vᵀ), column-major.
void lapackSvd(const Eigen::MatrixXd& a, Eigen::MatrixXd& u, Eigen::VectorXd& s, Eigen::MatrixXd& v)
{
    const lapack_int m = static_cast<lapack_int>(a.rows()), n = static_cast<lapack_int>(a.cols());
    const lapack_int p = std::min(m, n);
    Eigen::MatrixXd work = a;  // dgesdd destroys its input
    Eigen::MatrixXd vt(p, n);
    u.resize(m, p);
    s.resize(p);
    const lapack_int info = LAPACKE_dgesdd(LAPACK_COL_MAJOR, 'S', m, n, work.data(), m, s.data(), u.data(), m,
                                           vt.data(), p);
    if (info != 0) throw std::runtime_error("matrix: LAPACK dgesdd failed (info " + std::to_string(info) + ")");
    v = vt.transpose();
}
#endif

}  // namespace

CachedSvd::CachedSvd(const Eigen::MatrixXd& a, SvdBackend backend)
{
    if (a.rows() < 1 || a.cols() < 1) throw std::invalid_argument("matrix: must have at least one row and column");
    if (!a.allFinite()) throw std::invalid_argument("matrix: contains a non-finite number");
    if (backend == SvdBackend::Default) backend = defaultSvdBackend();
    backend_ = backend;
    if (backend == SvdBackend::Lapack) {
#ifdef SCULPTLINE_HAVE_LAPACKE
        lapackSvd(a, u_, sigma_, v_);
#else
        throw std::invalid_argument("backend: this build has no LAPACKE");
#endif
    } else {
        const Eigen::BDCSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeThinU | Eigen::ComputeThinV);
        u_ = svd.matrixU();
        v_ = svd.matrixV();
        sigma_ = svd.singularValues();
    }
    const double cut = static_cast<double>(std::max(a.rows(), a.cols())) * std::numeric_limits<double>::epsilon() *
                       (sigma_.size() > 0 ? sigma_(0) : 0.0);
    rank_ = 0;
    while (rank_ < sigma_.size() && sigma_(rank_) > cut) ++rank_;
}

const Eigen::MatrixXd& CachedSvd::nullBasis() const
{
    if (!nullDone_) {
        const int n = cols(), p = static_cast<int>(v_.cols());
        if (n > p) {
            // The last n − p columns of Q in V = Q R span the orthogonal complement of range(V).
            const Eigen::HouseholderQR<Eigen::MatrixXd> qr(v_);
            const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(n, n);
            null_ = q.rightCols(n - p);
        } else {
            null_.resize(n, 0);
        }
        nullDone_ = true;
    }
    return null_;
}

}  // namespace sculptline::solvers::regularization
