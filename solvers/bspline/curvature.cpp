#include "solvers/bspline/curvature.h"

#include "solvers/bspline/geometry_error.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace sculptline::solvers {

namespace {

/// |a x b| computed as a cross product, accurate to a few ulps of |a||b|. (Lagrange's identity,
/// |a|^2 |b|^2 - (a.b)^2, cancels catastrophically where the curve is nearly straight: its error
/// is eps |a|^2 |b|^2, whose square root gives a curvature of 1e-8 on a straight line.)
template <typename Vector>
double crossNorm(const Vector& a, const Vector& b)
{
    if constexpr (Vector::RowsAtCompileTime == 2) {
        return std::abs(a.x() * b.y() - a.y() * b.x());
    } else {
        return a.cross(b).norm();
    }
}

}  // namespace

template <int Dim>
double curvature(const BSplineCurve<Dim>& curve, double u, double minSpeed)
{
    const auto d = curve.derivatives(u, 2);
    const double speed = d[1].norm();
    if (!(speed > minSpeed) || speed == 0.0) return 0.0;
    return crossNorm(d[1], d[2]) / (speed * speed * speed);
}

template <int Dim>
std::vector<double> sampleCurvature(const BSplineCurve<Dim>& curve, double u0, double u1, int count, double minSpeed)
{
    if (count < 2) throw GeometryError("count: at least 2 samples");
    std::vector<double> kappa;
    kappa.reserve(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) kappa.push_back(curvature(curve, u0 + (u1 - u0) * i / (count - 1), minSpeed));
    return kappa;
}

template double curvature<2>(const BSplineCurve<2>&, double, double);
template double curvature<3>(const BSplineCurve<3>&, double, double);
template std::vector<double> sampleCurvature<2>(const BSplineCurve<2>&, double, double, int, double);
template std::vector<double> sampleCurvature<3>(const BSplineCurve<3>&, double, double, int, double);

}  // namespace sculptline::solvers
