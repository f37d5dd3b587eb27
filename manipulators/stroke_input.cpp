#include "manipulators/stroke_input.h"

#include <algorithm>
#include <cmath>

#include "scene/eigen_coin.h"
#include "scene/entity_path.h"
#include "scene/overlay_nodes.h"

#include <Inventor/SoPickedPoint.h>
#include <Inventor/SbLine.h>
#include <Inventor/SbViewVolume.h>
#include <Inventor/actions/SoHandleEventAction.h>
#include <Inventor/actions/SoRayPickAction.h>
#include <Inventor/lists/SoPickedPointList.h>
#include <Inventor/draggers/SoDragger.h>
#include <Inventor/events/SoLocation2Event.h>
#include <Inventor/events/SoMouseButtonEvent.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoEventCallback.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoSeparator.h>

#include <cmath>
#include <string>

namespace sculptline::manipulators {
namespace {

/// The pen's ink: red like the thesis's sketches (Fig. 5-2 a), distinct from finished curves.
const SbColor kPreviewColor(0.95f, 0.2f, 0.2f);
constexpr float kPreviewWidth = 2.0f;
/// Rays closer to parallel with the plane than this (cosine) miss it: the point would fly off to
/// where the plane is seen edge-on.
constexpr double kMinRayCosine = 1e-3;
/// A press and release whose pointer stayed within this many pixels (in x and in y) is a click,
/// however much the hand trembled: a mouse or a pen on a tablet wanders a pixel or two while it
/// clicks, and a curve drawn from that would be a dot of a pixel's size (at a high zoom, microns).
constexpr int kClickPixels = 3;
/// Pixels around the pointer within which a stroke's end counts as on a curve.
constexpr float kCurvePickRadius = 5.0f;

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

    auto* preview = scene::makeOverlayRoot();
    preview->setName("StrokePreview");
    previewPoints_ = scene::addStyledCoordinates(preview, kPreviewColor, 0.0f, kPreviewWidth);
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
    if (!enabled) clicking_ = false;
    enabled_ = enabled;
}

void StrokeInput::handleEvent(void* self, SoEventCallback* node) { static_cast<StrokeInput*>(self)->onEvent(node); }

bool StrokeInput::ray(SoEventCallback* node, Eigen::Vector3d& from, Eigen::Vector3d& direction) const
{
    return pointerRay(node, camera_ ? camera_() : nullptr, from, direction);
}

bool pointerRay(SoEventCallback* node, SoCamera* camera, Eigen::Vector3d& from, Eigen::Vector3d& direction)
{
    return pointerRay(node, camera, from, direction, 0, 0);
}

bool pointerRay(SoEventCallback* node, SoCamera* camera, Eigen::Vector3d& from, Eigen::Vector3d& direction, int dx,
                int dy)
{
    if (!camera) return false;
    // The volume the camera renders with: the viewer keeps the camera's aspectRatio field at 1
    // and adapts at render time (ADJUST_CAMERA), widening a tall view's volume by 1/aspect, as
    // SoCamera::GLRender does; the camera's field alone would squeeze x by the aspect ratio.
    const SbViewportRegion& viewport = node->getAction()->getViewportRegion();
    const float aspect = viewport.getViewportAspectRatio();
    SbViewVolume volume = camera->getViewVolume(aspect);
    if (aspect < 1.0f) volume.scale(1.0f / aspect);
    SbLine line;
    SbVec2f at = node->getEvent()->getNormalizedPosition(viewport);
    if (dx != 0 || dy != 0) {
        // Normalized coordinates as SoEvent::getNormalizedPosition computes them: pixel / size.
        const SbVec2s size = viewport.getViewportSizePixels();
        if (size[0] > 0) at[0] += static_cast<float>(dx) / static_cast<float>(size[0]);
        if (size[1] > 0) at[1] += static_cast<float>(dy) / static_cast<float>(size[1]);
    }
    volume.projectPointToLine(at, line);
    from = scene::toEigen(line.getPosition());
    direction = scene::toEigen(line.getDirection()).normalized();
    return true;
}

StrokeHit StrokeInput::hit(SoEventCallback* node, const Eigen::Vector3d& view) const { return pickCurve(node, view); }

StrokeHit pickCurve(SoEventCallback* node, const Eigen::Vector3d& view)
{
    StrokeHit result;
    result.view = view;
    // Every point under the pointer, nearest first: a curve counts even where a surface or another
    // shape lies in front of it (the designer aims at the curve, the surface is translucent to
    // intent).
    SoHandleEventAction* action = node->getAction();
    SoRayPickAction pick(action->getViewportRegion());
    pick.setPoint(node->getEvent()->getPosition());
    pick.setRadius(kCurvePickRadius);
    pick.setPickAll(TRUE);
    pick.apply(action->getPickRoot());
    const SoPickedPointList& points = pick.getPickedPointList();
    for (int k = 0; k < points.getLength(); ++k) {
        if (const auto curve = scene::entityAt(points[k]->getPath(), {model::EntityKind::Curve})) {
            result.curve = curve->id;
            result.point = scene::toEigen(points[k]->getPoint());
            return result;
        }
    }
    return result;
}

PointerClick pickSurface(SoEventCallback* node, const Eigen::Vector3d& view)
{
    PointerClick result;
    result.view = view;
    SoHandleEventAction* action = node->getAction();
    SoRayPickAction pick(action->getViewportRegion());
    pick.setPoint(node->getEvent()->getPosition());
    pick.setRadius(1.0f);
    pick.setPickAll(TRUE);
    pick.apply(action->getPickRoot());
    const SoPickedPointList& points = pick.getPickedPointList();
    for (int k = 0; k < points.getLength(); ++k) {
        if (pathHasDragger(points[k])) continue;
        if (const auto surface = scene::entityAt(points[k]->getPath(), {model::EntityKind::Surface})) {
            result.surface = surface->id;
            result.point = scene::toEigen(points[k]->getPoint());
            return result;
        }
    }
    return result;
}

void StrokeInput::click(SoEventCallback* node)
{
    if (!clicked_) return;
    Eigen::Vector3d from, direction;
    if (!ray(node, from, direction)) return;
    clicked_(pickSurface(node, direction));
}

std::optional<Eigen::Vector3d> intersectPlane(const model::PlaneFrame& frame, const Eigen::Vector3d& from,
                                              const Eigen::Vector3d& direction)
{
    const Eigen::Vector3d normal = frame.normal();
    const double facing = direction.dot(normal);
    if (std::abs(facing) < kMinRayCosine) return std::nullopt;
    const double t = (frame.origin - from).dot(normal) / facing;
    if (t <= 0.0) return std::nullopt;  // the plane is behind the eye
    Eigen::Vector3d local = frame.toLocal(from + t * direction);
    local.z() = 0.0;
    return local;
}

void reproject(FinishedStroke& stroke, const model::PlaneFrame& frame)
{
    stroke.frame = frame;
    stroke.points.clear();
    std::vector<double> times, pressure;
    const bool pressured = stroke.rayPressure.size() == stroke.rayOrigins.size();
    for (size_t i = 0; i < stroke.rayOrigins.size(); ++i) {
        if (const auto p = intersectPlane(frame, stroke.rayOrigins[i], stroke.rayDirections[i])) {
            stroke.points.push_back(*p);
            times.push_back(stroke.rayTimes[i]);
            if (pressured) pressure.push_back(stroke.rayPressure[i]);
        }
    }
    stroke.times = std::move(times);
    stroke.pressure = std::move(pressure);
}

double pixelFootprint(const FinishedStroke& stroke)
{
    std::vector<double> steps;
    const size_t n = std::min(stroke.rayOrigins.size(), stroke.pixelRays.size());
    steps.reserve(n);
    for (size_t i = 0; i < n; ++i) {
        const auto p = intersectPlane(stroke.frame, stroke.rayOrigins[i], stroke.rayDirections[i]);
        if (!p) continue;
        const FinishedStroke::PixelRays& r = stroke.pixelRays[i];
        const auto px = intersectPlane(stroke.frame, r.originX, r.directionX);
        const auto py = intersectPlane(stroke.frame, r.originY, r.directionY);
        if (!px || !py) continue;
        const double step = std::max((*px - *p).norm(), (*py - *p).norm());
        if (std::isfinite(step)) steps.push_back(step);
    }
    if (steps.empty()) return 0.0;
    auto middle = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
    std::nth_element(steps.begin(), middle, steps.end());
    return *middle;
}

void StrokeInput::onEvent(SoEventCallback* node)
{
    if (!enabled_) return;
    const SoEvent* event = node->getEvent();
    const double now = clock_ ? clock_() : event->getTime().getValue();
    if (SO_MOUSE_PRESS_EVENT(event, BUTTON1)) {
        // A press on a dragger moves the plane instead of starting a stroke.
        if (pathHasDragger(node->getPickedPoint())) return;
        Eigen::Vector3d from, direction;
        if (!ray(node, from, direction)) return;
        const StrokeHit start = hit(node, direction);
        const std::optional<model::PlaneFrame> plane = plane_ ? plane_(start) : std::nullopt;
        const SbVec2s at = event->getPosition();
        pixelBox_[0] = pixelBox_[2] = at[0];
        pixelBox_[1] = pixelBox_[3] = at[1];
        if (!plane) {
            // No stroke here; the press may still be a click (Sculpt mode's click tools).
            if (!clicked_ || !clickOnly_ || !clickOnly_()) return;
            clicking_ = true;
            node->setHandled();
            return;
        }
        drawing_ = true;
        startTime_ = now;
        stroke_ = {};
        stroke_.frame = *plane;
        stroke_.start = start;
        addSample(node, 0.0);
        node->setHandled();
    } else if (clicking_ && event->isOfType(SoLocation2Event::getClassTypeId())) {
        const SbVec2s at = event->getPosition();
        pixelBox_[0] = std::min<int>(pixelBox_[0], at[0]);
        pixelBox_[1] = std::min<int>(pixelBox_[1], at[1]);
        pixelBox_[2] = std::max<int>(pixelBox_[2], at[0]);
        pixelBox_[3] = std::max<int>(pixelBox_[3], at[1]);
        node->setHandled();
    } else if (clicking_ && SO_MOUSE_RELEASE_EVENT(event, BUTTON1)) {
        clicking_ = false;
        const SbVec2s at = event->getPosition();
        node->setHandled();
        if (std::max(pixelBox_[2], int(at[0])) - std::min(pixelBox_[0], int(at[0])) < kClickPixels &&
            std::max(pixelBox_[3], int(at[1])) - std::min(pixelBox_[1], int(at[1])) < kClickPixels)
            click(node);
    } else if (drawing_ && event->isOfType(SoLocation2Event::getClassTypeId())) {
        addSample(node, now - startTime_);
        node->setHandled();
    } else if (drawing_ && SO_MOUSE_RELEASE_EVENT(event, BUTTON1)) {
        addSample(node, now - startTime_);
        Eigen::Vector3d from, direction;
        if (ray(node, from, direction)) stroke_.end = hit(node, direction);
        node->setHandled();
        if (endStroke(true)) click(node);
    }
}

void StrokeInput::addSample(SoEventCallback* node, double time)
{
    const SbVec2s at = node->getEvent()->getPosition();
    pixelBox_[0] = std::min<int>(pixelBox_[0], at[0]);
    pixelBox_[1] = std::min<int>(pixelBox_[1], at[1]);
    pixelBox_[2] = std::max<int>(pixelBox_[2], at[0]);
    pixelBox_[3] = std::max<int>(pixelBox_[3], at[1]);
    Eigen::Vector3d from, direction;
    if (!ray(node, from, direction)) return;
    // Times must not decrease (replayed events may carry equal stamps).
    if (!stroke_.rayTimes.empty()) time = std::max(time, stroke_.rayTimes.back());
    stroke_.rayOrigins.push_back(from);
    stroke_.rayDirections.push_back(direction);
    stroke_.rayTimes.push_back(time);
    // The pen's pressure, kept while every sample has one (every earlier ray has its pressure; a
    // mouse, or a pen that loses its reading, leaves the stroke without).
    const std::optional<double> pressure = pressure_ ? pressure_() : std::nullopt;
    const bool pressured =
        pressure && std::isfinite(*pressure) && stroke_.rayPressure.size() + 1 == stroke_.rayOrigins.size();
    if (pressured) {
        stroke_.rayPressure.push_back(std::clamp(*pressure, 0.0, 1.0));
    } else {
        stroke_.rayPressure.clear();
        stroke_.pressure.clear();
    }
    FinishedStroke::PixelRays pixel;
    if (!pointerRay(node, camera_ ? camera_() : nullptr, pixel.originX, pixel.directionX, 1, 0) ||
        !pointerRay(node, camera_ ? camera_() : nullptr, pixel.originY, pixel.directionY, 0, 1)) {
        pixel = {from, direction, from, direction};  // (not reached: ray() succeeded with the same camera)
    }
    stroke_.pixelRays.push_back(pixel);
    // The preview shows the points on the plane chosen at the press; a ray that misses it adds none
    // (and no time: points and times stay pairs, or the fitter refuses the stroke).
    if (const auto local = intersectPlane(stroke_.frame, from, direction)) {
        stroke_.points.push_back(*local);
        stroke_.times.push_back(time);
        if (pressured) stroke_.pressure.push_back(stroke_.rayPressure.back());
        const int n = static_cast<int>(stroke_.points.size());
        previewPoints_->point.set1Value(n - 1, scene::toSb(stroke_.frame.toWorld(*local)));
        previewLine_->numVertices.setValue(n);
    }
    if (sampled_) sampled_();
}

bool StrokeInput::endStroke(bool keep)
{
    drawing_ = false;
    const FinishedStroke stroke = std::move(stroke_);
    stroke_ = {};
    previewPoints_->point.setNum(0);
    previewLine_->numVertices.setNum(0);
    const bool click = pixelBox_[2] - pixelBox_[0] < kClickPixels && pixelBox_[3] - pixelBox_[1] < kClickPixels;
    if (keep && finished_ && stroke.rayOrigins.size() >= 2 && !click) finished_(stroke);
    return keep && click;
}

}  // namespace sculptline::manipulators
