#pragma once
// The singular value decomposition A = U Σ Vᵀ of an m×n matrix, computed once and kept, so that every
// regularized solve (TSVD, MTSVD, the L-curve) re-uses it: a new right-hand side costs Uᵀb and sums
// (Hansen's Regularization Tools: `csvd` once, then `tsvd`, `mtsvd`, `l_curve` take its output).
//
// Two backends. Eigen's BDCSVD (divide and conquer, always there) and LAPACK's dgesdd through LAPACKE
// when the build found it (SCULPTLINE_HAVE_LAPACKE; Debian liblapacke-dev + libopenblas-dev). The
// faster one on a 1000×500 matrix (bench/regularization_bench.cpp, README "Regularization") is the
// default; the other stays selectable.
#include <Eigen/Core>

#include <string>

namespace sculptline::solvers::regularization {

enum class SvdBackend {
    Default,  ///< the measured faster one that this build has (see defaultSvdBackend())
    Eigen,    ///< Eigen::BDCSVD
    Lapack,   ///< LAPACKE_dgesdd; only when lapackAvailable()
};

/// Whether this build links LAPACKE (SvdBackend::Lapack usable).
bool lapackAvailable();

/// The backend SvdBackend::Default resolves to in this build.
SvdBackend defaultSvdBackend();

std::string svdBackendName(SvdBackend backend);

/// Thin SVD of A, singular values in decreasing order, with the numerical rank.
class CachedSvd {
public:
    /// @param a  m×n, finite, m, n >= 1.
    /// @param backend  Default, Eigen or Lapack (Lapack without LAPACKE throws std::invalid_argument).
    /// @throws std::invalid_argument on an empty or non-finite matrix.
    explicit CachedSvd(const Eigen::MatrixXd& a, SvdBackend backend = SvdBackend::Default);

    int rows() const { return static_cast<int>(u_.rows()); }
    int cols() const { return static_cast<int>(v_.rows()); }
    /// min(m, n) columns each.
    const Eigen::MatrixXd& u() const { return u_; }
    const Eigen::MatrixXd& v() const { return v_; }
    const Eigen::VectorXd& singularValues() const { return sigma_; }
    /// Numerical rank r: σ_i > max(m, n) · ε · σ_1 (LAPACK's and numpy's default cut-off); 0 for A = 0.
    int rank() const { return rank_; }
    SvdBackend backend() const { return backend_; }

    /// An orthonormal basis (n × (n − min(m, n))) of the complement of v()'s columns: with it,
    /// [v(), nullBasis()] is a full orthogonal V. Empty when m >= n. Computed on first use (not
    /// thread-safe: call it once before sharing a CachedSvd between threads).
    const Eigen::MatrixXd& nullBasis() const;

    /// Uᵀ B for B m×d: the only product with A's size a new right-hand side costs.
    Eigen::MatrixXd projectRhs(const Eigen::MatrixXd& b) const { return u_.transpose() * b; }

private:
    Eigen::MatrixXd u_, v_;
    Eigen::VectorXd sigma_;
    int rank_ = 0;
    SvdBackend backend_ = SvdBackend::Eigen;
    mutable Eigen::MatrixXd null_;
    mutable bool nullDone_ = false;
};

}  // namespace sculptline::solvers::regularization
