// SketchDocument's incidence modes (seed 000 §3.1, issue 14 §3): Interpolation (a surface through the
// designer's curves) and Sculpting (curves drawn onto a surface, which follows them), and the
// L-curve's truncation picked by the designer. The surface is a model entity without a recipe whose
// curves lie on it (curve-on-surface constraints): the model's incidence step solves it
// (model/solver_registry.cpp), live from a kept factorization while a plane is dragged.
#include "ui/sketch_document.h"

#include "solvers/incidence/incidence_solve.h"
#include "solvers/incidence/spanning_sheet.h"
#include "ui/undo_commands.h"

#include <algorithm>
#include <optional>

namespace sculptline::ui {
namespace {

/// Samples per curve for the spanning sheet's plane and extent: enough that a closed rim's extent is
/// found to well under a percent of its size (the sheet has a 5 % margin).
constexpr int kSheetSamplesPerCurve = 64;
/// A pre-image shorter than this, relative to the surface's domain, is a point: the curve lies
/// beyond the surface's edge (every foot on the boundary) and cannot be put on it.
constexpr double kMinPreimageExtent = 1e-6;

/// The curve-on-surface constraint of `curve` on `shape` (entity `surface`), its pre-image found by
/// projection onto the shape as it is now. @throws std::exception when the curve projects to a point.
model::Constraint onSurface(const model::Entity& curve, model::EntityId surface, const solvers::Surface3d& shape)
{
    const solvers::Curve2d domain = solvers::incidence::projectedDomain(shape, *curve.world);
    Eigen::Vector2d lo = domain.points().front(), hi = lo;
    for (const Eigen::Vector2d& p : domain.points()) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const double size = std::max(shape.domainEnd(solvers::Direction::U) - shape.domainStart(solvers::Direction::U),
                                 shape.domainEnd(solvers::Direction::V) - shape.domainStart(solvers::Direction::V));
    if ((hi - lo).maxCoeff() <= kMinPreimageExtent * size)
        throw std::invalid_argument("curve " + std::to_string(curve.id) + " lies beyond the surface's edge: it projects onto one point of it");
    model::Constraint c;
    c.type = model::ConstraintType::CurveOnSurface;
    c.targets = {curve.id, surface};
    c.preimage = model::preimageCurve(domain);
    return c;
}

}  // namespace

void SketchDocument::setIncidenceK(model::EntityId surface, int k)
{
    const model::Entity* s = model_.find(surface);
    if (!s || s->kind != model::EntityKind::Surface || s->recipe || k < 0 || s->incidenceK == k) return;
    undo_.push(new SetIncidenceKCommand(*this, surface, s->incidenceK, k));
}

void SketchDocument::pickIncidenceCurve(model::EntityId curve)
{
    const model::Entity* e = model_.find(curve);
    if (!e || e->kind != model::EntityKind::Curve) return;
    const auto at = std::find(incidenceCurves_.begin(), incidenceCurves_.end(), curve);
    if (at != incidenceCurves_.end()) incidenceCurves_.erase(at);  // picked again: taken back
    else incidenceCurves_.push_back(curve);
    view_->setMarked(incidenceCurves_);
    setSurfaceMessage(incidenceCurves_.empty()
                          ? tr("Interpolation: click the curves the surface goes through, then Enter.")
                          : tr("Interpolation: %n curve(s) picked; click more, Enter builds the surface through them (fixed curves are met exactly).",
                               nullptr, static_cast<int>(incidenceCurves_.size())));
}

bool SketchDocument::buildIncidenceSurface()
{
    const std::vector<model::EntityId> curves = incidenceCurves_;
    cancelIncidenceCurves();
    return surfaceThroughCurves(curves) != 0;
}

void SketchDocument::cancelIncidenceCurves()
{
    incidenceCurves_.clear();
    view_->setMarked({});
}

model::EntityId SketchDocument::surfaceThroughCurves(const std::vector<model::EntityId>& curves)
{
    scheduler_->flush();
    std::vector<Eigen::Vector3d> samples;
    for (model::EntityId id : curves) {
        const model::Entity* c = model_.find(id);
        if (!c || c->kind != model::EntityKind::Curve || !c->world) {
            setSurfaceMessage(tr("No surface: entity %1 is not a curve.").arg(id));
            return 0;
        }
        const double t0 = c->world->domainStart(), t1 = c->world->domainEnd();
        for (int k = 0; k < kSheetSamplesPerCurve; ++k) samples.push_back(c->world->evaluate(t0 + (t1 - t0) * k / (kSheetSamplesPerCurve - 1)));
    }
    if (curves.empty()) {
        setSurfaceMessage(tr("Interpolation: pick the curves the surface goes through first."));
        return 0;
    }
    model::Entity sheet;
    sheet.kind = model::EntityKind::Surface;
    std::vector<model::Constraint> constraints;
    try {
        // A closed curve among them bounds the surface (the dome's rim, seed 000 Fig. 2): its
        // pre-image is the domain's boundary, and the others lie inside. Else a flat sheet spans all.
        const auto rim = std::find_if(curves.begin(), curves.end(), [this](model::EntityId id) { return model_.find(id)->world->isClosed(); });
        std::optional<solvers::Curve2d> rimDomain;
        if (rim != curves.end()) {
            solvers::incidence::BoundedSheet bounded = solvers::incidence::sheetBoundedBy(*model_.find(*rim)->world);
            sheet.surface = bounded.surface;
            rimDomain = bounded.rimDomain;
        } else {
            sheet.surface = solvers::incidence::spanningSheet(samples);
        }
        for (model::EntityId id : curves) {
            if (rim != curves.end() && id == *rim) {
                model::Constraint c;
                c.type = model::ConstraintType::CurveOnSurface;
                c.targets = {id, 0};
                c.preimage = model::preimageCurve(*rimDomain);
                constraints.push_back(std::move(c));
            } else {
                constraints.push_back(onSurface(*model_.find(id), 0, *sheet.surface));
            }
        }
    } catch (const std::exception& error) {
        setSurfaceMessage(tr("No surface through the curves: %1.").arg(QString::fromStdString(error.what())));
        return 0;
    }
    const QString text = tr("Surface through %n curve(s)", nullptr, static_cast<int>(curves.size()));
    undo_.beginMacro(text);
    undo_.push(new AddEntitiesCommand(*this, {sheet}, text));
    const model::EntityId surface = selection_;
    for (model::Constraint& c : constraints) {
        c.targets.back() = surface;
        undo_.push(new AddConstraintCommand(*this, c, tr("Curve %1 on surface %2").arg(c.targets.front()).arg(surface)));
    }
    undo_.endMacro();
    scheduler_->flush();
    select(surface);
    incidenceBase_ = surface;
    const model::Entity* made = model_.find(surface);
    if (!made) return 0;
    setSurfaceMessage(made->failed() ? tr("Surface %1 made but not solved through the curves: %2")
                                           .arg(surface)
                                           .arg(QString::fromStdString(made->buildError))
                                     : tr("Surface %1 %2; %3 mm from the curves. Draw more curves onto it, drag their planes, fix curves "
                                          "(Ctrl+Shift+F) to hold them exactly.")
                                           .arg(surface)
                                           .arg(QString::fromStdString(made->solveMessage))
                                           .arg(made->maxDeviation, 0, 'g', 3));
    return surface;
}

model::EntityId SketchDocument::putOnSurface(model::EntityId curveId, model::EntityId surfaceId, QString* reason)
{
    scheduler_->flush();
    const model::Entity* curve = model_.find(curveId);
    const model::Entity* surface = model_.find(surfaceId);
    auto fail = [&](const QString& why) -> model::EntityId {
        if (reason) *reason = why;
        return 0;
    };
    if (!curve || curve->kind != model::EntityKind::Curve || !curve->world) return fail(tr("entity %1 is not a curve").arg(curveId));
    if (!surface || surface->kind != model::EntityKind::Surface || !surface->surface) return fail(tr("entity %1 is not a surface").arg(surfaceId));
    if (surface->fixed) return fail(tr("surface %1 is fixed: free it (Ctrl+Shift+F) to let curves shape it").arg(surfaceId));
    if (surface->surface->isRational()) return fail(tr("surface %1 is rational; the incidence solve takes B-spline surfaces").arg(surfaceId));
    // A surface built from curves: its recipe would rebuild it from them. It becomes free-form,
    // shaped by the curves on it, its input curves among them.
    std::vector<model::EntityId> inputs;
    if (surface->recipe) {
        if (!model_.dependents(surfaceId).empty())
            return fail(tr("surface %1 has surfaces built on it (a sculpt): draw onto the last of them").arg(surfaceId));
        const std::vector<model::EntityId> curves = surface->curveInputs();
        for (size_t k = 0; k < curves.size(); ++k) {
            if (model::inputLiesOnSurface(surface->recipe->mode, static_cast<int>(k)) && curves[k] != curveId) inputs.push_back(curves[k]);
        }
    }
    std::vector<model::Constraint> constraints;
    try {
        for (model::EntityId id : inputs) constraints.push_back(onSurface(*model_.find(id), surfaceId, *surface->surface));
        constraints.push_back(onSurface(*curve, surfaceId, *surface->surface));
    } catch (const std::exception& error) {
        return fail(QString::fromStdString(error.what()));
    }
    model::EntityId target = surfaceId;
    if (surface->recipe) {
        model::Entity free;
        free.kind = model::EntityKind::Surface;
        // The same shape with room to bend (a fill of four cubics has four inner points).
        free.surface = solvers::incidence::refinedForIncidence(*surface->surface);
        undo_.push(new DeleteEntityCommand(*this, surfaceId));
        undo_.push(new AddEntitiesCommand(*this, {free}, tr("Make surface %1 free-form").arg(surfaceId)));
        target = selection_;
    }
    for (model::Constraint& c : constraints) {
        c.targets.back() = target;
        undo_.push(new AddConstraintCommand(*this, c, tr("Curve %1 on surface %2").arg(c.targets.front()).arg(target)));
    }
    scheduler_->flush();
    incidenceBase_ = target;
    return target;
}

}  // namespace sculptline::ui
