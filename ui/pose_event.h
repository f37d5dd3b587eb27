#pragma once
// One sample of a 6-DOF device (a tracked pen or controller, a 3D mouse): the pose event of a
// recorded session (../shared/interfaces.md, "6-DOF input"), in model units.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <nlohmann/json_fwd.hpp>

#include <string>

namespace sculptline::ui {

struct PoseEvent {
    /// pointer: the dominant hand's pen, draws with its trigger held; plane: the non-dominant hand,
    /// carries the active projection plane with its grip held; view: moves the camera with its grip held.
    enum class Device { Pointer, View, Plane };
    Device device = Device::Pointer;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< model units, world
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< device -> world, unit
    bool trigger = false;
    bool grip = false;
};

/// How far a recorded orientation's norm may be from 1 before it is refused rather than normalized:
/// trackers report quaternions in single precision (norm within ~1e-7) and recordings round them to
/// a few digits (1e-4); a norm off by more is not a rotation but a wrong field.
constexpr double kQuaternionNormSlack = 1e-3;

const char* deviceName(PoseEvent::Device device);

/// Reads the fields of a pose event ({"type": "pose", "device", "position", "orientation",
/// "buttons"}); `path` names the event in messages.
/// @throws solvers::io::InputError naming the field ("events[3].orientation: ...").
PoseEvent poseEventFromJson(const nlohmann::json& j, const std::string& path);

}  // namespace sculptline::ui
