#pragma once
// Where a projection plane is: an origin and a rotation taking the plane's local frame (X and Y in
// the plane, Z its normal) to the world. Curves drawn on a plane are stored in this local frame, so
// moving the plane moves them rigidly without refitting (issue 5 §1).
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace sculptline::model {

struct PlaneFrame {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< centre, model units
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  ///< local -> world, unit
    double size = 200.0;  ///< edge length, model units, > 0

    Eigen::Vector3d normal() const { return rotation * Eigen::Vector3d::UnitZ(); }
    Eigen::Vector3d xAxis() const { return rotation * Eigen::Vector3d::UnitX(); }
    Eigen::Vector3d toWorld(const Eigen::Vector3d& local) const { return origin + rotation * local; }
    Eigen::Vector3d toLocal(const Eigen::Vector3d& world) const { return rotation.conjugate() * (world - origin); }

    /// The frame with this origin whose Z is `normal` (the shortest arc from +Z, as the document's
    /// plain "normal" has always been read) and whose X is `xAxis` projected into the plane when
    /// that is given and not parallel to the normal.
    static PlaneFrame fromNormal(const Eigen::Vector3d& origin, const Eigen::Vector3d& normal, double size,
                                 const Eigen::Vector3d& xAxis = Eigen::Vector3d::Zero());
};

inline bool operator==(const PlaneFrame& a, const PlaneFrame& b)
{
    return a.origin == b.origin && a.rotation.coeffs() == b.rotation.coeffs() && a.size == b.size;
}
inline bool operator!=(const PlaneFrame& a, const PlaneFrame& b) { return !(a == b); }

}  // namespace sculptline::model
