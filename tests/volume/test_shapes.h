#pragma once
// Exact B-spline shapes for the solid tests: a rational sphere by revolving a rational half circle
// (The NURBS Book §7.5 and §8.5), flat bilinear patches, and the analytic volumes to compare with.
#include "solvers/bspline/bspline_surface.h"

#include <vector>

namespace sculptline::volume_test {

/// The sphere of `radius` about `centre`: a rational quadratic half circle (two 90° arcs, weights
/// 1, √2/2, 1, √2/2, 1) in the xz plane from the south to the north pole, revolved 360° about z.
solvers::Surface3d sphere(double radius, const Eigen::Vector3d& centre = Eigen::Vector3d::Zero());

/// The flat patch [0, a] x [0, b] in the plane z = 0, degree 1 in both directions (normal +z).
solvers::Surface3d flatPatch(double a, double b);

/// The patch with corners p00, p10, p01, p11 (i along U, j along V), degree 1.
solvers::Surface3d bilinear(const Eigen::Vector3d& p00, const Eigen::Vector3d& p10, const Eigen::Vector3d& p01,
                            const Eigen::Vector3d& p11);

/// The six faces of the axis-aligned cube [0, a]³, each a separate bilinear patch.
std::vector<solvers::Surface3d> cubeFaces(double a);

/// Volume of the union of two balls of radius r whose centres are d apart (0 <= d <= 2r):
/// 2·(4/3)πr³ minus the lens π(4r + d)(2r − d)²/12 (Weisstein, "Sphere-Sphere Intersection", MathWorld).
double twoBallUnionVolume(double r, double d);

}  // namespace sculptline::volume_test
