// A "view" pose (../shared/interfaces.md, 6-DOF input) in the real window under Xvfb: with its grip
// held, the camera is carried rigidly by the device (ui/pose_input.h). The expected camera is
// computed here as a composition of rigid transforms (Eigen::Isometry3d: the device's pose now times
// its pose at the grip, inverted, times the camera's pose at the grip), not by the quaternion
// formula the input layer uses. Given / When / Then.
#include "model/document.h"
#include "scene/eigen_coin.h"
#include "tests/gui/window_shot.h"
#include "ui/pose_event.h"
#include "ui/pose_input.h"

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>
#include <Inventor/nodes/SoCamera.h>
#include <gtest/gtest.h>

namespace sculptline::ui {
namespace {

// Camera fields are single precision (SbVec3f, SbRotation): positions some hundreds of units from
// the origin keep about 1e-7 relative, so 1e-4 units and 1e-5 in a quaternion's components.
constexpr double kPositionTolerance = 1e-4;
constexpr double kOrientationTolerance = 1e-5;

PoseEvent view(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation, bool grip)
{
    PoseEvent e;
    e.device = PoseEvent::Device::View;
    e.position = position;
    e.orientation = orientation;
    e.grip = grip;
    return e;
}

Eigen::Isometry3d pose(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation)
{
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = orientation.toRotationMatrix();
    t.translation() = position;
    return t;
}

Eigen::Isometry3d cameraPose(const SoCamera& camera)
{
    return pose(scene::toEigen(camera.position.getValue()), scene::toEigen(camera.orientation.getValue()));
}

struct Window {
    struct Application {
        Application() { guitest::startApplication("pose_view_test"); }
    } application;  // before the window
    MainWindow window;
    PoseInput input{window};
    Window()
    {
        window.showDocument(model::freshDocument(), QString());
        window.setAutomated(true);
        window.resize(900, 700);
        window.show();
    }
    SoCamera& camera() { return *window.viewer()->getCamera(); }
};

void expectSamePose(const Eigen::Isometry3d& actual, const Eigen::Isometry3d& expected)
{
    EXPECT_LT((actual.translation() - expected.translation()).norm(), kPositionTolerance)
        << "at " << actual.translation().transpose() << ", expected " << expected.translation().transpose();
    const Eigen::Quaterniond a(actual.linear()), b(expected.linear());
    EXPECT_GT(std::abs(a.dot(b)), 1.0 - kOrientationTolerance) << "orientations differ";
}

}  // namespace

TEST(PoseView, GivenTheGripHeld_WhenTheDeviceMovesAndTurns_ThenTheCameraIsCarriedRigidlyAndStaysWhenTheGripIsReleased)
{
    Window w;
    const Eigen::Isometry3d camera0 = cameraPose(w.camera());
    // The device grabbed somewhere off the camera's axis, turned a little already.
    const Eigen::Vector3d p0(30.0, -20.0, 15.0);
    const Eigen::Quaterniond q0(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()));
    w.input.handle(view(p0, q0, true), 0.0);
    expectSamePose(cameraPose(w.camera()), camera0);  // grabbing alone moves nothing

    // When it moves 25 units and turns 40 degrees about a tilted axis, grip held
    const Eigen::Vector3d p1 = p0 + Eigen::Vector3d(10.0, 20.0, -5.0);
    const Eigen::Quaterniond q1 = Eigen::Quaterniond(Eigen::AngleAxisd(40.0 * M_PI / 180.0, Eigen::Vector3d(0, 1, 1).normalized())) * q0;
    w.input.handle(view(p1, q1, true), 0.1);

    // Then the camera moved as if fixed to the device
    const Eigen::Isometry3d expected = pose(p1, q1) * pose(p0, q0).inverse() * camera0;
    expectSamePose(cameraPose(w.camera()), expected);
    EXPECT_GT((cameraPose(w.camera()).translation() - camera0.translation()).norm(), 1.0) << "the camera moved";

    // When the grip is released and the device moves on
    w.input.handle(view(p1, q1, false), 0.2);
    w.input.handle(view(p1 + Eigen::Vector3d(50.0, 0.0, 0.0), q0, false), 0.3);

    // Then the camera stays where it was left
    expectSamePose(cameraPose(w.camera()), expected);

    // When gripped again elsewhere and moved straight along x
    const Eigen::Vector3d p2(-5.0, 5.0, 5.0);
    w.input.handle(view(p2, q0, true), 0.4);
    w.input.handle(view(p2 + Eigen::Vector3d(12.0, 0.0, 0.0), q0, true), 0.5);

    // Then the camera translates by the same 12 units and does not turn
    Eigen::Isometry3d shifted = expected;
    shifted.translation() += Eigen::Vector3d(12.0, 0.0, 0.0);
    expectSamePose(cameraPose(w.camera()), shifted);
}

}  // namespace sculptline::ui
