#include "ui/main_window.h"

#include "manipulators/curve_pull.h"
#include "manipulators/plane_binding.h"
#include "manipulators/stroke_input.h"
#include "scene/eigen_coin.h"
#include "scene/entity_path.h"
#include "ui/aesthetics_dock.h"
#include "ui/autosave.h"
#include "ui/entity_list_dock.h"
#include "ui/inspector_dock.h"
#include "ui/lcurve_dock.h"
#include "ui/modes_dock.h"
#include "ui/pose_input.h"
#include "ui/recognition_dock.h"
#include "ui/sketch_document.h"
#include "ui/solid_builder.h"
#include "ui/stereo_menu.h"
#include "ui/surface_display_menu.h"
#include "ui/tablet_pressure.h"
#include "ui/undo_history.h"
#include "ui/view_navigation.h"

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>
#include <Inventor/SbViewVolume.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPickedPoint.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoRayPickAction.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QGLWidget>
#include <QMenu>
#include <QMenuBar>
#include <QMouseEvent>
#include <QScreen>
#include <QStatusBar>
#include <QTimer>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace sculptline::ui {
namespace {

/// A dark neutral background: grid, warm curves and cool surfaces all keep their contrast on it.
const SbColor kBackground(0.16f, 0.17f, 0.2f);
/// From the front right (-Y, +X) and above: the three-quarter view of a draughtsman.
const Eigen::Vector3d kViewDirection(-1.0, 1.6, -0.9);
/// Share of viewAll's camera distance kept after framing (closer = larger scene on screen).
constexpr float kFramingZoom = 0.9f;
/// Edge of a plane added from the menu: the default plane's, a sheet of paper at arm's length.
constexpr double kNewPlaneSize = 120.0;
/// How long one resize waits for the GL area to reach its size: 20-120 ms on this machine idle,
/// up to 0.74 s (p50 0.14 s) with four GUI tests and two busy loops on two cores; beyond 5 s
/// something else is wrong and the viewport is left as it is, with a message.
constexpr qint64 kViewportSettleMs = 5000;
/// The pause between two looks at the GL area while it settles (events are handled meanwhile).
constexpr int kViewportSettleStepMs = 5;
/// The most the window may have around its GL area (menus, toolbar, docks, status bar): a bound on
/// a correction measured from a viewport that is not yet what it will be.
constexpr int kMaxViewportSurround = 4096;
/// Smallest 3D viewport: the docks may never squeeze the drawing area below a usable sketch pad.
constexpr int kMinViewportWidth = 480;
constexpr int kMinViewportHeight = 360;
/// Share of the screen a window opened without --size takes.
constexpr double kDefaultScreenShare = 0.85;
/// How far from a curve (pixels) a click in a surface mode still picks it: a fingertip's slack.
constexpr double kCurvePickRadius = 12.0;
/// Model units between a click's hits on a plane and on a curve drawn in it below which both are at
/// the same depth (the curve lies in the plane; its line is picked within a few pixels of it).
constexpr float kSameDepth = 0.5f;
/// Samples per curve when looking for the nearest one on screen.
constexpr int kCurvePickSamples = 128;

}  // namespace

MainWindow::MainWindow(QWidget* parent, bool withViewer) : QMainWindow(parent)
{
    auto* central = new QWidget(this);
    central->setMinimumSize(kMinViewportWidth, kMinViewportHeight);
    setCentralWidget(central);
    if (const QScreen* screen = QGuiApplication::primaryScreen()) {
        const QSize available = screen->availableGeometry().size();
        resize(static_cast<int>(available.width() * kDefaultScreenShare),
               static_cast<int>(available.height() * kDefaultScreenShare));
    }
    document_ = new SketchDocument(this);
    history_ = new UndoHistory(*document_, this);
    navigation_ = std::make_unique<ViewNavigation>();
    if (withViewer) {
        viewer_ = new StereoExaminerViewer(central);
        viewer_->setBackgroundColor(kBackground);
        // Sorted blending draws the translucent planes after, and back to front over, the opaque shapes.
        viewer_->setTransparencyType(SoGLRenderAction::SORTED_OBJECT_BLEND);
        viewer_->setFeedbackVisibility(FALSE);
        // No spin on after a quick turn: the view stops where the pointer does. No developer menu
        // on the right button: Sculptline's own context menu is there.
        viewer_->setAnimationEnabled(FALSE);
        viewer_->setPopupMenuEnabled(FALSE);
        viewer_->setEventCallback(&MainWindow::viewerEvent, this);
        document_->setCamera([this]() { return viewer_->getCamera(); });
        // A tablet pen's pressure goes with each stroke sample (the fitter trims light hooks).
        const TabletPressure* tablet = new TabletPressure(viewer_->getGLWidget());
        document_->strokeInput().setPressure([tablet]() { return tablet->pressure(); });
        new PoseInput(*this);  // 6-DOF devices and the 3D mouse (ui/pose_input.h)
    }
    createActions();
    createDocks();
    connect(document_, &SketchDocument::entitiesChanged, this, [this]() {
        entities_->refresh(document_->model(), document_->selection());
        inspector_->show(document_->model(), document_->selection());
    });
    connect(document_, &SketchDocument::selectionChanged, this, [this](model::EntityId id) {
        entities_->setSelection(id);
        inspector_->show(document_->model(), id);
        updateStatus();
    });
    connect(document_, &SketchDocument::selectionUpdated, this,
            [this]() { inspector_->followCurve(document_->model(), document_->selection()); });
    connect(document_, &SketchDocument::strokeFinished, this, [this]() {
        recognition_->refresh();
        statusBar()->showMessage(document_->lastStroke().message);
        if (automated_) {
            const StrokeReport& r = document_->lastStroke();
            std::cerr << "sculptline: " << r.message.toStdString()
                      << (r.pixel > 0.0 ? "; pixel " + std::to_string(r.pixel) + " mm" : std::string())
                      << (r.recognized.isEmpty() ? std::string() : "; recognized: " + r.recognized.toStdString())
                      << (r.habit.isEmpty() ? std::string() : "; " + r.habit.toStdString()) << "\n";
        }
    });
    connect(document_, &SketchDocument::strokeForgotten, this, [this]() { recognition_->refresh(); });
    connect(document_, &SketchDocument::habitsChanged, this, [this](const QString& message) { statusBar()->showMessage(message, 10000); });
    connect(document_, &SketchDocument::surfaceStateChanged, this, [this]() {
        updateStatus();
        // A replay has nobody reading the status bar: its log says what the surface modes did.
        if (automated_ && !document_->surfaceMessage().isEmpty())
            std::cerr << "sculptline: " << document_->surfaceMessage().toStdString() << "\n";
    });
    connect(document_->undoStack(), &QUndoStack::cleanChanged, this, [this]() { updateTitle(); });
    // Ready to draw: the left button sketches, the other buttons move the view (ui/view_navigation.h).
    setMode(Mode::Sketch);
}

MainWindow::~MainWindow()
{
    // The viewer holds a ref on the graph: detach it before the document frees its nodes.
    if (viewer_) viewer_->setSceneGraph(nullptr);
    // A normal end: the recovery file goes; the history must not follow the stack being emptied.
    delete autosaver_;
    delete history_;
    delete solids_;  // joins a running conversion while the model it reads still exists
    delete document_;
    document_ = nullptr;
    delete viewer_;
}

QWidget* MainWindow::viewport() const { return viewer_->getGLWidget(); }
SoSeparator* MainWindow::sceneRoot() const { return document_->root(); }

QAction* MainWindow::action(const QString& name) const { return findChild<QAction*>(name); }

QList<QAction*> MainWindow::namedActions() const
{
    QList<QAction*> all;
    for (QAction* a : findChildren<QAction*>()) {
        if (a->objectName().contains('.')) all << a;
    }
    std::sort(all.begin(), all.end(), [](QAction* a, QAction* b) { return a->objectName() < b->objectName(); });
    return all;
}

void MainWindow::createActions()
{
    auto make = [this](QMenu* menu, const char* name, const QString& text, const QKeySequence& key, auto slot) {
        auto* a = new QAction(text, this);
        a->setObjectName(QString::fromLatin1(name));
        if (!key.isEmpty()) a->setShortcut(key);
        connect(a, &QAction::triggered, this, slot);
        menu->addAction(a);
        return a;
    };
    QMenu* file = menuBar()->addMenu(tr("&File"));
    make(file, "file.new", tr("&New"), QKeySequence::New, [this]() { newDocument(); });
    make(file, "file.open", tr("&Open..."), QKeySequence::Open, [this]() { openDocument(); });
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    updateRecentMenu();
    make(file, "file.save", tr("&Save"), QKeySequence::Save, [this]() { saveDocument(); });
    make(file, "file.saveAs", tr("Save &As..."), QKeySequence::SaveAs, [this]() { saveDocumentAs(); });
    make(file, "file.exportIv", tr("&Export Open Inventor (.iv)..."), QKeySequence(), [this]() { exportDocument(); });
    make(file, "file.exportStep", tr("Export &STEP..."), QKeySequence(), [this]() { exportGeometry(solvers::exchange::Format::Step); });
    make(file, "file.exportIges", tr("Export &IGES..."), QKeySequence(), [this]() { exportGeometry(solvers::exchange::Format::Iges); });
    make(file, "file.exportStl", tr("Export S&TL..."), QKeySequence(), [this]() { exportGeometry(solvers::exchange::Format::Stl); });
    make(file, "file.exportObj", tr("Export &OBJ..."), QKeySequence(), [this]() { exportGeometry(solvers::exchange::Format::Obj); });
    make(file, "file.recover", tr("Recover &Unsaved Work..."), QKeySequence(), [this]() { recoverFromMenu(); });
    make(file, "file.autosaveInterval", tr("Autosave &Interval..."), QKeySequence(), [this]() { chooseAutosaveInterval(); });
    file->addSeparator();
    make(file, "file.quit", tr("&Quit"), QKeySequence::Quit, [this]() { close(); });

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = document_->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setObjectName(QStringLiteral("edit.undo"));
    undo->setShortcut(QKeySequence::Undo);
    edit->addAction(undo);
    QAction* redo = document_->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setObjectName(QStringLiteral("edit.redo"));
    redo->setShortcuts({QKeySequence::Redo, QKeySequence(QStringLiteral("Ctrl+Y"))});
    edit->addAction(redo);
    make(edit, "edit.delete", tr("&Delete selection"), QKeySequence::Delete, [this]() { document_->deleteSelection(); });
    // Seed 000 §3.2: a fixed element keeps its shape through every edit and solve; the plan changes.
    make(edit, "edit.toggleFixed", tr("&Fix / free the selection"), QKeySequence(QStringLiteral("Ctrl+Shift+F")),
         [this]() { document_->toggleSelectionFixed(); });
    make(edit, "edit.removePins", tr("Remove the selected curve's &pins"), QKeySequence(), [this]() { document_->removeSelectionPins(); });

    make(edit, "stroke.useRecognized", tr("Use the recognized shape for the last stroke"), QKeySequence(),
         [this]() { document_->chooseRecognized(true); });
    make(edit, "stroke.nextCandidate", tr("Use the next recognition candidate for the last stroke"),
         QKeySequence(QStringLiteral("N")), [this]() { document_->chooseNextCandidate(); });
    make(edit, "stroke.useFreeform", tr("Use the freeform curve for the last stroke"), QKeySequence(),
         [this]() { document_->chooseRecognized(false); });
    // Thesis §3.1.3: the user model learns from corrections; the designer can start afresh.
    make(edit, "stroke.forgetHabits", tr("Forget recognition &habits"), QKeySequence(), [this]() { document_->forgetHabits(); });

    QMenu* plane = menuBar()->addMenu(tr("&Plane"));
    make(plane, "plane.add", tr("&Add plane facing the view"), QKeySequence(QStringLiteral("Ctrl+P")), [this]() { addPlaneFacingViewer(); });

    QMenu* modeMenu = menuBar()->addMenu(tr("&Mode"));
    modes_ = new QActionGroup(this);
    // Each mode: its action name, a short label for the Modes dock's button, the menu text, the hot key.
    auto modeAction = [&](const char* name, const QString& label, const QString& text, const QString& key, Mode m,
                          std::optional<model::Construction> surface = std::nullopt) {
        QAction* a = make(modeMenu, name, text, QKeySequence(key), [this, m, surface]() { setMode(m, surface); });
        a->setIconText(label);
        a->setCheckable(true);
        modes_->addAction(a);
    };
    modeAction("mode.view", tr("View"), tr("&View (turn, pan, zoom)"), QStringLiteral("V"), Mode::View);
    modeAction("mode.sketch", tr("Sketch"), tr("&Sketch on the active plane"), QStringLiteral("S"), Mode::Sketch);
    modeAction("mode.oversketch", tr("Over-sketch"), tr("&Over-sketch a curve"), QStringLiteral("O"), Mode::Oversketch);
    modeAction("mode.lift", tr("Lift"), tr("&Lift a stroke between two curves into space"), QStringLiteral("L"), Mode::Lift);
    modeAction("mode.pull", tr("Pull"), tr("&Pull a curve point"), QStringLiteral("P"), Mode::Pull);
    modeAction("mode.select", tr("Select"), tr("S&elect"), QStringLiteral("E"), Mode::Select);
    // Thesis ch. 6: strokes near the selected surface become target curves it is deformed onto.
    modeAction("mode.sculpt", tr("Sculpt"), tr("Scul&pt the selected surface with target curves"), QStringLiteral("Y"), Mode::Sculpt);
    // Seed 000 §3.1: with a surface selected, Sculpting (strokes become curves it passes through);
    // without, Interpolation (picked curves get a surface through them).
    modeAction("mode.incidence", tr("Curves on surface"),
               tr("Curves on surface (&incidence): draw onto the selected surface, or pick curves for a surface through them"),
               QStringLiteral("I"), Mode::Incidence);
    modeMenu->addSeparator();
    // The surface modes (thesis §5.1.3, §5.2; seed 000): pick the curves, the surface follows them.
    auto surfaceAction = [&](const char* name, const QString& label, const QString& text, const QString& key, model::Construction mode) {
        modeAction(name, label, text, key, Mode::Surface, mode);
    };
    using model::Construction;
    surfaceAction("mode.fill", tr("Fill"), tr("&Fill 2-4 boundary curves"), QStringLiteral("F"), Construction::Fill);
    surfaceAction("mode.revolve", tr("Revolve"), tr("&Revolve a profile about an axis line"), QStringLiteral("R"), Construction::Revolve);
    surfaceAction("mode.extrude", tr("Extrude"), tr("E&xtrude: drag a curve out"), QStringLiteral("X"), Construction::Extrude);
    surfaceAction("mode.sweep", tr("Sweep"), tr("S&weep a profile along a path"), QStringLiteral("W"), Construction::Sweep);
    surfaceAction("mode.loft", tr("Loft / skin"), tr("Loft / s&kin through sections"), QStringLiteral("K"), Construction::Loft);
    surfaceAction("mode.boundaryRotation", tr("Boundary rot."), tr("&Boundary rotation of two outlines"), QStringLiteral("B"),
                  Construction::BoundaryRotation);
    surfaceAction("mode.railRotation", tr("Rail rot."), tr("Rail rotation (&G): two rails and a profile"), QStringLiteral("G"),
                  Construction::RailRotation);
    surfaceAction("mode.gordon", tr("Gordon"), tr("Gordon s&urface through a grid of curves"), QStringLiteral("U"), Construction::Gordon);
    surfaceAction("mode.network", tr("Network mesh"), tr("&Mesh a closed loop of curves"), QStringLiteral("M"), Construction::Network);
    QAction* g1 = make(modeMenu, "surface.fillTangent", tr("Fill &tangent to the surfaces its boundaries come from"),
                       QKeySequence(QStringLiteral("T")), [this](bool on) { document_->setFillTangent(on); });
    g1->setCheckable(true);
    g1->setChecked(document_->fillTangent());
    make(modeMenu, "surface.build", tr("Build the surface from the picked curves"), QKeySequence(Qt::Key_Return), [this]() {
        if (mode_ != Mode::Incidence) {
            document_->buildSurface();
        } else if (document_->buildIncidenceSurface()) {
            updateStatus();  // Interpolation made the surface: Sculpting on it from now on
        }
    });
    make(modeMenu, "surface.cancel", tr("Forget the picked curves"), QKeySequence(Qt::Key_Escape), [this]() {
        document_->cancelSurface();
        document_->cancelIncidenceCurves();
    });
    // Sculpt mode's tools (thesis ch. 6): what a stroke or a click on the surface does.
    QMenu* sculptMenu = menuBar()->addMenu(tr("Scul&pt"));
    auto* sculptTools = new QActionGroup(this);
    auto sculptTool = [&](const char* name, const QString& text, const QString& key, SketchDocument::SculptTool tool) {
        QAction* a = make(sculptMenu, name, text, QKeySequence(key), [this, tool]() {
            document_->setSculptTool(tool);
            if (mode_ != Mode::Sculpt) setMode(Mode::Sculpt);
            updateStatus();
        });
        a->setCheckable(true);
        a->setChecked(document_->sculptTool() == tool);
        sculptTools->addAction(a);
    };
    using Tool = SketchDocument::SculptTool;
    sculptTool("sculpt.target", tr("&Target curves: a stroke near the surface pulls it"), QStringLiteral("Alt+T"), Tool::Target);
    sculptTool("sculpt.bound", tr("&Bound: a closed stroke over the surface limits the sculpt"), QStringLiteral("Alt+B"), Tool::Bound);
    sculptTool("sculpt.handle", tr("&Handles: a click on the surface drops a point to drag and turn"), QStringLiteral("Alt+H"), Tool::Handle);
    sculptTool("sculpt.block", tr("B&lock: a click blocks or frees the nearest control point"), QStringLiteral("Alt+K"), Tool::Block);
    sculptTool("sculpt.distance", tr("&Distance: two clicks hold two surface points apart"), QStringLiteral("Alt+D"), Tool::Distance);
    // Seed 001 §5.2: a marking picks a parameter line of a free-form surface, a stroke over the strip redraws it.
    sculptTool("sculpt.resketch", tr("&Re-sketch a parameter line: mark it, then draw its new shape over the strip"), QStringLiteral("Alt+R"),
               Tool::Resketch);
    make(sculptMenu, "sculpt.resketchRulings", tr("Re-sketch: turn the strip's rulings (normal, &across, view direction)"),
         QKeySequence(QStringLiteral("Alt+A")), [this]() { document_->cycleResketchRulings(); });
    sculptMenu->addSeparator();
    QAction* holdTangent = make(sculptMenu, "sculpt.holdTangent", tr("Hold the surface's tangent &across the last target curve"),
                                QKeySequence(QStringLiteral("Alt+G")), [this](bool on) {
                                    document_->setSculptCurveTangent(document_->sculptBase(), document_->recognizedCurve(), on);
                                });
    holdTangent->setCheckable(true);
    createAestheticsMenu();
    createSolidMenu();
    QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
    make(viewMenu, "view.all", tr("&Frame the scene"), QKeySequence(QStringLiteral("Home")), [this]() { frameScene(); });
    QAction* polygons = make(viewMenu, "view.controlPolygons", tr("&Control polygons"), QKeySequence(QStringLiteral("C")),
                             [this](bool on) { document_->view().setControlPolygonsVisible(on); });
    polygons->setCheckable(true);
    // Hiding planes is a view setting, like the control polygons: not an edit of the model, not
    // undone, not saved (the boat's five planes bury its hull; the designer looks past them).
    viewMenu->addSeparator();
    make(viewMenu, "view.hidePlane", tr("&Hide the selected plane"), QKeySequence(QStringLiteral("H")), [this]() { hideSelectedPlane(); });
    make(viewMenu, "view.hidePlanes", tr("Hide &all planes"), QKeySequence(QStringLiteral("Ctrl+Shift+H")), [this]() { setPlanesVisible(false); });
    make(viewMenu, "view.showPlanes", tr("&Show all planes"), QKeySequence(QStringLiteral("Shift+H")), [this]() { setPlanesVisible(true); });
    viewMenu->addSeparator();
    // Zebra and curvature colouring of the selected surface (all surfaces when none is selected).
    createReferenceActions(file, edit, viewMenu);
    new SurfaceDisplayMenu(this, viewMenu, *document_,
                           viewer_ ? std::function<SoCamera*()>([this]() { return viewer_->getCamera(); }) : std::function<SoCamera*()>());
    // View > Stereo and View > VR session… (ui/stereo_menu.h).
    new StereoMenu(this, viewMenu, static_cast<StereoExaminerViewer*>(viewer_));
}

void MainWindow::hideSelectedPlane()
{
    const model::Entity* e = document_->model().find(document_->selection());
    if (!e || e->kind != model::EntityKind::Plane) {
        statusBar()->showMessage(tr("Select a plane to hide it (E, then click its jack), or View > Hide all planes."));
        return;
    }
    document_->planeDraggers().setVisible(e->id, false);
    // A hidden plane is not a visible selection: Delete must not remove what cannot be seen.
    document_->select(0);
    statusBar()->showMessage(tr("Plane %1 hidden; its curves stay. Shift+H shows all planes.").arg(e->id));
}

void MainWindow::setPlanesVisible(bool visible)
{
    int count = 0;
    for (const auto& [id, e] : document_->model().entities()) {
        if (e.kind != model::EntityKind::Plane) continue;
        document_->planeDraggers().setVisible(id, visible);
        ++count;
    }
    const model::Entity* selected = document_->model().find(document_->selection());
    if (!visible && selected && selected->kind == model::EntityKind::Plane) document_->select(0);
    statusBar()->showMessage(visible ? tr("%1 planes shown.").arg(count) : tr("%1 planes hidden; Shift+H shows them.").arg(count));
}

void MainWindow::createDocks()
{
    auto* modes = new ModesDock({action(QStringLiteral("mode.view")), action(QStringLiteral("mode.sketch")),
                                 action(QStringLiteral("mode.oversketch")), action(QStringLiteral("mode.lift")),
                                 action(QStringLiteral("mode.pull")),
                                 action(QStringLiteral("mode.select")), action(QStringLiteral("mode.sculpt")),
                                 action(QStringLiteral("mode.fill")),
                                 action(QStringLiteral("mode.revolve")), action(QStringLiteral("mode.extrude")),
                                 action(QStringLiteral("mode.sweep")), action(QStringLiteral("mode.loft")),
                                 action(QStringLiteral("mode.boundaryRotation")), action(QStringLiteral("mode.railRotation")),
                                 action(QStringLiteral("mode.gordon")), action(QStringLiteral("mode.network")),
                                 action(QStringLiteral("plane.add"))},
                                this);
    addDockWidget(Qt::LeftDockWidgetArea, modes);
    entities_ = new EntityListDock(this);
    addDockWidget(Qt::RightDockWidgetArea, entities_);
    inspector_ = new InspectorDock(this);
    addDockWidget(Qt::RightDockWidgetArea, inspector_);
    recognition_ = new RecognitionDock(*document_, action(QStringLiteral("stroke.useRecognized")),
                                       action(QStringLiteral("stroke.useFreeform")), this);
    addDockWidget(Qt::LeftDockWidgetArea, recognition_);
    // The L-curve of the selected incidence surface: a tab behind the inspector (the right column has
    // no room for a plot beside it), brought forward when such a surface is selected; View > L-curve.
    auto* lcurve = new LCurveDock(*document_, this);
    addDockWidget(Qt::RightDockWidgetArea, lcurve);
    tabifyDockWidget(inspector_, lcurve);
    // The selected curve's aesthetic analysis and the comb's controls: another tab there; View >
    // Aesthetics brings it forward, View > Curvature comb draws the comb.
    auto* aesthetics = new AestheticsDock(*document_, this);
    addDockWidget(Qt::RightDockWidgetArea, aesthetics);
    tabifyDockWidget(inspector_, aesthetics);
    inspector_->raise();
    lcurve->toggleViewAction()->setObjectName(QStringLiteral("view.lcurve"));
    if (auto* viewMenu = qobject_cast<QMenu*>(action(QStringLiteral("view.all"))->associatedWidgets().value(0))) {
        viewMenu->addAction(lcurve->toggleViewAction());
        viewMenu->addAction(aesthetics->showAction());
        viewMenu->addAction(aesthetics->combAction());
        // Each dock can be closed and brought back (a window fitted to a small screen hides them).
        QMenu* docks = viewMenu->addMenu(tr("&Docks"));
        for (QDockWidget* dock : {static_cast<QDockWidget*>(modes), static_cast<QDockWidget*>(recognition_),
                                  static_cast<QDockWidget*>(entities_), static_cast<QDockWidget*>(inspector_),
                                  static_cast<QDockWidget*>(aesthetics)})
            docks->addAction(dock->toggleViewAction());
    }
    connect(document_, &SketchDocument::entitiesChanged, lcurve, &LCurveDock::refresh);
    connect(document_, &SketchDocument::selectionChanged, lcurve, [lcurve]() {
        lcurve->refresh();
        if (lcurve->surface() != 0) lcurve->raise();
    });
    connect(inspector_, &InspectorDock::fixedPointsEdited, this,
            [this](model::EntityId curve, std::vector<int> fixed) { document_->setFixedPoints(curve, std::move(fixed)); });
    connect(inspector_, &InspectorDock::stiffnessEdited, this,
            [this](model::EntityId surface, double stiffness) { document_->setSculptStiffness(surface, stiffness); });
    connect(inspector_, &InspectorDock::holdNormalsEdited, this,
            [this](model::EntityId surface, bool hold) { document_->setSculptHoldNormals(surface, hold); });
    connect(inspector_, &InspectorDock::distanceEdited, this,
            [this](model::EntityId surface, int index, double distance) { document_->setSculptDistance(surface, index, distance); });
    connect(entities_, &EntityListDock::entityPicked, this, [this](model::EntityId id) { document_->select(id); });
}

void MainWindow::setMode(Mode mode, std::optional<model::Construction> surfaceMode)
{
    mode_ = mode;
    surfaceMode_ = mode == Mode::Surface ? surfaceMode : std::nullopt;
    document_->setSurfaceMode(surfaceMode_);
    // Sketching and selecting need the mouse in the scene graph (interaction mode); viewing gives it
    // to the examiner's camera.
    if (viewer_) viewer_->setViewing(mode == Mode::View ? TRUE : FALSE);
    document_->strokeInput().setEnabled(mode == Mode::Sketch || mode == Mode::Oversketch || mode == Mode::Lift || mode == Mode::Sculpt ||
                                        mode == Mode::Incidence);
    // Sculpt works on the surface selected when it starts (a later stroke deforms the last sculpt).
    document_->setSculptBase(mode == Mode::Sculpt ? document_->selection() : 0);
    // So do the incidence modes: a selected surface is drawn onto; a selected plane is where the
    // next curve goes onto the surface drawn onto before; else curves are picked (Interpolation).
    const model::Entity* selected = document_->model().find(document_->selection());
    if (mode == Mode::Incidence) {
        if (selected && selected->kind == model::EntityKind::Surface) document_->setIncidenceBase(selected->id);
        else if (!selected || selected->kind != model::EntityKind::Plane) document_->setIncidenceBase(0);
    }
    document_->cancelIncidenceCurves();
    document_->curvePull().setEnabled(mode == Mode::Pull || surfaceMode_ == model::Construction::Extrude);
    document_->setStrokeMode(mode == Mode::Oversketch ? SketchDocument::StrokeMode::Oversketch
                             : mode == Mode::Lift     ? SketchDocument::StrokeMode::Lift
                             : mode == Mode::Sculpt   ? SketchDocument::StrokeMode::Sculpt
                             : mode == Mode::Incidence ? SketchDocument::StrokeMode::Incidence
                                                      : SketchDocument::StrokeMode::Sketch);
    for (QAction* a : modes_->actions()) {
        if (a->objectName() == modeActionName()) a->setChecked(true);
    }
    updateStatus();
}

void MainWindow::updateTitle()
{
    const QString name = document_->path().isEmpty() ? tr("untitled") : QFileInfo(document_->path()).fileName();
    setWindowTitle(QStringLiteral("Sculptline — %1[*]").arg(name));
    setWindowModified(!document_->undoStack()->isClean());
}

void MainWindow::showDocument(const model::SceneDocument& doc, const QString& path)
{
    viewer_->setSceneGraph(nullptr);
    document_->load(doc, path);
    viewer_->setSceneGraph(document_->root());
    frameScene();
    updateTitle();
    updateStatus();
}

void MainWindow::frameScene()
{
    SoCamera* camera = viewer_->getCamera();
    if (!camera) return;
    // Z is up in the model; look from the front right and above.
    camera->orientation = scene::rotationLookingAlong(kViewDirection, Eigen::Vector3d::UnitZ());
    viewer_->viewAll();
    // viewAll frames the bounding sphere, which leaves a wide margin around a flat-ish scene.
    SbVec3f forward;
    camera->orientation.getValue().multVec(SbVec3f(0, 0, -1), forward);
    const float distance = camera->focalDistance.getValue();
    camera->position = camera->position.getValue() + forward * (distance * (1.0f - kFramingZoom));
    camera->focalDistance = distance * kFramingZoom;
}

void MainWindow::addPlaneFacingViewer()
{
    SoCamera* camera = viewer_->getCamera();
    if (!camera) return;
    // Through the point the view turns about, facing the viewer, its X along the screen's right:
    // a fresh sheet where the designer is looking.
    SbVec3f forward, right;
    camera->orientation.getValue().multVec(SbVec3f(0, 0, -1), forward);
    camera->orientation.getValue().multVec(SbVec3f(1, 0, 0), right);
    const SbVec3f centre = camera->position.getValue() + forward * camera->focalDistance.getValue();
    document_->addPlane(model::PlaneFrame::fromNormal(scene::toEigen(centre), -scene::toEigen(forward), kNewPlaneSize,
                                                      scene::toEigen(right)));
}

SbBool MainWindow::viewerEvent(void* self, QEvent* event)
{
    auto* window = static_cast<MainWindow*>(self);
    if (window->navigate(event)) return TRUE;
    if (event->type() != QEvent::MouseButtonPress) return FALSE;
    auto* mouse = static_cast<QMouseEvent*>(event);
    if (mouse->button() != Qt::LeftButton) return FALSE;
    if (window->mode_ == Mode::Surface && window->surfaceMode_ != model::Construction::Extrude) {
        // A click picks the nearest curve as the next input; nothing else sees the press.
        if (const model::EntityId curve = window->curveNear(mouse->pos())) window->document_->pickSurfaceInput(curve);
        return TRUE;
    }
    if (window->mode_ == Mode::Incidence && window->document_->incidenceBase() == 0) {
        // Interpolation: a click picks the nearest curve for the surface through them.
        if (const model::EntityId curve = window->curveNear(mouse->pos())) window->document_->pickIncidenceCurve(curve);
        return TRUE;
    }
    if (window->mode_ != Mode::Select) return FALSE;
    // Let the press go on to the scene graph as well, so a press on a dragger selects and drags.
    window->pickAt(mouse->pos());
    return FALSE;
}

bool MainWindow::navigate(QEvent* event)
{
    SoCamera* camera = viewer_->getCamera();
    switch (event->type()) {
    case QEvent::Wheel:
        ViewNavigation::wheel(*static_cast<QWheelEvent*>(event), camera);
        return true;
    case QEvent::MouseButtonPress: {
        // A stroke or a drag under way keeps the mouse; the other buttons wait for it to end.
        if (document_->strokeInput().drawing() || document_->dragging()) return false;
        return navigation_->press(*static_cast<QMouseEvent*>(event));
    }
    case QEvent::MouseMove:
        return navigation_->move(*static_cast<QMouseEvent*>(event), camera, viewport()->height());
    case QEvent::MouseButtonRelease: {
        bool click = false;
        auto* mouse = static_cast<QMouseEvent*>(event);
        if (!navigation_->release(*mouse, &click)) return false;
        if (click) showContextMenu(mouse->pos());
        return true;
    }
    default: return false;
    }
}

void MainWindow::showContextMenu(const QPoint& position)
{
    // What lies under the pointer is selected, as a left click in Select mode would, and the menu
    // offers what can be done to it (the same actions as the menus, so shortcuts and undo agree).
    pickAt(position);
    const model::Entity* e = document_->model().find(document_->selection());
    if (!contextMenu_) {
        contextMenu_ = new QMenu(this);
        contextMenu_->setObjectName(QStringLiteral("menu.context"));
    }
    contextMenu_->clear();
    auto add = [this](const char* name, const QString& text) {
        QAction* a = action(QString::fromLatin1(name));
        if (!a) return;
        QAction* item = contextMenu_->addAction(text, a, &QAction::trigger);
        item->setShortcut(a->shortcut());
        item->setObjectName(QStringLiteral("context.") + QString::fromLatin1(name));
    };
    if (!e) {
        contextMenu_->setTitle(tr("View"));
        add("plane.add", tr("Add a plane facing the view"));
        add("view.all", tr("Frame the scene"));
        add("view.showPlanes", tr("Show all planes"));
        add("view.hidePlanes", tr("Hide all planes"));
    } else if (e->kind == model::EntityKind::Curve) {
        contextMenu_->setTitle(tr("Curve %1").arg(e->id));
        add("edit.toggleFixed", e->fixed ? tr("Free curve %1").arg(e->id) : tr("Fix curve %1").arg(e->id));
        add("mode.oversketch", tr("Over-sketch it"));
        add("mode.pull", tr("Pull its points"));
        add("edit.removePins", tr("Remove its pins"));
        add("edit.delete", tr("Delete curve %1").arg(e->id));
    } else if (e->kind == model::EntityKind::Plane) {
        contextMenu_->setTitle(tr("Plane %1").arg(e->id));
        add("mode.sketch", tr("Sketch on plane %1").arg(e->id));
        add("view.hidePlane", tr("Hide plane %1").arg(e->id));
        add("edit.toggleFixed", e->fixed ? tr("Free plane %1").arg(e->id) : tr("Fix plane %1").arg(e->id));
        add("edit.delete", tr("Delete plane %1").arg(e->id));
    } else {
        contextMenu_->setTitle(tr("Surface %1").arg(e->id));
        add("mode.sculpt", tr("Sculpt it with target curves"));
        add("mode.incidence", tr("Draw curves onto it"));
        add("edit.toggleFixed", e->fixed ? tr("Free surface %1").arg(e->id) : tr("Fix surface %1").arg(e->id));
        add("edit.delete", tr("Delete surface %1").arg(e->id));
    }
    contextMenu_->popup(viewport()->mapToGlobal(position));
}

bool MainWindow::pickAt(const QPoint& position)
{
    const SbViewportRegion& viewport = viewer_->getViewportRegion();
    const SbVec2s size = viewport.getViewportSizePixels();
    SoRayPickAction pick(viewport);
    // Qt counts pixels from the top, Coin from the bottom.
    pick.setPoint(SbVec2s(static_cast<short>(position.x()), static_cast<short>(size[1] - 1 - position.y())));
    pick.setRadius(4);
    pick.setPickAll(TRUE);
    pick.apply(viewer_->getSceneManager()->getSceneGraph());
    model::EntityId picked = 0;
    // What a click selects: planes (through their draggers), curves and surfaces, the nearest; but a
    // curve drawn on a plane lies in it, so where the plane and one of its curves are hit at the same
    // depth the curve is meant.
    const SoPickedPointList& points = pick.getPickedPointList();
    const std::vector<model::EntityKind> kinds{model::EntityKind::Curve, model::EntityKind::Plane, model::EntityKind::Surface};
    if (points.getLength() > 0) {
        const auto first = scene::entityAt(points[0]->getPath(), kinds);
        if (first) picked = first->id;
        const model::Entity* e = document_->model().find(picked);
        for (int k = 1; e && e->kind == model::EntityKind::Plane && k < points.getLength(); ++k) {
            if ((points[k]->getPoint() - points[0]->getPoint()).length() > kSameDepth) break;
            const auto next = scene::entityAt(points[k]->getPath(), kinds);
            const model::Entity* curve = next ? document_->model().find(next->id) : nullptr;
            if (curve && curve->kind == model::EntityKind::Curve) {
                picked = curve->id;
                break;
            }
        }
    }
    document_->select(picked);
    return picked != 0;
}

QPoint MainWindow::pixelOf(const Eigen::Vector3d& world) const
{
    SoCamera* camera = viewer_->getCamera();
    if (!camera) return {};
    const SbViewportRegion& viewport = viewer_->getViewportRegion();
    const SbVec2s size = viewport.getViewportSizePixels();
    SbVec3f screen;
    camera->getViewVolume(viewport.getViewportAspectRatio()).projectToScreen(scene::toSb(world), screen);
    // Normalized [0, 1] with y up -> Qt pixels with y down (the inverse of pickAt's flip).
    return QPoint(static_cast<int>(std::lround(screen[0] * size[0])), static_cast<int>(std::lround(size[1] - 1 - screen[1] * size[1])));
}

model::EntityId MainWindow::curveNear(const QPoint& position) const
{
    model::EntityId best = 0;
    double bestDistance = kCurvePickRadius;
    for (const auto& [id, e] : document_->model().entities()) {
        if (e.kind != model::EntityKind::Curve || !e.world) continue;
        // Dense enough that the chord between samples stays within a pixel or two of the curve at
        // the sizes curves have on screen.
        const double u0 = e.world->domainStart(), u1 = e.world->domainEnd();
        for (int k = 0; k <= kCurvePickSamples; ++k) {
            const QPoint p = pixelOf(e.world->evaluate(u0 + (u1 - u0) * k / kCurvePickSamples));
            const double d = std::hypot(p.x() - position.x(), p.y() - position.y());
            if (d < bestDistance) {
                bestDistance = d;
                best = id;
            }
        }
    }
    return best;
}

bool MainWindow::refuseDialog(const char* action) const
{
    if (automated_) std::cerr << "sculptline: " << action << " needs a file dialog, which an automated run cannot answer; use --save/--export-iv/--export-step/--export-iges/--export-stl/--export-obj/--import-reference\n";
    return automated_;
}

QSize MainWindow::renderedViewportSize() const
{
    const SbVec2s pixels = viewer_->getViewportRegion().getWindowSize();
    const qreal ratio = viewport()->devicePixelRatioF();
    return QSize(qRound(pixels[0] / ratio), qRound(pixels[1] / ratio));
}

bool MainWindow::resizeViewport(int width, int height)
{
    // The GL area's share of the window is known only once the layout has run (docks, menu and
    // status bar settle after show()), so the window is corrected until the area matches. Two
    // measures of the area must agree: the viewport SoQt renders into, which it takes from its
    // component's resize as the layout runs, and the GL widget that is read back, which follows
    // that later, much later on a loaded machine. Measured by the GL widget alone, a window left
    // wide after its docks were hidden passed for the right size while the area still waited for
    // its share (CI drew a stereo test's sphere at x 672 of an 800-wide picture).
    QWidget* gl = viewport();
    const QSize target(width, height);
    QElapsedTimer clock;
    clock.start();
    // A layout change just made (docks hidden or tabbed) reaches the GL area only through events.
    QApplication::processEvents();
    for (;;) {
        const QSize area = gl->size();
        const QSize rendered = renderedViewportSize();
        if (area == target && rendered == target) return true;
        if (clock.elapsed() > kViewportSettleMs) return false;
        // The window is corrected by the size the renderer gives the area (the widget follows it).
        const QSize given = rendered.isEmpty() ? area : rendered;
        const QSize extra = size() - given;
        const QSize wanted(width + std::clamp(extra.width(), 0, kMaxViewportSurround),
                           height + std::clamp(extra.height(), 0, kMaxViewportSurround));
        if (given != target && wanted != size()) resize(wanted);
        // Events for a few milliseconds, sleeping between them rather than spinning.
        QEventLoop pause;
        QTimer::singleShot(kViewportSettleStepMs, &pause, &QEventLoop::quit);
        pause.exec();
    }
}

bool MainWindow::fitScreen()
{
    const QScreen* screen = this->screen() ? this->screen() : QGuiApplication::primaryScreen();
    if (!screen) return true;
    const QRect available = screen->availableGeometry();
    const QRect frame = frameGeometry();
    if (frame.width() > available.width() || frame.height() > available.height()) return false;
    // Big enough, but partly off the screen: moved onto it.
    if (!available.contains(frame)) {
        move(std::clamp(frame.left(), available.left(), available.right() + 1 - frame.width()),
             std::clamp(frame.top(), available.top(), available.bottom() + 1 - frame.height()));
        QApplication::processEvents();
    }
    return true;
}

void MainWindow::setViewportSize(int width, int height)
{
    // A hidden window's GL area has no size of its own yet (Qt's default 100 x 30, whatever the
    // window's): measured then, every correction grew the window (gui_surface_display drew its
    // picture at 13928 x 11138). The size is taken once the window is shown.
    if (!isVisible()) {
        pendingViewportSize_ = QSize(width, height);
        return;
    }
    pendingViewportSize_.reset();
    const auto settle = [this, width, height]() {
        if (resizeViewport(width, height) || !automated_) return;
        const QSize reached = viewport()->size();
        std::cerr << "sculptline: the viewport did not reach " << width << " x " << height << " within "
                  << kViewportSettleMs << " ms: it is " << reached.width() << " x " << reached.height() << "\n";
    };
    settle();
    if (fitScreen()) return;
    // The viewport's size is what a replay relies on; the docks give way: first one column of tabs
    // instead of two, then, where even that does not fit beside the viewport, no docks (View >
    // Docks brings each back).
    const QList<QDockWidget*> docks = findChildren<QDockWidget*>();
    QDockWidget* first = entities_;
    for (QDockWidget* dock : docks) {
        if (dock == first) continue;
        if (dockWidgetArea(dock) != Qt::RightDockWidgetArea) addDockWidget(Qt::RightDockWidgetArea, dock);
        if (!tabifiedDockWidgets(first).contains(dock)) tabifyDockWidget(first, dock);
    }
    first->raise();
    settle();
    QString message = tr("The docks are tabbed in one column to fit a %1 x %2 viewport on this screen.").arg(width).arg(height);
    if (!fitScreen()) {
        for (QDockWidget* dock : docks) dock->hide();
        settle();
        fitScreen();
        message = tr("The docks do not fit beside a %1 x %2 viewport on this screen: hidden (View > Docks shows them).").arg(width).arg(height);
    }
    statusBar()->showMessage(message);
    if (automated_) std::cerr << "sculptline: " << message.toStdString() << "\n";
}

void MainWindow::showEvent(QShowEvent* event)
{
    QMainWindow::showEvent(event);
    if (!pendingViewportSize_) return;
    // After the show has been handled: the layout needs the event loop to give the GL area its share.
    QTimer::singleShot(0, this, [this]() {
        if (pendingViewportSize_) setViewportSize(pendingViewportSize_->width(), pendingViewportSize_->height());
    });
}

void MainWindow::renderViewport() { viewer_->render(); }

QImage MainWindow::grabViewport()
{
    renderViewport();
    return static_cast<QGLWidget*>(viewer_->getGLWidget())->grabFrameBuffer();
}

}  // namespace sculptline::ui
