#include "model/auxiliary_plane.h"

#include "solvers/bspline/projection.h"

namespace sculptline::model {
namespace {

/// Below this sine between two directions they count as parallel (a plane through them would be
/// ill-defined to within a degree, about the precision of a hand-drawn stroke).
constexpr double kMinSine = 0.02;

}  // namespace

std::optional<PlaneFrame> planeAlongTangent(const Eigen::Vector3d& point, const Eigen::Vector3d& tangent,
                                            const Eigen::Vector3d& view, double size)
{
    if (tangent.norm() == 0.0 || view.norm() == 0.0) return std::nullopt;
    const Eigen::Vector3d t = tangent.normalized();
    const Eigen::Vector3d toEye = -view.normalized();
    const Eigen::Vector3d normal = toEye - toEye.dot(t) * t;
    if (normal.norm() < kMinSine) return std::nullopt;
    return PlaneFrame::fromNormal(point, normal, size, t);
}

std::optional<PlaneFrame> planeThroughPoints(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& binormal,
                                             const Eigen::Vector3d& view, double size)
{
    const Eigen::Vector3d chord = b - a;
    if (chord.norm() == 0.0 || binormal.norm() == 0.0) return std::nullopt;
    Eigen::Vector3d normal = chord.normalized().cross(binormal.normalized());
    if (normal.norm() < kMinSine) return std::nullopt;
    if (normal.dot(-view) < 0.0) normal = -normal;
    return PlaneFrame::fromNormal(0.5 * (a + b), normal, size, chord);
}

CurveFrameAt curveFrameNear(const solvers::Curve3d& curve, const Eigen::Vector3d& point, const Eigen::Vector3d& fallbackBinormal)
{
    const solvers::CurveProjection<3> foot = solvers::projectToCurve(curve, point);
    const std::vector<Eigen::Vector3d> d = curve.derivatives(foot.u, 2);
    CurveFrameAt frame;
    frame.point = foot.point;
    frame.tangent = d[1];
    const Eigen::Vector3d b = d[1].cross(d[2]);
    frame.binormal = b.norm() > kMinSine * d[1].squaredNorm() ? b.normalized() : fallbackBinormal;
    return frame;
}

}  // namespace sculptline::model
