#include "manipulators/plane_binding.h"

#include "manipulators/projection_plane_manipulator.h"
#include "scene/entity_path.h"
#include "scene/update_scheduler.h"

#include <Inventor/nodes/SoSeparator.h>

namespace sculptline::manipulators {

PlaneDraggers::PlaneDraggers(model::Model& model, scene::UpdateScheduler& scheduler)
    : model_(model), scheduler_(scheduler)
{
    root_ = new SoSeparator;
    root_->ref();
    root_->setName("Planes");
    for (const auto& [id, e] : model_.entities()) entityAdded(e);
    model_.addObserver(this);
}

PlaneDraggers::~PlaneDraggers()
{
    model_.removeObserver(this);
    manipulators_.clear();
    root_->unref();
}

ProjectionPlaneManipulator* PlaneDraggers::manipulator(model::EntityId id) const
{
    const auto it = manipulators_.find(id);
    return it == manipulators_.end() ? nullptr : it->second.get();
}

void PlaneDraggers::setDragCallbacks(StartedCallback started, FinishedCallback finished)
{
    started_ = std::move(started);
    finished_ = std::move(finished);
}

void PlaneDraggers::entityAdded(const model::Entity& e)
{
    if (e.kind != model::EntityKind::Plane) return;
    auto manipulator = std::make_unique<ProjectionPlaneManipulator>(e.frame);
    ProjectionPlaneManipulator* m = manipulator.get();
    const model::EntityId id = e.id;
    // Named as the model's entity, so that a pick on the dragger selects the plane (scene::entityAt).
    m->root()->setName(scene::entityNodeName(model::EntityKind::Plane, id).c_str());
    // Each dragger event only records the frame; the scheduler solves once per frame.
    m->setMovedCallback([this, m, id]() { model_.setPlaneFrame(id, m->frame()); });
    m->setDragCallbacks([this, id]() { dragStarted(id); }, [this, id]() { dragFinished(id); });
    root_->addChild(m->root());
    manipulators_[id] = std::move(manipulator);
}

void PlaneDraggers::entityRemoved(const model::Entity& e)
{
    const auto it = manipulators_.find(e.id);
    if (it == manipulators_.end()) return;
    if (root_->findChild(it->second->root()) >= 0) root_->removeChild(it->second->root());
    manipulators_.erase(it);
    hidden_.erase(e.id);
    if (dragging_ == e.id) dragging_ = 0;  // its dragger is gone: no release will come
}

void PlaneDraggers::setVisible(model::EntityId id, bool visible)
{
    ProjectionPlaneManipulator* m = manipulator(id);
    if (!m || visible == this->visible(id)) return;
    // Out of the graph rather than switched off: a hidden plane draws nothing and is never picked.
    if (visible) {
        hidden_.erase(id);
        root_->addChild(m->root());
    } else {
        hidden_.insert(id);
        root_->removeChild(m->root());
    }
}

void PlaneDraggers::entityUpdated(const model::Entity& e)
{
    // During a drag the manipulator is the source of the frame; any other change (undo, redo)
    // puts the manipulator where the model says.
    if (e.kind != model::EntityKind::Plane || e.id == dragging_) return;
    ProjectionPlaneManipulator* m = manipulator(e.id);
    if (m && m->frame() != e.frame) m->setFrame(e.frame);
}

void PlaneDraggers::dragStarted(model::EntityId plane)
{
    scheduler_.flush();
    dragging_ = plane;
    const model::Entity* e = model_.find(plane);
    dragStart_ = e ? e->frame : manipulator(plane)->frame();
    // The model sets up the solvers of what the plane drives (the surfaces' builders), once; each
    // dragger event then re-solves with them.
    model_.beginDrag(plane);
    if (started_) started_(plane);
}

void PlaneDraggers::dragFinished(model::EntityId plane)
{
    scheduler_.flush();
    // The surfaces the drag rebuilt incrementally come to rest as fresh builds.
    model_.endDrag();
    scheduler_.flush();
    dragging_ = 0;
    const model::Entity* e = model_.find(plane);
    const model::PlaneFrame after = e ? e->frame : dragStart_;
    if (finished_) finished_(plane, dragStart_, after);
}

}  // namespace sculptline::manipulators
