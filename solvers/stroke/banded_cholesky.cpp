#include "solvers/stroke/banded_cholesky.h"

#include <algorithm>
#include <cmath>

namespace sculptline::solvers::stroke {

bool BandMatrix::factor()
{
    for (int j = 0; j < n_; ++j) {
        double d = at(j, j);
        for (int k = std::max(0, j - w_); k < j; ++k) d -= at(j, k) * at(j, k);
        if (!(d > 0.0)) return false;
        const double ljj = std::sqrt(d);
        at(j, j) = ljj;
        for (int i = j + 1; i <= std::min(n_ - 1, j + w_); ++i) {
            double s = at(i, j);
            for (int k = std::max(0, i - w_); k < j; ++k) s -= at(i, k) * at(j, k);
            at(i, j) = s / ljj;
        }
    }
    return true;
}

void BandMatrix::solveInPlace(Eigen::MatrixXd& b) const
{
    for (int i = 0; i < n_; ++i) {  // L y = b
        for (int k = std::max(0, i - w_); k < i; ++k) b.row(i) -= at(i, k) * b.row(k);
        b.row(i) /= at(i, i);
    }
    for (int i = n_ - 1; i >= 0; --i) {  // L^T x = y
        for (int k = i + 1; k <= std::min(n_ - 1, i + w_); ++k) b.row(i) -= at(k, i) * b.row(k);
        b.row(i) /= at(i, i);
    }
}

void BandMatrix::solveInPlace(std::vector<Eigen::Vector3d>& b) const
{
    for (int i = 0; i < n_; ++i) {  // L y = b
        Eigen::Vector3d r = b[i];
        for (int k = std::max(0, i - w_); k < i; ++k) r -= at(i, k) * b[k];
        b[i] = r / at(i, i);
    }
    for (int i = n_ - 1; i >= 0; --i) {  // L^T x = y
        Eigen::Vector3d r = b[i];
        for (int k = i + 1; k <= std::min(n_ - 1, i + w_); ++k) r -= at(k, i) * b[k];
        b[i] = r / at(i, i);
    }
}

void CyclicBandMatrix::reset(int size)
{
    n_ = size;
    m_ = size - kBandwidth;
    band_.reset(m_, kBandwidth);
    w_.assign(static_cast<size_t>(m_), Eigen::Vector3d::Zero());
    d_.setZero();
}

bool CyclicBandMatrix::factor()
{
    if (!band_.factor()) return false;
    c_ = w_;
    band_.solveInPlace(w_);  // W = B^-1 C (the three border columns as the three right-hand sides)
    Eigen::Matrix3d s = d_.selfadjointView<Eigen::Lower>();
    for (int i = 0; i < m_; ++i) s.noalias() -= c_[static_cast<size_t>(i)] * w_[static_cast<size_t>(i)].transpose();
    schur_.compute(s);
    return schur_.info() == Eigen::Success;
}

void CyclicBandMatrix::solveInPlace(std::vector<Eigen::Vector3d>& b) const
{
    z_.assign(b.begin(), b.begin() + m_);
    band_.solveInPlace(z_);  // B^-1 b_1
    // r = b_2 - C^T B^-1 b_1: row k (a border unknown) holds its three coordinates.
    Eigen::Matrix3d r;
    for (int k = 0; k < kBandwidth; ++k) r.row(k) = b[static_cast<size_t>(m_ + k)].transpose();
    for (int i = 0; i < m_; ++i) r.noalias() -= c_[static_cast<size_t>(i)] * z_[static_cast<size_t>(i)].transpose();
    schur_.solveInPlace(r);  // x_2
    for (int i = 0; i < m_; ++i)
        b[static_cast<size_t>(i)] = z_[static_cast<size_t>(i)] - r.transpose() * w_[static_cast<size_t>(i)];
    for (int k = 0; k < kBandwidth; ++k) b[static_cast<size_t>(m_ + k)] = r.row(k).transpose();
}

}  // namespace sculptline::solvers::stroke
