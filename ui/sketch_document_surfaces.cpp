// SketchDocument's surface modes (issue 6): picking the input curves of a surface, building it as
// one undo step, and extrusion by dragging a curve. The surface itself is a model entity with a
// recipe (model/surface_recipe.h): the model rebuilds it whenever one of its curves changes.
#include "ui/sketch_document.h"

#include "manipulators/stroke_input.h"
#include "ui/undo_commands.h"

#include <algorithm>

namespace sculptline::ui {
namespace {

/// Pointer travel (model units) below which an extrusion is not started: a click is not a drag.
constexpr double kMinExtrusion = 1e-3;

}  // namespace

void SketchDocument::setSurfaceMode(std::optional<model::Construction> mode)
{
    if (mode == surfaceMode_) return;
    surfaceMode_ = mode;
    surfaceInputs_.clear();
    gordonFirstFamily_ = -1;
    view_->setMarked({});
    setSurfaceMessage(QString());
}

void SketchDocument::setSurfaceMessage(const QString& message)
{
    surfaceMessage_ = message;
    Q_EMIT surfaceStateChanged();
}

void SketchDocument::pickSurfaceInput(model::EntityId curve)
{
    const model::Entity* e = model_.find(curve);
    if (!surfaceMode_ || !e || e->kind != model::EntityKind::Curve) return;
    if (!surfaceInputs_.empty() && surfaceInputs_.back() == curve) {
        surfaceInputs_.pop_back();  // picked twice: taken back
    } else if (std::find(surfaceInputs_.begin(), surfaceInputs_.end(), curve) != surfaceInputs_.end()) {
        setSurfaceMessage(tr("Curve %1 is already an input of this surface.").arg(curve));
        return;
    } else {
        surfaceInputs_.push_back(curve);
    }
    view_->setMarked(surfaceInputs_);
    const model::InputCount count = model::surfaceInputCount(*surfaceMode_);
    if (static_cast<int>(surfaceInputs_.size()) >= count.max && surfaceMode_ != model::Construction::Gordon) {
        buildSurface();
        return;
    }
    setSurfaceMessage(QString());
}

bool SketchDocument::buildSurface()
{
    if (!surfaceMode_) return false;
    if (surfaceMode_ == model::Construction::Gordon && gordonFirstFamily_ < 0) {
        // The first Enter closes the first family; the curves picked next are the other one.
        if (surfaceInputs_.size() < 2) {
            setSurfaceMessage(tr("Gordon: pick at least two curves of the first family before Enter."));
            return false;
        }
        gordonFirstFamily_ = static_cast<int>(surfaceInputs_.size());
        setSurfaceMessage(tr("Gordon: %1 curves in the first family; now click the curves that cross them, then Enter.")
                              .arg(gordonFirstFamily_));
        return false;
    }
    const std::vector<model::EntityId> inputs = surfaceInputs_;
    const int firstFamily = gordonFirstFamily_;
    surfaceInputs_.clear();
    gordonFirstFamily_ = -1;
    view_->setMarked({});
    scheduler_->flush();
    if (surfaceMode_ == model::Construction::Network) {
        try {
            undo_.push(new AddEntitiesCommand(*this, {model_.makeMesh(inputs)}, tr("Mesh a curve network loop")));
        } catch (const std::exception& error) {
            setSurfaceMessage(tr("No mesh: %1").arg(QString::fromStdString(error.what())));
            return false;
        }
        const model::Entity* made = model_.find(selection_);
        setSurfaceMessage(tr("Mesh %1 made: %2 triangles.").arg(selection_).arg(made ? made->mesh->triangles.size() : 0));
        return true;
    }
    model::SurfaceRecipe recipe;
    recipe.mode = *surfaceMode_;
    const QString modeName = QString::fromLatin1(model::constructionName(*surfaceMode_));
    recipe.uCurves = firstFamily;
    if ((model::describe(*surfaceMode_).options & model::kTangentsOption) && fillG1_) recipe.tangents = adjacentSurfaces(inputs);
    try {
        model::Entity surface = model_.makeSurface(inputs, recipe);
        undo_.push(new AddEntitiesCommand(*this, {surface}, tr("Make %1 surface").arg(modeName)));
    } catch (const std::exception& error) {
        setSurfaceMessage(tr("No %1 surface: %2").arg(modeName, QString::fromStdString(error.what())));
        return false;
    }
    const model::Entity* made = model_.find(selection_);
    QString text = tr("Surface %1 made").arg(selection_);
    if (made && made->maxDeviation >= 0.0) text += tr(" (within %1 of its construction)").arg(made->maxDeviation, 0, 'g', 3);
    if (made && made->maxTangentAngle >= 0.0) {
        text += tr(", tangent to surface(s) along %1 boundaries within %2 degrees").arg(made->recipe->tangents.size()).arg(made->maxTangentAngle, 0, 'g', 2);
    }
    setSurfaceMessage(text + QStringLiteral("."));
    return true;
}

std::vector<model::SurfaceRecipe::Tangent> SketchDocument::adjacentSurfaces(const std::vector<model::EntityId>& boundaries) const
{
    // A boundary that a surface was built through (a loft's section, a revolve's profile, another
    // fill's boundary) lies on that surface: the fill is made G1 to it there (the first such).
    std::vector<model::SurfaceRecipe::Tangent> out;
    for (size_t k = 0; k < boundaries.size(); ++k) {
        for (const auto& [id, e] : model_.entities()) {
            if (e.kind != model::EntityKind::Surface || !e.recipe) continue;
            // Every curve input lies on its surface but a revolve's axis and a sweep's path.
            const std::vector<model::EntityId> curves = e.curveInputs();
            const auto at = std::find(curves.begin(), curves.end(), boundaries[k]);
            if (at == curves.end() || !model::inputLiesOnSurface(e.recipe->mode, static_cast<int>(at - curves.begin()))) continue;
            out.push_back({static_cast<int>(k), id});
            break;
        }
    }
    return out;
}

void SketchDocument::cancelSurface()
{
    surfaceInputs_.clear();
    gordonFirstFamily_ = -1;
    view_->setMarked({});
    setSurfaceMessage(QString());
}

std::optional<model::PlaneFrame> SketchDocument::grabExtrusion(const manipulators::StrokeHit& hit)
{
    const model::Entity* curve = model_.find(hit.curve);
    if (!curve || curve->kind != model::EntityKind::Curve) return std::nullopt;
    scheduler_->flush();
    // The drag plane contains the profile plane's normal and faces the viewer as much as it can:
    // pulling towards or away from the plane and sideways both read naturally on screen.
    const Eigen::Vector3d n = curve->plane() != 0 ? model_.find(curve->plane())->frame.normal() : Eigen::Vector3d::UnitZ();
    Eigen::Vector3d facing = -hit.view - (-hit.view).dot(n) * n;
    if (facing.norm() < 1e-6) facing = n.unitOrthogonal();  // looking along n: any plane containing it
    extrudeFrame_ = model::PlaneFrame::fromNormal(hit.point, facing.normalized(), 1.0, n);
    extrudeProfile_ = curve->id;
    extrusion_ = 0;
    select(curve->id);
    return extrudeFrame_;
}

void SketchDocument::extrudeTo(const Eigen::Vector3d& local)
{
    const model::Entity* profile = model_.find(extrudeProfile_);
    if (!profile) return;
    const Eigen::Vector3d world = extrudeFrame_.rotation * local;
    if (extrusion_ == 0 && world.norm() < kMinExtrusion) return;
    model::SurfaceRecipe recipe;
    recipe.mode = model::Construction::Extrude;
    // Stored in the profile plane's frame so that the extrusion turns with the plane.
    recipe.direction = profile->plane() != 0 ? Eigen::Vector3d(model_.find(profile->plane())->frame.rotation.conjugate() * world) : world;
    if (extrusion_ != 0) {
        model_.setSurfaceRecipe(extrusion_, recipe);  // rebuilt once per frame by the scheduler
        return;
    }
    try {
        // Shown live in the model, outside the undo stack, until the release makes it one step.
        extrusion_ = model_.addSurface({extrudeProfile_}, recipe);
    } catch (const std::exception& error) {
        setSurfaceMessage(tr("No extrusion: %1").arg(QString::fromStdString(error.what())));
    }
}

void SketchDocument::releaseExtrusion()
{
    scheduler_->flush();
    const model::EntityId id = extrusion_;
    extrusion_ = 0;
    extrudeProfile_ = 0;
    const model::Entity* e = model_.find(id);
    if (!e) return;
    std::vector<model::Entity> removed = model_.remove(id).entities;
    undo_.push(new AddEntitiesCommand(*this, removed, tr("Extrude curve %1").arg(removed.front().inputs.front())));
    setSurfaceMessage(tr("Surface %1 made.").arg(id));
}

}  // namespace sculptline::ui
