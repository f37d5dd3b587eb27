#pragma once
// The main window: a SoQt examiner viewer in the centre, docks for modes, entities and the
// inspector, File/Edit/Plane/Mode menus whose actions all carry an object name (`file.save`,
// `mode.sketch`, ...: the names replays and --list-actions use), and a status bar that tells the
// user what the current mode does with the mouse.
#include "model/model.h"
#include "model/document.h"
#include "solvers/exchange/exchange.h"

#include <QImage>
#include <QMainWindow>

#include <memory>
#include <string>

#include <Inventor/SbBasic.h>

class QAction;
class QActionGroup;
class QMenu;
class QEvent;
class SoQtExaminerViewer;
class SoSeparator;

namespace sculptline::ui {

class Autosaver;
class EntityListDock;
class InspectorDock;
class RecognitionDock;
class SketchDocument;
class SolidBuilder;
class UndoHistory;
class ViewNavigation;

/// Surface: one of the surface modes (MainWindow::surfaceMode() says which).
enum class Mode { View, Sketch, Oversketch, Lift, Pull, Select, Surface, Sculpt, Incidence };

/// @note SoQt::init() must have been called before construction.
class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    /// @param withViewer false: no 3D viewer (and no OpenGL), only the menus, actions and docks, as
    ///        `--list-actions` needs without a display; nothing that draws may be called then.
    explicit MainWindow(QWidget* parent = nullptr, bool withViewer = true);
    ~MainWindow() override;

    /// Replaces the document by `doc` and frames it (a three-quarter view from the front right).
    void showDocument(const model::SceneDocument& doc, const QString& path);

    /// Resizes the window so that the 3D viewport (the GL area) is width x height pixels. Where
    /// the window would then not fit its screen, the docks give way (tabbed in one column, or
    /// hidden) and the status bar says so; the window is moved onto the screen. On a hidden
    /// window this happens once it is shown (from the event loop after show()).
    void setViewportSize(int width, int height);
    /// The size of the viewport SoQt renders into, in the widget's (logical) pixels; the GL area's
    /// own size (viewport()) follows it one event later.
    QSize renderedViewportSize() const;
    /// Renders now (under Xvfb no expose may come to trigger the first frame, ../shared/NOTES.md).
    void renderViewport();
    /// Renders and reads the GL framebuffer (QWidget::grab() is black for a GL area).
    QImage grabViewport();

    SoQtExaminerViewer* viewer() const { return viewer_; }
    QWidget* viewport() const;
    SoSeparator* sceneRoot() const;
    SketchDocument& document() { return *document_; }
    /// Every named action, sorted by name.
    QList<QAction*> namedActions() const;
    QAction* action(const QString& name) const;
    /// The viewport pixel (origin top-left) where the camera shows model point `world`.
    QPoint pixelOf(const Eigen::Vector3d& world) const;
    Mode mode() const { return mode_; }
    /// The context menu a right click last opened (null before the first).
    QMenu* contextMenu() const { return contextMenu_; }
    /// The solvers/surfaces mode name while mode() is Surface.
    std::optional<model::Construction> surfaceMode() const { return surfaceMode_; }
    /// In an automated run (a replay) nobody can answer a dialog: file dialogs are not opened (the
    /// action says so on stderr) and unsaved changes are discarded without asking.
    void setAutomated(bool automated) { automated_ = automated; }
    bool automated() const { return automated_; }

    /// Tells a person in a dialog why the document they asked for is not the one open (the
    /// default scene is shown instead).
    void reportOpenFailure(const QString& reason);

    /// Writes the unsaved work to a recovery file in `folder` every `seconds` (ui/autosave.h);
    /// failures go to the status bar (and stderr in an automated run).
    void enableAutosave(const QString& folder, int seconds);
    Autosaver* autosaver() const { return autosaver_; }
    /// File > Autosave Interval: asks for the seconds between autosaves (0 = off), applies them
    /// and keeps them (QSettings "autosaveInterval") for the next start.
    void chooseAutosaveInterval();
    /// The interval File > Autosave Interval kept, or `fallback` when none was.
    static int autosaveIntervalSetting(int fallback);
    UndoHistory& history() { return *history_; }
    /// When a session that ended without saving left its work in `folder`, offers it (a dialog:
    /// Recover / Discard; closing it keeps the file for the next start), or with `ask` false
    /// recovers it at once: the document, its undo history and its path. True when recovered.
    bool offerRecovery(const QString& folder, bool ask);
    /// File > Recover Unsaved Work: offerRecovery() in the autosave's folder, for work whose
    /// start-up question was closed unanswered (or that another session left since).
    void recoverFromMenu();

protected:
    void closeEvent(QCloseEvent* event) override;
    /// Applies a viewport size asked for while the window was hidden.
    void showEvent(QShowEvent* event) override;

private:
    void createActions();
    void createAestheticsMenu();  // main_window_aesthetics.cpp
    void createSolidMenu();       // main_window_solid.cpp
    /// The selected entity when it is a solid, else null (main_window_solid.cpp).
    const model::Entity* selectedSolid() const;
    /// Gives `solid` a new recipe (undoable; it converts again), the outcome in the status bar.
    void changeSolid(model::EntityId solid, const model::SolidRecipe& recipe);
    /// Resizes the window until the GL area is width x height, both as drawn and as read back; false
    /// when that is not reached within kViewportSettleMs.
    bool resizeViewport(int width, int height);
    /// True when the window fits its screen's available area (moving it onto the screen if need be).
    bool fitScreen();
    void createDocks();
    void setMode(Mode mode, std::optional<model::Construction> surfaceMode = std::nullopt);
    void updateStatus();
    void updateTitle();
    /// The object name of the current mode's action ("mode.boundaryRotation", ...).
    QString modeActionName() const;
    /// Status text of a surface mode: what to pick next, or the last build's outcome.
    QString surfaceGuidance() const;
    void frameScene();
    bool maybeSave();
    /// File > Open Recent: the last kMaxRecentFiles documents opened or saved (QSettings).
    void rememberFile(const QString& path);
    void updateRecentMenu();
    /// True (with a message) when `action` would open a dialog in an automated run.
    bool refuseDialog(const char* action) const;
    bool saveTo(const QString& path);
    void newDocument();
    void openDocument();
    bool saveDocument();
    bool saveDocumentAs();
    void exportDocument();
    /// File > Import Reference, Edit > Remove References, View > References (main_window_references.cpp).
    void createReferenceActions(QMenu* file, QMenu* edit, QMenu* view);
    void importReference();
    /// File > Export STEP/IGES/STL/OBJ: a file dialog, then SketchDocument::exportGeometry.
    void exportGeometry(solvers::exchange::Format format);
    void addPlaneFacingViewer();
    static SbBool viewerEvent(void* self, QEvent* event);
    /// Turns, pans or zooms the view for the buttons that do not draw (every mode); true when
    /// `event` was taken for that.
    bool navigate(QEvent* event);
    /// Sculptline's context menu for what lies under `position` (viewport pixels).
    void showContextMenu(const QPoint& position);
    /// View > Hide the selected plane / Hide all planes / Show all planes (a view setting).
    void hideSelectedPlane();
    void setPlanesVisible(bool visible);
    bool pickAt(const QPoint& position);
    /// The curve drawn nearest to `position` (viewport pixels) within kCurvePickRadius, or 0: in
    /// the surface modes a click need not hit the thin line exactly.
    model::EntityId curveNear(const QPoint& position) const;

    SoQtExaminerViewer* viewer_ = nullptr;
    /// A viewport size asked for while the window was hidden (setViewportSize), applied on show.
    std::optional<QSize> pendingViewportSize_;
    std::unique_ptr<ViewNavigation> navigation_;
    SketchDocument* document_ = nullptr;
    EntityListDock* entities_ = nullptr;
    InspectorDock* inspector_ = nullptr;
    RecognitionDock* recognition_ = nullptr;
    QActionGroup* modes_ = nullptr;
    Mode mode_ = Mode::Sketch;
    std::optional<model::Construction> surfaceMode_;
    SolidBuilder* solids_ = nullptr;  ///< Solid menu's conversions (main_window_solid.cpp)
    bool automated_ = false;
    QMenu* recentMenu_ = nullptr;
    QMenu* contextMenu_ = nullptr;
    UndoHistory* history_ = nullptr;
    Autosaver* autosaver_ = nullptr;
    QString recoveryFolder_;  ///< where autosaves go and orphans are looked for
};

}  // namespace sculptline::ui
