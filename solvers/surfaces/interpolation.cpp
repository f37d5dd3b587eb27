#include "solvers/surfaces/interpolation.h"

#include "solvers/bspline/geometry_error.h"

#include <cmath>
#include <string>

namespace sculptline::solvers::surfaces {

namespace {
// Below this reciprocal condition number the solution would carry no correct digit (double
// precision has ~16), so the parameters are treated as coincident.
constexpr double kMinReciprocalCondition = 1e-13;
}  // namespace

std::vector<double> chordParameters(const ControlMatrix& data, int groupSize)
{
    const Eigen::Index n = data.rows();
    const Eigen::Index groups = data.cols() / groupSize;
    std::vector<double> t(n, 0.0);
    if (n < 2) return t;
    for (Eigen::Index k = 1; k < n; ++k) {
        double chord = 0.0;
        for (Eigen::Index g = 0; g < groups; ++g)
            chord += (data.row(k).segment(g * groupSize, groupSize) - data.row(k - 1).segment(g * groupSize, groupSize))
                         .norm();
        t[k] = t[k - 1] + chord / static_cast<double>(groups);
    }
    const double total = t.back();
    for (Eigen::Index k = 0; k < n; ++k) {
        // Uniform when every row coincides: there is no length to distribute.
        t[k] = total > 0.0 ? t[k] / total : static_cast<double>(k) / static_cast<double>(n - 1);
    }
    t.back() = 1.0;
    // Coincident neighbours (a repeated section) would make the system singular; the caller's
    // CurveInterpolator reports that, naming the parameters.
    return t;
}

KnotVector averagedKnots(const std::vector<double>& params, int degree)
{
    const int n = static_cast<int>(params.size()) - 1;
    KnotVector knots(degree + 1, 0.0);
    for (int j = 1; j <= n - degree; ++j) {
        double s = 0.0;
        for (int i = j; i < j + degree; ++i) s += params[i];
        knots.push_back(s / degree);  // eq. 9.8
    }
    knots.insert(knots.end(), degree + 1, 1.0);
    return knots;
}

std::vector<double> grevilleAbscissae(int degree, const KnotVector& knots)
{
    const int count = static_cast<int>(knots.size()) - degree - 1;
    std::vector<double> g(count);
    for (int i = 0; i < count; ++i) {
        double s = 0.0;
        for (int k = 1; k <= degree; ++k) s += knots[i + k];
        g[i] = s / degree;
    }
    return g;
}

CurveInterpolator::CurveInterpolator(std::vector<double> params, int degree)
    : params_(std::move(params)), degree_(degree)
{
    if (degree_ < 1 || degree_ >= static_cast<int>(params_.size()))
        throw GeometryError("params: " + std::to_string(params_.size()) + " values cannot be interpolated with degree " +
                            std::to_string(degree_));
    knots_ = averagedKnots(params_, degree_);
    factor();
}

CurveInterpolator::CurveInterpolator(std::vector<double> params, int degree, KnotVector knots)
    : params_(std::move(params)), degree_(degree), knots_(std::move(knots))
{
    validateKnots(degree_, static_cast<int>(params_.size()), knots_);
    factor();
}

void CurveInterpolator::factor()
{
    for (size_t k = 1; k < params_.size(); ++k)
        if (!(params_[k] > params_[k - 1]))
            throw GeometryError("params: not strictly increasing at " + std::to_string(k) +
                                " (two coincident sections or samples)");
    const int n = static_cast<int>(params_.size());
    double basis[kMaxDegree + 1];
    if (n > kDenseInterpolationLimit) {
        std::vector<Eigen::Triplet<double>> entries;
        for (int k = 0; k < n; ++k) {
            const int span = findSpan(degree_, knots_, params_[k]);
            basisFunctions(span, params_[k], degree_, knots_, basis);
            for (int i = 0; i <= degree_; ++i)
                if (basis[i] != 0.0) entries.emplace_back(k, span - degree_ + i, basis[i]);
        }
        Eigen::SparseMatrix<double> N(n, n);
        N.setFromTriplets(entries.begin(), entries.end());
        sparse_ = std::make_shared<Eigen::SparseLU<Eigen::SparseMatrix<double>>>();
        sparse_->compute(N);
        if (sparse_->info() != Eigen::Success)
            throw GeometryError("params: interpolation system is singular (sections or samples too close together)");
        return;
    }
    Eigen::MatrixXd N = Eigen::MatrixXd::Zero(n, n);
    for (int k = 0; k < n; ++k) {
        const int span = findSpan(degree_, knots_, params_[k]);
        basisFunctions(span, params_[k], degree_, knots_, basis);
        for (int i = 0; i <= degree_; ++i) N(k, span - degree_ + i) = basis[i];
    }
    lu_.compute(N);
    // Reciprocal condition estimate: a (near-)singular collocation matrix means the parameters
    // violate Schoenberg-Whitney; say so instead of returning garbage.
    if (!(lu_.rcond() >= kMinReciprocalCondition))
        throw GeometryError("params: interpolation system is singular (sections or samples too close together)");
}

ControlMatrix CurveInterpolator::solve(const ControlMatrix& data) const
{
    if (sparse_) {
        const Eigen::MatrixXd x = sparse_->solve(Eigen::MatrixXd(data));
        return x;
    }
    const Eigen::MatrixXd x = lu_.solve(Eigen::MatrixXd(data));
    return x;
}

}  // namespace sculptline::solvers::surfaces
