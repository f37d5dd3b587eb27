#include "ui/replay_session.h"

#include "solvers/io/geometry_json.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace sculptline::ui {
namespace io = solvers::io;
using nlohmann::json;

namespace {

double bounded(const json& j, const std::string& path)
{
    const double v = io::numberFromJson(j, path);
    if (v < 0.0 || v > kMaxReplayMs) throw io::InputError(path + ": must be between 0 and 600000 ms");
    return v;
}

ReplayEvent eventFromJson(const json& j, const std::string& path)
{
    if (!j.is_object()) throw io::InputError(path + ": must be a JSON object");
    const json& typeJson = io::member(j, "type", path);
    if (!typeJson.is_string()) throw io::InputError(path + ".type: must be a string");
    const std::string type = typeJson.get<std::string>();
    ReplayEvent e;
    if (const auto it = j.find("t"); it != j.end()) e.t = bounded(*it, path + ".t");
    if (type == "press" || type == "move" || type == "release") {
        e.type = type == "press" ? ReplayEvent::Type::Press : type == "move" ? ReplayEvent::Type::Move : ReplayEvent::Type::Release;
        if (const auto at = j.find("at"); at != j.end()) {
            e.at = io::pointFromJson(*at, path + ".at");
        } else {
            e.x = io::integerFromJson(io::member(j, "x", path), path + ".x", -100000, 100000);
            e.y = io::integerFromJson(io::member(j, "y", path), path + ".y", -100000, 100000);
        }
        if (const auto it = j.find("button"); it != j.end()) {
            const std::string b = it->is_string() ? it->get<std::string>() : "";
            if (b == "left") e.button = Qt::LeftButton;
            else if (b == "middle") e.button = Qt::MiddleButton;
            else if (b == "right") e.button = Qt::RightButton;
            else throw io::InputError(path + ".button: must be \"left\", \"middle\" or \"right\"");
        }
        if (const auto it = j.find("pressure"); it != j.end()) {
            const double v = io::numberFromJson(*it, path + ".pressure");
            if (!(v >= 0.0 && v <= 1.0)) throw io::InputError(path + ".pressure: must be between 0 and 1");
            e.pressure = v;
        }
        if (const auto it = j.find("modifiers"); it != j.end()) {
            if (!it->is_array()) throw io::InputError(path + ".modifiers: must be an array");
            for (const json& m : *it) {
                const std::string name = m.is_string() ? m.get<std::string>() : "";
                if (name == "shift") e.modifiers |= Qt::ShiftModifier;
                else if (name == "ctrl") e.modifiers |= Qt::ControlModifier;
                else if (name == "alt") e.modifiers |= Qt::AltModifier;
                else throw io::InputError(path + ".modifiers: each must be \"shift\", \"ctrl\" or \"alt\"");
            }
        }
    } else if (type == "key") {
        e.type = ReplayEvent::Type::Key;
        const json& key = io::member(j, "key", path);
        if (!key.is_string()) throw io::InputError(path + ".key: must be a string such as \"Ctrl+Z\"");
        e.key = QKeySequence(QString::fromStdString(key.get<std::string>()));
        if (e.key.count() != 1 || e.key[0] == 0 || (e.key[0] & ~Qt::KeyboardModifierMask) == Qt::Key_unknown) {
            throw io::InputError(path + ".key: not a key: \"" + key.get<std::string>() + "\"");
        }
    } else if (type == "action") {
        e.type = ReplayEvent::Type::Action;
        const json& name = io::member(j, "name", path);
        if (!name.is_string()) throw io::InputError(path + ".name: must be a string (see --list-actions)");
        e.name = QString::fromStdString(name.get<std::string>());
    } else if (type == "wait") {
        e.type = ReplayEvent::Type::Wait;
        e.waitMs = static_cast<int>(bounded(io::member(j, "ms", path), path + ".ms"));
    } else if (type == "pose") {
        e.type = ReplayEvent::Type::Pose;
        e.pose = poseEventFromJson(j, path);
    } else {
        throw io::InputError(path + ".type: must be press, move, release, key, action, wait or pose, not \"" + type + "\"");
    }
    return e;
}

ReplaySession sessionFromJson(const json& j)
{
    if (!j.is_object()) throw io::InputError("session: must be a JSON object");
    ReplaySession s;
    if (const auto it = j.find("size"); it != j.end()) {
        if (!it->is_array() || it->size() != 2) throw io::InputError("size: must be [width, height]");
        s.width = io::integerFromJson((*it)[0], "size[0]", 16, 8192);
        s.height = io::integerFromJson((*it)[1], "size[1]", 16, 8192);
    }
    const json& events = io::member(j, "events", "session");
    if (!events.is_array()) throw io::InputError("events: must be an array");
    if (events.size() > kMaxReplayEvents) throw io::InputError("events: more than 200000 events");
    for (size_t i = 0; i < events.size(); ++i) s.events.push_back(eventFromJson(events[i], "events[" + std::to_string(i) + "]"));
    return s;
}

}  // namespace

ReplaySession parseReplaySession(const std::string& text)
{
    return sessionFromJson(io::parseJson(text));
}

ReplaySession loadReplaySession(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw io::InputError(path + ": cannot open file");
    std::ostringstream text;
    text << in.rdbuf();
    try {
        return parseReplaySession(text.str());
    } catch (const io::InputError& e) {
        throw io::InputError(path + ": " + e.what());
    }
}

}  // namespace sculptline::ui
