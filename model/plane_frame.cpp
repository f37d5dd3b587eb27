#include "model/plane_frame.h"

namespace sculptline::model {

PlaneFrame PlaneFrame::fromNormal(const Eigen::Vector3d& origin, const Eigen::Vector3d& normal, double size,
                                  const Eigen::Vector3d& xAxis)
{
    PlaneFrame frame;
    frame.origin = origin;
    frame.size = size;
    const Eigen::Vector3d z = normal.normalized();
    const Eigen::Vector3d x = xAxis - xAxis.dot(z) * z;
    if (x.norm() > 1e-9 * std::max(1.0, xAxis.norm())) {
        Eigen::Matrix3d axes;
        axes.col(0) = x.normalized();
        axes.col(2) = z;
        axes.col(1) = z.cross(axes.col(0));
        frame.rotation = Eigen::Quaterniond(axes).normalized();
    } else if (z.z() < -1.0 + 1e-12) {
        // FromTwoVectors picks an arbitrary axis for the antiparallel case; a half turn about X
        // matches SbRotation's choice, so old documents keep their look.
        frame.rotation = Eigen::Quaterniond(0.0, 1.0, 0.0, 0.0);
    } else {
        frame.rotation = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), z);
    }
    return frame;
}

}  // namespace sculptline::model
