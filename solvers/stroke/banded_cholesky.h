#pragma once
// Cholesky factorization of a symmetric positive definite band matrix, O(n w^2) time and O(n w)
// memory (Golub & Van Loan, Matrix Computations, 4th ed., Alg. 4.3.5 "band Cholesky").
// The least-squares B-spline normal matrix of degree p has half-bandwidth p (de Boor,
// A Practical Guide to Splines, ch. XIV: B_i B_j vanishes for |i - j| > p).
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <vector>

namespace sculptline::solvers::stroke {

/// A symmetric band matrix stored by its lower band: entry (i, i - d), d = 0..bandwidth.
class BandMatrix {
public:
    BandMatrix() = default;
    BandMatrix(int size, int bandwidth) { reset(size, bandwidth); }
    /// Zero matrix of this size and bandwidth, reusing the storage.
    void reset(int size, int bandwidth)
    {
        n_ = size;
        w_ = bandwidth;
        a_.assign(static_cast<size_t>(size) * (bandwidth + 1), 0.0);
    }
    int size() const { return n_; }
    int bandwidth() const { return w_; }
    /// Entry (i, j) of the lower triangle, |i - j| <= bandwidth, j <= i.
    double& at(int i, int j) { return a_[static_cast<size_t>(i) * (w_ + 1) + (i - j)]; }
    double at(int i, int j) const { return a_[static_cast<size_t>(i) * (w_ + 1) + (i - j)]; }
    /// Adds v to (i, j) of the symmetric matrix (either triangle).
    void add(int i, int j, double v) { i >= j ? at(i, j) += v : at(j, i) += v; }

    /// Factors in place into L (L L^T = A). Returns false if a pivot is not positive.
    bool factor();
    /// Solves A X = B for the factored matrix; B has one row per unknown, any number of columns.
    void solveInPlace(Eigen::MatrixXd& b) const;
    /// The same for three right-hand sides stored as one 3-vector per unknown (the least-squares
    /// fit's x, y, z): fixed-size rows, no dynamic-matrix indexing in the inner loops.
    void solveInPlace(std::vector<Eigen::Vector3d>& b) const;

private:
    int n_ = 0;
    int w_ = 0;
    std::vector<double> a_;
};

/// A symmetric positive definite cyclic band matrix of half-bandwidth 3 (a periodic cubic
/// B-spline least squares' normal matrix): A(i, j) = 0 unless i and j are within 3 of each other
/// modulo the size. Solved by block elimination, O(n): with m = n - 3, the leading m x m block B
/// is a plain band matrix (two of its indices within 3 modulo n are within 3 outright), the last 3
/// unknowns border it. B = L L^T (BandMatrix), W = B^-1 C for the border columns C, the Schur
/// complement S = D - C^T W (3 x 3, positive definite as A is) by a dense Cholesky; then
/// x_2 = S^-1 (b_2 - C^T B^-1 b_1) and x_1 = B^-1 b_1 - W x_2 (Golub & Van Loan, Matrix
/// Computations, 4th ed., §4.5.4 on block elimination).
class CyclicBandMatrix {
public:
    static constexpr int kBandwidth = 3;
    /// Zero matrix of this size (> kBandwidth), reusing the storage.
    void reset(int size);
    int size() const { return n_; }
    /// Adds v to entry (i, j), i >= j, of the lower triangle (the symmetric entry is the same).
    void addLower(int i, int j, double v)
    {
        if (i < m_)
            band_.at(i, j) += v;
        else if (j < m_)
            w_[static_cast<size_t>(j)][i - m_] += v;
        else
            d_(i - m_, j - m_) += v;
    }
    /// Factors in place. Returns false if the matrix is not positive definite.
    bool factor();
    /// Solves A X = B for the factored matrix, three right-hand sides as one 3-vector per unknown.
    void solveInPlace(std::vector<Eigen::Vector3d>& b) const;

private:
    int n_ = 0, m_ = 0;
    BandMatrix band_;
    std::vector<Eigen::Vector3d> c_;  // the border C, one row of 3 per unknown of B (after factor())
    std::vector<Eigen::Vector3d> w_;  // C before factor(), B^-1 C after
    Eigen::Matrix3d d_;               // the lower triangle of D
    Eigen::LLT<Eigen::Matrix3d> schur_;
    mutable std::vector<Eigen::Vector3d> z_;
};

}  // namespace sculptline::solvers::stroke
