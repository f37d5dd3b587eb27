#include "manipulators/projection_plane_manipulator.h"

#include "scene/eigen_coin.h"
#include "scene/plane_node.h"

#include <Inventor/draggers/SoJackDragger.h>
#include <Inventor/SbRotation.h>
#include <Inventor/nodes/SoScale.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoTransform.h>

namespace sculptline::manipulators {

ProjectionPlaneManipulator::ProjectionPlaneManipulator(const model::PlaneSpec& plane)
    : ProjectionPlaneManipulator(model::PlaneFrame::fromNormal(plane.origin, plane.normal, plane.size, plane.xAxis))
{
}

ProjectionPlaneManipulator::ProjectionPlaneManipulator(const model::PlaneFrame& plane)
    : size_(plane.size), draggerScale_(kDraggerScale * plane.size)
{
    root_ = new SoSeparator;
    root_->ref();
    root_->setName("ProjectionPlane");

    placement_ = new SoTransform;
    placement_->translation = scene::toSb(plane.origin);
    placement_->rotation = scene::toSb(plane.rotation);
    root_->addChild(placement_);
    const SbVec3f up = SbVec3f(1, 1, 1) * static_cast<float>(draggerScale_);

    // The plane, moved by the dragger through field connections (a dragger moves only its own
    // geometry). Between the two scales, motion acts as S * T * S^-1, i.e. translations in dragger
    // units times s: the plane stays under the dragger as it moves.
    auto* planeGroup = new SoSeparator;
    auto* scaleUp = new SoScale;
    scaleUp->scaleFactor = up;
    planeGroup->addChild(scaleUp);
    motion_ = new SoTransform;
    planeGroup->addChild(motion_);
    auto* scaleDown = new SoScale;
    scaleDown->scaleFactor.setValue(1.0f / up[0], 1.0f / up[1], 1.0f / up[2]);
    planeGroup->addChild(scaleDown);
    planeGroup->addChild(scene::makePlaneGeometry(plane.size));
    root_->addChild(planeGroup);

    // The dragger in a separator of its own, drawn after the translucent plane; only the
    // placement above is shared, so the dragger and the plane meet in the same frame.
    auto* draggerGroup = new SoSeparator;
    auto* draggerScale = new SoScale;
    draggerScale->scaleFactor = up;
    draggerGroup->addChild(draggerScale);
    dragger_ = new SoJackDragger;
    // Planes are moved and turned, not resized: without its scaler, a press on the jack's centre
    // goes to the translator instead of shrinking the plane towards nothing.
    dragger_->setPart("scaler", nullptr);
    draggerGroup->addChild(dragger_);
    root_->addChild(draggerGroup);

    motion_->translation.connectFrom(&dragger_->translation);
    motion_->rotation.connectFrom(&dragger_->rotation);

    sensor_.setFunction(&ProjectionPlaneManipulator::motionChanged);
    sensor_.setData(this);
    // Immediate: the callback only records the motion; coalescing happens in the model's scheduler.
    sensor_.setPriority(0);
    sensor_.attach(motion_);
    dragger_->addStartCallback(&ProjectionPlaneManipulator::dragStarted, this);
    dragger_->addFinishCallback(&ProjectionPlaneManipulator::dragFinished, this);
}

ProjectionPlaneManipulator::~ProjectionPlaneManipulator()
{
    sensor_.detach();
    dragger_->removeStartCallback(&ProjectionPlaneManipulator::dragStarted, this);
    dragger_->removeFinishCallback(&ProjectionPlaneManipulator::dragFinished, this);
    root_->unref();
}

model::PlaneFrame ProjectionPlaneManipulator::frame() const
{
    // Composition of the graph above applied to a local point p: placement (R0, O0), then
    // S * motion * S^-1 = translate by s * T after the motion rotation Rm (a uniform scale commutes
    // with rotations): world = O0 + R0 (s T + Rm p).
    const Eigen::Quaterniond placed = scene::toEigen(placement_->rotation.getValue());
    const Eigen::Quaterniond moved = scene::toEigen(motion_->rotation.getValue());
    const Eigen::Vector3d offset = scene::toEigen(motion_->translation.getValue()) * draggerScale_;
    model::PlaneFrame now;
    now.origin = scene::toEigen(placement_->translation.getValue()) + placed * offset;
    now.rotation = (placed * moved).normalized();
    now.size = size_;
    return now;
}

model::PlaneSpec ProjectionPlaneManipulator::plane() const
{
    const model::PlaneFrame now = frame();
    model::PlaneSpec spec;
    spec.origin = now.origin;
    spec.normal = now.normal();
    spec.xAxis = now.xAxis();
    spec.size = now.size;
    return spec;
}

void ProjectionPlaneManipulator::setFrame(const model::PlaneFrame& frame)
{
    sensor_.detach();
    placement_->translation = scene::toSb(frame.origin);
    placement_->rotation = scene::toSb(frame.rotation);
    dragger_->translation = SbVec3f(0, 0, 0);
    dragger_->rotation = SbRotation::identity();
    sensor_.attach(motion_);
}

void ProjectionPlaneManipulator::setDragCallbacks(std::function<void()> started, std::function<void()> finished)
{
    started_ = std::move(started);
    finished_ = std::move(finished);
}

void ProjectionPlaneManipulator::dragStarted(void* self, SoDragger*)
{
    auto* manipulator = static_cast<ProjectionPlaneManipulator*>(self);
    if (manipulator->started_) manipulator->started_();
}

void ProjectionPlaneManipulator::dragFinished(void* self, SoDragger*)
{
    auto* manipulator = static_cast<ProjectionPlaneManipulator*>(self);
    if (manipulator->finished_) manipulator->finished_();
}

void ProjectionPlaneManipulator::motionChanged(void* self, SoSensor*)
{
    auto* manipulator = static_cast<ProjectionPlaneManipulator*>(self);
    if (manipulator->moved_) manipulator->moved_();
}

}  // namespace sculptline::manipulators
