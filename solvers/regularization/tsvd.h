#pragma once
// Truncated SVD with a prior (seed 000 §4.2, eqs. 3–4):
//   x_k = Σ_{i≤k} (u_iᵀ b / σ_i) v_i + V_{k+1} V_{k+1}ᵀ x0,
// the rank-k solution whose free part (the span of v_{k+1}..v_n) is taken from the previously known x0.
// Several right-hand sides are solved at once (B m×d, e.g. the x, y, z of control points) with one k;
// norms are then Frobenius norms. Everything here works on a CachedSvd: a new B costs Uᵀ B and sums.
#include "solvers/regularization/cached_svd.h"

#include <Eigen/Core>

namespace sculptline::solvers::regularization {

/// ρ_k = ‖A x_k − B‖ and η_k (TSVD: ‖x_k − x0‖; MTSVD: ‖L (x_k − x0)‖) for k = 1..r, at index k − 1.
struct LCurve {
    Eigen::VectorXd rho;
    Eigen::VectorXd eta;
    /// σ_k at index k − 1 when known (tsvdLCurve, MtsvdSolver::lcurve), else empty. The corner skips
    /// the k whose σ_k is at round-off: their v_k is set by rounding errors, not by A.
    Eigen::VectorXd sigma;
};

/// A right-hand side and prior in the SVD's coordinates (p = min(m, n) rows each).
struct ProjectedRhs {
    Eigen::MatrixXd beta;   ///< Uᵀ B
    Eigen::MatrixXd alpha;  ///< V_pᵀ X0 (zero without a prior)
    Eigen::MatrixXd x0;     ///< n×d, the prior (zero without one)
    double outsideSq = 0.0; ///< ‖B − U Uᵀ B‖²: the part of B outside range(A), no solution fits it
};

/// Uᵀ B, V_pᵀ X0 and the part of B outside the range.
/// @param b  m×d right-hand sides, finite.
/// @param x0  n×d prior, or empty (0×0) for none (x0 = 0).
/// @throws std::invalid_argument on a size mismatch.
ProjectedRhs projectRhs(const CachedSvd& svd, const Eigen::MatrixXd& b, const Eigen::MatrixXd& x0 = {});

/// x_k (n×d) of eqs. 3–4.
/// @param k  truncation, 1 <= k <= svd.rank().
/// @throws std::invalid_argument for k out of range.
Eigen::MatrixXd tsvdSolution(const CachedSvd& svd, const ProjectedRhs& rhs, int k);

/// ρ_k and η_k for k = 1..r from the SVD coordinates alone (O(r·d) after projectRhs):
///   x_k − x0 = Σ_{i≤k} γ_i v_i with γ_i = β_i/σ_i − α_i, so η_k² = Σ_{i≤k} ‖γ_i‖²;
///   A x_k − B = Σ_{i>k} u_i (σ_i α_i − β_i) − (B − U Uᵀ B), so ρ_k² = Σ_{k<i≤p} ‖σ_i α_i − β_i‖² + outside².
LCurve tsvdLCurve(const CachedSvd& svd, const ProjectedRhs& rhs);

/// The stateful form (geometry-central's Solver pattern): factor A once, then each right-hand side and
/// prior is the "two products" re-solve, Uᵀ B and sums.
class TsvdSolver {
public:
    explicit TsvdSolver(const Eigen::MatrixXd& a, SvdBackend backend = SvdBackend::Default) : svd_(a, backend) {}
    explicit TsvdSolver(CachedSvd svd) : svd_(std::move(svd)) {}

    const CachedSvd& svd() const { return svd_; }
    /// Sets B and X0 (empty: none) and returns their L-curve.
    const LCurve& setRhs(const Eigen::MatrixXd& b, const Eigen::MatrixXd& x0 = {});
    const LCurve& lcurve() const { return lcurve_; }
    const ProjectedRhs& rhs() const { return rhs_; }
    Eigen::MatrixXd solution(int k) const { return tsvdSolution(svd_, rhs_, k); }

private:
    CachedSvd svd_;
    ProjectedRhs rhs_;
    LCurve lcurve_;
};

}  // namespace sculptline::solvers::regularization
