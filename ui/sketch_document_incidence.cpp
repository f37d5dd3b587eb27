// SketchDocument's incidence modes (seed 000 §3.1, issue 14 §3): Interpolation (a surface through the
// designer's curves) and Sculpting (curves drawn onto a surface, which follows them), and the
// L-curve's truncation picked by the designer. The surface is a model entity without a recipe whose
// curves lie on it (curve-on-surface constraints): the model's incidence step solves it
// (model/solver_registry.cpp), live from a kept factorization while a plane is dragged.
#include "ui/sketch_document.h"

#include "ui/undo_commands.h"

namespace sculptline::ui {

void SketchDocument::setIncidenceK(model::EntityId surface, int k)
{
    const model::Entity* s = model_.find(surface);
    if (!s || s->kind != model::EntityKind::Surface || s->recipe || k < 0 || s->incidenceK == k) return;
    undo_.push(new SetIncidenceKCommand(*this, surface, s->incidenceK, k));
}

}  // namespace sculptline::ui
