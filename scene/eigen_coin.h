#pragma once
// The one place where Eigen (the model's double precision) meets Coin's Sb types (single precision,
// the renderer's). Every conversion in the scene, manipulator and ui layers goes through here, so
// the narrowing to float happens in exactly one spot.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Inventor/SbRotation.h>
#include <Inventor/SbVec3f.h>
#include <Inventor/fields/SoMFVec3f.h>

#include <vector>

namespace sculptline::scene {

/// Eigen -> Coin; narrows to float (sub-micrometre loss at millimetre model scales up to ~10 m).
SbVec3f toSb(const Eigen::Vector3d& p);
/// Coin -> Eigen.
Eigen::Vector3d toEigen(const SbVec3f& p);
/// Rotations both ways (both store x, y, z, w).
SbRotation toSb(const Eigen::Quaterniond& q);
Eigen::Quaterniond toEigen(const SbRotation& r);

/// The rotation taking +Z to `normal` (the shortest arc). A plane node is modelled in its local XY
/// plane; this places it so that its normal points along `normal`.
/// @note normal must be non-zero; it need not be unit.
SbRotation rotationFromZ(const Eigen::Vector3d& normal);

/// The orientation of a Coin camera (which looks along its local -Z with +Y up) looking along
/// `view` with `up` as close to the screen's vertical as possible.
/// @note view non-zero and not parallel to up.
SbRotation rotationLookingAlong(const Eigen::Vector3d& view, const Eigen::Vector3d& up);

/// Replaces the field's values with `points` in one edit (one notification, not one per point).
void setPoints(SoMFVec3f& field, const std::vector<Eigen::Vector3d>& points);

}  // namespace sculptline::scene
