// The model's incidence bookkeeping (issue 14, seed 000 §3.1): a free-form surface that curves lie
// on keeps its shape before the first curve (its prior F0, from which every incidence solve starts)
// and the truncation k the designer chose; editing such a surface edits its prior.
#include "model/model.h"

namespace sculptline::model {

void Model::setSurfaceShape(EntityId surface, const solvers::Surface3d& shape)
{
    auto it = entities_.find(surface);
    if (it == entities_.end() || it->second.kind != EntityKind::Surface || it->second.recipe || it->second.fixed) return;
    for (const Eigen::Vector3d& p : shape.points()) {
        if (!p.allFinite()) return;
    }
    // An incidence surface's edit is an edit of what its curves bend (its prior).
    if (it->second.prior) it->second.prior = shape;
    it->second.surface = shape;
    it->second.buildError.clear();
    ++it->second.shapeVersion;
    for (ModelObserver* o : observers_) o->entityUpdated(it->second);
    markDirty(surface);
}

void Model::curvesOnSurfaceChanged(EntityId surface)
{
    auto it = entities_.find(surface);
    if (it == entities_.end() || it->second.kind != EntityKind::Surface || it->second.recipe || !it->second.surface) return;
    Entity& e = it->second;
    bool any = false;
    for (ConstraintId c : constraintsOn(surface)) any = any || constraints_.at(c).type == ConstraintType::CurveOnSurface;
    if (any && !e.prior) {
        e.prior = e.surface;
    } else if (!any && e.prior) {
        e.surface = *e.prior;
        e.prior.reset();
        e.incidence.reset();
        e.solveMessage.clear();
        e.buildError.clear();
        ++e.shapeVersion;
        for (ModelObserver* o : observers_) o->entityUpdated(e);
    }
    markDirty(surface);
}

void Model::setIncidencePrior(EntityId surface, const std::optional<solvers::Surface3d>& prior)
{
    auto it = entities_.find(surface);
    if (it == entities_.end() || it->second.kind != EntityKind::Surface || it->second.recipe) return;
    it->second.prior = prior;
    markDirty(surface);
}

void Model::setIncidenceK(EntityId surface, int k)
{
    auto it = entities_.find(surface);
    if (it == entities_.end() || it->second.kind != EntityKind::Surface || it->second.fixed || k < 0) return;
    if (it->second.incidenceK == k) return;
    it->second.incidenceK = k;
    markDirty(surface);
}

}  // namespace sculptline::model
