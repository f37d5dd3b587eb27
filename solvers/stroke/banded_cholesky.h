#pragma once
// Cholesky factorization of a symmetric positive definite band matrix, O(n w^2) time and O(n w)
// memory (Golub & Van Loan, Matrix Computations, 4th ed., Alg. 4.3.5 "band Cholesky").
// The least-squares B-spline normal matrix of degree p has half-bandwidth p (de Boor,
// A Practical Guide to Splines, ch. XIV: B_i B_j vanishes for |i - j| > p).
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

}  // namespace sculptline::solvers::stroke
