#pragma once
// Rotation-minimizing frames by the double reflection method (W. Wang, B. Jüttler, D. Zheng,
// Y. Liu, "Computation of rotation minimizing frames", ACM TOG 27(1), 2008, Algorithm 1): frames
// along a curve that do not twist about the tangent, so a swept profile does not flip.
#include "solvers/bspline/bspline_curve.h"
#include "solvers/bspline/curve_jet.h"
#include "solvers/math_constants.h"

#include <Eigen/Core>
#include <vector>

namespace sculptline::solvers::surfaces {

/// An orthonormal frame at a point of a curve: tangent t, reference (normal) r, s = t × r.
struct Frame {
    Eigen::Vector3d origin;
    Eigen::Vector3d tangent;
    Eigen::Vector3d normal;
    Eigen::Vector3d binormal;
    /// Columns (t, r, s): maps frame coordinates to world directions.
    Eigen::Matrix3d axes() const;
};

/// One double-reflection step from frame f to the point x1 with unit tangent t1 (Wang et al. eq. 6):
/// reflect in the bisector plane of x0 x1, then in the plane that takes the reflected tangent to t1.
Frame propagateFrame(const Frame& f, const Eigen::Vector3d& x1, const Eigen::Vector3d& t1);

/// Frames at increasing parameters of `path`, the first with normal `initialNormal` made
/// orthogonal to the tangent (any vector not parallel to it).
std::vector<Frame> rotationMinimizingFrames(const Curve3d& path, const std::vector<double>& params,
                                            const Eigen::Vector3d& initialNormal);

/// The same, with the path's jet (the kernel's allocation-free C, C', C'') already built (sweeps
/// reuse it).
std::vector<Frame> rotationMinimizingFrames(const CurveJet3d& path, const std::vector<double>& params,
                                            const Eigen::Vector3d& initialNormal);

/// Throws GeometryError ("path: ...") if the path has no length, a vanishing derivative, or a
/// tangent that turns back by more than kCuspTurn between neighbouring dense samples (a cusp, or
/// a C0 corner sharp enough that a swept profile would fold over itself).
void requireNoCusp(const Curve3d& path);

/// A tangent turning by more than 90 degrees between samples 1/64 of a knot span apart is a cusp
/// for sweeping: a smooth path cannot turn that fast at ordinary sketch scales, and a profile swept
/// around such a turn intersects itself.
constexpr double kCuspTurn = 0.5 * kPi;

/// Unit tangent of the path at u (the one-sided limit from the right at the domain start, from the
/// left at the end).
Eigen::Vector3d unitTangent(const Curve3d& path, double u);

}  // namespace sculptline::solvers::surfaces
