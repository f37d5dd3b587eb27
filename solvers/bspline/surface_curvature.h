#pragma once
// Gaussian and mean curvature of B-spline surfaces, rational or not, from the first and second
// fundamental forms (do Carmo, Differential Geometry of Curves and Surfaces, §3-3, eqs. (4)-(5)):
//   E = Su.Su, F = Su.Sv, G = Sv.Sv,   L = Suu.n, M = Suv.n, N = Svv.n,   n = Su x Sv / |Su x Sv|,
//   K = (LN - M^2) / (EG - F^2),       H = (EN - 2FM + GL) / (2 (EG - F^2)).
// Sign of H: relative to n = Su x Sv. H > 0 where the surface bends towards n (a sphere whose
// normals point inwards has H = +1/r), H < 0 where it bends away (outward normals: H = -1/r).
// K does not depend on the orientation.
#include "solvers/bspline/bspline_surface.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace sculptline::solvers {

/// The metric is degenerate (no tangent plane, curvature undefined) where EG - F^2 <= this times
/// E G, i.e. where Su and Sv are parallel to within sin(angle) = 1e-8. Above it the fundamental
/// forms keep about 8 significant digits of the double-precision derivatives.
constexpr double kDegenerateMetric = 1e-16;
/// ... or where one first derivative is shorter than this times the other: a collapsed edge (the
/// pole of a revolved profile that ends on its axis), whose tiny derivative is rounding noise of
/// the coincident control points, in no meaningful direction.
constexpr double kCollapsedDerivative = 1e-8;

struct SurfaceCurvature {
    double gaussian = 0.0;  ///< K, 1 / model unit^2
    double mean = 0.0;      ///< H, 1 / model unit, sign relative to Su x Sv
    bool defined = false;   ///< false at degenerate points (kDegenerateMetric); K = H = 0 then
};

/// K and H from the first and second partial derivatives at one point.
SurfaceCurvature curvatureFromDerivatives(const Eigen::Vector3d& su, const Eigen::Vector3d& sv, const Eigen::Vector3d& suu,
                                          const Eigen::Vector3d& suv, const Eigen::Vector3d& svv);

/// K and H of `surface` at (u, v) (clamped to the domain), through Surface3d::derivatives (The
/// NURBS Book A3.6 and, for rational surfaces, A4.4). At a knot the second derivatives are those
/// of the span that starts there.
SurfaceCurvature surfaceCurvature(const Surface3d& surface, double u, double v);

/// K and H on a parameter grid (rows u, columns v; index r * cols + c, as solvers::GridMesh). Keeps
/// each grid line's span and basis derivatives (up to order 2), so that re-evaluating a surface
/// whose control points or weights moved (a drag) costs one small dense product per vertex.
class CurvatureGrid {
public:
    CurvatureGrid(const Surface3d& surface, std::vector<double> u, std::vector<double> v);
    /// True when `surface` has the degrees, knots and net size this grid was made for.
    bool fits(const Surface3d& surface) const;
    const std::vector<double>& u() const { return u_; }
    const std::vector<double>& v() const { return v_; }
    /// One SurfaceCurvature per grid vertex, equal (to rounding) to surfaceCurvature() there.
    /// `surface` must fit().
    void evaluate(const Surface3d& surface, std::vector<SurfaceCurvature>& out) const;

private:
    struct Line {
        int span = 0;
        Eigen::MatrixXd d;  ///< rows 0..2: values, first and second derivatives of degree+1 functions
    };
    int degreeU_ = 0, degreeV_ = 0, countU_ = 0, countV_ = 0;
    KnotVector knotsU_, knotsV_;
    std::vector<double> u_, v_;
    std::vector<Line> bu_, bv_;
};

}  // namespace sculptline::solvers
