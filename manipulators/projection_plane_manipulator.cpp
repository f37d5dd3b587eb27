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
    now.size = initial_.size;
    return now;
}

void ProjectionPlaneManipulator::motionChanged(void* self, SoSensor*)
{
    auto* manipulator = static_cast<ProjectionPlaneManipulator*>(self);
    if (manipulator->moved_) manipulator->moved_();
}

}  // namespace sculptline::manipulators
