#include "manipulators/stroke_input.h"

#include "scene/eigen_coin.h"

#include <Inventor/SoPickedPoint.h>
#include <Inventor/SbLine.h>
#include <Inventor/SbViewVolume.h>
#include <Inventor/actions/SoHandleEventAction.h>
#include <Inventor/draggers/SoDragger.h>
#include <Inventor/events/SoLocation2Event.h>
#include <Inventor/events/SoMouseButtonEvent.h>
#include <Inventor/nodes/SoBaseColor.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoEventCallback.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoPickStyle.h>
#include <Inventor/nodes/SoSeparator.h>

#include <cmath>

namespace sculptline::manipulators {
namespace {

/// The pen's ink: red like the thesis's sketches (Fig. 5-2 a), distinct from finished curves.
const SbColor kPreviewColor(0.95f, 0.2f, 0.2f);
constexpr float kPreviewWidth = 2.0f;
/// Rays closer to parallel with the plane than this (cosine) miss it: the point would fly off to
/// where the plane is seen edge-on.
constexpr double kMinRayCosine = 1e-3;

bool pathHasDragger(const SoPickedPoint* picked)
{
    if (!picked) return false;
    const SoPath* path = picked->getPath();
    for (int i = 0; i < path->getLength(); ++i) {
        if (path->getNode(i)->isOfType(SoDragger::getClassTypeId())) return true;
    }
    return false;
}

}  // namespace

StrokeInput::StrokeInput()
{
    root_ = new SoSeparator;
    root_->ref();
    root_->setName("StrokeInput");
    callback_ = new SoEventCallback;
    callback_->addEventCallback(SoMouseButtonEvent::getClassTypeId(), &StrokeInput::handleEvent, this);
    callback_->addEventCallback(SoLocation2Event::getClassTypeId(), &StrokeInput::handleEvent, this);
    root_->addChild(callback_);

    auto* preview = new SoSeparator;
    preview->setName("StrokePreview");
    auto* pick = new SoPickStyle;
    pick->style = SoPickStyle::UNPICKABLE;
    preview->addChild(pick);
    auto* light = new SoLightModel;
    light->model = SoLightModel::BASE_COLOR;
    preview->addChild(light);
    auto* color = new SoBaseColor;
    color->rgb = kPreviewColor;
    preview->addChild(color);
    auto* style = new SoDrawStyle;
    style->lineWidth = kPreviewWidth;
    preview->addChild(style);
    previewPoints_ = new SoCoordinate3;
    previewPoints_->point.setNum(0);
    preview->addChild(previewPoints_);
    previewLine_ = new SoLineSet;
    previewLine_->numVertices.setNum(0);
    preview->addChild(previewLine_);
    root_->addChild(preview);
}

StrokeInput::~StrokeInput()
{
    callback_->removeEventCallback(SoMouseButtonEvent::getClassTypeId(), &StrokeInput::handleEvent, this);
    callback_->removeEventCallback(SoLocation2Event::getClassTypeId(), &StrokeInput::handleEvent, this);
    root_->unref();
}

void StrokeInput::setEnabled(bool enabled)
{
    if (!enabled && drawing_) endStroke(false);
    enabled_ = enabled;
}

void StrokeInput::handleEvent(void* self, SoEventCallback* node) { static_cast<StrokeInput*>(self)->onEvent(node); }

std::optional<Eigen::Vector3d> StrokeInput::planePoint(SoEventCallback* node) const
{
    SoCamera* camera = camera_ ? camera_() : nullptr;
    if (!camera) return std::nullopt;
    const SbViewportRegion& viewport = node->getAction()->getViewportRegion();
    SbViewportRegion used;
    const SbViewVolume volume = camera->getViewVolume(viewport, used);
    SbLine line;
    volume.projectPointToLine(node->getEvent()->getNormalizedPosition(used), line);
    const Eigen::Vector3d from = scene::toEigen(line.getPosition());
    const Eigen::Vector3d direction = scene::toEigen(line.getDirection()).normalized();
    const Eigen::Vector3d normal = frame_.normal();
    const double facing = direction.dot(normal);
    if (std::abs(facing) < kMinRayCosine) return std::nullopt;
    const double t = (frame_.origin - from).dot(normal) / facing;
    if (t <= 0.0) return std::nullopt;  // the plane is behind the eye
    Eigen::Vector3d local = frame_.toLocal(from + t * direction);
    local.z() = 0.0;
    return local;
}

void StrokeInput::onEvent(SoEventCallback* node)
{
    if (!enabled_) return;
    const SoEvent* event = node->getEvent();
    const double now = clock_ ? clock_() : event->getTime().getValue();
    if (SO_MOUSE_PRESS_EVENT(event, BUTTON1)) {
        // A press on a dragger moves the plane instead of starting a stroke.
        if (pathHasDragger(node->getPickedPoint())) return;
        const std::optional<scene::PlaneFrame> plane = plane_ ? plane_() : std::nullopt;
        if (!plane) return;
        frame_ = *plane;
        const std::optional<Eigen::Vector3d> p = planePoint(node);
        if (!p) return;
        drawing_ = true;
        startTime_ = now;
        stroke_ = {};
        addSample(*p, 0.0);
        node->setHandled();
    } else if (drawing_ && event->isOfType(SoLocation2Event::getClassTypeId())) {
        if (const std::optional<Eigen::Vector3d> p = planePoint(node)) addSample(*p, now - startTime_);
        node->setHandled();
    } else if (drawing_ && SO_MOUSE_RELEASE_EVENT(event, BUTTON1)) {
        if (const std::optional<Eigen::Vector3d> p = planePoint(node)) addSample(*p, now - startTime_);
        node->setHandled();
        endStroke(true);
    }
}

void StrokeInput::addSample(const Eigen::Vector3d& local, double time)
{
    // Times must not decrease (replayed events may carry equal stamps).
    if (!stroke_.times.empty()) time = std::max(time, stroke_.times.back());
    stroke_.points.push_back(local);
    stroke_.times.push_back(time);
    const int n = static_cast<int>(stroke_.points.size());
    previewPoints_->point.set1Value(n - 1, scene::toSb(frame_.toWorld(local)));
    previewLine_->numVertices.setValue(n);
    if (sampled_) sampled_();
}

void StrokeInput::endStroke(bool keep)
{
    drawing_ = false;
    const FinishedStroke stroke = std::move(stroke_);
    stroke_ = {};
    previewPoints_->point.setNum(0);
    previewLine_->numVertices.setNum(0);
    if (keep && finished_ && stroke.points.size() >= 2) finished_(stroke);
}

}  // namespace sculptline::manipulators
