#include "solvers/bspline/surface_curvature.h"

#include "solvers/bspline/basis.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sculptline::solvers {

SurfaceCurvature curvatureFromDerivatives(const Eigen::Vector3d& su, const Eigen::Vector3d& sv, const Eigen::Vector3d& suu,
                                          const Eigen::Vector3d& suv, const Eigen::Vector3d& svv)
{
    // do Carmo §3-3: the first (E, F, G) and second (L, M, N) fundamental forms.
    const double E = su.dot(su), F = su.dot(sv), G = sv.dot(sv);
    const double metric = E * G - F * F;
    SurfaceCurvature out;
    const double collapsed = kCollapsedDerivative * kCollapsedDerivative * std::max(E, G);
    if (!(metric > kDegenerateMetric * E * G) || !(std::min(E, G) > collapsed) || !std::isfinite(metric)) return out;
    // |Su x Sv|^2 = EG - F^2 (Lagrange's identity): the unit normal without a second square root.
    const Eigen::Vector3d n = su.cross(sv) / std::sqrt(metric);
    const double L = suu.dot(n), M = suv.dot(n), N = svv.dot(n);
    out.gaussian = (L * N - M * M) / metric;
    out.mean = (E * N - 2.0 * F * M + G * L) / (2.0 * metric);
    out.defined = std::isfinite(out.gaussian) && std::isfinite(out.mean);
    if (!out.defined) out = {};
    return out;
}

SurfaceCurvature surfaceCurvature(const Surface3d& surface, double u, double v)
{
    const auto d = surface.derivatives(u, v, 2);
    return curvatureFromDerivatives(d[1][0], d[0][1], d[2][0], d[1][1], d[0][2]);
}

namespace {

/// Span and basis derivatives up to order 2 (rows 0..2; rows beyond the degree are zero).
template <typename Line>
std::vector<Line> gridLines(int degree, const KnotVector& knots, const std::vector<double>& params, double lo, double hi)
{
    std::vector<Line> lines(params.size());
    for (size_t k = 0; k < params.size(); ++k) {
        const double t = std::clamp(params[k], lo, hi);
        lines[k].span = findSpan(degree, knots, t);
        lines[k].d = Eigen::MatrixXd::Zero(3, degree + 1);
        const int n = std::min(2, degree);
        lines[k].d.topRows(n + 1) = basisDerivatives(lines[k].span, t, degree, n, knots);
    }
    return lines;
}

}  // namespace

CurvatureGrid::CurvatureGrid(const Surface3d& surface, std::vector<double> u, std::vector<double> v)
    : degreeU_(surface.degreeU()), degreeV_(surface.degreeV()), countU_(surface.countU()), countV_(surface.countV()),
      knotsU_(surface.knotsU()), knotsV_(surface.knotsV()), u_(std::move(u)), v_(std::move(v))
{
    bu_ = gridLines<Line>(degreeU_, knotsU_, u_, surface.domainStart(Direction::U), surface.domainEnd(Direction::U));
    bv_ = gridLines<Line>(degreeV_, knotsV_, v_, surface.domainStart(Direction::V), surface.domainEnd(Direction::V));
}

bool CurvatureGrid::fits(const Surface3d& surface) const
{
    return surface.degreeU() == degreeU_ && surface.degreeV() == degreeV_ && surface.countU() == countU_ &&
           surface.countV() == countV_ && surface.knotsU() == knotsU_ && surface.knotsV() == knotsV_;
}

void CurvatureGrid::evaluate(const Surface3d& surface, std::vector<SurfaceCurvature>& out) const
{
    const int p = degreeU_, q = degreeV_;
    const size_t rows = u_.size(), cols = v_.size();
    out.assign(rows * cols, SurfaceCurvature{});
    // Row r's u-derivatives (k = 0..2) of the window's columns: temp[k] is 4 x (q+1).
    Eigen::Matrix<double, 4, Eigen::Dynamic> temp[3];
    for (auto& t : temp) t.resize(4, q + 1);
    for (size_t r = 0; r < rows; ++r) {
        const Line& lu = bu_[r];
        for (size_t c = 0; c < cols; ++c) {
            const Line& lv = bv_[c];
            // A[k][l] = d^(k+l)(wS, w)/du^k dv^l for k + l <= 2 (The NURBS Book A3.6).
            Eigen::Vector4d a[3][3];
            for (auto& t : temp) t.setZero();
            for (int s = 0; s <= q; ++s) {
                for (int i = 0; i <= p; ++i) {
                    const int ii = lu.span - p + i, jj = lv.span - q + s;
                    const double w = surface.weight(ii, jj);
                    Eigen::Vector4d h;
                    h << surface.point(ii, jj) * w, w;
                    for (int k = 0; k <= 2; ++k) temp[k].col(s) += lu.d(k, i) * h;
                }
            }
            for (int k = 0; k <= 2; ++k)
                for (int l = 0; k + l <= 2; ++l) a[k][l] = temp[k] * lv.d.row(l).transpose();
            // The NURBS Book A4.4 up to order 2: from (wS, w) to S.
            const double w = a[0][0][3];
            const Eigen::Vector3d s = a[0][0].head<3>() / w;
            const Eigen::Vector3d su = (a[1][0].head<3>() - a[1][0][3] * s) / w;
            const Eigen::Vector3d sv = (a[0][1].head<3>() - a[0][1][3] * s) / w;
            const Eigen::Vector3d suu = (a[2][0].head<3>() - 2.0 * a[1][0][3] * su - a[2][0][3] * s) / w;
            const Eigen::Vector3d svv = (a[0][2].head<3>() - 2.0 * a[0][1][3] * sv - a[0][2][3] * s) / w;
            const Eigen::Vector3d suv = (a[1][1].head<3>() - a[1][0][3] * sv - a[0][1][3] * su - a[1][1][3] * s) / w;
            out[r * cols + c] = curvatureFromDerivatives(su, sv, suu, suv, svv);
        }
    }
}

}  // namespace sculptline::solvers
