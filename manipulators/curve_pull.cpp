#include "manipulators/curve_pull.h"

#include "scene/eigen_coin.h"
#include "scene/update_scheduler.h"
#include "solvers/bspline/projection.h"
#include "scene/overlay_nodes.h"

#include <Inventor/events/SoLocation2Event.h>
#include <Inventor/events/SoMouseButtonEvent.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoEventCallback.h>
#include <Inventor/nodes/SoPointSet.h>
#include <Inventor/nodes/SoSeparator.h>

namespace sculptline::manipulators {
namespace {

/// The handle: a large green dot, the colour of "grabbed" in most modellers, never a curve colour.
const SbColor kHandleColor(0.3f, 0.95f, 0.4f);
constexpr float kHandleSize = 10.0f;

}  // namespace

CurvePull::CurvePull()
{
    root_ = new SoSeparator;
    root_->ref();
    root_->setName("CurvePull");
    callback_ = new SoEventCallback;
    callback_->addEventCallback(SoMouseButtonEvent::getClassTypeId(), &CurvePull::handleEvent, this);
    callback_->addEventCallback(SoLocation2Event::getClassTypeId(), &CurvePull::handleEvent, this);
    root_->addChild(callback_);
    auto* marker = scene::makeOverlayRoot();
    handle_ = scene::addStyledCoordinates(marker, kHandleColor, kHandleSize, 0.0f);
    marker->addChild(new SoPointSet);
    root_->addChild(marker);
}

CurvePull::~CurvePull()
{
    callback_->removeEventCallback(SoMouseButtonEvent::getClassTypeId(), &CurvePull::handleEvent, this);
    callback_->removeEventCallback(SoLocation2Event::getClassTypeId(), &CurvePull::handleEvent, this);
    root_->unref();
}

void CurvePull::setEnabled(bool enabled)
{
    if (!enabled && pulling_) {
        pulling_ = false;
        handle_->point.setNum(0);
        if (release_) release_();
    }
    enabled_ = enabled;
}

void CurvePull::setCallbacks(Grab grab, Move move, std::function<void()> release)
{
    grab_ = std::move(grab);
    move_ = std::move(move);
    release_ = std::move(release);
}

void CurvePull::handleEvent(void* self, SoEventCallback* node) { static_cast<CurvePull*>(self)->onEvent(node); }

void CurvePull::showHandle(const Eigen::Vector3d& world) { handle_->point.setValue(scene::toSb(world)); }

void CurvePull::onEvent(SoEventCallback* node)
{
    if (!enabled_) return;
    const SoEvent* event = node->getEvent();
    Eigen::Vector3d from, direction;
    if (!pointerRay(node, camera_ ? camera_() : nullptr, from, direction)) return;
    if (SO_MOUSE_PRESS_EVENT(event, BUTTON1)) {
        StrokeHit hit = pickCurve(node, direction);
        if (hit.curve == 0 || !grab_) return;
        hit.shift = event->wasShiftDown();
        const std::optional<model::PlaneFrame> frame = grab_(hit);
        if (!frame) {
            node->setHandled();  // the press was taken (a pin added) or refused: not a stroke either
            return;
        }
        frame_ = *frame;
        pulling_ = true;
        showHandle(hit.point);
        node->setHandled();
    } else if (pulling_ && event->isOfType(SoLocation2Event::getClassTypeId())) {
        if (const auto local = intersectPlane(frame_, from, direction)) {
            showHandle(frame_.toWorld(*local));
            if (move_) move_(*local);
        }
        node->setHandled();
    } else if (pulling_ && SO_MOUSE_RELEASE_EVENT(event, BUTTON1)) {
        pulling_ = false;
        handle_->point.setNum(0);
        node->setHandled();
        if (release_) release_();
    }
}

}  // namespace sculptline::manipulators

namespace sculptline::manipulators {

CurvePullBinding::CurvePullBinding(model::Model& model, scene::UpdateScheduler& scheduler) : model_(model), scheduler_(scheduler) {}

std::optional<model::PlaneFrame> CurvePullBinding::grab(const StrokeHit& hit, std::string* error)
{
    const model::Entity* curve = model_.find(hit.curve);
    if (!curve || curve->kind != model::EntityKind::Curve || curve->plane() == 0) return std::nullopt;
    const model::PlaneFrame frame = model_.find(curve->plane())->frame;
    const double u = solvers::projectToCurve(*curve->local, frame.toLocal(hit.point)).u;
    scheduler_.flush();
    try {
        model_.beginPull(curve->id, u);
    } catch (const std::exception& e) {
        if (error) *error = e.what();
        return std::nullopt;
    }
    pulled_ = curve->id;
    before_ = curve->local;
    message_.clear();
    return frame;
}

void CurvePullBinding::moveTo(const Eigen::Vector3d& local)
{
    if (pulled_ == 0) return;
    // Marks the curve changed only: the scheduler updates its dependents once per frame.
    const std::string message = model_.pullTo(local);
    if (!message.empty()) message_ = message;
}

void CurvePullBinding::release()
{
    if (pulled_ == 0) return;
    scheduler_.flush();
    model_.endDrag();  // the surfaces it drove come to rest as fresh builds
    scheduler_.flush();
    const model::EntityId curve = pulled_;
    pulled_ = 0;
    if (finished_) finished_(curve, *before_, message_);
    before_.reset();
    message_.clear();
}

}  // namespace sculptline::manipulators
