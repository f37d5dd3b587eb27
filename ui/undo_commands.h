#pragma once
// The undoable edits. Each command changes only the model (and the selection); the Coin view, the
// manipulators and the docks follow the model as observers, so undo and redo redraw exactly what
// the original edit did.
#include "model/model.h"

#include <QUndoCommand>
#include <optional>

#include <memory>
#include <string>
#include <vector>

namespace sculptline::ui {

class SketchDocument;

/// In an AddEntitiesCommand, an input naming the entity added just before (a curve on the
/// auxiliary plane made for it, whose id is known only once the plane is added).
constexpr model::EntityId kPreviousEntity = 0xffffffffu;

/// Adds entities (a plane; a curve from a stroke; an auxiliary plane and its curve). Redo re-adds
/// them under their first ids, so later commands that name them stay valid.
class AddEntitiesCommand : public QUndoCommand {
public:
    AddEntitiesCommand(SketchDocument& doc, std::vector<model::Entity> entities, const QString& text);
    void redo() override;
    void undo() override;

private:
    SketchDocument& doc_;
    std::vector<model::Entity> entities_;  ///< in creation (dependency) order, ids assigned
};

/// Removes an entity and its dependents (a plane takes its curves along); undo restores them.
class DeleteEntityCommand : public QUndoCommand {
public:
    DeleteEntityCommand(SketchDocument& doc, model::EntityId id);
    void redo() override;
    void undo() override;

private:
    SketchDocument& doc_;
    model::EntityId id_;
    model::Removed removed_;
};

/// Adds one of the designer's constraints (a pin); undo removes it, redo restores it under its id.
class AddConstraintCommand : public QUndoCommand {
public:
    AddConstraintCommand(SketchDocument& doc, model::Constraint constraint, const QString& text);
    void redo() override;
    void undo() override;

private:
    SketchDocument& doc_;
    model::Constraint constraint_;
};

/// A surface's new recipe (a sculpt's stiffness); the surface is rebuilt with it.
class SetRecipeCommand : public QUndoCommand {
public:
    SetRecipeCommand(SketchDocument& doc, model::EntityId surface, model::SurfaceRecipe before, model::SurfaceRecipe after,
                     const QString& text);
    void redo() override { apply(after_); }
    void undo() override { apply(before_); }

private:
    void apply(const model::SurfaceRecipe& recipe);

    SketchDocument& doc_;
    model::EntityId surface_;
    model::SurfaceRecipe before_, after_;
};

/// A solid's new recipe (its shell thickness or voxel size). The solid converts again off the GUI
/// thread (ui/solid_builder.h); each side keeps the conversion it had when it was left, so an undo,
/// or a redo after a finished conversion, shows its solid at once instead of converting again.
class SetSolidRecipeCommand : public QUndoCommand {
public:
    SetSolidRecipeCommand(SketchDocument& doc, model::EntityId solid, model::SolidRecipe before, model::SolidRecipe after,
                          const QString& text);
    void redo() override { swapTo(after_, afterResult_, beforeResult_); }
    void undo() override { swapTo(before_, beforeResult_, afterResult_); }

private:
    /// Keeps the solid's current conversion in `leaving`, then applies `recipe` with `result`.
    void swapTo(const model::SolidRecipe& recipe, const std::optional<solvers::volume::Solid>& result,
                std::optional<solvers::volume::Solid>& leaving);

    SketchDocument& doc_;
    model::EntityId solid_;
    model::SolidRecipe before_, after_;
    std::optional<solvers::volume::Solid> beforeResult_, afterResult_;
};

/// Removes one of the designer's constraints; undo restores it under its id.
class RemoveConstraintCommand : public QUndoCommand {
public:
    RemoveConstraintCommand(SketchDocument& doc, model::Constraint constraint);
    void redo() override;
    void undo() override;

private:
    SketchDocument& doc_;
    model::Constraint constraint_;
};

/// An incidence surface's truncation k (0 = the L-curve's corner; the L-curve dock's pick).
class SetIncidenceKCommand : public QUndoCommand {
public:
    SetIncidenceKCommand(SketchDocument& doc, model::EntityId surface, int before, int after);
    void redo() override { apply(after_); }
    void undo() override { apply(before_); }

private:
    void apply(int k);
    SketchDocument& doc_;
    model::EntityId surface_;
    int before_, after_;
};

/// Fixes or frees an entity (seed 000 §3.2: a fixed one keeps its shape through every edit and solve).
class SetFixedCommand : public QUndoCommand {
public:
    SetFixedCommand(SketchDocument& doc, model::EntityId id, bool fixed);
    void redo() override;
    void undo() override;

private:
    SketchDocument& doc_;
    model::EntityId id_;
    bool fixed_;
};

/// One plane drag, from press to release. The drag has already moved the model when the command
/// is pushed, so the first redo does nothing.
class MovePlaneCommand : public QUndoCommand {
public:
    MovePlaneCommand(SketchDocument& doc, model::EntityId plane, const model::PlaneFrame& before,
                     const model::PlaneFrame& after);
    void redo() override;
    void undo() override;

private:
    void apply(const model::PlaneFrame& frame);

    SketchDocument& doc_;
    model::EntityId plane_;
    model::PlaneFrame before_, after_;
    bool applied_ = true;
};

/// One drag of a sculpt handle's point (moved and turned), from press to release. The drag has
/// already moved the model when the command is pushed, so the first redo does nothing.
class MovePointCommand : public QUndoCommand {
public:
    struct Pose {
        Eigen::Vector3d position = Eigen::Vector3d::Zero();
        Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
    };
    MovePointCommand(SketchDocument& doc, model::EntityId point, const Pose& before, const Pose& after);
    void redo() override;
    void undo() override;

private:
    void apply(const Pose& pose);

    SketchDocument& doc_;
    model::EntityId point_;
    Pose before_, after_;
    bool applied_ = true;
};

/// A curve's new shape (an over-sketch); the first redo applies it.
class ReplaceCurveCommand : public QUndoCommand {
public:
    ReplaceCurveCommand(SketchDocument& doc, model::EntityId curve, solvers::Curve3d before, solvers::Curve3d after);
    void redo() override;
    void undo() override;

private:
    SketchDocument& doc_;
    model::EntityId curve_;
    solvers::Curve3d before_, after_;
};

/// A free-form surface's new control net (a re-sketched parameter line); the first redo applies it.
class ReplaceSurfaceCommand : public QUndoCommand {
public:
    ReplaceSurfaceCommand(SketchDocument& doc, model::EntityId surface, solvers::Surface3d before, solvers::Surface3d after,
                          const QString& text);
    void redo() override;
    void undo() override;

private:
    SketchDocument& doc_;
    model::EntityId surface_;
    solvers::Surface3d before_, after_;
};

/// Which control points of a curve stay fixed when it is pulled (the inspector's check boxes).
class SetFixedPointsCommand : public QUndoCommand {
public:
    SetFixedPointsCommand(SketchDocument& doc, model::EntityId curve, std::vector<int> before, std::vector<int> after);
    void redo() override;
    void undo() override;

private:
    SketchDocument& doc_;
    model::EntityId curve_;
    std::vector<int> before_, after_;
};

/// A step of a recovered session's history: the whole document before and after it (JSON text, as
/// ui/undo_history.h keeps it). While `suspended` is true, redo and undo do nothing (the history
/// is being rebuilt around a model that already shows the right state).
class RestoreStateCommand : public QUndoCommand {
public:
    RestoreStateCommand(SketchDocument& doc, std::shared_ptr<const std::string> before, std::shared_ptr<const std::string> after,
                        const QString& text, const bool& suspended);
    void redo() override;
    void undo() override;

private:
    void apply(const std::string& state);

    SketchDocument& doc_;
    std::shared_ptr<const std::string> before_, after_;
    const bool& suspended_;
};


}  // namespace sculptline::ui
