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

}  // namespace sculptline::solvers::stroke
