#include "ui/sketch_document.h"

#include "manipulators/aesthetic_drag.h"
#include "manipulators/curve_pull.h"
#include "manipulators/plane_binding.h"
#include "manipulators/point_handles.h"
#include "manipulators/stroke_input.h"
#include "scene/ground_grid.h"
#include "scene/iv_export.h"
#include "model/model_document.h"
#include "model/atomic_file.h"
#include "ui/reference_set.h"
#include "ui/undo_commands.h"

#include <Inventor/nodes/SoSeparator.h>

#include <QFileInfo>

#include <nlohmann/json.hpp>

#include <cmath>

namespace sculptline::ui {

SketchDocument::SketchDocument(QObject* parent) : QObject(parent)
{
    root_ = new SoSeparator;
    root_->ref();
    root_->setName("SculptlineScene");
    strokeInput_ = std::make_unique<manipulators::StrokeInput>();
    // First, so that a press on empty space starts a stroke before anything else sees it.
    root_->addChild(strokeInput_->root());
    strokeInput_->setActivePlane([this](const manipulators::StrokeHit& start) { return strokePlane(start); });
    strokeInput_->setFinishedCallback([this](const manipulators::FinishedStroke& s) { addStroke(s); });
    curvePull_ = std::make_unique<manipulators::CurvePull>();
    root_->addChild(curvePull_->root());
    // One handle for two drags: pulling a curve point, or (extrude mode) pulling a curve out into
    // a surface.
    curvePull_->setCallbacks(
        [this](const manipulators::StrokeHit& hit) { return surfaceMode_ == model::Construction::Extrude ? grabExtrusion(hit) : grabCurve(hit); },
        [this](const Eigen::Vector3d& local) { extrusion_ || extrudeProfile_ ? extrudeTo(local) : pullBinding_->moveTo(local); },
        [this]() { extrudeProfile_ ? releaseExtrusion() : pullBinding_->release(); });
    gridNode_ = scene::makeGroundGrid(grid_);
    root_->addChild(gridNode_);
    view_ = std::make_unique<scene::ModelView>(model_);
    root_->addChild(view_->root());
    // Reference geometry right after the model: drawn greyed, never picked (ui/reference_set.h).
    references_ = std::make_unique<ReferenceSet>();
    root_->addChild(references_->root());
    comb_ = std::make_unique<scene::CurvatureComb>(model_);
    root_->addChild(comb_->root());
    feedback_ = std::make_unique<scene::StrokeFeedback>();
    root_->addChild(feedback_->root());
    // An undo past the last stroke's edit takes its markers and its report with it.
    connect(&undo_, &QUndoStack::indexChanged, this, [this](int index) {
        if (strokeIndex_ >= 0 && index < strokeIndex_) forgetStroke();
    });
    scheduler_ = std::make_unique<scene::UpdateScheduler>(model_);
    pullBinding_ = std::make_unique<manipulators::CurvePullBinding>(model_, *scheduler_);
    pullBinding_->setFinishedCallback([this](model::EntityId curve, const solvers::Curve3d& before, const std::string& message) {
        pullFinished(curve, before, message);
    });
    // Last: the planes are translucent and drawn over what lies behind them.
    planeDraggers_ = std::make_unique<manipulators::PlaneDraggers>(model_, *scheduler_);
    planeDraggers_->setDragCallbacks([this](model::EntityId plane) { dragStarted(plane); },
                                     [this](model::EntityId plane, const model::PlaneFrame& before,
                                            const model::PlaneFrame& after) { dragFinished(plane, before, after); });
    // Sculpt handles' jacks: opaque, before the translucent planes.
    pointHandles_ = std::make_unique<manipulators::PointHandles>(model_, *scheduler_);
    pointHandles_->setDragCallbacks([this](model::EntityId) {},
                                    [this](model::EntityId point, const manipulators::PointPose& before,
                                           const manipulators::PointPose& after) { pointDragFinished(point, before, after); });
    root_->addChild(pointHandles_->root());
    setUpAesthetics();
    root_->addChild(planeDraggers_->root());
    // Sculpt mode's click tools: a click on the surface drops a handle, blocks a point, picks a
    // distance's end; those tools draw no strokes.
    auto clickTool = [this]() {
        return strokeMode_ == StrokeMode::Sculpt && sculptTool_ != SculptTool::Target && sculptTool_ != SculptTool::Bound &&
               sculptTool_ != SculptTool::Resketch;
    };
    strokeInput_->setClickCallback(
        [this, clickTool](const manipulators::PointerClick& c) {
            if (clickTool()) sculptClick(c.surface, c.point);
        },
        clickTool);
    model_.addObserver(this);
}

SketchDocument::~SketchDocument()
{
    undo_.clear();
    model_.endDrag();
    model_.removeObserver(this);
    pointHandles_.reset();
    aestheticBinding_.reset();
    aestheticHandle_.reset();
    planeDraggers_.reset();
    pullBinding_.reset();
    scheduler_.reset();
    comb_.reset();
    view_.reset();
    root_->unref();
}

void SketchDocument::setCamera(std::function<SoCamera*()> camera)
{
    strokeInput_->setCamera(camera);
    setResketchCamera(camera);
    curvePull_->setCamera(std::move(camera));
}

void SketchDocument::setNurbsNodes(bool nurbs)
{
    const int index = root_->findChild(view_->root());
    view_ = std::make_unique<scene::ModelView>(model_, nurbs);
    root_->replaceChild(index, view_->root());
}

void SketchDocument::load(const model::SceneDocument& doc, const QString& path)
{
    undo_.clear();
    path_ = path;  // first: the references are found relative to the document's folder
    restoreModel(doc);
    Q_EMIT replaced();
}

void SketchDocument::restoreModel(const model::SceneDocument& doc)
{
    selection_ = 0;
    lastPlane_ = 0;
    grid_ = doc.grid;
    SoSeparator* grid = scene::makeGroundGrid(grid_);
    root_->replaceChild(gridNode_, grid);
    gridNode_ = grid;
    model::populateModel(doc, model_);
    referenceProblems_ = references_->restore(doc.references, path_.isEmpty() ? QString() : QFileInfo(path_).absolutePath());
    view_->setHighlighted(0);
    comb_->setCurve(0);
    Q_EMIT entitiesChanged();
    Q_EMIT selectionChanged(0);
}

void SketchDocument::save(const QString& path)
{
    scheduler_->flush();
    model::writeFileAtomically(path.toStdString(), documentJson(QFileInfo(path).absolutePath()).dump(2) + "\n", true);
    path_ = path;
    undo_.setClean();
}

void SketchDocument::exportIv(const QString& path)
{
    scheduler_->flush();
    scene::exportIv(model_, grid_, path.toStdString());
}

model::EntityId SketchDocument::activePlane() const
{
    if (const model::Entity* e = model_.find(selection_)) {
        if (e->kind == model::EntityKind::Plane) return e->id;
        if (e->plane() != 0) return e->plane();
    }
    if (model_.find(lastPlane_)) return lastPlane_;
    for (const auto& [id, e] : model_.entities()) {
        if (e.kind == model::EntityKind::Plane) return id;
    }
    return 0;
}

void SketchDocument::select(model::EntityId id)
{
    if (id != 0 && !model_.find(id)) id = 0;
    const model::Entity* e = model_.find(id);
    if (e && e->kind == model::EntityKind::Plane) lastPlane_ = id;
    if (e && e->plane() != 0) lastPlane_ = e->plane();
    if (id == selection_) return;
    selection_ = id;
    view_->setHighlighted(e && e->kind == model::EntityKind::Curve ? id : 0);
    comb_->setCurve(id);
    Q_EMIT selectionChanged(id);
}

void SketchDocument::addPlane(const model::PlaneFrame& frame)
{
    model::Entity plane;
    plane.kind = model::EntityKind::Plane;
    plane.frame = frame;
    undo_.push(new AddEntitiesCommand(*this, {plane}, tr("Add plane")));
}

void SketchDocument::setFixedPoints(model::EntityId curve, std::vector<int> fixed)
{
    const model::Entity* e = model_.find(curve);
    if (!e || e->kind != model::EntityKind::Curve || model_.fixedPoints(curve) == fixed) return;
    undo_.push(new SetFixedPointsCommand(*this, curve, model_.fixedPoints(curve), std::move(fixed)));
}

void SketchDocument::notifyChanged()
{
    QMetaObject::invokeMethod(this, [this]() { Q_EMIT entitiesChanged(); }, Qt::QueuedConnection);
}

void SketchDocument::deleteSelection()
{
    if (selection_ == 0) return;
    undo_.push(new DeleteEntityCommand(*this, selection_));
}

void SketchDocument::setSculptBase(model::EntityId surface)
{
    pendingDistance_.reset();
    const model::Entity* e = model_.find(surface);
    sculptBase_ = e && e->kind == model::EntityKind::Surface && e->surface ? surface : 0;
    pendingBound_.clear();
    clearResketch();
}

void SketchDocument::setSculptStiffness(model::EntityId surface, double stiffness)
{
    const model::Entity* e = model_.find(surface);
    if (!e || !e->recipe || e->recipe->mode != model::Construction::Sculpt || e->recipe->stiffness == stiffness) return;
    model::SurfaceRecipe after = *e->recipe;
    after.stiffness = stiffness;
    undo_.push(new SetRecipeCommand(*this, surface, *e->recipe, after, tr("Sculpt stiffness %1 %").arg(std::lround(100 * stiffness))));
}

void SketchDocument::toggleSelectionFixed()
{
    const model::Entity* e = model_.find(selection_);
    if (!e) return;
    undo_.push(new SetFixedCommand(*this, e->id, !e->fixed));
}

void SketchDocument::removeSelectionPins()
{
    std::vector<model::Constraint> pins;
    for (model::ConstraintId id : model_.constraintsOn(selection_)) {
        const model::Constraint* c = model_.findConstraint(id);
        if (c->type == model::ConstraintType::Position || c->type == model::ConstraintType::Tangent) pins.push_back(*c);
    }
    if (pins.empty()) return;
    undo_.beginMacro(tr("Remove the pins of curve %1").arg(selection_));
    for (model::Constraint& pin : pins) undo_.push(new RemoveConstraintCommand(*this, std::move(pin)));
    undo_.endMacro();
}

void SketchDocument::entityAdded(const model::Entity& e)
{
    // The plane's dragger comes from planeDraggers_, which observes the model too.
    if (e.kind == model::EntityKind::Plane) lastPlane_ = e.id;
    Q_EMIT entitiesChanged();
}

void SketchDocument::entityRemoved(const model::Entity& e)
{
    if (selection_ == e.id) selection_ = 0;
    Q_EMIT entitiesChanged();
}

void SketchDocument::entityUpdated(const model::Entity& e)
{
    // The stroke feedback dots move with their plane (planeDraggers_ moves the plane's dragger).
    if (e.kind == model::EntityKind::Plane && e.id == feedbackPlane_) feedback_->setFrame(e.frame);
    if (e.kind == model::EntityKind::Surface) resketchSurfaceUpdated(e.id);
    if (e.id == selection_) Q_EMIT selectionUpdated();
}

bool SketchDocument::dragging() const
{
    return planeDraggers_->dragging() != 0 || pointHandles_->dragging() != 0 || aestheticBinding_->active();
}

void SketchDocument::pointDragFinished(model::EntityId point, const manipulators::PointPose& before, const manipulators::PointPose& after)
{
    view_->refineSurfaces();
    if (model_.find(point) && after != before)
        undo_.push(new MovePointCommand(*this, point, {before.position, before.rotation}, {after.position, after.rotation}));
    Q_EMIT entitiesChanged();
}

// planeDraggers_ ran the pending update before either call, so the frames are the model's.
void SketchDocument::dragStarted(model::EntityId plane) { select(plane); }

void SketchDocument::dragFinished(model::EntityId plane, const model::PlaneFrame& before, const model::PlaneFrame& after)
{
    view_->refineSurfaces();  // live rebuilds reused their grids; the resting shape adapts again
    if (model_.find(plane) && after != before) undo_.push(new MovePlaneCommand(*this, plane, before, after));
    Q_EMIT entitiesChanged();
}

}  // namespace sculptline::ui
