#include "solvers/bspline/surface_jet.h"

#include "solvers/bspline/basis.h"
#include "solvers/bspline/geometry_error.h"

#include <algorithm>
#include <cmath>

namespace sculptline::solvers {

SurfaceJet::SurfaceJet(const BSplineSurface<3>& surface)
    : degree_{surface.degreeU(), surface.degreeV()},
      countV_(surface.countV()),
      rational_(surface.isRational()),
      knots_{surface.knotsU(), surface.knotsV()}
{
    points_.reserve(static_cast<size_t>(surface.countU()) * static_cast<size_t>(countV_));
    for (int i = 0; i < surface.countU(); ++i) {
        for (int j = 0; j < countV_; ++j) {
            const double w = surface.weight(i, j);
            Homogeneous h;
            h << w * surface.point(i, j), w;
            points_.push_back(h);
        }
    }
}

SurfaceJet::Values SurfaceJet::evaluate(double u, double v) const
{
    if (!std::isfinite(u) || !std::isfinite(v)) throw GeometryError("params: not a finite number");
    const int p = degree_[0], q = degree_[1];
    const int countU = static_cast<int>(points_.size()) / countV_;
    u = std::clamp(u, knots_[0][p], knots_[0][countU]);
    v = std::clamp(v, knots_[1][q], knots_[1][countV_]);
    const int uspan = findSpan(p, knots_[0], u);
    const int vspan = findSpan(q, knots_[1], v);
    // Rows k = 0..2 of the basis derivatives (a row beyond the degree is zero, basis.h).
    double Nu[3 * (kMaxDegree + 1)], Nv[3 * (kMaxDegree + 1)];
    basisDerivatives(uspan, u, p, 2, knots_[0], Nu);
    basisDerivatives(vspan, v, q, 2, knots_[1], Nv);
    // A_kl = sum_r sum_s N_r^(k)(u) N_s^(l)(v) Pw_rs for k + l <= 2, through the column sums
    // T_k(s) = sum_r N_r^(k)(u) Pw_rs (The NURBS Book A3.6).
    Homogeneous A00 = Homogeneous::Zero(), A10 = A00, A01 = A00, A20 = A00, A11 = A00, A02 = A00;
    for (int s = 0; s <= q; ++s) {
        Homogeneous T0 = Homogeneous::Zero(), T1 = T0, T2 = T0;
        const int j = vspan - q + s;
        for (int r = 0; r <= p; ++r) {
            const Homogeneous& P = points_[static_cast<size_t>(uspan - p + r) * countV_ + j];
            T0 += Nu[r] * P;
            T1 += Nu[(p + 1) + r] * P;
            T2 += Nu[2 * (p + 1) + r] * P;
        }
        const double n0 = Nv[s], n1 = Nv[(q + 1) + s], n2 = Nv[2 * (q + 1) + s];
        A00 += n0 * T0;
        A01 += n1 * T0;
        A02 += n2 * T0;
        A10 += n0 * T1;
        A11 += n1 * T1;
        A20 += n0 * T2;
    }
    Values out;
    if (!rational_) {
        // w = 1: the quotient rule would only add round-off.
        out.s = A00.head<3>();
        out.su = A10.head<3>();
        out.sv = A01.head<3>();
        out.suu = A20.head<3>();
        out.suv = A11.head<3>();
        out.svv = A02.head<3>();
        return out;
    }
    // S = A/w and its derivatives by the quotient rule (The NURBS Book A4.4 for k + l <= 2).
    const double w = A00[3];
    out.s = A00.head<3>() / w;
    out.su = (A10.head<3>() - A10[3] * out.s) / w;
    out.sv = (A01.head<3>() - A01[3] * out.s) / w;
    out.suu = (A20.head<3>() - 2.0 * A10[3] * out.su - A20[3] * out.s) / w;
    out.svv = (A02.head<3>() - 2.0 * A01[3] * out.sv - A02[3] * out.s) / w;
    out.suv = (A11.head<3>() - A10[3] * out.sv - A01[3] * out.su - A11[3] * out.s) / w;
    return out;
}

}  // namespace sculptline::solvers
