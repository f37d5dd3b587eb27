#pragma once
// Modified TSVD (Hansen, Sekii & Shibahashi 1992; seed 000 §4.4, eq. 5): of all solutions that keep
// the TSVD's fit in the first k singular directions, x = x_k + V_{k+1} f, the one minimizing
// ‖L (x − x0)‖:
//   x_{L,k} = x_k − V_{k+1} (L V_{k+1})⁺ L (x_k − x0),
// with x_k the TSVD solution with prior (tsvd.h) and L a p×n smoothing matrix.
#include "solvers/regularization/tsvd.h"

#include <Eigen/Core>

namespace sculptline::solvers::regularization {

/// The (n−2)×n second-difference matrix, rows [.. 1 −2 1 ..] (Regularization Tools' get_l(n, 2)).
/// @param n  >= 3.
Eigen::MatrixXd secondDifferences(int n);

/// MTSVD on a cached SVD. The full V (n×n, with the null space when m < n) and L·V are formed once.
///
/// The L-curve sweeps k = 1..r with one QR of L V_{k+1} updated across k: going from k to k+1 deletes
/// the first column of L V_{k+1}, and Givens rotations restore the triangle (Golub & Van Loan §12.5),
/// O(c (c + p)) per step instead of a new O(p c²) factorization. The update starts at the first k with
/// p >= n − k (a QR needs as many rows as columns); smaller k, and any k where the triangle turns out
/// numerically singular, are solved from scratch by a complete orthogonal decomposition (the minimum
/// norm least-squares solution, i.e. the pseudo-inverse).
class MtsvdSolver {
public:
    /// @param l  p×n, finite, p >= 1.
    /// @throws std::invalid_argument when l's column count is not A's.
    /// @note Keeps a reference to `svd`: it must outlive the solver.
    MtsvdSolver(const CachedSvd& svd, const Eigen::MatrixXd& l);

    /// ρ_k = ‖A x_{L,k} − B‖ and η_k = ‖L (x_{L,k} − x0)‖ for k = 1..r.
    LCurve lcurve(const ProjectedRhs& rhs) const;

    /// x_{L,k} (n×d), solved directly (one complete orthogonal decomposition of L V_{k+1}).
    /// @param k  1 <= k <= rank.
    Eigen::MatrixXd solution(const ProjectedRhs& rhs, int k) const;

    /// How many k of the last lcurve() were solved from scratch rather than by the QR update.
    int fallbackCount() const { return fallbacks_; }

private:
    Eigen::MatrixXd gammaCoefficients(const ProjectedRhs& rhs) const;
    const CachedSvd& svd_;
    Eigen::MatrixXd vFull_;  // [v(), nullBasis()]
    Eigen::MatrixXd lv_;     // L · vFull_
    mutable int fallbacks_ = 0;
};

}  // namespace sculptline::solvers::regularization
