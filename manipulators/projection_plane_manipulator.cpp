#include "manipulators/projection_plane_manipulator.h"

#include "scene/eigen_coin.h"
#include "scene/plane_node.h"

#include <Inventor/draggers/SoJackDragger.h>
#include <Inventor/nodes/SoScale.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoTransform.h>

namespace sculptline::manipulators {

ProjectionPlaneManipulator::ProjectionPlaneManipulator(const scene::PlaneSpec& plane)
    : initial_(plane), draggerScale_(kDraggerScale * plane.size)
{
    root_ = new SoSeparator;
    root_->ref();
    root_->setName("ProjectionPlane");

    placement_ = scene::makePlanePlacement(plane);
    root_->addChild(placement_);
    auto* up = new SoScale;
    up->scaleFactor.setValue(SbVec3f(1, 1, 1) * static_cast<float>(draggerScale_));
    root_->addChild(up);
    dragger_ = new SoJackDragger;
    root_->addChild(dragger_);

    // A dragger moves only its own geometry; the plane follows through these field connections.
    // Between the two scales, motion acts as S * T * S^-1, i.e. translations in dragger units
    // times s: the plane stays under the dragger as it moves.
    motion_ = new SoTransform;
    motion_->translation.connectFrom(&dragger_->translation);
    motion_->rotation.connectFrom(&dragger_->rotation);
    motion_->scaleFactor.connectFrom(&dragger_->scaleFactor);
    root_->addChild(motion_);
    auto* down = new SoScale;
    down->scaleFactor.setValue(SbVec3f(1, 1, 1) / static_cast<float>(draggerScale_));
    root_->addChild(down);
    root_->addChild(scene::makePlaneGeometry(plane.size));

    sensor_.setFunction(&ProjectionPlaneManipulator::motionChanged);
    sensor_.setData(this);
    sensor_.attach(motion_);
}

ProjectionPlaneManipulator::~ProjectionPlaneManipulator()
{
    sensor_.detach();
    root_->unref();
}

scene::PlaneSpec ProjectionPlaneManipulator::plane() const
{
    // Composition of the graph above applied to the plane's local origin and +Z: SoTransform
    // scales, then rotates, then translates; the two SoScale nodes cancel except on the translation.
    const SbRotation placed = placement_->rotation.getValue();
    const SbRotation moved = motion_->rotation.getValue();
    SbVec3f offset = motion_->translation.getValue() * static_cast<float>(draggerScale_);
    placed.multVec(offset, offset);
    SbVec3f normal(0, 0, 1);
    moved.multVec(normal, normal);
    placed.multVec(normal, normal);

    scene::PlaneSpec now;
    now.origin = initial_.origin + scene::toEigen(offset);
    now.normal = scene::toEigen(normal).normalized();
    // The jack scales uniformly, so any component is the scale.
    now.size = initial_.size * motion_->scaleFactor.getValue()[0];
    return now;
}

void ProjectionPlaneManipulator::motionChanged(void* self, SoSensor*)
{
    auto* manipulator = static_cast<ProjectionPlaneManipulator*>(self);
    if (manipulator->moved_) manipulator->moved_();
}

}  // namespace sculptline::manipulators
