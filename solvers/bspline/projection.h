#pragma once
// Closest-point projection onto curves and surfaces, global (not just the nearest local minimum).
#include "solvers/bspline/bspline_surface.h"
#include "solvers/bspline/curve_jet.h"
#include "solvers/bspline/surface_jet.h"

#include <algorithm>

namespace sculptline::solvers {

/// One Newton step toward a foot point of x on a curve (The NURBS Book eq. 6.3): on
/// f(u) = C'(u)·(C(u) - x), f'(u) = C''(u)·(C(u) - x) + |C'(u)|², from c = C(u), d1 = C'(u),
/// d2 = C''(u) (any evaluator: CurveJet, a solver's own power form); u moves to u - f / f'
/// clamped to [lo, hi]. Returns false, u unchanged, where f' <= 0 (no minimum of the distance
/// nearby: Newton would climb). The solvers iterate it in their own loops: a fixed count of passes
/// or until the distance is small enough; CurveProjector brackets and safeguards it instead.
template <class Vector>
bool footPointNewtonStep(const Vector& c, const Vector& d1, const Vector& d2, const Vector& x, double lo, double hi,
                         double& u)
{
    const Vector r = c - x;
    const double df = d2.dot(r) + d1.squaredNorm();
    if (!(df > 0.0)) return false;
    u = std::clamp(u - d1.dot(r) / df, lo, hi);
    return true;
}

template <int Dim>
struct CurveProjection {
    double u = 0.0;
    Eigen::Matrix<double, Dim, 1> point;
    double distance = 0.0;
};

struct SurfaceProjection {
    double u = 0.0;
    double v = 0.0;
    Eigen::Vector3d point;
    double distance = 0.0;
};

/// Projects points onto one curve. The curve is sampled once (a few samples per knot span, enough
/// that each sample interval holds at most one local minimum of the distance for ordinary curves);
/// each query brackets every sampled local minimum, refines both of its half-intervals (a C0 knot
/// has a minimum on each side) with Newton's method on
/// f(u) = C'(u)·(C(u) - x) (The NURBS Book eq. 6.3) safeguarded by bisection, compares with the
/// end points (open curves) and returns the best. Closed curves wrap across the seam.
template <int Dim>
class CurveProjector {
public:
    using Point = Eigen::Matrix<double, Dim, 1>;
    /// @param samplesPerSpan coarse samples per non-empty knot span (>= 2).
    explicit CurveProjector(BSplineCurve<Dim> curve, int samplesPerSpan = 16);
    CurveProjection<Dim> project(const Point& x) const;
    const BSplineCurve<Dim>& curve() const { return curve_; }

private:
    double refine(const Point& x, double lo, double hi, double guess) const;

    BSplineCurve<Dim> curve_;
    CurveJet<Dim> jet_;  // C, C', C'' for the Newton iterations without allocating
    std::vector<double> params_;
    std::vector<Point> samples_;
};

template <int Dim>
CurveProjection<Dim> projectToCurve(const BSplineCurve<Dim>& curve, const Eigen::Matrix<double, Dim, 1>& x);

/// Projects points onto a 3D surface: a coarse grid per knot-span pair, every grid local minimum
/// refined by Newton's method on the normal equations (The NURBS Book eqs. 6.6-6.7) with a
/// backtracking line search and clamping to the domain, and the four boundary curves projected
/// with CurveProjector so that minima on the boundary are found exactly. Then every grid cell
/// that could still hold a closer point (its bounding box, see kCellBulge in projection.cpp,
/// nearer than the best found) is searched by Newton confined to the cell, nearest cell first:
/// where the surface folds or wiggles within a cell (a lofted section's jittered end), the grid's
/// local minima can all lie in other valleys of the distance.
class SurfaceProjector {
public:
    /// @param samplesPerSpan coarse grid samples per non-empty knot span (>= 2); fewer in a
    /// direction with so many spans that the grid would exceed kMaxGridSamples (projection.cpp).
    explicit SurfaceProjector(BSplineSurface<3> surface, int samplesPerSpan = 8);
    SurfaceProjection project(const Eigen::Vector3d& x) const;

private:
    // Newton from (u, v) kept inside the box [ua, ub] x [va, vb].
    // *budget (when given) counts down the surface evaluations; Newton stops when it runs out.
    SurfaceProjection newton(const Eigen::Vector3d& x, double u, double v, double ua, double ub, double va, double vb,
                             long* budget = nullptr) const;

    BSplineSurface<3> surface_;
    SurfaceJet jet_;  // S and its derivatives for Newton without allocating
    std::vector<double> us_, vs_;
    std::vector<Eigen::Vector3d> grid_;  // grid_[i * vs_.size() + j]
    // Per cell (i, j) between grid lines i, i+1 and j, j+1 (index i * (vs_.size() - 1) + j): a
    // box that holds the cell's patch (its nine sample points' box, padded by their bulge).
    std::vector<Eigen::Vector3d> cellLow_, cellHigh_;
    // Blocks of kBlockCells x kBlockCells cells (index bi * blockCountV_ + bj) with the box of their
    // cells' boxes: a point's search tests the blocks and only the cells of blocks that can be nearer.
    int blockCountV_ = 0;
    std::vector<Eigen::Vector3d> blockLow_, blockHigh_;
    std::vector<CurveProjector<3>> boundaries_;
    std::vector<std::pair<int, double>> boundaryParams_;  // (fixed direction 0:u fixed / 1:v fixed, value)
};

SurfaceProjection projectToSurface(const BSplineSurface<3>& surface, const Eigen::Vector3d& x);

extern template class CurveProjector<2>;
extern template class CurveProjector<3>;

}  // namespace sculptline::solvers
