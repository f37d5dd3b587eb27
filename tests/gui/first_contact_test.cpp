// A newcomer's first minutes in the real main window (run under Xvfb by ctest): the window opens
// ready to draw, the other buttons move the view in every drawing mode and the view stops when the
// pointer does. Mouse events go through Qt to the viewer's GL widget, as a person's would.
#include "model/document.h"
#include "ui/main_window.h"
#include "ui/sketch_document.h"

#include <Inventor/Qt/SoQt.h>
#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>
#include <Inventor/nodes/SoCamera.h>

#include <QAction>
#include <QApplication>
#include <QElapsedTimer>
#include <QMouseEvent>
#include <QStatusBar>
#include <QWheelEvent>
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace sculptline::ui
