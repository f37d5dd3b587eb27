#include "ui/undo_commands.h"

#include "model/document.h"
#include "solvers/io/geometry_json.h"
#include "ui/sketch_document.h"

#include <nlohmann/json.hpp>

namespace sculptline::ui {

AddEntitiesCommand::AddEntitiesCommand(SketchDocument& doc, std::vector<model::Entity> entities, const QString& text)
    : doc_(doc), entities_(std::move(entities))
{
    setText(text);
}

void AddEntitiesCommand::redo()
{
    for (size_t i = 0; i < entities_.size(); ++i) {
        model::Entity& e = entities_[i];
        auto resolve = [&](model::EntityId& id) {
            if (id == kPreviousEntity && i > 0) id = entities_[i - 1].id;
        };
        for (model::EntityId& input : e.inputs) resolve(input);
        if (e.recipe) {
            // A sculpt's handle or curve tangent on the target added just before it.
            for (auto& h : e.recipe->handles) resolve(h.point);
            for (auto& t : e.recipe->curveTangents) resolve(t.curve);
        }
        // First run: the model assigns the id (0 asks for a fresh one); later runs reuse it.
        e.id = doc_.model().restore(e);
    }
    doc_.scheduler().flush();
    if (!entities_.empty()) doc_.select(entities_.back().id);
}

void AddEntitiesCommand::undo()
{
    for (auto it = entities_.rbegin(); it != entities_.rend(); ++it) doc_.model().remove(it->id);
    doc_.select(0);
}

DeleteEntityCommand::DeleteEntityCommand(SketchDocument& doc, model::EntityId id) : doc_(doc), id_(id)
{
    const model::Entity* e = doc.model().find(id);
    setText(QStringLiteral("Delete %1 %2").arg(e ? model::kindName(e->kind) : "entity").arg(id));
}

void DeleteEntityCommand::redo()
{
    doc_.select(0);
    removed_ = doc_.model().remove(id_);
}

void DeleteEntityCommand::undo()
{
    doc_.model().restore(removed_);
    doc_.scheduler().flush();
    doc_.select(id_);
}

AddConstraintCommand::AddConstraintCommand(SketchDocument& doc, model::Constraint constraint, const QString& text)
    : doc_(doc), constraint_(std::move(constraint))
{
    setText(text);
}

void AddConstraintCommand::redo()
{
    // First run: the model numbers it; later runs restore it under that number.
    constraint_.id = doc_.model().addConstraint(constraint_);
    doc_.notifyChanged();
}

void AddConstraintCommand::undo()
{
    doc_.model().removeConstraint(constraint_.id);
    doc_.notifyChanged();
}

SetRecipeCommand::SetRecipeCommand(SketchDocument& doc, model::EntityId surface, model::SurfaceRecipe before,
                                   model::SurfaceRecipe after, const QString& text)
    : doc_(doc), surface_(surface), before_(std::move(before)), after_(std::move(after))
{
    setText(text);
}

void SetRecipeCommand::apply(const model::SurfaceRecipe& recipe)
{
    doc_.model().setSurfaceRecipe(surface_, recipe);
    doc_.scheduler().flush();
    doc_.notifyChanged();
}

SetSolidRecipeCommand::SetSolidRecipeCommand(SketchDocument& doc, model::EntityId solid, model::SolidRecipe before,
                                             model::SolidRecipe after, const QString& text)
    : doc_(doc), solid_(solid), before_(before), after_(after)
{
    setText(text);
}

void SetSolidRecipeCommand::swapTo(const model::SolidRecipe& recipe, const std::optional<solvers::volume::Solid>& result,
                                   std::optional<solvers::volume::Solid>& leaving)
{
    const model::Entity* e = doc_.model().find(solid_);
    // Only a current conversion belongs to the recipe being left (a stale one shows older input).
    leaving = e && !e->solidStale() ? e->solid : std::nullopt;
    doc_.model().setSolidRecipe(solid_, recipe, result);
    doc_.notifyChanged();
}

SetIncidenceKCommand::SetIncidenceKCommand(SketchDocument& doc, model::EntityId surface, int before, int after)
    : doc_(doc), surface_(surface), before_(before), after_(after)
{
    setText(after == 0 ? QStringLiteral("Surface %1 at the L-curve's corner").arg(surface)
                       : QStringLiteral("Surface %1 truncated at k = %2").arg(surface).arg(after));
}

void SetIncidenceKCommand::apply(int k)
{
    doc_.model().setIncidenceK(surface_, k);
    doc_.scheduler().flush();
    doc_.notifyChanged();
}

RemoveConstraintCommand::RemoveConstraintCommand(SketchDocument& doc, model::Constraint constraint)
    : doc_(doc), constraint_(std::move(constraint))
{
    setText(QStringLiteral("Remove constraint c%1").arg(constraint_.id));
}

void RemoveConstraintCommand::redo()
{
    doc_.model().removeConstraint(constraint_.id);
    doc_.notifyChanged();
}

void RemoveConstraintCommand::undo()
{
    doc_.model().addConstraint(constraint_);
    doc_.notifyChanged();
}

SetFixedCommand::SetFixedCommand(SketchDocument& doc, model::EntityId id, bool fixed) : doc_(doc), id_(id), fixed_(fixed)
{
    setText(fixed ? QStringLiteral("Fix %1").arg(id) : QStringLiteral("Free %1").arg(id));
}

void SetFixedCommand::redo()
{
    doc_.model().setFixed(id_, fixed_);
    doc_.notifyChanged();
}

void SetFixedCommand::undo()
{
    doc_.model().setFixed(id_, !fixed_);
    doc_.notifyChanged();
}

MovePlaneCommand::MovePlaneCommand(SketchDocument& doc, model::EntityId plane, const model::PlaneFrame& before,
                                   const model::PlaneFrame& after)
    : doc_(doc), plane_(plane), before_(before), after_(after)
{
    setText(QStringLiteral("Move plane %1").arg(plane));
}

void MovePlaneCommand::redo()
{
    if (applied_) {
        applied_ = false;
        return;
    }
    apply(after_);
}

void MovePlaneCommand::undo() { apply(before_); }

void MovePlaneCommand::apply(const model::PlaneFrame& frame)
{
    doc_.model().setPlaneFrame(plane_, frame);
    doc_.scheduler().flush();
}

MovePointCommand::MovePointCommand(SketchDocument& doc, model::EntityId point, const Pose& before, const Pose& after)
    : doc_(doc), point_(point), before_(before), after_(after)
{
    setText(QStringLiteral("Move point %1").arg(point));
}

void MovePointCommand::redo()
{
    if (applied_) {
        applied_ = false;
        return;
    }
    apply(after_);
}

void MovePointCommand::undo() { apply(before_); }

void MovePointCommand::apply(const Pose& pose)
{
    doc_.model().setPointPose(point_, pose.position, pose.rotation);
    doc_.scheduler().flush();
}

}  // namespace sculptline::ui

namespace sculptline::ui {

ReplaceCurveCommand::ReplaceCurveCommand(SketchDocument& doc, model::EntityId curve, solvers::Curve3d before, solvers::Curve3d after)
    : doc_(doc), curve_(curve), before_(std::move(before)), after_(std::move(after))
{
    setText(QStringLiteral("Over-sketch curve %1").arg(curve));
}

void ReplaceCurveCommand::redo()
{
    doc_.model().setCurveShape(curve_, after_);
    doc_.scheduler().flush();
    doc_.select(curve_);
}

void ReplaceCurveCommand::undo()
{
    doc_.model().setCurveShape(curve_, before_);
    doc_.scheduler().flush();
    doc_.select(curve_);
}

}  // namespace sculptline::ui

namespace sculptline::ui {

ReplaceSurfaceCommand::ReplaceSurfaceCommand(SketchDocument& doc, model::EntityId surface, solvers::Surface3d before,
                                             solvers::Surface3d after, const QString& text)
    : doc_(doc), surface_(surface), before_(std::move(before)), after_(std::move(after))
{
    setText(text);
}

void ReplaceSurfaceCommand::redo()
{
    doc_.model().setSurfaceShape(surface_, after_);
    doc_.scheduler().flush();
    doc_.select(surface_);
}

void ReplaceSurfaceCommand::undo()
{
    doc_.model().setSurfaceShape(surface_, before_);
    doc_.scheduler().flush();
    doc_.select(surface_);
}

SetFixedPointsCommand::SetFixedPointsCommand(SketchDocument& doc, model::EntityId curve, std::vector<int> before, std::vector<int> after)
    : doc_(doc), curve_(curve), before_(std::move(before)), after_(std::move(after))
{
    setText(QStringLiteral("Fix control points of curve %1").arg(curve));
}

void SetFixedPointsCommand::redo()
{
    doc_.model().setFixedPoints(curve_, after_);
    doc_.notifyChanged();
}

void SetFixedPointsCommand::undo()
{
    doc_.model().setFixedPoints(curve_, before_);
    doc_.notifyChanged();
}

RestoreStateCommand::RestoreStateCommand(SketchDocument& doc, std::shared_ptr<const std::string> before,
                                         std::shared_ptr<const std::string> after, const QString& text, const bool& suspended)
    : doc_(doc), before_(std::move(before)), after_(std::move(after)), suspended_(suspended)
{
    setText(text);
}

void RestoreStateCommand::redo()
{
    if (!suspended_) apply(*after_);
}

void RestoreStateCommand::undo()
{
    if (!suspended_) apply(*before_);
}

void RestoreStateCommand::apply(const std::string& state)
{
    // The states were written by this program and read back once already (on recovery): a
    // failure here is a bug, not bad input.
    doc_.restoreModel(model::documentFromJson(solvers::io::parseJson(state)));
}

}  // namespace sculptline::ui
