// A newcomer's first minutes in the real main window (run under Xvfb by ctest): the window opens
// ready to draw, the other buttons move the view in every drawing mode and the view stops when the
// pointer does. Mouse events go through Qt to the viewer's GL widget, as a person's would.
#include "manipulators/plane_binding.h"
#include "model/document.h"
#include "scene/eigen_coin.h"
#include "ui/main_window.h"
#include "ui/recognition_dock.h"
#include "ui/sketch_document.h"

#include <Inventor/Qt/SoQt.h>
#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>
#include <Inventor/nodes/SoCamera.h>

#include <gtest/gtest.h>
#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QMouseEvent>
#include <QScreen>
#include <QStatusBar>
#include <QTabletEvent>
#include <QUndoStack>
#include <QWheelEvent>

#include <cstdlib>

namespace sculptline::ui {
namespace {

void startApplication()
{
    static int argc = 1;
    static char name[] = "first_contact_test";
    static char* argv[] = {name, nullptr};
    static QApplication* app = nullptr;
    if (app) return;
    app = new QApplication(argc, argv);
    SoQt::init(static_cast<QWidget*>(nullptr));
}

/// Camera positions closer than this (mm) are the same view.
constexpr float kSameView = 1e-3f;

void mouse(MainWindow& window, QEvent::Type type, const QPoint& at, Qt::MouseButton button, Qt::MouseButtons held,
           Qt::KeyboardModifiers modifiers = Qt::NoModifier)
{
    QWidget* gl = window.viewport();
    QMouseEvent event(type, QPointF(at), QPointF(at), QPointF(gl->mapToGlobal(at)), button, held, modifiers);
    QApplication::sendEvent(gl, &event);
}

/// One sample of a tablet pen: where, and how hard (0..1).
struct PenSample {
    QPoint at;
    double pressure;
};

/// A stroke drawn with a tablet pen along `path`: each sample a QTabletEvent followed by the mouse
/// event Qt synthesizes from it (which the scene graph sees; ui/tablet_pressure.h keeps the reading).
void penStroke(MainWindow& window, const std::vector<PenSample>& path)
{
    QWidget* gl = window.viewport();
    const auto pen = [&](QEvent::Type tablet, QEvent::Type mouseType, const PenSample& s, Qt::MouseButton button, Qt::MouseButtons held) {
        QTabletEvent t(tablet, QPointF(s.at), QPointF(gl->mapToGlobal(s.at)), QTabletEvent::Stylus, QTabletEvent::Pen,
                       s.pressure, 0, 0, 0.0, 0.0, 0, Qt::NoModifier, 1, button, held);
        QApplication::sendEvent(gl, &t);
        QMouseEvent m(mouseType, QPointF(s.at), QPointF(s.at), QPointF(gl->mapToGlobal(s.at)), button, held,
                      Qt::NoModifier, Qt::MouseEventSynthesizedByQt);
        QApplication::sendEvent(gl, &m);
    };
    pen(QEvent::TabletPress, QEvent::MouseButtonPress, path.front(), Qt::LeftButton, Qt::LeftButton);
    for (size_t i = 1; i < path.size(); ++i) pen(QEvent::TabletMove, QEvent::MouseMove, path[i], Qt::NoButton, Qt::LeftButton);
    pen(QEvent::TabletRelease, QEvent::MouseButtonRelease, path.back(), Qt::LeftButton, Qt::NoButton);
}

/// The same path drawn with the mouse (no pressure).
void mouseStroke(MainWindow& window, const std::vector<PenSample>& path)
{
    mouse(window, QEvent::MouseButtonPress, path.front().at, Qt::LeftButton, Qt::LeftButton);
    for (size_t i = 1; i < path.size(); ++i) mouse(window, QEvent::MouseMove, path[i].at, Qt::NoButton, Qt::LeftButton);
    mouse(window, QEvent::MouseButtonRelease, path.back().at, Qt::LeftButton, Qt::NoButton);
}

/// A drag with `button` from `from` by (dx, dy) pixels in 10 steps.
void drag(MainWindow& window, Qt::MouseButton button, const QPoint& from, int dx, int dy, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
{
    mouse(window, QEvent::MouseButtonPress, from, button, button, modifiers);
    for (int k = 1; k <= 10; ++k) mouse(window, QEvent::MouseMove, from + QPoint(dx * k / 10, dy * k / 10), Qt::NoButton, button, modifiers);
    mouse(window, QEvent::MouseButtonRelease, from + QPoint(dx, dy), button, Qt::NoButton, modifiers);
}

/// Runs the event loop for `ms` milliseconds (timers, sensors: an animation would go on meanwhile).
void wait(int ms)
{
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < ms) QApplication::processEvents(QEventLoop::AllEvents, 10);
}

struct Fixture {
    MainWindow window;
    Fixture()
    {
        window.showDocument(model::loadDocument(SCULPTLINE_DATA_DIR "/default_scene.json"), QString());
        window.show();
        window.setViewportSize(800, 600);
        window.renderViewport();
        QApplication::processEvents();
    }
    SoCamera* camera() { return window.viewer()->getCamera(); }
    /// The pixel of the default plane's (id 1) local point (x, y).
    QPoint onPlane(double x, double y) { return window.pixelOf(window.document().model().find(1)->frame.toWorld(Eigen::Vector3d(x, y, 0))); }
    size_t curves()
    {
        size_t n = 0;
        for (const auto& [id, e] : window.document().model().entities()) n += e.kind == model::EntityKind::Curve;
        return n;
    }
};

TEST(FirstContact, TheWindowOpensReadyToDrawWithTheLeftButton)
{
    // Given a fresh window on the default scene
    startApplication();
    Fixture f;
    const size_t before = f.curves();

    // When the left button drags across the middle of the plane
    const QPoint a = f.onPlane(-30, -20), b = f.onPlane(30, 20);
    drag(f.window, Qt::LeftButton, a, b.x() - a.x(), b.y() - a.y());

    // Then a curve was drawn, in Sketch mode, and the status bar says how to move the view
    EXPECT_EQ(f.window.mode(), Mode::Sketch);
    EXPECT_TRUE(f.window.action(QStringLiteral("mode.sketch"))->isChecked());
    EXPECT_EQ(f.curves(), before + 1);
    f.window.action(QStringLiteral("mode.sketch"))->trigger();  // the stroke's report gave way to the mode's
    const QString status = f.window.statusBar()->currentMessage();
    EXPECT_TRUE(status.contains(QStringLiteral("left button"))) << status.toStdString();
    EXPECT_TRUE(status.contains(QStringLiteral("middle-drag"))) << status.toStdString();
    EXPECT_TRUE(status.contains(QStringLiteral("wheel"))) << status.toStdString();
}

TEST(FirstContact, TheOtherButtonsMoveTheViewInEveryDrawingModeAndDrawNothing)
{
    startApplication();
    Fixture f;
    const QPoint centre(400, 300);
    for (const char* mode : {"mode.sketch", "mode.oversketch", "mode.lift", "mode.pull", "mode.select", "mode.view"}) {
        f.window.action(QString::fromLatin1(mode))->trigger();
        const size_t before = f.curves();
        struct Case {
            const char* what;
            Qt::MouseButton button;
            Qt::KeyboardModifiers modifiers;
        };
        for (const Case& c : {Case{"middle-drag turns", Qt::MiddleButton, Qt::NoModifier},
                              Case{"Alt+left turns", Qt::LeftButton, Qt::AltModifier},
                              Case{"Shift+middle pans", Qt::MiddleButton, Qt::ShiftModifier},
                              Case{"right-drag pans", Qt::RightButton, Qt::NoModifier},
                              Case{"Alt+right zooms", Qt::RightButton, Qt::AltModifier}}) {
            // Given the camera where it is
            const SbVec3f position = f.camera()->position.getValue();
            const SbRotation orientation = f.camera()->orientation.getValue();
            // When the button drags
            drag(f.window, c.button, centre, 60, 40, c.modifiers);
            // Then the view moved and nothing was drawn
            const bool moved = (f.camera()->position.getValue() - position).length() > kSameView ||
                               !f.camera()->orientation.getValue().equals(orientation, 1e-6f);
            EXPECT_TRUE(moved) << mode << ": " << c.what;
            EXPECT_EQ(f.curves(), before) << mode << ": " << c.what;
        }
        // The wheel zooms: one notch towards the screen brings the camera nearer
        const float distance = f.camera()->focalDistance.getValue();
        QWheelEvent wheel(QPointF(centre), QPointF(f.window.viewport()->mapToGlobal(centre)), QPoint(), QPoint(0, 120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(f.window.viewport(), &wheel);
        EXPECT_LT(f.camera()->focalDistance.getValue(), distance) << mode;
    }
}

TEST(FirstContact, AQuickTurnDoesNotLeaveTheSceneSpinning)
{
    // Given View mode (the examiner turns with the left button) and a quick flick released in motion
    startApplication();
    Fixture f;
    f.window.action(QStringLiteral("mode.view"))->trigger();
    drag(f.window, Qt::LeftButton, QPoint(400, 300), 150, 0);
    const SbRotation released = f.camera()->orientation.getValue();

    // When the event loop runs on
    wait(300);

    // Then the view stays where it was let go
    EXPECT_TRUE(f.camera()->orientation.getValue().equals(released, 1e-6f));
    EXPECT_FALSE(f.window.viewer()->isAnimationEnabled());
}

TEST(FirstContact, AnUndoneStrokeLeavesNoMarkerAndTheRecognitionDockForgetsIt)
{
    // Given a stroke drawn with the mouse: its sampling dots are shown, the dock reports it
    startApplication();
    Fixture f;
    const size_t before = f.curves();
    const QPoint a = f.onPlane(-40, -30), b = f.onPlane(40, 30);
    drag(f.window, Qt::LeftButton, a, b.x() - a.x(), b.y() - a.y());
    ASSERT_EQ(f.curves(), before + 1);
    const scene::StrokeFeedback& feedback = f.window.document().strokeFeedback();
    ASSERT_GT(feedback.sampleCount(), 0);
    auto* dock = f.window.findChild<RecognitionDock*>();
    ASSERT_NE(dock, nullptr);
    auto* summary = dock->findChild<QLabel*>();
    ASSERT_NE(summary, nullptr);
    EXPECT_TRUE(summary->text().contains(QStringLiteral("fitted"))) << summary->text().toStdString();

    // When it is undone (Ctrl+Z)
    f.window.action(QStringLiteral("edit.undo"))->trigger();

    // Then the curve, its markers and its report are gone, and its shape can no longer be chosen
    EXPECT_EQ(f.curves(), before);
    EXPECT_EQ(feedback.sampleCount(), 0);
    EXPECT_EQ(feedback.cornerCount(), 0);
    EXPECT_FALSE(summary->text().contains(QStringLiteral("fitted"))) << summary->text().toStdString();
    EXPECT_EQ(dock->findChild<QListWidget*>()->count(), 0);
    EXPECT_FALSE(f.window.action(QStringLiteral("stroke.useRecognized"))->isEnabled());
}

/// A right click (press and release in place) at `at`.
void rightClick(MainWindow& window, const QPoint& at)
{
    mouse(window, QEvent::MouseButtonPress, at, Qt::RightButton, Qt::RightButton);
    mouse(window, QEvent::MouseButtonRelease, at, Qt::RightButton, Qt::NoButton);
    QApplication::processEvents();
}

/// The object names of the context menu's items.
QStringList menuItems(const MainWindow& window)
{
    QStringList names;
    if (window.contextMenu()) {
        for (QAction* a : window.contextMenu()->actions()) names << a->objectName();
    }
    return names;
}

TEST(FirstContact, RightClickOpensSculptlinesMenuForWhatIsUnderThePointer)
{
    startApplication();
    Fixture f;
    EXPECT_FALSE(f.window.viewer()->isPopupMenuEnabled());  // not SoQt's developer menu

    // On empty space (a corner of the viewport): adding a plane, framing, the planes' visibility
    rightClick(f.window, QPoint(5, 5));
    ASSERT_NE(f.window.contextMenu(), nullptr);
    EXPECT_TRUE(f.window.contextMenu()->isVisible());
    EXPECT_TRUE(menuItems(f.window).contains(QStringLiteral("context.plane.add"))) << menuItems(f.window).join(' ').toStdString();
    EXPECT_TRUE(menuItems(f.window).contains(QStringLiteral("context.view.all")));
    f.window.contextMenu()->close();

    // On the default plane's jack (plane 1): the plane is selected and can be hidden from the menu
    const QPoint jack = f.onPlane(0, 0);
    rightClick(f.window, jack);
    EXPECT_EQ(f.window.document().selection(), 1u);
    const QStringList items = menuItems(f.window);
    EXPECT_TRUE(items.contains(QStringLiteral("context.view.hidePlane"))) << items.join(' ').toStdString();
    EXPECT_TRUE(items.contains(QStringLiteral("context.edit.delete")));
    EXPECT_FALSE(items.contains(QStringLiteral("context.plane.add")));
    QAction* hide = nullptr;
    for (QAction* a : f.window.contextMenu()->actions()) {
        if (a->objectName() == QStringLiteral("context.view.hidePlane")) hide = a;
    }
    ASSERT_NE(hide, nullptr);
    if (const char* dir = std::getenv("SCULPTLINE_FIRST_CONTACT_SHOTS"))
        f.window.contextMenu()->grab().save(QString::fromLocal8Bit(dir) + "/first_contact_plane_menu.png");
    f.window.contextMenu()->close();
    hide->trigger();
    EXPECT_FALSE(f.window.document().planeDraggers().visible(1));

    // A right-drag pans and opens no menu
    f.window.contextMenu()->close();
    drag(f.window, Qt::RightButton, QPoint(400, 300), 50, 0);
    EXPECT_FALSE(f.window.contextMenu()->isVisible());
}

TEST(FirstContact, PlanesCanBeHiddenAndShownWithoutAnEdit)
{
    // Given the default scene's plane, selected
    startApplication();
    Fixture f;
    SketchDocument& doc = f.window.document();
    manipulators::PlaneDraggers& planes = doc.planeDraggers();
    doc.select(1);
    const int undoSteps = doc.undoStack()->count();

    // When it is hidden (View > Hide the selected plane, H)
    f.window.action(QStringLiteral("view.hidePlane"))->trigger();

    // Then it is not drawn and cannot be picked: a click on its jack selects no plane
    EXPECT_FALSE(planes.visible(1));
    f.window.action(QStringLiteral("mode.select"))->trigger();
    const QPoint jack = f.onPlane(0, 0);
    mouse(f.window, QEvent::MouseButtonPress, jack, Qt::LeftButton, Qt::LeftButton);
    mouse(f.window, QEvent::MouseButtonRelease, jack, Qt::LeftButton, Qt::NoButton);
    EXPECT_NE(doc.selection(), 1u);
    // And the model did not change: no undo step, nothing to save
    EXPECT_EQ(doc.undoStack()->count(), undoSteps);
    EXPECT_TRUE(doc.undoStack()->isClean());

    // When all planes are shown again (Shift+H), then hidden all at once
    f.window.action(QStringLiteral("view.showPlanes"))->trigger();
    EXPECT_TRUE(planes.visible(1));
    f.window.action(QStringLiteral("view.hidePlanes"))->trigger();
    EXPECT_EQ(planes.hiddenCount(), 1u);
    f.window.action(QStringLiteral("view.showPlanes"))->trigger();
    EXPECT_EQ(planes.hiddenCount(), 0u);
}

/// Puts the camera `distance` mm from the default plane's centre, looking along `direction`, Z up.
void look(Fixture& f, const Eigen::Vector3d& direction, double distance)
{
    const Eigen::Vector3d centre = f.window.document().model().find(1)->frame.origin;
    SoCamera* camera = f.camera();
    camera->orientation = scene::rotationLookingAlong(direction.normalized(), Eigen::Vector3d::UnitZ());
    camera->position = scene::toSb(centre - distance * direction.normalized());
    camera->focalDistance = static_cast<float>(distance);
    f.window.renderViewport();
}

TEST(FirstContact, AStrokeThatWouldLandOutOfSightIsRefusedWithTheReason)
{
    startApplication();
    Fixture f;
    SketchDocument& doc = f.window.document();
    doc.select(1);
    const size_t before = f.curves();

    // Given the default plane (normal -Y) seen almost edge-on: the view 3° off its surface
    const double tilt = 3.0 / 57.29577951308232;
    look(f, Eigen::Vector3d(std::cos(tilt), std::sin(tilt), 0.0), 400.0);
    // When a stroke is drawn across the middle of the viewport
    drag(f.window, Qt::LeftButton, QPoint(300, 250), 200, 100);
    // Then no curve is made and the status bar says why
    EXPECT_EQ(f.curves(), before);
    EXPECT_TRUE(f.window.statusBar()->currentMessage().contains(QStringLiteral("edge-on"))) << f.window.statusBar()->currentMessage().toStdString();

    // Given the plane face-on from far away, when a stroke is drawn far outside its 120 mm square
    look(f, Eigen::Vector3d(0, 1, 0), 3000.0);
    const QPoint a = f.onPlane(400, 0), b = f.onPlane(480, 60);
    ASSERT_TRUE(f.window.viewport()->rect().contains(a) && f.window.viewport()->rect().contains(b));
    drag(f.window, Qt::LeftButton, a, b.x() - a.x(), b.y() - a.y());
    // Then it is refused too, with the distance
    EXPECT_EQ(f.curves(), before);
    EXPECT_TRUE(f.window.statusBar()->currentMessage().contains(QStringLiteral("far outside"))) << f.window.statusBar()->currentMessage().toStdString();

    // And a stroke over the plane, from there, is drawn
    const QPoint c = f.onPlane(-40, -20), d = f.onPlane(40, 30);
    drag(f.window, Qt::LeftButton, c, d.x() - c.x(), d.y() - c.y());
    EXPECT_EQ(f.curves(), before + 1);
}

// A tablet pen reaches the scene graph as mouse events Qt synthesizes from its QTabletEvents
// (ui/tablet_pressure.h keeps the pen's reading for the stroke). Its pen-down hook (seed 003 §3.1:
// the tip skids while the pressure builds up) is drawn lightly, so the fitter trims it; the same
// path drawn with a mouse carries no pressure and nothing is trimmed.
TEST(FirstContact, APensLightPressureHookIsTrimmedAndAMouseStrokeKeepsEverySample)
{
    startApplication();
    Fixture f;
    SketchDocument& doc = f.window.document();
    // Four light samples curling in from below, then an arch of 80 at full pressure.
    std::vector<PenSample> path;
    for (int k = 0; k < 4; ++k) path.push_back({QPoint(308 + k, 338 - 2 * k), 0.15});
    for (int k = 0; k < 80; ++k) {
        const double a = k / 79.0;
        path.push_back({QPoint(static_cast<int>(std::lround(312 + 180 * a)),
                               static_cast<int>(std::lround(330 - 60 * std::sin(3.14159265358979 * a)))),
                        0.8});
    }
    // When the pen draws it
    penStroke(f.window, path);
    // Then the light hook's samples are left out, and the status says so
    ASSERT_TRUE(doc.lastStroke().fitted) << doc.lastStroke().message.toStdString();
    EXPECT_EQ(doc.lastStroke().dropped, 4) << doc.lastStroke().message.toStdString();
    EXPECT_TRUE(doc.lastStroke().message.contains(QStringLiteral("left out as a hook")))
        << doc.lastStroke().message.toStdString();

    // And when a mouse draws the same path after the pen, no pressure is left over from it
    mouseStroke(f.window, path);
    ASSERT_TRUE(doc.lastStroke().fitted) << doc.lastStroke().message.toStdString();
    EXPECT_EQ(doc.lastStroke().dropped, 0) << doc.lastStroke().message.toStdString();
}

// Over-sketch, lift and re-sketch take the stroke as drawn, not through the fitter: a pen's light
// pen-up hook is left out there by the fitter's rule (solvers::stroke::withoutPressureHooks), and the
// status says so; the same over-sketch by mouse keeps every sample.
TEST(FirstContact, AnOversketchByPenLeavesOutItsLightPressureHook)
{
    startApplication();
    Fixture f;
    SketchDocument& doc = f.window.document();
    // An arch drawn by mouse, then over-sketched
    const auto arch = [](double a, double height) {
        return QPoint(static_cast<int>(std::lround(312 + 180 * a)),
                      static_cast<int>(std::lround(330 - height * std::sin(3.14159265358979 * a))));
    };
    mouse(f.window, QEvent::MouseButtonPress, arch(0, 60), Qt::LeftButton, Qt::LeftButton);
    for (int k = 1; k < 80; ++k) mouse(f.window, QEvent::MouseMove, arch(k / 79.0, 60), Qt::NoButton, Qt::LeftButton);
    mouse(f.window, QEvent::MouseButtonRelease, arch(1, 60), Qt::LeftButton, Qt::NoButton);
    ASSERT_TRUE(doc.lastStroke().fitted) << doc.lastStroke().message.toStdString();
    const size_t curves = f.curves();
    f.window.action(QStringLiteral("mode.oversketch"))->trigger();
    // The middle of the arch drawn 10 px higher at full pressure, then four light samples skidding
    // away where the pen lifts
    std::vector<PenSample> path;
    for (int k = 0; k <= 60; ++k) path.push_back({arch(0.2 + 0.6 * k / 60.0, 70), 0.8});
    for (int k = 1; k <= 4; ++k) path.push_back({path.back().at + QPoint(1, 1), 0.15});
    // When the pen over-sketches
    penStroke(f.window, path);
    // Then the curve is changed, not added to, without the hook, and the status says so
    ASSERT_TRUE(doc.lastStroke().fitted) << doc.lastStroke().message.toStdString();
    EXPECT_EQ(f.curves(), curves);
    // (five light samples: the four moves and the release, a sample of its own at the last point)
    EXPECT_EQ(doc.lastStroke().dropped, 5) << doc.lastStroke().message.toStdString();
    EXPECT_TRUE(doc.lastStroke().message.contains(QStringLiteral("light-pressure hook")))
        << doc.lastStroke().message.toStdString();

    // And the same over-sketch by mouse keeps every sample
    mouseStroke(f.window, path);
    ASSERT_TRUE(doc.lastStroke().fitted) << doc.lastStroke().message.toStdString();
    EXPECT_EQ(doc.lastStroke().dropped, 0) << doc.lastStroke().message.toStdString();
    EXPECT_FALSE(doc.lastStroke().message.contains(QStringLiteral("light-pressure hook")))
        << doc.lastStroke().message.toStdString();
    // And the over-sketch holds the drawing, not the pixels' staircase: its tolerance is never below
    // a pixel's footprint, as a sketched stroke's (at 0.002 of the stroke's length, 0.17 mm against
    // a 0.75 mm pixel, the same strokes in a replay gave 42 control points and visible steps)
    EXPECT_LE(doc.lastStroke().controlPoints, 12) << doc.lastStroke().message.toStdString();
}

TEST(FirstContact, TheWindowFitsTheScreenItOpensOn)
{
    // Given a 1280-wide screen (tests/gui/xvfb.sh) and the viewport size replays ask for
    startApplication();
    MainWindow window;
    window.showDocument(model::loadDocument(SCULPTLINE_DATA_DIR "/default_scene.json"), QString());
    window.show();
    QApplication::processEvents();

    // When the viewport is set to 1200 x 850
    window.setViewportSize(1200, 850);
    QApplication::processEvents();

    // Then the viewport has that size and nothing of the window, docks included, is off-screen
    EXPECT_EQ(window.viewport()->size(), QSize(1200, 850));
    const QRect screen = window.screen()->availableGeometry();
    EXPECT_TRUE(screen.contains(window.frameGeometry())) << window.frameGeometry().width() << " x " << window.frameGeometry().height();
    for (QDockWidget* dock : window.findChildren<QDockWidget*>()) {
        if (!dock->isVisible()) continue;
        const QRect global(dock->mapToGlobal(QPoint(0, 0)), dock->size());
        EXPECT_TRUE(screen.contains(global)) << dock->objectName().toStdString();
    }
    if (const char* dir = std::getenv("SCULPTLINE_FIRST_CONTACT_SHOTS")) window.grab().save(QString::fromLocal8Bit(dir) + "/first_contact_1200x850.png");
}

}  // namespace
}  // namespace sculptline::ui
