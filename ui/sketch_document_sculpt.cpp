// SketchDocument's Sculpt mode (thesis ch. 6): targets and handles added to one sculpt, its bound
// from a closed stroke, the curve tangents held along its targets. Split from
// sketch_document_input.cpp, which turns strokes into curves.
#include "ui/sketch_document.h"

#include "solvers/bspline/projection.h"
#include "ui/undo_commands.h"

#include <algorithm>

namespace sculptline::ui {
namespace {

/// A bound stroke is closed when its ends lie within this fraction of its extent (a hand-drawn
/// loop rarely meets itself exactly; a C-shape leaves a third of its size or more open).
constexpr double kClosedStrokeFraction = 0.15;
/// Points of a bound polygon at most: a stroke has a few hundred samples, and the bound is tested
/// once per control point and key point when a sculpt is factored.
constexpr size_t kMaxBoundPoints = 128;

}  // namespace

model::EntityId SketchDocument::sculptWith(std::vector<model::Entity> added, const std::function<void(model::SurfaceRecipe&)>& edit,
                                           const QString& text)
{
    const model::Entity* base = model_.find(sculptBase_);
    if (!base || added.empty()) return 0;
    const bool extend = base->recipe && base->recipe->mode == model::Construction::Sculpt && model_.dependents(base->id).empty();
    model::Entity sculpted;
    sculpted.kind = model::EntityKind::Surface;
    model::SurfaceRecipe recipe;
    recipe.mode = model::Construction::Sculpt;
    if (extend) {
        recipe = *base->recipe;
        sculpted.inputs = base->inputs;
    } else {
        sculpted.inputs = {sculptBase_};
        recipe.bound = pendingBound_;  // drawn before the first target
    }
    pendingBound_.clear();
    // Target curves before handle points, as documents list them.
    if (added.back().kind == model::EntityKind::Curve) {
        auto at = std::find_if(sculpted.inputs.begin() + 1, sculpted.inputs.end(), [this](model::EntityId id) {
            const model::Entity* e = model_.find(id);
            return e && e->kind == model::EntityKind::Point;
        });
        sculpted.inputs.insert(at, kPreviousEntity);
    } else {
        sculpted.inputs.push_back(kPreviousEntity);
    }
    if (edit) edit(recipe);
    sculpted.recipe = recipe;
    added.push_back(std::move(sculpted));
    const model::EntityId old = sculptBase_;
    undo_.beginMacro(text);
    // The old sculpt goes first (nothing depends on it), then the target and the sculpt with it.
    if (extend) undo_.push(new DeleteEntityCommand(*this, old));
    undo_.push(new AddEntitiesCommand(*this, std::move(added), text));
    undo_.endMacro();
    const model::Entity* made = model_.find(selection_);
    if (!made || made->kind != model::EntityKind::Surface) return 0;
    sculptBase_ = made->id;
    return made->id;
}

void SketchDocument::setSculptBound(const std::vector<Eigen::Vector3d>& world)
{
    const model::Entity* sculpt = model_.find(sculptBase_);
    lastStroke_ = {};
    lastStroke_.samples = static_cast<int>(world.size());
    if (!sculpt || world.size() < 3) {
        lastStroke_.message = tr("Bound not used: select a surface to sculpt first, then draw a closed loop over it");
        return;
    }
    Eigen::AlignedBox3d box;
    for (const Eigen::Vector3d& p : world) box.extend(p);
    const double extent = box.diagonal().norm();
    if (extent == 0.0 || (world.front() - world.back()).norm() > kClosedStrokeFraction * extent) {
        lastStroke_.message = tr("Bound not used: the stroke is not closed (its ends are %1 mm apart); draw a loop around the region")
                                  .arg((world.front() - world.back()).norm(), 0, 'f', 1);
        return;
    }
    // The bound lies in the domain of the surface the sculpt deforms: its base.
    const bool isSculpt = sculpt->recipe && sculpt->recipe->mode == model::Construction::Sculpt;
    const model::Entity* base = isSculpt ? model_.find(sculpt->inputs.front()) : sculpt;
    if (!base || !base->surface) return;
    const solvers::SurfaceProjector projector(*base->surface);
    const size_t step = (world.size() + kMaxBoundPoints - 1) / kMaxBoundPoints;
    std::vector<Eigen::Vector2d> bound;
    for (size_t k = 0; k < world.size(); k += step) {
        const solvers::SurfaceProjection f = projector.project(world[k]);
        bound.emplace_back(f.u, f.v);
    }
    if (isSculpt) {
        model::SurfaceRecipe after = *sculpt->recipe;
        after.bound = bound;
        undo_.push(new SetRecipeCommand(*this, sculpt->id, *sculpt->recipe, after, tr("Bound sculpt %1").arg(sculpt->id)));
    } else {
        // A surface not sculpted yet: the bound waits for the first target or handle (a sculpt
        // has one at least), and that sculpt takes it.
        lastStroke_.message = tr("Bound drawn on surface %1: draw target curves or drop handles inside it").arg(sculpt->id);
        pendingBound_ = bound;
        Q_EMIT strokeFinished();
        return;
    }
    lastStroke_.message = tr("Bound of %1 points set on sculpt %2: only the region inside deforms").arg(bound.size()).arg(sculpt->id);
    Q_EMIT strokeFinished();
}

void SketchDocument::setSculptCurveTangent(model::EntityId sculpt, model::EntityId curve, bool hold)
{
    const model::Entity* e = model_.find(sculpt);
    const model::Entity* c = model_.find(curve);
    if (!e || !e->recipe || e->recipe->mode != model::Construction::Sculpt || !c || !c->world || !e->surface) return;
    model::SurfaceRecipe after = *e->recipe;
    auto& tangents = after.curveTangents;
    tangents.erase(std::remove_if(tangents.begin(), tangents.end(), [curve](const auto& t) { return t.curve == curve; }), tangents.end());
    if (hold) {
        // The direction the surface has across the curve now, at its middle (the sculpt as it is).
        const solvers::SurfaceProjector projector(*e->surface);
        const solvers::Curve3d& g = *c->world;
        const solvers::SurfaceProjection f = projector.project(g.evaluate(0.5 * (g.domainStart() + g.domainEnd())));
        const auto der = e->surface->derivatives(f.u, f.v, 1);
        const Eigen::Vector3d along = g.derivatives(0.5 * (g.domainStart() + g.domainEnd()), 1)[1];
        const Eigen::Vector3d normal = der[1][0].cross(der[0][1]);
        Eigen::Vector3d across = normal.cross(along);
        if (across.norm() == 0.0 || !across.allFinite()) return;
        tangents.push_back({curve, across.normalized()});
    }
    undo_.push(new SetRecipeCommand(*this, sculpt, *e->recipe, after,
                                    hold ? tr("Hold the tangent along curve %1").arg(curve) : tr("Release the tangent along curve %1").arg(curve)));
}

}  // namespace sculptline::ui
