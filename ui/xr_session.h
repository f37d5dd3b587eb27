#pragma once
// A VR session through OpenXR (Khronos OpenXR 1.0, Debian's loader libopenxr-loader1): the Coin
// scene rendered to a headset, and the controllers' aim poses turned into the 6-DOF pose events of
// the replay format (../shared/interfaces.md: {"type": "pose", "device": "pointer"|"view"|"plane",
// "position", "orientation", "buttons", "t"}).
//
// Built with OpenXR when CMake finds the `openxr` pkg-config module (SCULPTLINE_HAVE_OPENXR);
// otherwise start() says that this build has none. Without an OpenXR runtime (Debian 12 packages
// none: no Monado), start() reports the loader's result and the desktop goes on.
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <QObject>
#include <QPointer>
#include <QWidget>
#include <QString>

#include <memory>
#include <string>
#include <vector>

class SoQtViewer;

namespace sculptline::ui {

/// One 6-DOF pose in model units: a pose event of the replay format. Kept local to the VR module;
/// toReplayEvent() is the adapter to the shared form the 6-DOF input layer reads.
struct XrPoseEvent {
    std::string device;  ///< "pointer" (the dominant hand draws) or "plane" (the other hand carries the plane)
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< model units
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< unit quaternion, model frame
    std::vector<std::string> buttons;  ///< "trigger", "grip" while held
    double t = 0.0;  ///< ms since the session began
};

/// The replay-format pose event: {"type": "pose", "device", "position": [x, y, z],
/// "orientation": [x, y, z, w], "buttons": [..], "t"}.
nlohmann::json toReplayEvent(const XrPoseEvent& event);

/// Where the VR stage (OpenXR: metres, y up, -z forward) puts the model (model units, z up): the
/// model's point `modelAtOrigin` stands at the stage's origin, `unitsPerMetre` model units to a metre.
struct StageToModel {
    double unitsPerMetre = 1000.0;  ///< millimetre models at their real size by default
    Eigen::Vector3d modelAtOrigin = Eigen::Vector3d::Zero();

    /// Stage axes to model axes: x stays, stage up (y) is model up (z), stage back (z) is model -y.
    static Eigen::Matrix3d axes();
    Eigen::Vector3d point(const Eigen::Vector3d& stageMetres) const;
    Eigen::Quaterniond rotation(const Eigen::Quaterniond& stage) const;

    /// A mapping that shows a model of bounding-box `diagonal` (model units) `sizeMetres` across,
    /// its centre `centre` at `standAt` on the stage (metres; e.g. at the chest, half a metre ahead).
    static StageToModel framing(const Eigen::Vector3d& centre, double diagonal, double sizeMetres, const Eigen::Vector3d& standAt);
};

/// Pressed above this value (OpenXR float actions run 0..1), a trigger or grip counts as held.
constexpr float kButtonHeld = 0.5f;

enum class Hand { Left, Right };

/// One controller's state in stage space -> a pose event: the right (dominant) hand is the
/// "pointer" that draws with its trigger, the left hand the "plane" carried while its grip is held.
XrPoseEvent controllerPoseEvent(Hand hand, const Eigen::Vector3d& stagePosition, const Eigen::Quaterniond& stageOrientation,
                                float trigger, float grip, double tMs, const StageToModel& stage);

class VrSession : public QObject {
    Q_OBJECT

public:
    /// @param viewer whose GL context and scene graph the headset shares.
    VrSession(SoQtViewer* viewer, QObject* parent = nullptr);
    ~VrSession() override;

    /// True when this build links the OpenXR loader.
    static bool compiledWithOpenXr();

    /// Starts a session: the status message to show (what runs, or plainly why nothing does, with
    /// the OpenXR result's name). Never throws; the desktop view is untouched either way.
    QString start();
    void stop();
    bool running() const;

Q_SIGNALS:
    /// A controller pose, once per rendered frame and controller while the session runs.
    void poseEvent(const sculptline::ui::XrPoseEvent& event);
    /// State changes of the session worth a status-bar line (stopped by the runtime, lost, ...).
    void message(const QString& text);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    SoQtViewer* viewer_;
    QPointer<QWidget> viewerAlive_;  ///< the viewer's base widget: null once the viewer is deleted
};

}  // namespace sculptline::ui
