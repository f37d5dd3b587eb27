#include "ui/pose_event.h"

#include "solvers/io/geometry_json.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace sculptline::ui {
namespace io = solvers::io;
using nlohmann::json;

const char* deviceName(PoseEvent::Device device)
{
    switch (device) {
    case PoseEvent::Device::Pointer: return "pointer";
    case PoseEvent::Device::View: return "view";
    case PoseEvent::Device::Plane: return "plane";
    }
    return "?";
}

PoseEvent poseEventFromJson(const json& j, const std::string& path)
{
    PoseEvent e;
    const json& device = io::member(j, "device", path);
    const std::string name = device.is_string() ? device.get<std::string>() : "";
    if (name == "pointer") e.device = PoseEvent::Device::Pointer;
    else if (name == "view") e.device = PoseEvent::Device::View;
    else if (name == "plane") e.device = PoseEvent::Device::Plane;
    else throw io::InputError(path + ".device: must be \"pointer\", \"view\" or \"plane\"");
    e.position = io::pointFromJson(io::member(j, "position", path), path + ".position");
    if (const auto it = j.find("orientation"); it != j.end()) {
        if (!it->is_array() || it->size() != 4) throw io::InputError(path + ".orientation: must be [x, y, z, w]");
        double q[4];
        for (int k = 0; k < 4; ++k) q[k] = io::numberFromJson((*it)[static_cast<size_t>(k)], path + ".orientation[" + std::to_string(k) + "]");
        const Eigen::Quaterniond r(q[3], q[0], q[1], q[2]);
        if (!(std::abs(r.norm() - 1.0) <= kQuaternionNormSlack)) throw io::InputError(path + ".orientation: must be a unit quaternion");
        e.orientation = r.normalized();
    }
    if (const auto it = j.find("buttons"); it != j.end()) {
        if (!it->is_array()) throw io::InputError(path + ".buttons: must be an array");
        for (const json& b : *it) {
            const std::string button = b.is_string() ? b.get<std::string>() : "";
            if (button == "trigger") e.trigger = true;
            else if (button == "grip") e.grip = true;
            else throw io::InputError(path + ".buttons: each must be \"trigger\" or \"grip\"");
        }
    }
    return e;
}

}  // namespace sculptline::ui
