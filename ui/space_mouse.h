#pragma once
// A 3D mouse (3Dconnexion SpaceNavigator and kin) through spacenavd: Debian's libspnav, its socket
// watched by a QSocketNotifier. Pushing and twisting the cap moves the camera, or the selected plane
// when a plane is selected (one undo step per push: the move ends when the cap rests kIdleMs).
// Where no spacenavd runs, the status bar says so once and the desktop works as before.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <QObject>
#include <QString>

class QSocketNotifier;
class QTimer;

namespace sculptline::ui {

class MainWindow;

/// One motion report of the cap as a rigid step in the camera's frame (x right, y up, z towards
/// the viewer). `axes` are spacenavd's x, y, z, rx, ry, rz counts, full deflection about
/// kFullDeflection; `seconds` the report's period.
struct SpaceMouseStep {
    Eigen::Vector3d translation = Eigen::Vector3d::Zero();  ///< model units, camera frame
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  ///< about the camera's axes
};

/// spacenavd's counts at full deflection of the cap (SpaceNavigator: about 350).
constexpr double kFullDeflection = 350.0;
/// At full deflection the camera or plane moves the default plane's edge per second (200 mm/s)
/// and turns a quarter turn per second: slow enough to place a plane to a millimetre, fast
/// enough to cross the default scene in a second.
constexpr double kMaxSpeed = 200.0;
constexpr double kMaxTurnRate = 1.5707963267948966;
/// The cap at rest this long ends a plane move (one undo step).
constexpr int kIdleMs = 300;
/// How long the "No 3D mouse" notice stays in the status bar: long enough to be read at start-up.
constexpr int kNoticeMs = 15000;

SpaceMouseStep spaceMouseStep(const int axes[6], double seconds);

class SpaceMouse : public QObject {
    Q_OBJECT

public:
    /// Connects to spacenavd (spnav_open); without it, a notice in the status bar (a label of its
    /// own, "spaceMouseNotice", for kNoticeMs) and in an automated run a line on stderr, once.
    SpaceMouse(MainWindow& window, QObject* parent);
    ~SpaceMouse() override;
    bool connected() const { return notifier_ != nullptr; }
    /// Empty when connected, else why there is no 3D mouse.
    const QString& message() const { return message_; }

private:
    void readEvents();
    void apply(const SpaceMouseStep& step);

    MainWindow& window_;
    QSocketNotifier* notifier_ = nullptr;
    QTimer* idle_ = nullptr;
    QString message_;
};

}  // namespace sculptline::ui
