#pragma once
// The binding of projection-plane draggers to the model: one ProjectionPlaneManipulator per plane
// entity, kept in step with the model as its observer. A drag writes the plane's frame into the
// model on every dragger event (the model only marks it dirty; scene/update_scheduler.h solves once
// per frame); any other change of a frame (undo, redo, a document) moves the manipulator to where
// the model says. The caller decides what a finished drag means (the ui pushes one undo step).
//   SoSeparator "Planes" { SoSeparator "Plane<id>" (a manipulator's root) .. }
#include "model/model.h"
#include "model/plane_frame.h"

#include <functional>
#include <map>
#include <set>
#include <memory>
#include <utility>

class SoSeparator;

namespace sculptline::scene {
class UpdateScheduler;
}

namespace sculptline::manipulators {

class ProjectionPlaneManipulator;

class PlaneDraggers : public model::ModelObserver {
public:
    /// A drag of `plane` began (its frame in the model is up to date).
    using StartedCallback = std::function<void(model::EntityId plane)>;
    /// A drag of `plane` ended: the frame at the press and the model's frame at the release (equal
    /// when the plane did not move, or is gone).
    using FinishedCallback =
        std::function<void(model::EntityId plane, const model::PlaneFrame& before, const model::PlaneFrame& after)>;

    /// Observes `model` (and gives every plane it already holds a manipulator). `scheduler` runs the
    /// pending update when a drag starts and ends, so the frames recorded are the model's own.
    /// Both must outlive this object.
    PlaneDraggers(model::Model& model, scene::UpdateScheduler& scheduler);
    ~PlaneDraggers() override;
    PlaneDraggers(const PlaneDraggers&) = delete;
    PlaneDraggers& operator=(const PlaneDraggers&) = delete;

    /// The graph root holding every manipulator (ref()ed by this object; add it to a scene, last:
    /// the planes are translucent).
    SoSeparator* root() const { return root_; }
    /// The manipulator of plane `id`, or null.
    ProjectionPlaneManipulator* manipulator(model::EntityId id) const;
    size_t size() const { return manipulators_.size(); }
    /// The plane being dragged (between the press on its dragger and the release), 0 = none.
    model::EntityId dragging() const { return dragging_; }

    void setDragCallbacks(StartedCallback started, FinishedCallback finished);

    /// Shows or hides plane `id`'s square and jack (a view setting: the model and the plane's
    /// curves are untouched; a hidden plane cannot be picked or dragged). A plane removed and
    /// added again (undo) comes back shown.
    void setVisible(model::EntityId id, bool visible);
    bool visible(model::EntityId id) const { return manipulators_.count(id) > 0 && hidden_.count(id) == 0; }
    /// Number of planes hidden.
    size_t hiddenCount() const { return hidden_.size(); }

    void entityAdded(const model::Entity& entity) override;
    void entityRemoved(const model::Entity& entity) override;
    void entityUpdated(const model::Entity& entity) override;

private:
    void dragStarted(model::EntityId plane);
    void dragFinished(model::EntityId plane);

    model::Model& model_;
    scene::UpdateScheduler& scheduler_;
    SoSeparator* root_ = nullptr;
    std::map<model::EntityId, std::unique_ptr<ProjectionPlaneManipulator>> manipulators_;
    std::set<model::EntityId> hidden_;
    model::EntityId dragging_ = 0;
    model::PlaneFrame dragStart_;
    StartedCallback started_;
    FinishedCallback finished_;
};

}  // namespace sculptline::manipulators
