// SketchDocument's pen input: strokes (sketch, auxiliary planes, over-sketch, lift, recognition
// choices) and pulling a curve point. Split from sketch_document.cpp, which keeps the document's
// life cycle, selection and the Coin side's bookkeeping.
#include "ui/sketch_document.h"

#include "manipulators/curve_pull.h"
#include "manipulators/stroke_input.h"
#include "model/auxiliary_plane.h"
#include "solvers/bspline/projection.h"
#include "solvers/editing/lift.h"
#include "solvers/editing/oversketch.h"
#include "solvers/stroke/conditioning.h"
#include "solvers/stroke/shape_recognizer.h"
#include "solvers/stroke/stroke_fitter.h"
#include "ui/undo_commands.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace sculptline::ui {
namespace {

/// Edge limits of an auxiliary plane, model units: big enough to grab, never a sky-sized sheet.
constexpr double kMinAuxiliarySize = 40.0;
constexpr double kMaxAuxiliarySize = 1000.0;
/// A recognition candidate smaller than this fraction of the freeform curve of its stroke is not
/// used: a regularized shape keeps the size of what was drawn (a circle, a line across it), and one
/// that collapses it (the line between the ends of a loop) is not what the stroke showed.
constexpr double kMinCandidateFraction = 0.05;
/// A stroke on a plane whose pointer rays meet it more grazingly than this (|cos|, about 85° from
/// face-on) is not used: the pointer's jitter would throw its points across the plane.
constexpr double kMinStrokeFacing = 0.09;
/// A stroke reaching farther from its plane's centre than this many half-edges is not used: it
/// would lie far outside the square the designer sees, behind other geometry.
constexpr double kMaxStrokeReach = 4.0;
constexpr double kDegreesPerRadian = 57.29577951308232;

/// A pen's light-pressure hooks at the stroke's ends left out, by the fitter's rule
/// (solvers::stroke::withoutPressureHooks), from a stroke that over-sketch, lift and re-sketch take
/// as drawn rather than through the fitter. The rays go with the points where there is one point
/// per ray (every ray met the plane), else they are kept whole. Returns how many samples were left
/// out (0 for a mouse: no pressure).
int leaveOutPressureHooks(manipulators::FinishedStroke& s)
{
    const size_t n = s.points.size();
    if (s.pressure.size() != n) return 0;
    solvers::stroke::Stroke drawn;
    drawn.points = s.points;
    drawn.pressure = s.pressure;
    const auto [first, last] = solvers::stroke::withoutPressureHooks(drawn);
    const size_t kept = static_cast<size_t>(last - first + 1);
    if (kept == n) return 0;
    const auto trim = [&](auto& v) {
        if (v.size() != n) return;
        v.erase(v.begin() + last + 1, v.end());
        v.erase(v.begin(), v.begin() + first);
    };
    trim(s.points);
    trim(s.times);
    trim(s.pressure);
    trim(s.rayOrigins);
    trim(s.rayDirections);
    trim(s.rayTimes);
    trim(s.rayPressure);
    trim(s.pixelRays);
    return static_cast<int>(n - kept);
}

}  // namespace

std::optional<model::PlaneFrame> SketchDocument::strokePlane(const manipulators::StrokeHit& start)
{
    feedback_->clear();
    strokeOnPlane_ = 0;
    oversketchTarget_ = 0;
    // Sculpt mode's Handle, Block and Distance tools take clicks on the surface, no strokes.
    if (strokeMode_ == StrokeMode::Sculpt && sculptTool_ == SculptTool::Resketch) return resketchPlane(start);
    if (strokeMode_ == StrokeMode::Sculpt && sculptTool_ != SculptTool::Target && sculptTool_ != SculptTool::Bound) return std::nullopt;
    if (strokeMode_ == StrokeMode::Lift) {
        // Drawn in the view plane through the starting curve point (seed 004 lifts an image-plane
        // stroke); the depths come from the curve points at its ends.
        if (!model_.find(start.curve)) return std::nullopt;
        return model::PlaneFrame::fromNormal(start.point, -start.view, kMinAuxiliarySize);
    }
    if (strokeMode_ == StrokeMode::Oversketch) {
        // Over the curve the pen went down on, in its plane; else over the active plane's curves.
        const model::Entity* curve = model_.find(start.curve);
        const model::Entity* plane = model_.find(curve && curve->plane() != 0 ? curve->plane() : activePlane());
        if (!plane) return std::nullopt;
        if (curve && curve->plane() == plane->id) oversketchTarget_ = curve->id;
        strokeOnPlane_ = plane->id;
        return plane->frame;
    }
    // Seed 000 §3.1, case 1: from a curve into the air, on the plane along its tangent there.
    if (const std::optional<model::CurveFrameAt> at = curveFrame(start)) {
        if (auto plane = model::planeAlongTangent(at->point, at->tangent, start.view, kMinAuxiliarySize)) return plane;
    }
    const model::Entity* plane = model_.find(activePlane());
    if (!plane) return std::nullopt;
    strokeOnPlane_ = plane->id;
    return plane->frame;
}

std::optional<model::CurveFrameAt> SketchDocument::curveFrame(const manipulators::StrokeHit& hit) const
{
    const model::Entity* curve = model_.find(hit.curve);
    if (!curve || curve->kind != model::EntityKind::Curve || !curve->world) return std::nullopt;
    // A planar curve's binormal is its plane's normal; a straight one has none of its own.
    const model::Entity* plane = model_.find(curve->plane());
    const Eigen::Vector3d fallback = plane ? plane->frame.normal() : -hit.view;
    return model::curveFrameNear(*curve->world, hit.point, fallback);
}

void SketchDocument::addStroke(const manipulators::FinishedStroke& stroke)
{
    const int before = undo_.index();
    applyStroke(stroke);
    strokeIndex_ = undo_.index() > before ? undo_.index() : -1;
}

QString SketchDocument::noteHooks(int hooks)
{
    lastStroke_.dropped = hooks;
    return hooks > 0 ? tr("; %n sample(s) left out as a light-pressure hook", nullptr, hooks) : QString();
}

QString SketchDocument::noteLeftOut(const solvers::stroke::FitResult& fit)
{
    lastStroke_.dropped = static_cast<int>(fit.dropped.size());
    lastStroke_.outliers = static_cast<int>(fit.outliers.size());
    const int others = lastStroke_.dropped - lastStroke_.outliers;
    QString note;
    if (lastStroke_.dropped > 0) {
        if (others == 0)
            note = tr("; %n sample(s) left out as noise beyond the tolerance", nullptr, lastStroke_.outliers);
        else if (lastStroke_.outliers == 0)
            note = tr("; %n sample(s) left out as a hook or overshoot", nullptr, others);
        else
            note = tr("; %1 samples left out (%2 as a hook or overshoot, %3 as noise beyond the tolerance)")
                       .arg(lastStroke_.dropped)
                       .arg(others)
                       .arg(lastStroke_.outliers);
    }
    // The fitter keeps every sample within the tolerance; where no curve it tried also stayed near
    // the stroke between two samples, it keeps the one that strays least, and the designer is told
    // how far and where, as the share of the drawing's samples before it (a loop's closing gap, a
    // sharp turn between sparse samples).
    lastStroke_.stray = fit.stray.excess > 1.0 ? fit.stray.distance : 0.0;
    if (lastStroke_.stray > 0.0) {
        const int along = lastStroke_.samples > 1 && fit.stray.after >= 0
                              ? static_cast<int>(std::lround(100.0 * fit.stray.after / (lastStroke_.samples - 1)))
                              : -1;
        note +=
            along >= 0
                ? tr("; %1 % of the way along the stroke, between two samples, the curve strays %2 mm from it")
                      .arg(std::min(along, 100))
                      .arg(lastStroke_.stray, 0, 'f', 2)
                : tr("; between two samples the curve strays %1 mm from the stroke").arg(lastStroke_.stray, 0, 'f', 2);
    }
    return note;
}

QString SketchDocument::farFromSight(const manipulators::FinishedStroke& stroke) const
{
    // Only strokes on an existing plane: an auxiliary plane is made to face the stroke.
    const model::Entity* plane = model_.find(strokeOnPlane_);
    if (!plane) return {};
    // Where the plane is seen nearly edge-on, a pixel of the hand spans metres of the plane: the
    // curve would land far behind everything, out of sight.
    double facing = 1.0;
    for (const Eigen::Vector3d& d : stroke.rayDirections) facing = std::min(facing, std::abs(d.dot(plane->frame.normal())));
    if (facing < kMinStrokeFacing) {
        return tr("plane %1 is seen almost edge-on there (%2° from face-on); turn the view (middle-drag) or add a plane facing it (Ctrl+P)")
            .arg(plane->id)
            .arg(std::acos(facing) * kDegreesPerRadian, 0, 'f', 0);
    }
    double reach = 0.0;
    for (const Eigen::Vector3d& p : stroke.points) reach = std::max(reach, p.head<2>().cwiseAbs().maxCoeff());
    if (reach > kMaxStrokeReach * plane->frame.size / 2) {
        return tr("it would land %1 mm from the centre of plane %2, far outside its %3 mm square; draw over the plane, or add one where "
                  "you draw (Ctrl+P)")
            .arg(reach, 0, 'f', 0)
            .arg(plane->id)
            .arg(plane->frame.size, 0, 'f', 0);
    }
    return {};
}

void SketchDocument::forgetStroke()
{
    feedback_->clear();
    feedbackPlane_ = 0;
    lastStroke_ = {};
    freeformFit_.reset();
    regularizedFit_.reset();
    lastFit_.reset();
    recognition_.reset();
    candidateInUse_ = -1;
    recognizedCurve_ = 0;
    strokeIndex_ = -1;
    Q_EMIT strokeForgotten();
}

void SketchDocument::applyStroke(const manipulators::FinishedStroke& finished)
{
    const bool oversketch = strokeMode_ == StrokeMode::Oversketch, lift = strokeMode_ == StrokeMode::Lift;
    const bool resketch = strokeMode_ == StrokeMode::Sculpt && sculptTool_ == SculptTool::Resketch;
    if (oversketch || lift || resketch) {
        // These take the stroke as drawn: a pen's light-pressure hooks are left out here, as the
        // fitter leaves them out of a sketched stroke (noteHooks tells the designer).
        manipulators::FinishedStroke trimmed = finished;
        const int hooks = leaveOutPressureHooks(trimmed);
        if (oversketch)
            oversketchStroke(trimmed, hooks);
        else if (lift)
            liftStroke(trimmed, hooks);
        else
            resketchStroke(trimmed, hooks);
        return;
    }
    manipulators::FinishedStroke stroke = finished;
    lastStroke_ = {};
    lastStroke_.samples = static_cast<int>(stroke.rayOrigins.size());
    // Case 2: a stroke connecting two curves lies on the plane through both points that contains
    // the first curve's binormal.
    const std::optional<model::CurveFrameAt> from = curveFrame(stroke.start);
    const std::optional<model::CurveFrameAt> to = curveFrame(stroke.end);
    if (from && to && stroke.end.curve != stroke.start.curve) {
        if (auto plane = model::planeThroughPoints(from->point, to->point, from->binormal, stroke.start.view, kMinAuxiliarySize)) {
            manipulators::reproject(stroke, *plane);
            strokeOnPlane_ = 0;
            // The stroke connects the two curves: its ends go exactly onto them (the picked points
            // lie on the curves' tessellation, a fraction of a millimetre off), and the fit
            // interpolates its ends, so the curves meet to round-off (a rail-rotation profile, a
            // fill boundary).
            if (stroke.points.size() >= 2) {
                stroke.points.front() = plane->toLocal(from->point);
                stroke.points.back() = plane->toLocal(to->point);
                stroke.points.front().z() = stroke.points.back().z() = 0.0;
            }
        }
    }
    if (stroke.points.size() < 2) return;
    if (strokeMode_ == StrokeMode::Sculpt && sculptTool_ == SculptTool::Bound) {
        std::vector<Eigen::Vector3d> world;
        for (const Eigen::Vector3d& p : stroke.points) world.push_back(stroke.frame.toWorld(p));
        setSculptBound(world);
        return;
    }
    // (A bound is drawn over the surface, which it is projected onto: the plane is only the pen's
    // support there, however far from its square.)
    if (const QString why = farFromSight(stroke); !why.isEmpty()) {
        lastStroke_.message = tr("Stroke not used: %1").arg(why);
        Q_EMIT strokeFinished();
        return;
    }
    std::vector<model::Entity> added;
    model::EntityId plane = strokeOnPlane_;
    if (plane == 0) {
        // An auxiliary plane made for this stroke, centred on it and large enough to show it
        // whole. Centred, not at the curve point: its dragger would sit on the curve's end and take
        // the press of the next stroke started there.
        Eigen::Vector3d lo = stroke.points.front(), hi = lo;
        for (const Eigen::Vector3d& p : stroke.points) {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
        const Eigen::Vector3d centre = 0.5 * (lo + hi);
        for (Eigen::Vector3d& p : stroke.points) p -= centre;
        model::Entity aux;
        aux.kind = model::EntityKind::Plane;
        aux.frame = stroke.frame;
        aux.frame.origin = stroke.frame.toWorld(centre);
        aux.frame.size = std::clamp(1.2 * (hi - lo).head<2>().maxCoeff(), kMinAuxiliarySize, kMaxAuxiliarySize);
        added.push_back(aux);
        plane = kPreviousEntity;
    }
    solvers::stroke::Stroke input;
    input.points = stroke.points;
    input.times = stroke.times;
    // A tablet pen's pressure: the fitter trims the light-pressure hooks at either end.
    if (stroke.pressure.size() == stroke.points.size()) input.pressure = stroke.pressure;
    input.dimension = 2;
    try {
        // The stroke issue's fitter (solvers/stroke): conditioning, corners, dynamic sampling and
        // least squares, in the plane's local frame and model units.
        // The fit the recognizer reads (a self-crossing stroke refitted open, a nearly closed
        // loop refitted closed: solvers/stroke recognizeStroke, tuned on real pen data).
        // The pointer's samples are whole pixels: the tolerance is never below one pixel's
        // footprint on the plane (FitOptions::resolution), or the curve would follow the staircase.
        solvers::stroke::FitOptions fitOptions;
        fitOptions.resolution = manipulators::pixelFootprint(stroke);
        const auto fitStart = std::chrono::steady_clock::now();
        const solvers::stroke::FitResult fit = solvers::stroke::recognizeStroke(input, fitOptions).fit;
        lastStroke_.fitMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - fitStart).count();
        model::requireCurveExtent(fit.curve);
        model::Entity curve;
        curve.kind = model::EntityKind::Curve;
        curve.inputs = {plane};
        curve.local = fit.curve;
        added.push_back(curve);
        lastStroke_.fitted = true;
        lastStroke_.controlPoints = fit.curve.pointCount();
        lastStroke_.maxError = fit.maxError;
        lastStroke_.tolerance = fit.tolerance;
        lastStroke_.pixel = fitOptions.resolution;
        lastStroke_.message = tr("Stroke of %1 samples fitted: degree %2, %3 control points, max error %4 mm "
                                 "(tolerance %5 mm)%6%7")
                                  .arg(lastStroke_.samples)
                                  .arg(fit.curve.degree())
                                  .arg(lastStroke_.controlPoints)
                                  .arg(fit.maxError, 0, 'f', 3)
                                  .arg(fit.tolerance, 0, 'f', 3)
                                  .arg(noteLeftOut(fit))
                                  .arg(added.size() > 1 ? tr(", on a new auxiliary plane") : QString());
        recognize(fit);
        if (!lastStroke_.habit.isEmpty() && regularizedFit_) {
            // A habit decided the shape: the designer chose it for a stroke like this one before, so
            // the curve is made as that shape at once (the freeform fit stays one click away).
            try {
                model::requireCurveExtent(*regularizedFit_, std::max(model::kMinCurveExtent, kMinCandidateFraction * model::curveExtent(fit.curve)));
                added.back().local = *regularizedFit_;
                candidateInUse_ = 0;
                lastStroke_.controlPoints = regularizedFit_->pointCount();
                lastStroke_.message += tr("; made a %1 by your habit").arg(lastStroke_.recognized);
            } catch (const std::exception&) {
                // Too small a shape to use: the freeform fit stays, the dock still offers the shape.
            }
        }
        // Sampling points and corners where the stroke was drawn (indices into the raw samples),
        // in the plane's frame so that they follow the plane.
        const model::PlaneFrame& drawn = added.size() > 1 ? added.front().frame : stroke.frame;
        std::vector<Eigen::Vector3d> samples, corners;
        for (int i : fit.samples) samples.push_back(stroke.points[static_cast<size_t>(i)]);
        for (int i : fit.corners) corners.push_back(stroke.points[static_cast<size_t>(i)]);
        feedback_->show(drawn, samples, corners);
        const bool sculpt = strokeMode_ == StrokeMode::Sculpt && model_.find(sculptBase_);
        const QString text = sculpt ? tr("Sculpt surface %1 onto a target curve").arg(sculptBase_)
                             : added.size() > 1 ? tr("Sketch curve on an auxiliary plane")
                                                : tr("Sketch curve on plane %1").arg(plane);
        if (sculpt) {
            // Thesis §5.2.3, ch. 6: the curve is a target; the base surface is deformed onto it, by
            // a sculpt that follows the curve (and its plane's dragger) from now on — the same
            // sculpt as the targets before it, so that all are met together.
            sculptWith(std::move(added), {}, text);
            const model::Entity* made = model_.find(selection_);  // the sculpt
            lastStroke_.message += made && made->failed() ? tr("; sculpt not solved: %1").arg(QString::fromStdString(made->buildError))
                                   : made && !made->solveMessage.empty()
                                       ? tr("; surface %1 sculpted: %2").arg(selection_).arg(QString::fromStdString(made->solveMessage))
                                       : tr("; surface %1 sculpted onto it (deviation %2 mm at the key points)")
                                             .arg(selection_)
                                             .arg(made ? made->maxDeviation : 0.0, 0, 'g', 3);
        } else if (strokeMode_ == StrokeMode::Incidence && model_.find(incidenceBase_)) {
            // Seed 000 §3.1, Sculpting: the curve is drawn as on any plane, and the surface is
            // solved to pass through it from now on (its plane's drag and over-sketches included).
            const model::EntityId base = incidenceBase_;
            undo_.beginMacro(tr("Draw a curve onto surface %1").arg(base));
            undo_.push(new AddEntitiesCommand(*this, std::move(added), text));
            const model::EntityId drawnCurve = selection_;
            QString why;
            const model::EntityId on = putOnSurface(drawnCurve, base, &why);
            undo_.endMacro();
            select(drawnCurve);
            const model::Entity* s = model_.find(on);
            lastStroke_.message += !s ? tr("; not put on surface %1: %2").arg(base).arg(why)
                                   : s->failed() ? tr("; surface %1 not solved through it: %2").arg(on).arg(QString::fromStdString(s->buildError))
                                                 : tr("; surface %1%2 %3, %4 mm from its curves")
                                                       .arg(on)
                                                       .arg(on != base ? tr(" (surface %1 made free-form)").arg(base) : QString())
                                                       .arg(QString::fromStdString(s->solveMessage))
                                                       .arg(s->maxDeviation, 0, 'g', 3);
        } else {
            undo_.push(new AddEntitiesCommand(*this, std::move(added), text));
        }
        // The command selects what it added last: the curve, or the sculpt made from it.
        const model::Entity* last = model_.find(selection_);
        recognizedCurve_ = selection_;
        if (sculpt && last) {
            // The sculpt's newest target curve: the last curve among its inputs.
            for (model::EntityId id : last->inputs) {
                const model::Entity* in = model_.find(id);
                if (in && in->kind == model::EntityKind::Curve) recognizedCurve_ = id;
            }
        }
        const model::Entity* made = model_.find(recognizedCurve_);
        feedbackPlane_ = made ? made->plane() : 0;
    } catch (const std::exception& e) {
        // A click or a stroke too short to have a shape: nothing to add, say why.
        lastStroke_.message = tr("Stroke not used: %1").arg(QString::fromStdString(e.what()));
    }
    Q_EMIT strokeFinished();
}

void SketchDocument::recognize(const solvers::stroke::FitResult& fit)
{
    freeformFit_ = fit.curve;
    regularizedFit_.reset();
    recognition_.reset();
    lastFit_ = fit;
    candidateInUse_ = -1;
    recognizedCurve_ = 0;
    habitFromLastStroke_ = false;
    try {
        // The recognizer of the stroke issue; the freeform fit stays the default curve, the
        // regularized primitive is one click away (RecognitionDock), and so is every other candidate.
        // The designer's habits re-rank the candidates first (a similar stroke corrected before).
        solvers::stroke::Recognition r = solvers::stroke::recognizeShape(fit);
        recognizerKind_ = r.kind;
        userModel_.applyHabits(r, fit);
        if (r.kind != recognizerKind_) {
            lastStroke_.habit = tr("Your habit decided: %1 (you made a stroke like this one a %1 before; "
                                   "the recognizer alone picked %2)")
                                    .arg(QString::fromLatin1(solvers::stroke::shapeName(r.kind)),
                                         QString::fromLatin1(solvers::stroke::shapeName(recognizerKind_)));
        }
        recognition_ = r;
        lastStroke_.recognized = QString::fromLatin1(solvers::stroke::shapeName(r.kind));
        for (const solvers::stroke::ShapeCandidate& c : r.candidates) {
            lastStroke_.candidates.emplace_back(QString::fromLatin1(solvers::stroke::shapeName(c.kind)), c.score);
        }
        if (r.kind != solvers::stroke::ShapeKind::Freeform) regularizedFit_ = r.regularized;
    } catch (const std::exception& e) {
        lastStroke_.recognized.clear();
        lastStroke_.message += tr(" (not recognized: %1)").arg(QString::fromStdString(e.what()));
    }
}

bool SketchDocument::recognitionChoiceAvailable() const
{
    return recognizedCurve_ != 0 && model_.find(recognizedCurve_) && freeformFit_ && regularizedFit_;
}

void SketchDocument::chooseRecognized(bool regularized)
{
    if (!recognitionChoiceAvailable()) return;
    const bool wasShape = candidateInUse_ >= 0;
    candidateInUse_ = regularized ? 0 : -1;
    if (!replaceRecognizedCurve(regularized ? *regularizedFit_ : *freeformFit_)) return;
    // The offered shape confirms (replacing a correction of this stroke); the freeform fit instead
    // of a shape in use is a correction.
    if (regularized) learnChoice(recognition_->kind);
    else if (wasShape) learnChoice(solvers::stroke::ShapeKind::Freeform);
}

bool SketchDocument::replaceRecognizedCurve(const solvers::Curve3d& target)
{
    const model::Entity* curve = model_.find(recognizedCurve_);
    if (curve->local->points() == target.points() && curve->local->knots() == target.knots()) return true;
    try {
        // A candidate must keep the stroke's size: the line through the ends of a stroke drawn as
        // a loop is a point, which nobody asked for and no solver can edit.
        const double stroke = freeformFit_ ? model::curveExtent(*freeformFit_) : 0.0;
        model::requireCurveExtent(target, std::max(model::kMinCurveExtent, kMinCandidateFraction * stroke));
    } catch (const std::exception& e) {
        lastStroke_.message = tr("Shape not used: %1").arg(QString::fromStdString(e.what()));
        Q_EMIT strokeFinished();
        return false;
    }
    undo_.push(new ReplaceCurveCommand(*this, recognizedCurve_, *curve->local, target));
    Q_EMIT strokeFinished();
    return true;
}

void SketchDocument::chooseCandidate(int index)
{
    const model::Entity* curve = model_.find(recognizedCurve_);
    if (!curve || !recognition_ || !lastFit_ || index < 0 || index >= static_cast<int>(recognition_->candidates.size())) return;
    const solvers::Curve3d target =
        solvers::stroke::regularizeAs(*recognition_, *lastFit_, recognition_->candidates[static_cast<size_t>(index)].kind);
    candidateInUse_ = index;
    lastStroke_.message = tr("Curve %1 is now the %2").arg(recognizedCurve_).arg(lastStroke_.candidates[static_cast<size_t>(index)].first);
    if (replaceRecognizedCurve(target)) learnChoice(recognition_->candidates[static_cast<size_t>(index)].kind);
}

void SketchDocument::chooseNextCandidate()
{
    if (!recognition_ || recognition_->candidates.empty()) return;
    chooseCandidate((candidateInUse_ + 1) % static_cast<int>(recognition_->candidates.size()));
}

void SketchDocument::oversketchStroke(const manipulators::FinishedStroke& stroke, int hooks)
{
    lastStroke_ = {};
    lastStroke_.samples = static_cast<int>(stroke.points.size());
    // The target: the curve the stroke started on, else the plane's curve nearest to the stroke
    // (mean distance of its samples, plane-local).
    model::EntityId target = oversketchTarget_;
    if (target == 0) {
        double best = std::numeric_limits<double>::infinity();
        for (model::EntityId id : model_.dependents(strokeOnPlane_)) {
            const solvers::CurveProjector<3> projector(*model_.find(id)->local);
            double sum = 0.0;
            for (const Eigen::Vector3d& p : stroke.points) sum += projector.project(p).distance;
            if (sum < best) {
                best = sum;
                target = id;
            }
        }
    }
    const model::Entity* curve = model_.find(target);
    if (!curve || stroke.points.size() < 2) {
        lastStroke_.message = tr("Over-sketch: no curve on plane %1 to change").arg(strokeOnPlane_);
        Q_EMIT strokeFinished();
        return;
    }
    applyOversketch(target, *curve->local, stroke.points, tr("Curve %1 over-sketched"),
                    manipulators::pixelFootprint(stroke), hooks);
}

void SketchDocument::liftStroke(const manipulators::FinishedStroke& stroke, int hooks)
{
    lastStroke_ = {};
    lastStroke_.samples = static_cast<int>(stroke.points.size());
    const std::optional<model::CurveFrameAt> from = curveFrame(stroke.start);
    const std::optional<model::CurveFrameAt> to = curveFrame(stroke.end);
    if (!from || !to || stroke.points.size() < 2) {
        lastStroke_.message = tr("Lift: start and end the stroke on curves");
        Q_EMIT strokeFinished();
        return;
    }
    // The stroke in the view plane's frame; its ends pinned to the curve points' footprints, whose
    // heights above the view plane are the depth range of the lift.
    const model::PlaneFrame& frame = stroke.frame;
    std::vector<Eigen::Vector2d> flat;
    for (const Eigen::Vector3d& p : stroke.points) flat.push_back(p.head<2>());
    const Eigen::Vector3d a = frame.toLocal(from->point), b = frame.toLocal(to->point);
    flat.front() = a.head<2>();
    flat.back() = b.head<2>();
    solvers::editing::ViewFrame view;
    view.origin = frame.origin;
    view.right = frame.xAxis();
    view.up = frame.rotation * Eigen::Vector3d::UnitY();
    view.depth = frame.normal();
    try {
        const solvers::editing::LiftResult lifted = solvers::editing::liftStroke(flat, a.z(), b.z(), {}, view);
        model::requireCurveExtent(lifted.curve);
        model::Entity curve;
        curve.kind = model::EntityKind::Curve;
        curve.local = lifted.curve;
        lastStroke_.fitted = true;
        lastStroke_.controlPoints = lifted.curve.pointCount();
        lastStroke_.maxError = lifted.fitError;
        lastStroke_.message = tr("Lifted to a space curve: %1 control points, fit error %2 mm")
                                  .arg(lifted.curve.pointCount())
                                  .arg(lifted.fitError, 0, 'f', 3) +
                              noteHooks(hooks);
        undo_.push(new AddEntitiesCommand(*this, {curve}, tr("Lift a space curve")));
    } catch (const std::exception& e) {
        lastStroke_.message = tr("Lift not possible: %1").arg(QString::fromStdString(e.what()));
    }
    Q_EMIT strokeFinished();
}

std::optional<model::PlaneFrame> SketchDocument::grabCurve(const manipulators::StrokeHit& hit)
{
    const model::Entity* curve = model_.find(hit.curve);
    if (!curve || curve->kind != model::EntityKind::Curve || curve->plane() == 0) return std::nullopt;
    if (hit.shift) {
        const model::PlaneFrame& frame = model_.find(curve->plane())->frame;
        const double u = solvers::projectToCurve(*curve->local, frame.toLocal(hit.point)).u;
        // Shift+press pins the curve there: a position constraint kept by every later pull.
        model::Constraint pin;
        pin.type = model::ConstraintType::Position;
        pin.targets = {curve->id};
        pin.parameters = {u};
        undo_.push(new AddConstraintCommand(*this, std::move(pin), tr("Pin curve %1").arg(curve->id)));
        return std::nullopt;
    }
    // The binding (manipulators/curve_pull.h) has the model factor the curve's least-change solver
    // once, here; each pointer event is then one solve.
    std::string error;
    const std::optional<model::PlaneFrame> frame = pullBinding_->grab(hit, &error);
    if (!frame) {
        lastStroke_ = {};
        lastStroke_.message = tr("Curve %1 cannot be pulled: %2").arg(hit.curve).arg(QString::fromStdString(error));
        Q_EMIT strokeFinished();
        return std::nullopt;
    }
    select(hit.curve);
    return frame;
}

void SketchDocument::pullFinished(model::EntityId id, const solvers::Curve3d& before, const std::string& message)
{
    view_->refineSurfaces();
    const model::Entity* curve = model_.find(id);
    if (curve && curve->local->points() != before.points()) undo_.push(new ReplaceCurveCommand(*this, id, before, *curve->local));
    if (!message.empty()) {
        // Too few free points for the constraints, or contradictory ones (thesis §7.5): say so.
        lastStroke_ = {};
        lastStroke_.message = tr("Pull: %1").arg(QString::fromStdString(message));
        Q_EMIT strokeFinished();
    }
    Q_EMIT entitiesChanged();
}

void SketchDocument::applyOversketch(model::EntityId target, const solvers::Curve3d& curve,
                                     const std::vector<Eigen::Vector3d>& stroke, const QString& done, double pixel,
                                     int hooks)
{
    try {
        // The samples are whole pixels: the fit's tolerance is never below one pixel's footprint
        // (kResolutionTolerance pixels, as a sketched stroke's fit), or it follows their staircase
        // (a 110-pixel arch over-sketched at 0.002 of its length, 0.17 mm against a 0.75 mm pixel,
        // took 42 control points and showed the steps).
        solvers::editing::OversketchOptions options;
        options.resolution = solvers::stroke::kResolutionTolerance * pixel;
        double maxError = 0.0;
        solvers::Curve3d changed = solvers::editing::oversketch<3>(curve, stroke, options, nullptr, &maxError);
        model::requireCurveExtent(changed);
        lastStroke_.fitted = true;
        lastStroke_.controlPoints = changed.pointCount();
        lastStroke_.maxError = maxError;
        lastStroke_.message = tr("%1: %2 control points, max error %3 mm")
                                  .arg(done.arg(target))
                                  .arg(changed.pointCount())
                                  .arg(maxError, 0, 'f', 3) +
                              noteHooks(hooks);
        undo_.push(new ReplaceCurveCommand(*this, target, curve, std::move(changed)));
    } catch (const std::exception& e) {
        lastStroke_.message = tr("Over-sketch not applied: %1").arg(QString::fromStdString(e.what()));
    }
    Q_EMIT strokeFinished();
}

}  // namespace sculptline::ui
