#pragma once
// Auxiliary projection planes from existing curves (seed 000 §3.1, after [MKB02]): a stroke that
// starts on a curve and ends in the air lies on the plane through the curve point that contains the
// curve's tangent there and faces the viewer; a stroke that connects two curves lies on the plane
// through both points that contains the first curve's binormal. Plain geometry, no Coin.
#include "model/plane_frame.h"
#include "solvers/bspline/bspline_curve.h"

#include <optional>

namespace sculptline::model {

/// Plane through `point` containing `tangent`, its normal the part of -view orthogonal to the
/// tangent (as much facing the eye as a plane holding the tangent can). X axis along the tangent.
/// Empty when the tangent is zero or parallel to the view (the plane would be seen edge-on).
/// @param view direction from the eye towards the point; any length.
std::optional<PlaneFrame> planeAlongTangent(const Eigen::Vector3d& point, const Eigen::Vector3d& tangent,
                                            const Eigen::Vector3d& view, double size);

/// Plane through `a` and `b` containing `binormal` (the first curve's), normal turned towards the
/// eye; X axis from a to b. Empty when b - a is parallel to the binormal or too short.
std::optional<PlaneFrame> planeThroughPoints(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& binormal,
                                             const Eigen::Vector3d& view, double size);

/// The tangent and binormal of `curve` at the point closest to `point` (binormal C' x C''; for a
/// straight piece, where that vanishes, `fallbackBinormal`, e.g. the normal of the curve's plane).
struct CurveFrameAt {
    Eigen::Vector3d point, tangent, binormal;
};
CurveFrameAt curveFrameNear(const solvers::Curve3d& curve, const Eigen::Vector3d& point, const Eigen::Vector3d& fallbackBinormal);

}  // namespace sculptline::model
