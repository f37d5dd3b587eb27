#include "ui/pose_input.h"

#include "scene/eigen_coin.h"
#include "ui/main_window.h"
#include "ui/sketch_document.h"
#include "ui/space_mouse.h"

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>
#include <Inventor/nodes/SoBaseColor.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoPickStyle.h>
#include <Inventor/nodes/SoSeparator.h>

#include <QTimer>

namespace sculptline::ui {
namespace {

/// The live stroke's look: cyan, a colour no curve (warm colours), surface (blues, greens, violet) or
/// selection (white) has, so it reads as "not a curve yet"; 2 px, unlit and unpickable, so that it
/// never takes a click meant for what lies behind it.
constexpr float kLiveColor[3] = {0.1f, 0.9f, 0.9f};
constexpr float kLiveWidth = 2.0f;

}  // namespace

PoseInput::PoseInput(MainWindow& window) : QObject(&window), window_(window)
{
    setObjectName(QStringLiteral("poseInput"));
    live_ = new SoSeparator;
    live_->ref();
    live_->setName("PoseStroke");
    auto* pick = new SoPickStyle;
    pick->style = SoPickStyle::UNPICKABLE;
    auto* light = new SoLightModel;
    light->model = SoLightModel::BASE_COLOR;
    auto* color = new SoBaseColor;
    color->rgb.setValue(kLiveColor);
    auto* style = new SoDrawStyle;
    style->lineWidth = kLiveWidth;
    liveCoords_ = new SoCoordinate3;
    liveCoords_->point.setNum(0);
    live_->addChild(pick);
    live_->addChild(light);
    live_->addChild(color);
    live_->addChild(style);
    live_->addChild(liveCoords_);
    live_->addChild(new SoLineSet);
    // After the window's set-up (an automated run is marked after construction): the 3D mouse
    // says once whether it is there.
    QTimer::singleShot(0, this, [this]() { spaceMouse_ = new SpaceMouse(window_, this); });
}

// The document (an older child of the window) may be gone already: only our own reference is dropped.
PoseInput::~PoseInput() { live_->unref(); }

QString PoseInput::spaceMouseMessage() const { return spaceMouse_ ? spaceMouse_->message() : QString(); }

void PoseInput::handle(const PoseEvent& e, double seconds)
{
    switch (e.device) {
    case PoseEvent::Device::Pointer: pointer(e, seconds); break;
    case PoseEvent::Device::Plane: plane(e); break;
    case PoseEvent::Device::View: view(e); break;
    }
}

std::vector<Eigen::Vector3d> PoseInput::livePolyline() const
{
    std::vector<Eigen::Vector3d> world = points_;
    if (const model::Entity* p = window_.document().model().find(strokePlane_)) {
        for (Eigen::Vector3d& q : world) q = p->frame.toWorld(q);
    }
    return world;
}

void PoseInput::pointer(const PoseEvent& e, double seconds)
{
    SketchDocument& doc = window_.document();
    if (e.trigger && !drawing_) {
        // The two-hands rule: a stroke that starts while the plane is carried is planar on it.
        drawing_ = true;
        strokePlane_ = doc.carriedPlane();
        points_.clear();
        times_.clear();
        startTime_ = seconds;
        if (doc.root()->findChild(live_) < 0) doc.root()->addChild(live_);
    }
    if (!drawing_) return;
    if (e.trigger) {
        Eigen::Vector3d p = e.position;
        if (const model::Entity* plane = doc.model().find(strokePlane_)) {
            p = plane->frame.toLocal(p);
            p.z() = 0.0;
        }
        points_.push_back(p);
        times_.push_back(seconds - startTime_);
        showLive();
        return;
    }
    // Released: the stroke ends (the release pose itself is not a sample: the trigger was up).
    drawing_ = false;
    liveCoords_->point.setNum(0);
    if (doc.root()->findChild(live_) >= 0) doc.root()->removeChild(live_);
    const std::vector<Eigen::Vector3d> world = livePolyline();
    const std::uint32_t plane = strokePlane_;
    strokePlane_ = 0;
    points_.clear();
    if (plane != 0 && doc.model().find(plane)) doc.addStrokeOnPlane(plane, world, times_);
    else doc.addSpaceStroke(world, times_);
}

void PoseInput::showLive() { scene::setPoints(liveCoords_->point, livePolyline()); }

void PoseInput::plane(const PoseEvent& e)
{
    SketchDocument& doc = window_.document();
    if (e.grip && !carrying_) {
        doc.beginCarry(doc.activePlane());
        carrying_ = doc.carriedPlane() != 0;
        if (!carrying_) return;
    }
    if (!carrying_) return;
    if (e.grip) {
        doc.carryTo(e.position, e.orientation);
        if (drawing_ && strokePlane_ == doc.carriedPlane()) showLive();  // the stroke moves with its plane
        return;
    }
    carrying_ = false;
    doc.endCarry();
}

void PoseInput::view(const PoseEvent& e)
{
    SoCamera* camera = window_.viewer() ? window_.viewer()->getCamera() : nullptr;
    if (!camera) return;
    if (e.grip && !moving_) {
        moving_ = true;
        grabPosition_ = e.position;
        grabOrientation_ = e.orientation;
        cameraPosition_ = scene::toEigen(camera->position.getValue());
        cameraOrientation_ = scene::toEigen(camera->orientation.getValue());
    }
    if (!moving_) return;
    if (!e.grip) {
        moving_ = false;
        return;
    }
    // The camera is held rigidly by the device: the device's motion since the grip, applied to the
    // camera as it was then (turning about the device, not about the camera).
    const Eigen::Quaterniond turn = e.orientation * grabOrientation_.conjugate();
    camera->position.setValue(scene::toSb(Eigen::Vector3d(e.position + turn * (cameraPosition_ - grabPosition_))));
    camera->orientation.setValue(scene::toSb(Eigen::Quaterniond(turn * cameraOrientation_).normalized()));
}

}  // namespace sculptline::ui
