// SketchDocument's 6-DOF input (ui/pose_input.h feeds it): strokes drawn in space by a tracked
// pointer become space curves through the same fitter as planar strokes (thesis ch. 4 §4.1 on 3D
// samples), or over-sketch a curve in space (thesis §4.2); a pointer stroke drawn while the plane is
// carried is a planar stroke on it; the carried plane moves as one undo step per grip.
#include "ui/sketch_document.h"

#include "manipulators/stroke_input.h"
#include "solvers/bspline/projection.h"
#include "solvers/editing/oversketch.h"
#include "solvers/geometry/plane_fit.h"
#include "solvers/stroke/stroke_fitter.h"
#include "ui/undo_commands.h"


#include <algorithm>
#include <cmath>
#include <limits>

namespace sculptline::ui {
namespace {

/// Of the stroke's length, the share over which a snapped end's displacement fades out: the snap
/// moves the end by up to kSpaceSnapDistance, and spread over this much of the stroke it bends the
/// path by a few degrees instead of putting a hook (a false corner) at its end.
constexpr double kSnapRamp = 0.15;

/// Largest distance of the points from their best-fit plane: the status line's measure of how far
/// from planar a space curve is.
double offPlane(const std::vector<Eigen::Vector3d>& pts)
{
    const solvers::PlaneFit plane = solvers::bestFitPlane(pts);
    double d = 0.0;
    for (const Eigen::Vector3d& p : pts) d = std::max(d, std::abs((p - plane.centroid).dot(plane.normal)));
    return d;
}

}  // namespace

std::optional<SketchDocument::SpaceSnap> SketchDocument::snapToCurve(const Eigen::Vector3d& world) const
{
    std::optional<SpaceSnap> best;
    for (const auto& [id, e] : model_.entities()) {
        if (e.kind != model::EntityKind::Curve || !e.world) continue;
        const solvers::CurveProjection<3> p = solvers::projectToCurve(*e.world, world);
        if (p.distance <= kSpaceSnapDistance && (!best || p.distance < best->distance)) best = SpaceSnap{id, p.point, p.distance};
    }
    return best;
}

void SketchDocument::addSpaceStroke(const std::vector<Eigen::Vector3d>& world, const std::vector<double>& times)
{
    feedback_->clear();
    lastStroke_ = {};
    lastStroke_.samples = static_cast<int>(world.size());
    if (strokeMode_ == StrokeMode::Oversketch) {
        oversketchInSpace(world);
        return;
    }
    std::vector<Eigen::Vector3d> pts = world;
    double length = 0.0;
    std::vector<double> arc(pts.size(), 0.0);
    for (size_t i = 1; i < pts.size(); ++i) arc[i] = length += (pts[i] - pts[i - 1]).norm();
    // A stroke that starts or ends within the snapping distance of a curve starts or ends on it
    // (the space counterpart of a planar stroke connecting two curves, seed 000 §3.1 case 2): the
    // end goes onto its nearest curve point, the displacement fading out along the stroke; the fit
    // interpolates the ends, so the curves meet to round-off.
    QStringList snapped;
    if (pts.size() >= 2 && length > 0.0) {
        for (const bool atEnd : {false, true}) {
            const Eigen::Vector3d end = atEnd ? pts.back() : pts.front();
            const std::optional<SpaceSnap> s = snapToCurve(end);
            if (!s) continue;
            const Eigen::Vector3d shift = s->point - end;
            const double ramp = kSnapRamp * length;
            for (size_t i = 0; i < pts.size(); ++i) {
                const double d = atEnd ? length - arc[i] : arc[i];
                if (d < ramp) pts[i] += shift * (1.0 - d / ramp);
            }
            (atEnd ? pts.back() : pts.front()) = s->point;
            snapped << tr("%1 on curve %2").arg(atEnd ? tr("end") : tr("start")).arg(s->curve);
        }
    }
    solvers::stroke::Stroke input;
    input.points = pts;
    input.times = times.size() == pts.size() ? times : std::vector<double>{};
    input.dimension = 3;
    try {
        const solvers::stroke::FitResult fit = solvers::stroke::fitStroke(input);
        model::requireCurveExtent(fit.curve);
        model::Entity curve;
        curve.kind = model::EntityKind::Curve;
        curve.local = fit.curve;  // no plane: world coordinates
        lastStroke_.fitted = true;
        lastStroke_.controlPoints = fit.curve.pointCount();
        lastStroke_.maxError = fit.maxError;
        std::vector<Eigen::Vector3d> dense;
        for (int i = 0; i <= 200; ++i) dense.push_back(fit.curve.evaluate(fit.curve.domainStart() + (fit.curve.domainEnd() - fit.curve.domainStart()) * i / 200));
        lastStroke_.message = tr("Space stroke of %1 samples fitted: %2 control points, %3 corners, max error %4 mm, "
                                 "%5 mm off its best plane%6%7")
                                  .arg(lastStroke_.samples)
                                  .arg(fit.curve.pointCount())
                                  .arg(fit.corners.size())
                                  .arg(fit.maxError, 0, 'f', 3)
                                  .arg(offPlane(dense), 0, 'f', 1)
                                  .arg(noteLeftOut(fit))
                                  .arg(snapped.isEmpty() ? QString() : tr("; %1").arg(snapped.join(tr(", "))));
        undo_.push(new AddEntitiesCommand(*this, {curve}, tr("Draw a space curve")));
        recognizedCurve_ = 0;  // no recognition in space: the shapes it knows are planar
    } catch (const std::exception& e) {
        lastStroke_.message = tr("Space stroke not used: %1").arg(QString::fromStdString(e.what()));
    }
    Q_EMIT strokeFinished();
}

void SketchDocument::oversketchInSpace(const std::vector<Eigen::Vector3d>& world)
{
    // The target: the curve nearest to the stroke (mean distance of its samples, world). A curve on
    // a plane stays on it: the stroke is projected onto the plane first (its local z dropped).
    model::EntityId target = 0;
    double best = std::numeric_limits<double>::infinity();
    for (const auto& [id, e] : model_.entities()) {
        if (e.kind != model::EntityKind::Curve || !e.world) continue;
        const solvers::CurveProjector<3> projector(*e.world);
        double sum = 0.0;
        for (const Eigen::Vector3d& p : world) sum += projector.project(p).distance;
        if (sum < best) {
            best = sum;
            target = id;
        }
    }
    const model::Entity* curve = model_.find(target);
    if (!curve || world.size() < 2) {
        lastStroke_.message = tr("Over-sketch: no curve to change");
        Q_EMIT strokeFinished();
        return;
    }
    std::vector<Eigen::Vector3d> stroke = world;
    if (const model::Entity* plane = model_.find(curve->plane())) {
        for (Eigen::Vector3d& p : stroke) {
            p = plane->frame.toLocal(p);
            p.z() = 0.0;
        }
    }
    applyOversketch(target, *curve->local, stroke, tr("Curve %1 over-sketched in space"));
}

void SketchDocument::addStrokeOnPlane(model::EntityId plane, const std::vector<Eigen::Vector3d>& world, const std::vector<double>& times)
{
    const model::Entity* e = model_.find(plane);
    if (!e || e->kind != model::EntityKind::Plane) {
        addSpaceStroke(world, times);
        return;
    }
    // The planar stroke path (applyStroke), as a mouse stroke on this plane arrives there: points in
    // the plane's frame with z = 0 (the pointer's positions projected along the normal), one time
    // per point; no rays (the pen touched the plane, nothing was seen through a camera).
    manipulators::FinishedStroke stroke;
    stroke.frame = e->frame;
    for (const Eigen::Vector3d& p : world) {
        Eigen::Vector3d local = e->frame.toLocal(p);
        local.z() = 0.0;
        stroke.points.push_back(local);
    }
    stroke.times = times.size() == world.size() ? times : std::vector<double>(world.size(), 0.0);
    stroke.rayOrigins.assign(world.size(), Eigen::Vector3d::Zero());  // counts the samples (lastStroke_.samples)
    feedback_->clear();
    strokeOnPlane_ = plane;
    oversketchTarget_ = 0;
    addStroke(stroke);
}

void SketchDocument::beginCarry(model::EntityId plane)
{
    const model::Entity* e = model_.find(plane);
    if (!e || e->kind != model::EntityKind::Plane) return;
    carried_ = plane;
    carriedFrom_ = e->frame;
    select(plane);
}

void SketchDocument::carryTo(const Eigen::Vector3d& origin, const Eigen::Quaterniond& rotation)
{
    const model::Entity* e = model_.find(carried_);
    if (!e) return;
    model::PlaneFrame frame = e->frame;
    frame.origin = origin;
    frame.rotation = rotation.normalized();
    model_.setPlaneFrame(carried_, frame);
}

void SketchDocument::endCarry()
{
    const model::Entity* e = model_.find(carried_);
    if (e) dragFinished(carried_, carriedFrom_, e->frame);
    carried_ = 0;
}

}  // namespace sculptline::ui
