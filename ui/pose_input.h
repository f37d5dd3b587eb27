#pragma once
// The one input layer of 6-DOF devices (a tracked pointer, a second hand's controller, a 3D mouse):
// poses become the same model edits as the mouse's (../shared/interfaces.md, "6-DOF input").
//   pointer + trigger: draws a stroke in space, shown live as a cyan polyline; on release it is fitted
//     (SketchDocument::addSpaceStroke). While the plane is carried (plane + grip) when the trigger
//     goes down, the stroke is planar on the carried plane instead: each position is projected onto
//     the plane as it is at that moment, so the stroke moves with the hand that holds the plane.
//   plane + grip: carries the active projection plane: its origin goes to the position, its frame
//     to the orientation; one undo step per grip.
//   view + grip: the camera moves rigidly with the device from where the grip went down.
#include "ui/pose_event.h"

#include <QObject>
#include <QString>

#include <vector>

class SoCoordinate3;
class SoSeparator;

namespace sculptline::ui {

class MainWindow;
class SpaceMouse;

class PoseInput : public QObject {
    Q_OBJECT

public:
    /// A child of `window` (findChild<PoseInput*>() finds it); opens the 3D mouse once the event
    /// loop runs.
    explicit PoseInput(MainWindow& window);
    ~PoseInput() override;

    /// One device sample, `seconds` since the session started (stroke timing).
    void handle(const PoseEvent& e, double seconds);
    /// True while the pointer's trigger is held (a stroke is being drawn).
    bool drawing() const { return drawing_; }
    /// The stroke drawn so far, world (the live polyline).
    std::vector<Eigen::Vector3d> livePolyline() const;
    /// The 3D mouse's state: empty when it works, else what the status bar said.
    QString spaceMouseMessage() const;

private:
    void pointer(const PoseEvent& e, double seconds);
    void plane(const PoseEvent& e);
    void view(const PoseEvent& e);
    void showLive();

    MainWindow& window_;
    SpaceMouse* spaceMouse_ = nullptr;
    // pointer
    bool drawing_ = false;
    std::uint32_t strokePlane_ = 0;  ///< the carried plane the stroke is planar on (0: a space stroke)
    std::vector<Eigen::Vector3d> points_;  ///< world, or the plane's local frame (z = 0) when strokePlane_
    std::vector<double> times_;
    double startTime_ = 0.0;
    SoSeparator* live_ = nullptr;  ///< ref()ed; under the document's root while drawing
    SoCoordinate3* liveCoords_ = nullptr;
    // plane
    bool carrying_ = false;
    // view
    bool moving_ = false;
    Eigen::Vector3d grabPosition_ = Eigen::Vector3d::Zero(), cameraPosition_ = Eigen::Vector3d::Zero();
    Eigen::Quaterniond grabOrientation_ = Eigen::Quaterniond::Identity(), cameraOrientation_ = Eigen::Quaterniond::Identity();
};

}  // namespace sculptline::ui
