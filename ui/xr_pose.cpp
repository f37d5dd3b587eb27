// The VR module's pure part: stage <-> model mapping and controller states -> pose events. No
// OpenXR here, so it is built and tested whether or not the loader is installed.
#include "ui/xr_session.h"

namespace sculptline::ui {

nlohmann::json toReplayEvent(const XrPoseEvent& e)
{
    const Eigen::Quaterniond q = e.orientation.normalized();
    return {{"type", "pose"},
            {"device", e.device},
            {"position", {e.position.x(), e.position.y(), e.position.z()}},
            {"orientation", {q.x(), q.y(), q.z(), q.w()}},
            {"buttons", e.buttons},
            {"t", e.t}};
}

Eigen::Matrix3d StageToModel::axes()
{
    Eigen::Matrix3d a;
    // Columns: where the stage's x, y (up) and z (toward the viewer) go in the model (z up).
    a.col(0) = Eigen::Vector3d::UnitX();
    a.col(1) = Eigen::Vector3d::UnitZ();
    a.col(2) = -Eigen::Vector3d::UnitY();
    return a;
}

Eigen::Vector3d StageToModel::point(const Eigen::Vector3d& stageMetres) const
{
    return modelAtOrigin + unitsPerMetre * (axes() * stageMetres);
}

Eigen::Quaterniond StageToModel::rotation(const Eigen::Quaterniond& stage) const
{
    // The device's own axes, seen in model coordinates: a controller's local -z (its aim) stays its
    // aim, so a plane carried by the hand faces along the hand (normal = local z).
    return Eigen::Quaterniond(axes() * stage.normalized().toRotationMatrix()).normalized();
}

StageToModel StageToModel::framing(const Eigen::Vector3d& centre, double diagonal, double sizeMetres, const Eigen::Vector3d& standAt)
{
    StageToModel s;
    if (diagonal > 0.0 && sizeMetres > 0.0) s.unitsPerMetre = diagonal / sizeMetres;
    s.modelAtOrigin = centre - s.unitsPerMetre * (axes() * standAt);
    return s;
}

XrPoseEvent controllerPoseEvent(Hand hand, const Eigen::Vector3d& stagePosition, const Eigen::Quaterniond& stageOrientation,
                                float trigger, float grip, double tMs, const StageToModel& stage)
{
    XrPoseEvent e;
    e.device = hand == Hand::Right ? "pointer" : "plane";
    e.position = stage.point(stagePosition);
    e.orientation = stage.rotation(stageOrientation);
    if (trigger > kButtonHeld) e.buttons.push_back("trigger");
    if (grip > kButtonHeld) e.buttons.push_back("grip");
    e.t = tMs;
    return e;
}

}  // namespace sculptline::ui
