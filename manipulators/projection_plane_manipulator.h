#pragma once
// A projection plane the user can move: the plane's look (scene/plane_node.h) carried by a Coin
// SoJackDragger (without its scaler: planes keep their size) whose translation and rotation fields
// drive the plane's transform.
#include "model/plane_frame.h"
#include "model/document.h"

#include <Inventor/sensors/SoNodeSensor.h>

#include <functional>

class SoDragger;
class SoJackDragger;
class SoSeparator;
class SoTransform;

namespace sculptline::manipulators {

/// Dragger size relative to the plane's edge: large enough to grab, small enough not to hide the
/// plane (the jack's own geometry spans about two units).
constexpr double kDraggerScale = 0.12;

/// Owns (ref()s) a graph
///   SoSeparator "ProjectionPlane" {
///     SoTransform placement        plane origin and normal from the document
///     SoSeparator {
///       SoScale s                  dragger size (kDraggerScale * plane size)
///       SoTransform motion         fields connected from the dragger's translation and rotation
///       SoScale 1/s                undoes s for the plane, so the plane moves with the dragger
///       plane geometry }
///     SoSeparator { SoScale s, SoJackDragger } }
/// Dragger fields are the public API: setting them (from code, a replay, or the mouse) moves the
/// plane through the field connections; an immediate node sensor reports every move to the callback,
/// which should only record it (the model coalesces, scene/update_scheduler.h).
class ProjectionPlaneManipulator {
public:
    explicit ProjectionPlaneManipulator(const model::PlaneFrame& frame);
    explicit ProjectionPlaneManipulator(const model::PlaneSpec& plane);
    ~ProjectionPlaneManipulator();
    ProjectionPlaneManipulator(const ProjectionPlaneManipulator&) = delete;
    ProjectionPlaneManipulator& operator=(const ProjectionPlaneManipulator&) = delete;

    /// The graph root; add it to a scene (the scene refs it too; this object keeps its own ref).
    SoSeparator* root() const { return root_; }
    SoJackDragger* dragger() const { return dragger_; }
    /// The transform the dragger drives (in dragger units: see the graph above).
    SoTransform* motion() const { return motion_; }

    /// The plane where it is now, in model coordinates (origin, unit normal, edge length).
    model::PlaneSpec plane() const;

    /// The full frame where the plane is now (origin, rotation including the turn about its normal).
    model::PlaneFrame frame() const;
    /// Puts the plane at `frame` (undo, redo, a document) without calling the moved callback: the
    /// placement takes the frame and the dragger returns to its rest position.
    void setFrame(const model::PlaneFrame& frame);

    /// Called immediately on every change of the dragger's motion (several times per mouse event).
    void setMovedCallback(std::function<void()> callback) { moved_ = std::move(callback); }
    /// Called when the user presses on and releases the dragger (one undo step per drag).
    void setDragCallbacks(std::function<void()> started, std::function<void()> finished);

private:
    static void motionChanged(void* self, SoSensor* sensor);
    static void dragStarted(void* self, SoDragger* dragger);
    static void dragFinished(void* self, SoDragger* dragger);

    double size_;
    double draggerScale_;
    SoSeparator* root_ = nullptr;
    SoTransform* placement_ = nullptr;
    SoJackDragger* dragger_ = nullptr;
    SoTransform* motion_ = nullptr;
    SoNodeSensor sensor_;
    std::function<void()> moved_;
    std::function<void()> started_;
    std::function<void()> finished_;
};

}  // namespace sculptline::manipulators
