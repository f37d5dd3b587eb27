#pragma once
// A recorded session (../shared/interfaces.md, "sculptline (GUI) automation flags"): viewport size
// and a list of press/move/release/key/action/wait events. Parsed and checked before Qt starts, so a
// bad session is a message and exit status 2, never a crash.
#include <QKeySequence>
#include <QString>
#include <Qt>

#include <string>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "ui/pose_event.h"

namespace sculptline::ui {

struct ReplayEvent {
    enum class Type { Press, Move, Release, Key, Action, Wait, Pose };
    Type type = Type::Wait;
    int x = 0, y = 0;  ///< viewport pixels, origin top-left
    /// Instead of x, y: a model point ("at": [x, y, z]) whose pixel the current camera gives when
    /// the event is played, so a session can name the geometry it means, whatever the framing.
    std::optional<Eigen::Vector3d> at;
    Qt::MouseButton button = Qt::LeftButton;
    Qt::KeyboardModifiers modifiers;
    /// A pen's pressure, 0..1 ("pressure"), as a tablet reports it; none: a mouse.
    std::optional<double> pressure;
    double t = -1.0;  ///< ms since the replay started; < 0 = as soon as the previous event is done
    QKeySequence key;
    QString name;  ///< action name
    int waitMs = 0;
    PoseEvent pose;  ///< Type::Pose: a 6-DOF device sample
};

struct ReplaySession {
    int width = 0, height = 0;  ///< viewport size; 0 = keep
    std::vector<ReplayEvent> events;
};

/// Most events a session may hold: a minute of 1 kHz pointer input, far beyond any recording.
constexpr size_t kMaxReplayEvents = 200000;
/// Longest wait or timestamp accepted, ms: a session is a test, not a screensaver.
constexpr double kMaxReplayMs = 600000.0;

/// @throws solvers::io::InputError naming the path and field ("s.json: events[3].button: ...").
ReplaySession loadReplaySession(const std::string& path);

/// Parses a session from its JSON text (what loadReplaySession reads from the file).
/// @throws solvers::io::InputError naming the field ("events[3].button: ...").
ReplaySession parseReplaySession(const std::string& text);

}  // namespace sculptline::ui
