#pragma once
// Position and derivatives up to second order of a surface without allocating.
#include "solvers/bspline/bspline_surface.h"

#include <Eigen/Core>
#include <vector>

namespace sculptline::solvers {

/// S, S_u, S_v, S_uu, S_uv, S_vv of a (rational) 3D surface at (u, v) without allocating: the basis
/// derivatives by The NURBS Book A2.3 on stack arrays, the homogeneous sums of A3.6 and the
/// quotient rule of A4.4 (k + l <= 2) for rational surfaces. The same values as
/// BSplineSurface::derivatives(u, v, 2) to round-off (same clamping to the domain, same span at a
/// knot), which allocates a dozen times per call: for foot-point iterations that evaluate one
/// surface at many parameters (SurfaceProjector's Newton).
class SurfaceJet {
public:
    using Point = Eigen::Vector3d;
    struct Values {
        Point s, su, sv, suu, suv, svv;
    };

    explicit SurfaceJet(const BSplineSurface<3>& surface);

    Values evaluate(double u, double v) const;

private:
    using Homogeneous = Eigen::Vector4d;

    int degree_[2];
    int countV_;
    bool rational_;
    KnotVector knots_[2];
    std::vector<Homogeneous> points_;  // (w P, w) at i * countV + j; w = 1 for a non-rational surface
};

}  // namespace sculptline::solvers
