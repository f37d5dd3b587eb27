#include "ui/view_navigation.h"

#include <Inventor/SbRotation.h>
#include <Inventor/nodes/SoOrthographicCamera.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>

#include <QMouseEvent>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace sculptline::ui {
namespace {

/// Radians of turn per pixel of pointer motion: half a turn for about a third of a large viewport.
constexpr double kTurnPerPixel = 0.008;
/// Distance scale per pixel of a zoom drag (down = away), exp(kZoomPerPixel · dy).
constexpr double kZoomPerPixel = 0.005;
/// Distance scale per wheel notch towards the user (a notch away zooms in by the inverse).
constexpr double kWheelStep = 1.15;
/// One wheel notch in QWheelEvent::angleDelta units (eighths of a degree, 15° a notch).
constexpr double kWheelNotch = 120.0;
/// The view never tips quite over the pole: |forward · Z| stays below this (a turntable flips there).
constexpr double kMaxPitchCosine = 0.995;
/// Pixels a right press may wander and still be a click (the context menu), as the stroke input's click.
constexpr int kClickPixels = 3;

SbVec3f lookedAt(const SoCamera* camera)
{
    SbVec3f forward;
    camera->orientation.getValue().multVec(SbVec3f(0, 0, -1), forward);
    return camera->position.getValue() + forward * camera->focalDistance.getValue();
}

}  // namespace

ViewNavigation::Gesture ViewNavigation::gestureFor(const QMouseEvent& press)
{
    const Qt::KeyboardModifiers mods = press.modifiers();
    const bool alt = mods & Qt::AltModifier;
    switch (press.button()) {
    case Qt::LeftButton: return alt ? Gesture::Turn : Gesture::None;
    case Qt::MiddleButton:
        if (alt || (mods & Qt::ShiftModifier)) return Gesture::Pan;
        return (mods & Qt::ControlModifier) ? Gesture::Zoom : Gesture::Turn;
    case Qt::RightButton: return alt ? Gesture::Zoom : Gesture::RightButton;
    default: return Gesture::None;
    }
}

bool ViewNavigation::press(const QMouseEvent& event)
{
    if (gesture_ != Gesture::None) return true;  // a second button during a gesture changes nothing
    gesture_ = gestureFor(event);
    if (gesture_ == Gesture::None) return false;
    button_ = event.button();
    start_ = last_ = event.pos();
    dragged_ = false;
    return true;
}

bool ViewNavigation::move(const QMouseEvent& event, SoCamera* camera, int viewportHeight)
{
    if (gesture_ == Gesture::None) return false;
    const QPoint delta = event.pos() - last_;
    last_ = event.pos();
    if (!dragged_ && (std::abs(event.pos().x() - start_.x()) >= kClickPixels || std::abs(event.pos().y() - start_.y()) >= kClickPixels))
        dragged_ = true;
    if (!camera || !dragged_) return true;
    switch (gesture_) {
    case Gesture::Turn: turn(camera, delta.x(), delta.y()); break;
    case Gesture::RightButton:
    case Gesture::Pan: pan(camera, delta.x(), delta.y(), viewportHeight); break;
    case Gesture::Zoom: zoom(camera, std::exp(kZoomPerPixel * delta.y())); break;
    case Gesture::None: break;
    }
    return true;
}

bool ViewNavigation::release(const QMouseEvent& event, bool* click)
{
    if (gesture_ == Gesture::None) return false;
    if (event.button() != button_) return true;
    if (click) *click = gesture_ == Gesture::RightButton && !dragged_;
    gesture_ = Gesture::None;
    button_ = Qt::NoButton;
    return true;
}

void ViewNavigation::wheel(const QWheelEvent& event, SoCamera* camera)
{
    if (!camera) return;
    const double notches = event.angleDelta().y() / kWheelNotch;
    if (notches != 0.0) zoom(camera, std::pow(kWheelStep, -notches));
}

void ViewNavigation::turn(SoCamera* camera, double dx, double dy)
{
    const SbVec3f pivot = lookedAt(camera);
    const SbRotation orientation = camera->orientation.getValue();
    SbVec3f right, forward;
    orientation.multVec(SbVec3f(1, 0, 0), right);
    orientation.multVec(SbVec3f(0, 0, -1), forward);
    // Yaw about the model's up axis; pitch about the camera's right axis unless it would tip over.
    const SbRotation yaw(SbVec3f(0, 0, 1), static_cast<float>(-dx * kTurnPerPixel));
    SbRotation pitch(right, static_cast<float>(-dy * kTurnPerPixel));
    SbVec3f pitched;
    pitch.multVec(forward, pitched);
    if (std::abs(pitched[2]) > kMaxPitchCosine) pitch = SbRotation::identity();
    const SbRotation change = pitch * yaw;
    SbVec3f offset;
    change.multVec(camera->position.getValue() - pivot, offset);
    camera->orientation = orientation * change;
    camera->position = pivot + offset;
}

void ViewNavigation::pan(SoCamera* camera, double dx, double dy, int viewportHeight)
{
    if (viewportHeight <= 0) return;
    // Model units per pixel on the plane through the point looked at.
    double height = 0.0;
    if (camera->isOfType(SoPerspectiveCamera::getClassTypeId())) {
        const double angle = static_cast<SoPerspectiveCamera*>(camera)->heightAngle.getValue();
        height = 2.0 * camera->focalDistance.getValue() * std::tan(angle / 2.0);
    } else if (camera->isOfType(SoOrthographicCamera::getClassTypeId())) {
        height = static_cast<SoOrthographicCamera*>(camera)->height.getValue();
    }
    const double unit = height / viewportHeight;
    SbVec3f right, up;
    camera->orientation.getValue().multVec(SbVec3f(1, 0, 0), right);
    camera->orientation.getValue().multVec(SbVec3f(0, 1, 0), up);
    // The model follows the pointer: the camera moves the other way (Qt's y grows downwards).
    camera->position = camera->position.getValue() + (right * static_cast<float>(-dx * unit)) + (up * static_cast<float>(dy * unit));
}

void ViewNavigation::zoom(SoCamera* camera, double factor)
{
    if (!(factor > 0.0)) return;
    if (camera->isOfType(SoOrthographicCamera::getClassTypeId())) {
        auto* ortho = static_cast<SoOrthographicCamera*>(camera);
        ortho->height = static_cast<float>(ortho->height.getValue() * factor);
        return;
    }
    const SbVec3f pivot = lookedAt(camera);
    SbVec3f forward;
    camera->orientation.getValue().multVec(SbVec3f(0, 0, -1), forward);
    const float distance = static_cast<float>(camera->focalDistance.getValue() * factor);
    camera->focalDistance = distance;
    camera->position = pivot - forward * distance;
}

}  // namespace sculptline::ui
