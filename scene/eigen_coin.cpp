#include "scene/eigen_coin.h"

#include <Eigen/Geometry>

namespace sculptline::scene {

SbVec3f toSb(const Eigen::Vector3d& p)
{
    return SbVec3f(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()));
}

Eigen::Vector3d toEigen(const SbVec3f& p) { return Eigen::Vector3d(p[0], p[1], p[2]); }

SbRotation toSb(const Eigen::Quaterniond& q)
{
    return SbRotation(static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z()), static_cast<float>(q.w()));
}

Eigen::Quaterniond toEigen(const SbRotation& r)
{
    float x, y, z, w;
    r.getValue(x, y, z, w);
    return Eigen::Quaterniond(w, x, y, z).normalized();
}

SbRotation rotationFromZ(const Eigen::Vector3d& normal)
{
    // SbRotation(from, to) handles the antiparallel case (normal = -Z) with a half turn.
    return SbRotation(SbVec3f(0.0f, 0.0f, 1.0f), toSb(normal.normalized()));
}

SbRotation rotationLookingAlong(const Eigen::Vector3d& view, const Eigen::Vector3d& up)
{
    // Columns: where the camera's local X (right), Y (up) and Z (backwards) go in the world.
    const Eigen::Vector3d back = -view.normalized();
    const Eigen::Vector3d right = up.cross(back).normalized();
    Eigen::Matrix3d axes;
    axes << right, back.cross(right), back;
    const Eigen::Quaterniond q(axes);
    return SbRotation(static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z()),
                      static_cast<float>(q.w()));
}

void setPoints(SoMFVec3f& field, const std::vector<Eigen::Vector3d>& points)
{
    field.setNum(static_cast<int>(points.size()));
    SbVec3f* out = field.startEditing();
    for (size_t i = 0; i < points.size(); ++i) out[i] = toSb(points[i]);
    field.finishEditing();
}

}  // namespace sculptline::scene
