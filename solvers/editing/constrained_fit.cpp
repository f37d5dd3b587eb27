#include "solvers/editing/constrained_fit.h"

#include "solvers/bspline/geometry_error.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>

namespace sculptline::solvers::editing {
namespace {

// Fairing weight per sample and control point (see fitFixedKnots): 1e-6 moves a well-sampled fit by
// ~1e-6 of its second differences (far below any sketch tolerance) and bounds the condition number
// of the stacked system by ~1e3 / sqrt(1e-6) when a span is empty.
constexpr double kFitFairing = 1e-6;

}  // namespace

KnotVector clampedUniformKnots(int degree, int spans, double a, double b)
{
    KnotVector k(degree, a);
    for (int i = 0; i <= spans; ++i) k.push_back(a + (b - a) * i / spans);
    k.back() = b;
    for (int i = 0; i < degree; ++i) k.push_back(b);
    return k;
}

template <int Dim>
std::vector<double> chordLengths(const std::vector<Eigen::Matrix<double, Dim, 1>>& pts)
{
    std::vector<double> s(pts.size(), 0.0);
    for (size_t i = 1; i < pts.size(); ++i) s[i] = s[i - 1] + (pts[i] - pts[i - 1]).norm();
    return s;
}

template <int Dim>
std::vector<Eigen::Matrix<double, Dim, 1>> resampleByArcLength(const std::vector<Eigen::Matrix<double, Dim, 1>>& pts,
                                                               int count)
{
    const std::vector<double> s = chordLengths<Dim>(pts);
    std::vector<Eigen::Matrix<double, Dim, 1>> out;
    size_t seg = 1;
    for (int k = 0; k < count; ++k) {
        const double target = s.back() * k / (count - 1);
        while (seg + 1 < pts.size() && s[seg] < target) ++seg;
        const double len = s[seg] - s[seg - 1];
        const double t = len > 0.0 ? std::clamp((target - s[seg - 1]) / len, 0.0, 1.0) : 0.0;
        out.push_back(pts[seg - 1] + t * (pts[seg] - pts[seg - 1]));
    }
    out.front() = pts.front();
    out.back() = pts.back();
    return out;
}

template <int Dim>
std::vector<Eigen::Matrix<double, Dim, 1>> dropDuplicates(const std::vector<Eigen::Matrix<double, Dim, 1>>& pts,
                                                          double minDistance)
{
    std::vector<Eigen::Matrix<double, Dim, 1>> out;
    for (const auto& p : pts) {
        if (out.empty() || (p - out.back()).norm() > minDistance) out.push_back(p);
    }
    if (out.size() > 1 && (pts.back() - out.back()).norm() > 0.0) out.back() = pts.back();
    return out;
}

template <int Dim>
std::vector<Eigen::Matrix<double, Dim, 1>> fitFixedKnots(const FixedKnotFit<Dim>& pr)
{
    using Point = Eigen::Matrix<double, Dim, 1>;
    const int p = pr.degree;
    const int n = static_cast<int>(pr.knots.size()) - p - 1;
    if (n < p + 1) throw GeometryError("knots: too few for the degree");
    if (pr.params.size() != pr.samples.size()) throw GeometryError("samples: one parameter per sample needed");
    std::vector<int> col(n, -1);
    int m = 0;
    for (int i = 0; i < n; ++i) {
        if (pr.fixed.empty() || !pr.fixed[i]) col[i] = m++;
    }
    std::vector<Point> result(n, Point::Zero());
    for (int i = 0; i < n; ++i) {
        if (col[i] < 0) result[i] = *pr.fixed[i];
    }
    if (m == 0) return result;

    const int rowsData = static_cast<int>(pr.samples.size());
    const int rowsFair = std::max(0, n - 2);
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(rowsData + rowsFair, m);
    Eigen::Matrix<double, Eigen::Dynamic, Dim> rhs(rowsData + rowsFair, Dim);
    rhs.setZero();
    double basis[kMaxDegree + 1];
    const bool rational = !pr.weights.empty();
    if (rational && static_cast<int>(pr.weights.size()) != n) {
        throw GeometryError("weights: one per control point needed");
    }
    for (int k = 0; k < rowsData; ++k) {
        const int span = findSpan(p, pr.knots, pr.params[k]);
        basisFunctions(span, pr.params[k], p, pr.knots, basis);
        if (rational) {  // R_i = w_i N_i / Σ w_j N_j (The NURBS Book eq. 4.2)
            double W = 0.0;
            for (int j = 0; j <= p; ++j) W += (basis[j] *= pr.weights[span - p + j]);
            for (int j = 0; j <= p; ++j) basis[j] /= W;
        }
        rhs.row(k) = pr.samples[k].transpose();
        for (int j = 0; j <= p; ++j) {
            const int i = span - p + j;
            if (col[i] >= 0)
                a(k, col[i]) += basis[j];
            else
                rhs.row(k) -= basis[j] * result[i].transpose();
        }
    }
    const double w = std::sqrt(kFitFairing * std::max(1.0, double(rowsData) / n));
    for (int r = 0; r < rowsFair; ++r) {
        const double coef[3] = {w, -2.0 * w, w};
        for (int j = 0; j < 3; ++j) {
            const int i = r + j;
            if (col[i] >= 0)
                a(rowsData + r, col[i]) += coef[j];
            else
                rhs.row(rowsData + r) -= coef[j] * result[i].transpose();
        }
    }
    const Eigen::Matrix<double, Eigen::Dynamic, Dim> x = a.householderQr().solve(rhs);
    for (int i = 0; i < n; ++i) {
        if (col[i] >= 0) result[i] = x.row(col[i]).transpose();
    }
    return result;
}

#define SCULPTLINE_INSTANTIATE(D)                                                                  \
    template std::vector<Eigen::Matrix<double, D, 1>> fitFixedKnots<D>(const FixedKnotFit<D>&);    \
    template std::vector<double> chordLengths<D>(const std::vector<Eigen::Matrix<double, D, 1>>&); \
    template std::vector<Eigen::Matrix<double, D, 1>> resampleByArcLength<D>(                      \
        const std::vector<Eigen::Matrix<double, D, 1>>&, int);                                     \
    template std::vector<Eigen::Matrix<double, D, 1>> dropDuplicates<D>(                           \
        const std::vector<Eigen::Matrix<double, D, 1>>&, double);
SCULPTLINE_INSTANTIATE(2)
SCULPTLINE_INSTANTIATE(3)
#undef SCULPTLINE_INSTANTIATE

}  // namespace sculptline::solvers::editing
