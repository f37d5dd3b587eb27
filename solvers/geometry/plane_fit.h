#pragma once
// The best-fit (total least squares) plane of a point set: through the centroid, spanned by the two
// largest principal axes of the scatter matrix; its normal is the smallest (Pearson 1901; Golub &
// Van Loan §6.3, orthogonal regression). One definition for every caller that needs "the plane the
// points lie in": strokes drawn in space, outlines rotated out of their plane.
#include <Eigen/Core>

#include <vector>

namespace sculptline::solvers {

struct PlaneFit {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    Eigen::Vector3d axisU = Eigen::Vector3d::UnitX();   ///< the largest principal axis (unit)
    Eigen::Vector3d axisV = Eigen::Vector3d::UnitY();   ///< the middle one (unit)
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< the smallest one (unit)
    /// Eigenvalues of the scatter matrix sum (p - c)(p - c)^T, ascending: [normal, V, U]; squared
    /// model units. spread(0) = 0 for exactly planar points, spread(1) = 0 for collinear ones.
    Eigen::Vector3d spread = Eigen::Vector3d::Zero();
};

/// @param points  at least one point; the axes of fewer than three distinct points are arbitrary
///                (spread says so).
/// @throws GeometryError for an empty set.
PlaneFit bestFitPlane(const std::vector<Eigen::Vector3d>& points);

}  // namespace sculptline::solvers
