#include "manipulators/aesthetic_drag.h"

#include "scene/eigen_coin.h"
#include "scene/update_scheduler.h"
#include "solvers/bspline/geometry_error.h"

#include <Inventor/draggers/SoTranslate1Dragger.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoSwitch.h>
#include <Inventor/nodes/SoTransform.h>
#include <Inventor/sensors/SoNodeSensor.h>

#include <Eigen/Geometry>

#include <cmath>

namespace sculptline::manipulators {

namespace aes = solvers::aesthetics;

// The handle's length relative to the curve's size: big enough to grab, small beside the curve.
constexpr double kHandleFraction = 0.08;

AestheticOperation prepareAesthetic(const model::Model& model, model::EntityId id, aes::Operator op, const aes::OperatorOptions& options)
{
    const model::Entity* e = model.find(id);
    if (!e || e->kind != model::EntityKind::Curve || !e->local) throw solvers::GeometryError("curve: select a curve");
    aes::PlaneFrame planarFrame;
    const solvers::Curve2d planar = aes::planarCurve(*e->local, 1e-6, &planarFrame);
    const aes::CurveAnalysis analysis = aes::analyzeCurve(planar, options.thresholds);
    AestheticOperation o{aes::operatorSetup(planar, analysis, op, options), planarFrame, {}};
    // The handle: at the constraint that moves most per unit amount, along its direction (the
    // accelerated end: at the end, inward along the tangent).
    size_t best = 0;
    for (size_t j = 1; j < o.setup.direction.size(); ++j) {
        if (o.setup.direction[j].norm() > o.setup.direction[best].norm()) best = j;
    }
    const auto& c = o.setup.constraints[best];
    Eigen::Vector2d at = o.setup.curve.evaluate(c.u), dir = o.setup.direction[best].normalized();
    if (c.type == solvers::editing::ConstraintType::Tangent) {
        // C' grows along the tangent; the handle (the second control point) moves against it at the
        // end, with it at the start.
        dir = c.u == o.setup.curve.domainEnd() ? Eigen::Vector2d(-dir) : dir;
    }
    const model::PlaneFrame frame = e->plane() ? model.find(e->plane())->frame : model::PlaneFrame{};
    const auto toWorld = [&](const Eigen::Vector2d& p) {
        return frame.toWorld(o.planar.origin + p.x() * o.planar.e1 + p.y() * o.planar.e2);
    };
    o.handle.point = toWorld(at);
    o.handle.direction = (toWorld(at + dir) - o.handle.point).normalized();
    o.handle.size = kHandleFraction * std::max(analysis.length, 1e-9);
    return o;
}

AestheticHandle::AestheticHandle()
{
    root_ = new SoSeparator;
    root_->ref();
    root_->setName("AestheticHandle");
    switch_ = new SoSwitch;
    switch_->whichChild = SO_SWITCH_NONE;
    root_->addChild(switch_);
    auto* group = new SoSeparator;
    placement_ = new SoTransform;
    group->addChild(placement_);
    dragger_ = new SoTranslate1Dragger;
    group->addChild(dragger_);
    switch_->addChild(group);
    sensor_ = new SoNodeSensor(&AestheticHandle::changedCb, this);
    sensor_->setPriority(0);
    sensor_->attach(dragger_);
    dragger_->addStartCallback(&AestheticHandle::startedCb, this);
    dragger_->addFinishCallback(&AestheticHandle::finishedCb, this);
}

AestheticHandle::~AestheticHandle()
{
    sensor_->detach();
    delete sensor_;
    dragger_->removeStartCallback(&AestheticHandle::startedCb, this);
    dragger_->removeFinishCallback(&AestheticHandle::finishedCb, this);
    root_->unref();
}

void AestheticHandle::show(const AestheticHandlePlacement& p)
{
    sensor_->detach();
    size_ = p.size;
    placement_->translation = scene::toSb(p.point);
    // The dragger moves along its local x axis.
    placement_->rotation = scene::toSb(Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), p.direction));
    placement_->scaleFactor.setValue(static_cast<float>(size_), static_cast<float>(size_), static_cast<float>(size_));
    dragger_->translation = SbVec3f(0, 0, 0);
    switch_->whichChild = 0;
    sensor_->attach(dragger_);
}

void AestheticHandle::hide()
{
    switch_->whichChild = SO_SWITCH_NONE;
}

bool AestheticHandle::visible() const { return switch_->whichChild.getValue() == 0; }

double AestheticHandle::amount() const { return dragger_->translation.getValue()[0] * size_; }

void AestheticHandle::setCallbacks(std::function<void()> started, std::function<void(double)> moved, std::function<void()> finished)
{
    started_ = std::move(started);
    moved_ = std::move(moved);
    finished_ = std::move(finished);
}

void AestheticHandle::startedCb(void* self, SoDragger*)
{
    auto* h = static_cast<AestheticHandle*>(self);
    h->dragging_ = true;
    if (h->started_) h->started_();
}

void AestheticHandle::finishedCb(void* self, SoDragger*)
{
    auto* h = static_cast<AestheticHandle*>(self);
    h->dragging_ = false;
    if (h->finished_) h->finished_();
}

void AestheticHandle::changedCb(void* self, SoSensor*)
{
    auto* h = static_cast<AestheticHandle*>(self);
    if (h->dragging_ && h->moved_) h->moved_(h->amount());
}

AestheticDragBinding::AestheticDragBinding(model::Model& model, scene::UpdateScheduler& scheduler) : model_(model), scheduler_(scheduler) {}

bool AestheticDragBinding::grab(model::EntityId curve, aes::Operator op, const aes::OperatorOptions& options, std::string* error)
{
    scheduler_.flush();
    try {
        operation_ = prepareAesthetic(model_, curve, op, options);
        drag_ = std::make_unique<aes::OperatorDrag>(operation_->setup);
    } catch (const std::exception& e) {
        if (error) *error = e.what();
        operation_.reset();
        drag_.reset();
        return false;
    }
    if (model_.state(curve) == model::State::Fixed) {
        if (error) *error = "the curve is fixed";
        operation_.reset();
        drag_.reset();
        return false;
    }
    before_ = model_.find(curve)->local;
    curve_ = curve;
    amount_ = 0.0;
    message_.clear();
    model_.beginDrag(curve);
    return true;
}

void AestheticDragBinding::moveTo(double amount)
{
    if (curve_ == 0) return;
    amount_ = std::max(0.0, amount);
    solvers::editing::ManipulationReport report;
    const solvers::Curve2d c = drag_->at(amount_, &report);
    if (report.compromise) message_ = report.message;
    // Marks the curve changed only: the scheduler updates its dependents once per frame.
    model_.setCurveShape(curve_, aes::spaceCurve(c, operation_->planar));
}

void AestheticDragBinding::release()
{
    if (curve_ == 0) return;
    scheduler_.flush();
    model_.endDrag();
    scheduler_.flush();
    const model::EntityId curve = curve_;
    curve_ = 0;
    drag_.reset();
    operation_.reset();
    if (finished_) finished_(curve, *before_, amount_, message_);
    before_.reset();
}

}  // namespace sculptline::manipulators
