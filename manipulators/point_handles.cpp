#include "manipulators/point_handles.h"

#include "scene/eigen_coin.h"
#include "scene/entity_path.h"
#include "scene/update_scheduler.h"

#include <Inventor/draggers/SoJackDragger.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoPickStyle.h>
#include <Inventor/nodes/SoScale.h>
#include <Inventor/nodes/SoSphere.h>
#include <Inventor/nodes/SoTranslation.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoTransform.h>
#include <Inventor/sensors/SoNodeSensor.h>

#include <algorithm>

namespace sculptline::manipulators {
namespace {

/// The jack's half-size as a fraction of the extent of the surface the point drives: big enough to
/// grab, small beside the surface (the jack's own geometry spans about two units).
constexpr double kHandleFraction = 0.04;
/// Half-size of a point that drives nothing (yet), model units.
constexpr double kDefaultHandleSize = 4.0;
/// The point itself: an orange ball at the jack's centre (jack units), unpickable so that a press
/// there reaches the jack's translator.
constexpr float kMarkerRadius = 0.3f;
const SbColor kMarkerColor(1.0f, 0.55f, 0.1f);

}  // namespace

PointHandle::PointHandle(const PointPose& pose, double size) : size_(size)
{
    root_ = new SoSeparator;
    root_->ref();
    placement_ = new SoTransform;
    root_->addChild(placement_);
    auto* scale = new SoScale;
    scale->scaleFactor.setValue(static_cast<float>(size), static_cast<float>(size), static_cast<float>(size));
    root_->addChild(scale);
    // The point's ball moves with the jack's translation (connected), drawn before the jack.
    auto* marker = new SoSeparator;
    auto* pick = new SoPickStyle;
    pick->style = SoPickStyle::UNPICKABLE;
    marker->addChild(pick);
    auto* material = new SoMaterial;
    material->diffuseColor = kMarkerColor;
    material->emissiveColor = kMarkerColor * 0.4f;
    marker->addChild(material);
    markerAt_ = new SoTranslation;
    marker->addChild(markerAt_);
    auto* ball = new SoSphere;
    ball->radius = kMarkerRadius;
    marker->addChild(ball);
    root_->addChild(marker);
    dragger_ = new SoJackDragger;
    // Points are moved and turned, not scaled: without its scaler a press on the centre translates.
    dragger_->setPart("scaler", nullptr);
    root_->addChild(dragger_);
    markerAt_->translation.connectFrom(&dragger_->translation);
    setPose(pose);
    sensor_ = new SoNodeSensor(&PointHandle::changed, this);
    // Immediate: the callback only records the pose; the scheduler solves once per frame.
    sensor_->setPriority(0);
    sensor_->attach(dragger_);
    dragger_->addStartCallback(&PointHandle::started, this);
    dragger_->addFinishCallback(&PointHandle::finished, this);
}

PointHandle::~PointHandle()
{
    sensor_->detach();
    delete sensor_;
    dragger_->removeStartCallback(&PointHandle::started, this);
    dragger_->removeFinishCallback(&PointHandle::finished, this);
    root_->unref();
}

PointPose PointHandle::pose() const
{
    // placement (R0, O0), then the scale s, then the dragger's (T, Rm): world = O0 + R0 (s T + Rm p).
    const Eigen::Quaterniond placed = scene::toEigen(placement_->rotation.getValue());
    const Eigen::Quaterniond moved = scene::toEigen(dragger_->rotation.getValue());
    PointPose now;
    now.position = scene::toEigen(placement_->translation.getValue()) + placed * (scene::toEigen(dragger_->translation.getValue()) * size_);
    now.rotation = (placed * moved).normalized();
    return now;
}

void PointHandle::setPose(const PointPose& pose)
{
    if (sensor_) sensor_->detach();
    placement_->translation = scene::toSb(pose.position);
    placement_->rotation = scene::toSb(pose.rotation);
    dragger_->translation = SbVec3f(0, 0, 0);
    dragger_->rotation = SbRotation::identity();
    if (sensor_) sensor_->attach(dragger_);
}

bool PointHandle::atRest() const
{
    return dragger_->translation.getValue() == SbVec3f(0, 0, 0) && dragger_->rotation.getValue() == SbRotation::identity();
}

void PointHandle::setDragCallbacks(std::function<void()> started, std::function<void()> finished)
{
    started_ = std::move(started);
    finished_ = std::move(finished);
}

void PointHandle::changed(void* self, SoSensor*)
{
    auto* h = static_cast<PointHandle*>(self);
    if (h->moved_) h->moved_();
}

void PointHandle::started(void* self, SoDragger*)
{
    auto* h = static_cast<PointHandle*>(self);
    if (h->started_) h->started_();
}

void PointHandle::finished(void* self, SoDragger*)
{
    auto* h = static_cast<PointHandle*>(self);
    if (h->finished_) h->finished_();
}

PointHandles::PointHandles(model::Model& model, scene::UpdateScheduler& scheduler) : model_(model), scheduler_(scheduler)
{
    root_ = new SoSeparator;
    root_->ref();
    root_->setName("PointHandles");
    for (const auto& [id, e] : model_.entities()) entityAdded(e);
    model_.addObserver(this);
}

PointHandles::~PointHandles()
{
    model_.removeObserver(this);
    handles_.clear();
    root_->unref();
}

PointHandle* PointHandles::handle(model::EntityId id) const
{
    const auto it = handles_.find(id);
    return it == handles_.end() ? nullptr : it->second.get();
}

void PointHandles::setDragCallbacks(StartedCallback started, FinishedCallback finished)
{
    started_ = std::move(started);
    finished_ = std::move(finished);
}

double PointHandles::sizeFor(double extent) { return extent > 0.0 ? kHandleFraction * extent : kDefaultHandleSize; }

double PointHandles::sizeOf(const model::Entity& point) const
{
    // The largest surface the point drives (a sculpt made with it comes after the point is added,
    // so the surface whose domain the point was dropped on is used when nothing depends on it yet).
    double extent = 0.0;
    for (const auto& [id, e] : model_.entities()) {
        if (e.kind != model::EntityKind::Surface || !e.surface) continue;
        Eigen::AlignedBox3d box;
        for (const Eigen::Vector3d& p : e.surface->points()) box.extend(p);
        if (box.exteriorDistance(point.position) > 0.5 * box.diagonal().norm()) continue;  // far away
        extent = std::max(extent, box.diagonal().norm());
    }
    return sizeFor(extent);
}

void PointHandles::entityAdded(const model::Entity& e)
{
    if (e.kind != model::EntityKind::Point) return;
    auto handle = std::make_unique<PointHandle>(PointPose{e.position, e.rotation}, sizeOf(e));
    PointHandle* h = handle.get();
    const model::EntityId id = e.id;
    // Named as the model's entity, so that a pick on the jack names the point (scene::entityAt).
    h->root()->setName(scene::entityNodeName(model::EntityKind::Point, id).c_str());
    h->setMovedCallback([this, h, id]() {
        // Only the designer's drag writes the model, and only once the jack moved (a press alone
        // changes the jack's parts, not its pose).
        if (dragging_ != id || h->atRest()) return;
        const PointPose now = h->pose();
        model_.setPointPose(id, now.position, now.rotation);
    });
    h->setDragCallbacks([this, id]() { dragStarted(id); }, [this, id]() { dragFinished(id); });
    root_->addChild(h->root());
    handles_[id] = std::move(handle);
}

void PointHandles::entityRemoved(const model::Entity& e)
{
    const auto it = handles_.find(e.id);
    if (it == handles_.end()) return;
    root_->removeChild(it->second->root());
    handles_.erase(it);
    if (dragging_ == e.id) dragging_ = 0;
}

void PointHandles::entityUpdated(const model::Entity& e)
{
    if (e.kind != model::EntityKind::Point || e.id == dragging_) return;
    PointHandle* h = handle(e.id);
    const PointPose pose{e.position, e.rotation};
    if (h && h->pose() != pose) h->setPose(pose);
}

void PointHandles::dragStarted(model::EntityId point)
{
    scheduler_.flush();
    dragging_ = point;
    const model::Entity* e = model_.find(point);
    dragStart_ = e ? PointPose{e->position, e->rotation} : handle(point)->pose();
    // The sculpts the point drives factor once; each dragger event then changes values only.
    model_.beginDrag(point);
    if (started_) started_(point);
}

void PointHandles::dragFinished(model::EntityId point)
{
    scheduler_.flush();
    model_.endDrag();
    scheduler_.flush();
    dragging_ = 0;
    const model::Entity* e = model_.find(point);
    const PointPose after = e ? PointPose{e->position, e->rotation} : dragStart_;
    if (finished_) finished_(point, dragStart_, after);
}

}  // namespace sculptline::manipulators
