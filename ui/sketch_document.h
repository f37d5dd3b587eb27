#pragma once
// The open document: the model, its Coin view, one dragger-carried manipulator per plane, the stroke
// input, the selection and the undo stack. Every edit goes through a QUndoCommand
// (ui/undo_commands.h) that changes the model; the Coin side follows the model as its observer.
#include "model/auxiliary_plane.h"
#include "model/model.h"
#include "scene/curvature_comb.h"
#include "solvers/aesthetics/curve_operators.h"
#include "scene/model_view.h"
#include "scene/update_scheduler.h"
#include "model/document.h"
#include "scene/stroke_feedback.h"
#include "solvers/editing/curve_manipulation.h"
#include "solvers/exchange/exchange.h"
#include "solvers/stroke/shape_recognizer.h"
#include "solvers/stroke/stroke_fitter.h"
#include "solvers/stroke/user_model.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <QUndoStack>

#include <map>
#include <utility>
#include <vector>
#include <optional>
#include <functional>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>

class SoCamera;
class SoSeparator;

namespace sculptline::manipulators {
class PlaneDraggers;
class PointHandles;
struct PointerClick;
struct PointPose;
class StrokeInput;
class CurvePull;
class CurvePullBinding;
class AestheticHandle;
class AestheticDragBinding;
struct FinishedStroke;
struct StrokeHit;
}  // namespace sculptline::manipulators

namespace sculptline::ui {

class ReferenceSet;
struct Reference;

/// What the last finished stroke became (status bar, inspector).
struct StrokeReport {
    int samples = 0;
    int controlPoints = 0;
    double maxError = 0.0;  ///< model units
    double tolerance = 0.0;  ///< the fit's tolerance (FitResult::tolerance), model units
    /// One pointer pixel's footprint on the stroke's plane (manipulators::pixelFootprint), model
    /// units: the fit's resolution; 0 = unknown.
    double pixel = 0.0;
    bool fitted = false;  ///< false: the stroke was rejected (too short, degenerate)
    /// Samples left out of the fit and of maxError (FitResult::dropped: a loop's overshoot, hooks,
    /// and `outliers`, the samples the digitizer's noise put beyond the tolerance).
    int dropped = 0;
    int outliers = 0;
    /// Where the curve strays from the stroke between two samples beyond the tolerance and a sixth
    /// of the chord there (FitResult::stray, excess above 1): how far, model units; 0 when it does not.
    double stray = 0.0;
    /// Wall time of the fit and recognition at pen-up (recognizeStroke), ms; 0 when not run. The
    /// replayer's `--stats` reports it as the `stroke_fit` series (issue 15 §3).
    double fitMs = 0.0;
    QString message;
    QString recognized;  ///< the recognizer's shape ("line", "arc", ..), empty when not run
    std::vector<std::pair<QString, double>> candidates;  ///< ranked, best first, with scores
    /// Non-empty when one of the designer's habits (a correction of a similar stroke) decided the
    /// shape: says which and what the recognizer alone would have picked.
    QString habit;
};

struct ResketchState;

class SketchDocument : public QObject, public model::ModelObserver {
    Q_OBJECT

public:
    explicit SketchDocument(QObject* parent = nullptr);
    ~SketchDocument() override;

    /// Replaces everything by `doc` (the undo history is cleared); `path` empty = untitled.
    void load(const model::SceneDocument& doc, const QString& path);
    /// The model becomes `doc` (grid, entities with their ids); the undo stack and the path stay.
    void restoreModel(const model::SceneDocument& doc);
    /// Writes the document atomically, keeping the previous version as "<path>.bak"; the undo
    /// stack becomes clean. @throws solvers::io::InputError (the file is then unchanged).
    void save(const QString& path);
    void exportIv(const QString& path);
    /// The document as saved: modelToJson plus "references" (relative to `folder` when given).
    nlohmann::json documentJson(const QString& folder) const;

    /// Reference geometry (ui/reference_set.h, ui/sketch_document_references.cpp): File > Import
    /// Reference reads and validates `path` and adds it as one undo step; returns what it draws.
    /// @throws solvers::io::InputError "path: problem" (nothing is added).
    QString importReference(const QString& path);
    /// Adds an already validated reference (--import-reference checks the file before Qt starts).
    void addReference(const Reference& reference);
    /// Removes every reference, one undo step; false when there was none.
    bool removeReferences();
    ReferenceSet& references() { return *references_; }
    /// The references the last load()/restoreModel() could not read, one line each.
    const QStringList& referenceProblems() const { return referenceProblems_; }
    /// Writes the world geometry (curves, surfaces; network meshes to STL/OBJ only) in `format`
    /// (solvers/exchange/exchange.h). Returns the bytes written.
    /// @throws solvers::exchange::ExchangeError naming what cannot be written (nothing to export,
    ///         a path that cannot be written).
    std::uintmax_t exportGeometry(const QString& path, solvers::exchange::Format format);

    model::Model& model() { return model_; }
    const model::Model& model() const { return model_; }
    scene::UpdateScheduler& scheduler() { return *scheduler_; }
    scene::ModelView& view() { return *view_; }
    /// The selected curve's curvature comb (hidden until shown; follows the selection).
    scene::CurvatureComb& comb() { return *comb_; }
    QUndoStack* undoStack() { return &undo_; }
    manipulators::StrokeInput& strokeInput() { return *strokeInput_; }
    manipulators::CurvePull& curvePull() { return *curvePull_; }
    scene::StrokeFeedback& strokeFeedback() { return *feedback_; }
    SoSeparator* root() const { return root_; }
    const QString& path() const { return path_; }
    const model::GridSpec& grid() const { return grid_; }
    const StrokeReport& lastStroke() const { return lastStroke_; }
    /// True between a press on a plane's dragger and its release.
    bool dragging() const;

    /// The plane strokes go onto: the selected plane, the selected curve's plane, else the plane
    /// added or used last; 0 when there is none.
    model::EntityId activePlane() const;
    /// The planes' draggers (one per plane; hiding a plane is a view setting kept there).
    manipulators::PlaneDraggers& planeDraggers() { return *planeDraggers_; }
    model::EntityId selection() const { return selection_; }
    void select(model::EntityId id);

    /// What a finished stroke does: becomes a new curve, or over-sketches the curve it was drawn
    /// over (solvers/editing, local-c2 by default).
    /// Lift: a stroke between two curve points becomes a minimum-curvature space curve (seed 004).
    /// Incidence (seed 000 §3.1, Sculpting): a stroke becomes a curve on the active plane that the
    /// incidence base surface is solved to pass through.
    enum class StrokeMode { Sketch, Oversketch, Lift, Sculpt, Incidence };
    /// Sculpt: the surface the next target curve deforms (0 = none, or not a surface).
    void setSculptBase(model::EntityId surface);
    /// Sets a sculpt's stiffness λ (undoable); the surface is solved again.
    void setSculptStiffness(model::EntityId surface, double stiffness);
    /// A solid made otherwise: its shell thickness or voxel size (Solid menu with the solid
    /// selected), one undo step; it converts again (ui/solid_builder.h). Returns false when the
    /// recipe is the one it has.
    /// @throws std::invalid_argument when `solid` is no solid or the recipe is invalid.
    bool setSolidRecipe(model::EntityId solid, const model::SolidRecipe& recipe);
    model::EntityId sculptBase() const { return sculptBase_; }
    /// What Sculpt mode's input does (thesis ch. 6): a stroke becomes a target curve, or the bound
    /// of the sculpt (a closed stroke over the surface); a click drops a point handle, blocks or
    /// frees the nearest control point, or picks one end of a distance.
    /// Resketch: a marking picks a parameter line, the next stroke re-sketches it (seed 001 §5.2;
    /// ui/sketch_document_resketch.cpp).
    enum class SculptTool { Target, Bound, Handle, Block, Distance, Resketch };
    void setSculptTool(SculptTool tool)
    {
        sculptTool_ = tool;
        pendingDistance_.reset();
        clearResketch();
    }
    /// Re-sketch: the auxiliary strip's rulings turn to the next of surface normal, across the line,
    /// the view direction (the camera's, as it is now).
    void cycleResketchRulings();
    /// Re-sketch: what to do next (status bar).
    QString resketchGuidance() const;
    SculptTool sculptTool() const { return sculptTool_; }
    /// Adds a target (the last of `added`: a curve from a stroke, or a handle's point) to the sculpt
    /// of the sculpt base, and `edit`s its recipe (a new target's id reads kPreviousEntity until it
    /// is added). A base that is a sculpt nothing depends on is replaced by one with this target
    /// too (all its targets solved together, each plane's drag re-solving one factorization);
    /// otherwise a new sculpt of the base is made. One undo step; the sculpt becomes the selection
    /// and the next base. Returns the sculpt, 0 when there is no base.
    model::EntityId sculptWith(std::vector<model::Entity> added, const std::function<void(model::SurfaceRecipe&)>& edit,
                               const QString& text);
    /// The sculpt base's bound from a closed stroke (world points; projected onto the base surface,
    /// the nearest points). Sets lastStroke().message to what happened.
    void setSculptBound(const std::vector<Eigen::Vector3d>& world);
    /// A click in Sculpt mode with the Handle, Block or Distance tool on the surface being sculpted
    /// (or its base), at `point` (world) on surface `surface` (0 = the click missed every surface).
    /// Handle: a Point at the surface point and a handle there (one undo step, sculptWith). Block:
    /// the base's control point nearest by Greville abscissae is blocked, or freed when it was.
    /// Distance: the first click picks one end, the second the other; the distance between them is
    /// held at what it is. Sets lastStroke().message to what happened.
    void sculptClick(model::EntityId surface, const Eigen::Vector3d& point);
    /// A sculpt's handles hold their normals (thesis Fig. 6-5 d) or only their positions; undoable.
    void setSculptHoldNormals(model::EntityId sculpt, bool hold);
    /// A sculpt's distance constraint `index` set to `distance` (model units); undoable.
    void setSculptDistance(model::EntityId sculpt, int index, double distance);
    /// Incidence mode (seed 000 §3.1). Sculpting: with a surface as the base, each stroke becomes a
    /// curve the surface is solved to pass through (curve-on-surface); fix a curve (Ctrl+Shift+F) to
    /// hold it exactly, over-sketch it or drag its plane and the surface follows. 0 = no base:
    /// Interpolation, where picked curves get a surface through them (buildIncidenceSurface).
    void setIncidenceBase(model::EntityId surface) { incidenceBase_ = surface; }
    model::EntityId incidenceBase() const { return model_.find(incidenceBase_) ? incidenceBase_ : 0; }
    /// Interpolation: adds `curve` to the picked curves, or takes it back when picked again.
    void pickIncidenceCurve(model::EntityId curve);
    const std::vector<model::EntityId>& incidenceCurves() const { return incidenceCurves_; }
    /// Interpolation: a surface through the picked curves (surfaceThroughCurves); the picks are
    /// cleared. False with surfaceMessage() saying why.
    bool buildIncidenceSurface();
    void cancelIncidenceCurves();
    /// Interpolation (seed 000 §3.1): a new free-form surface spanning `curves` (a flat bicubic sheet
    /// in their least-squares plane, solvers/incidence/spanning_sheet.h) that the model's incidence
    /// step bends through them: each curve gets a curve-on-surface constraint with its pre-image by
    /// projection. Fixed curves are met exactly, the others by the regularized solve. One undo step;
    /// the surface becomes the selection and the incidence base. Returns it, or 0 with
    /// surfaceMessage() saying why.
    model::EntityId surfaceThroughCurves(const std::vector<model::EntityId>& curves);
    /// Sculpting: `curve` put on `surface` (its pre-image by projection onto the surface as it is).
    /// A surface built from curves is first made free-form (its recipe dropped, the input curves
    /// that lie on it put on it the same way): a free-form surface's curves are what shape it. One
    /// undo step with `text` (the commands pushed since the caller's macro began, when it is in one).
    /// Returns the surface the curve is on (a freed surface has a new id), or 0 with `reason` set.
    model::EntityId putOnSurface(model::EntityId curve, model::EntityId surface, QString* reason);
    /// An incidence surface's truncation k (0 = the L-curve's corner); undoable. Ignored for a surface
    /// with a recipe, a negative k or the k it has.
    void setIncidenceK(model::EntityId surface, int k);
    /// The first end of a distance being picked (Distance tool), if any.
    const std::optional<Eigen::Vector2d>& pendingDistance() const { return pendingDistance_; }
    manipulators::PointHandles& pointHandles() { return *pointHandles_; }
    /// Along the sculpt base's target curve `curve`, holds the surface's tangent across it at the
    /// direction it has now in the middle (Fig. 6-4 d), or releases it; undoable.
    void setSculptCurveTangent(model::EntityId sculpt, model::EntityId curve, bool hold);
    /// The curve the last stroke made (a sculpt's newest target curve in Sculpt mode), or 0.
    model::EntityId recognizedCurve() const { return model_.find(recognizedCurve_) ? recognizedCurve_ : 0; }
    void setStrokeMode(StrokeMode mode) { strokeMode_ = mode; }
    StrokeMode strokeMode() const { return strokeMode_; }

    /// The last sketched curve as the recognizer's regularized shape (true) or as the freeform fit
    /// (false); undoable. Available while that curve exists and the shape is not freeform.
    void chooseRecognized(bool regularized);
    bool recognitionChoiceAvailable() const;
    /// The last sketched curve regularized as candidate `index` of lastStroke().candidates (0 = the
    /// best; a freeform candidate gives the fitted curve); undoable. Ignored when out of range or
    /// when that curve is gone.
    void chooseCandidate(int index);
    /// The next-ranked candidate after the one in use (wrapping), for the hot key / replays.
    void chooseNextCandidate();

    /// The designer's recognition habits (thesis §3.1.3, Table 3-2: the user model adapts to its
    /// user). Choosing another candidate for the last stroke, or its freeform fit instead of the
    /// shape, teaches the model a correction, and using the offered shape a confirmation
    /// (UserModel::learnShape); every recognition applies it, and a shape a habit decided is used
    /// for the new curve at once (one undo step with the stroke).
    /// Reads the model kept at `path` (empty: kept in memory only, nothing read or written); a file
    /// that does not exist is an empty model. Returns an empty string, or the message saying why
    /// the file could not be read (the model is then empty and the unreadable file is left as it is
    /// until a correction overwrites it). Never throws.
    QString openUserModel(const QString& path);
    const solvers::stroke::UserModel& userModel() const { return userModel_; }
    const QString& userModelPath() const { return userModelPath_; }
    /// Forgets every learned habit (the file is rewritten without them); returns how many.
    int forgetHabits();
    /// The default place of the model: the user's config folder (QStandardPaths::AppConfigLocation)
    /// /recognition_habits.json.
    static QString defaultUserModelPath();

    /// Undoable edits.
    void addPlane(const model::PlaneFrame& frame);
    /// Which control points of `curve` stay fixed when it is pulled.
    void setFixedPoints(model::EntityId curve, std::vector<int> fixed);
    /// Tells the docks the model's data changed (after the current event: an inspector edit may be
    /// what is running).
    void notifyChanged();
    void deleteSelection();
    /// Fixes the selected entity, or frees it when it is fixed (undoable).
    void toggleSelectionFixed();
    /// Removes the pins (position and tangent constraints) of the selected curve (undoable).
    void removeSelectionPins();
    void addStroke(const manipulators::FinishedStroke& stroke);

    /// 6-DOF input (ui/sketch_document_space.cpp). A stroke drawn in space (world points, seconds
    /// since the trigger went down): fitted into a space curve with no plane, its ends snapped onto
    /// curves within kSpaceSnapDistance; in over-sketch mode it over-sketches the nearest curve.
    void addSpaceStroke(const std::vector<Eigen::Vector3d>& world, const std::vector<double>& times);
    /// A pointer stroke drawn while `plane` is carried: planar on it (the positions projected along
    /// its normal), then the planar stroke path of addStroke.
    void addStrokeOnPlane(model::EntityId plane, const std::vector<Eigen::Vector3d>& world, const std::vector<double>& times);
    /// The non-dominant hand carries a plane: live moves between begin and end, one undo step.
    void beginCarry(model::EntityId plane);
    void carryTo(const Eigen::Vector3d& origin, const Eigen::Quaterniond& rotation);
    void endCarry();
    model::EntityId carriedPlane() const { return carried_; }
    /// A space stroke's end this close to a curve (model units) starts or ends on it. A pen held in
    /// the air has nothing to rest on: its endpoints scatter by a few millimetres around the point
    /// meant (hand tremor, no haptic stop), ten times a tablet's; 5 mm catches that, and is 2.5 % of
    /// the default 200 mm plane, so a stroke meant to end in the air rarely snaps by accident.
    static constexpr double kSpaceSnapDistance = 5.0;
    /// The stroke feedback and the last stroke's report and recognition are dropped (an undo took
    /// the stroke back): nothing on screen speaks of a stroke that is no longer there.
    void forgetStroke();

    /// Surface modes (issue 6): curves picked one by one become the inputs of a surface of
    /// `mode` (a solvers/surfaces mode name; empty = no surface mode). When the mode's largest
    /// count is reached the surface is built; fill and loft can be built earlier (buildSurface()).
    /// Extrude instead drags a picked curve: the surface follows the pointer and is one undo step.
    void setSurfaceMode(std::optional<model::Construction> mode);
    std::optional<model::Construction> surfaceMode() const { return surfaceMode_; }
    /// Adds `curve` to the picked inputs (a second pick of the last one takes it back).
    void pickSurfaceInput(model::EntityId curve);
    const std::vector<model::EntityId>& surfaceInputs() const { return surfaceInputs_; }
    /// Builds the surface (network: the mesh) from the picked inputs (undoable); false with
    /// `surfaceMessage()` when it cannot (too few inputs, the curves do not meet, ...); the picks
    /// are cleared then. Gordon: the first call closes the first family of curves instead.
    bool buildSurface();
    void cancelSurface();
    /// Fill: boundaries that other surfaces were built through are made G1 to those surfaces.
    void setFillTangent(bool on) { fillG1_ = on; }
    bool fillTangent() const { return fillG1_; }
    /// What the surface mode wants next, or why the last build failed.
    const QString& surfaceMessage() const { return surfaceMessage_; }

    /// Draws curves and surfaces with SoNurbsCurve / SoNurbsSurface (the frame-time comparison of
    /// issue 5 §4); call before load().
    void setNurbsNodes(bool nurbs);

    /// Where the viewer's camera is (for strokes, and for new planes facing the viewer).
    void setCamera(std::function<SoCamera*()> camera);

    void entityAdded(const model::Entity& entity) override;
    void entityRemoved(const model::Entity& entity) override;
    void entityUpdated(const model::Entity& entity) override;

    /// Aesthetic operators (thesis §7.4) on the selected planar curve: applied at once with
    /// `amount` (one undo step); the status text says the name before and after, or why not.
    QString applyAesthetic(solvers::aesthetics::Operator op, double amount);
    /// Shows the operator's handle on the selected curve's operated point (or hides it: nullopt);
    /// dragging it sets the amount live, one undo step per drag. Returns why not, or empty.
    QString showAestheticHandle(std::optional<solvers::aesthetics::Operator> op);
    std::optional<solvers::aesthetics::Operator> aestheticHandleOperator() const { return handleOperator_; }
    /// A fiftieth of the selected curve's length (0 without a curve): the menu's amount.
    double defaultAestheticAmount() const;
    manipulators::AestheticHandle& aestheticHandle() { return *aestheticHandle_; }

Q_SIGNALS:
    /// An aesthetic operator was applied or refused (status bar).
    void aestheticApplied(const QString& message);
    /// load() replaced the document (and cleared the undo stack).
    void replaced();
    /// The set of entities or their data changed (lists, inspector).
    void entitiesChanged();
    void selectionChanged(model::EntityId id);
    /// The selected entity was recomputed by a model update (each frame of a drag that moves it).
    void selectionUpdated();
    void strokeFinished();
    /// forgetStroke() dropped the last stroke's report (the recognition dock shows nothing).
    void strokeForgotten();
    /// A habit was learned or the habits were forgotten; `message` says what happened (status bar).
    void habitsChanged(const QString& message);
    /// The surface mode's picks or message changed (status bar).
    void surfaceStateChanged();

private:
    /// The plane a stroke starting at `start` is drawn on (records strokeOnPlane_).
    std::optional<model::PlaneFrame> strokePlane(const manipulators::StrokeHit& start);
    /// addStroke()'s work, by mode; addStroke() notes where in the undo stack the stroke went.
    void applyStroke(const manipulators::FinishedStroke& stroke);
    /// Why a stroke on the active plane would land out of sight (the plane seen almost edge-on, or
    /// far outside its square); empty when it lands within sight.
    QString farFromSight(const manipulators::FinishedStroke& stroke) const;
    /// The frame of the curve `hit` landed on, if it landed on one.
    std::optional<model::CurveFrameAt> curveFrame(const manipulators::StrokeHit& hit) const;
    /// `hooks`: the samples applyStroke left out of `stroke` as a pen's light-pressure hooks (the
    /// same for liftStroke and resketchStroke), reported in the status (noteHooks).
    void oversketchStroke(const manipulators::FinishedStroke& stroke, int hooks);
    void oversketchInSpace(const std::vector<Eigen::Vector3d>& world);
    /// Over-sketches curve `target` with `stroke` (in the curve's local frame) as one undo step;
    /// `done` is the message's first words ("Curve %1 over-sketched").
    /// @param pixel the pointer pixel's footprint on the stroke's plane, model units (0: unknown, a
    ///              stroke in space): the fit's tolerance is never below it.
    /// @param hooks samples left out of the stroke as a pen's light-pressure hooks (noteHooks).
    void applyOversketch(model::EntityId target, const solvers::Curve3d& curve,
                         const std::vector<Eigen::Vector3d>& stroke, const QString& done, double pixel = 0.0,
                         int hooks = 0);
    struct SpaceSnap {
        model::EntityId curve = 0;
        Eigen::Vector3d point;
        double distance = 0.0;
    };
    /// The curve point nearest to `world` within kSpaceSnapDistance, if any.
    std::optional<SpaceSnap> snapToCurve(const Eigen::Vector3d& world) const;
    /// Re-sketch tool (ui/sketch_document_resketch.cpp): a marking or a line's new shape.
    void resketchStroke(const manipulators::FinishedStroke& stroke, int hooks);
    std::optional<model::PlaneFrame> resketchPlane(const manipulators::StrokeHit& start);
    void showResketchStrip();
    /// The strip follows its surface (a re-sketch, an undo).
    void resketchSurfaceUpdated(model::EntityId surface);
    void clearResketch();
    void setResketchCamera(std::function<SoCamera*()> camera);
    ResketchState& resketchState();
    /// Runs the recognizer on a fitted stroke (fills lastStroke_'s shape and candidates).
    void recognize(const solvers::stroke::FitResult& fit);
    /// Notes in lastStroke_ the samples `fit` left out (StrokeReport::dropped, outliers) and where
    /// it strays between samples (StrokeReport::stray), and returns the message's clauses that say
    /// so (empty when neither).
    QString noteLeftOut(const solvers::stroke::FitResult& fit);
    /// "; n sample(s) left out as a light-pressure hook" for a stroke used as drawn (over-sketch,
    /// lift, re-sketch), empty when none was; sets lastStroke_.dropped.
    QString noteHooks(int hooks);
    void liftStroke(const manipulators::FinishedStroke& stroke, int hooks);
    /// The last sketched curve replaced by `target` (undoable), when it differs.
    /// False (with the reason in lastStroke_) when the target is refused.
    bool replaceRecognizedCurve(const solvers::Curve3d& target);
    /// Pulling a curve point (solvers/editing's constrained manipulation, factored at the grab).
    std::optional<model::PlaneFrame> grabCurve(const manipulators::StrokeHit& hit);
    /// A pull ended (manipulators::CurvePullBinding): one undo step, and the solver's remark.
    void pullFinished(model::EntityId curve, const solvers::Curve3d& before, const std::string& message);
    /// Extrude mode's drag (the pointer pulls the picked curve out into a surface).
    std::optional<model::PlaneFrame> grabExtrusion(const manipulators::StrokeHit& hit);
    void extrudeTo(const Eigen::Vector3d& local);
    void releaseExtrusion();
    void setSurfaceMessage(const QString& message);
    /// For each boundary another surface was built through: that surface (G1 fill).
    std::vector<model::SurfaceRecipe::Tangent> adjacentSurfaces(const std::vector<model::EntityId>& boundaries) const;
    void pointDragFinished(model::EntityId point, const manipulators::PointPose& before, const manipulators::PointPose& after);
    /// The sculpt of the sculpt base (the base itself when it is a sculpt), or null.
    const model::Entity* currentSculpt() const;
    void dragStarted(model::EntityId plane);
    /// One undo step for the drag (when the plane moved).
    void dragFinished(model::EntityId plane, const model::PlaneFrame& before, const model::PlaneFrame& after);

    model::Model model_;
    model::GridSpec grid_;
    std::unique_ptr<scene::ModelView> view_;
    std::unique_ptr<scene::CurvatureComb> comb_;
    std::unique_ptr<scene::UpdateScheduler> scheduler_;
    std::unique_ptr<manipulators::StrokeInput> strokeInput_;
    std::unique_ptr<manipulators::CurvePull> curvePull_;
    std::unique_ptr<scene::StrokeFeedback> feedback_;
    std::unique_ptr<manipulators::CurvePullBinding> pullBinding_;
    std::unique_ptr<manipulators::PlaneDraggers> planeDraggers_;  ///< one dragger per plane, bound to the model
    std::unique_ptr<manipulators::PointHandles> pointHandles_;  ///< one jack per point (sculpt handles)
    std::unique_ptr<manipulators::AestheticHandle> aestheticHandle_;
    std::unique_ptr<manipulators::AestheticDragBinding> aestheticBinding_;
    std::optional<solvers::aesthetics::Operator> handleOperator_;
    void setUpAesthetics();
    /// Puts the aesthetic handle where its operator acts on the selection now (after edits, undo).
    void placeAestheticHandle();
    void aestheticDragFinished(model::EntityId curve, const solvers::Curve3d& before, double amount, const std::string& message);
    std::unique_ptr<ReferenceSet> references_;
    QStringList referenceProblems_;
    SoSeparator* root_ = nullptr;  ///< ref()ed
    SoSeparator* gridNode_ = nullptr;
    QUndoStack undo_;
    QString path_;
    model::EntityId selection_ = 0;
    model::EntityId lastPlane_ = 0;
    /// The existing plane the current stroke is on; 0 = an auxiliary plane made for it.
    model::EntityId strokeOnPlane_ = 0;
    StrokeReport lastStroke_;
    model::EntityId recognizedCurve_ = 0;  ///< the curve the last stroke made
    std::optional<solvers::Curve3d> freeformFit_, regularizedFit_;
    /// The last stroke's fit and recognition (for picking another candidate), and the candidate
    /// in use (-1: the freeform fit as made).
    std::optional<solvers::stroke::FitResult> lastFit_;
    std::optional<solvers::stroke::Recognition> recognition_;
    int candidateInUse_ = -1;
    /// The recognizer's own pick for the last stroke, before the habits re-ranked it.
    solvers::stroke::ShapeKind recognizerKind_ = solvers::stroke::ShapeKind::Freeform;
    bool habitFromLastStroke_ = false;  ///< the newest habit was learned from the last stroke
    solvers::stroke::UserModel userModel_ = solvers::stroke::UserModel::predefined();
    QString userModelPath_;
    /// The designer chose `intended` for the last stroke: remember it, and save the model.
    void learnChoice(solvers::stroke::ShapeKind intended);
    /// Writes the model to userModelPath_ (atomically); the message on failure, else empty.
    QString saveUserModel() const;
    StrokeMode strokeMode_ = StrokeMode::Sketch;
    model::EntityId sculptBase_ = 0;
    model::EntityId incidenceBase_ = 0;
    std::vector<model::EntityId> incidenceCurves_;  ///< Interpolation's picks
    SculptTool sculptTool_ = SculptTool::Target;
    /// A bound drawn on a surface not sculpted yet, for its first sculpt.
    std::vector<Eigen::Vector2d> pendingBound_;
    /// Distance tool: the (u, v) of the first end picked, on the sculpt's domain.
    std::optional<Eigen::Vector2d> pendingDistance_;
    model::EntityId oversketchTarget_ = 0;  ///< the curve the current over-stroke started on
    std::shared_ptr<ResketchState> resketch_;  ///< the Re-sketch tool's picked line and strip
    /// The undo stack's index just after the last stroke's edit; an undo below it takes the
    /// stroke back (-1: the last stroke made no edit).
    int strokeIndex_ = -1;
    model::EntityId feedbackPlane_ = 0;  ///< the plane the stroke feedback dots move with
    std::optional<model::Construction> surfaceMode_;
    bool fillG1_ = true;
    int gordonFirstFamily_ = -1;  ///< gordon: picks in the first family once Enter closed it
    std::vector<model::EntityId> surfaceInputs_;
    QString surfaceMessage_;
    /// Extrude drag: the profile, the surface shown live (in the model, not yet on the undo
    /// stack), the grabbed point and the drag plane.
    model::EntityId extrudeProfile_ = 0, extrusion_ = 0;
    model::PlaneFrame extrudeFrame_;
    model::EntityId carried_ = 0;  ///< the plane a pose carries (0: none)
    model::PlaneFrame carriedFrom_;
};

}  // namespace sculptline::ui
