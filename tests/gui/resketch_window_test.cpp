// Sculpt mode's Re-sketch tool in the real main window (run under Xvfb by ctest; seed
// 001_08db50965017e161 §5.2): on the free-form jug, a marking picks the rim, Alt+A turns the strip
// across it, a stroke over the strip re-sketches it in one undo step, the status bar says what to do
// next; a surface built from curves is refused with the reason. Strokes are delivered as the stroke
// input delivers them (rays), seen along the window's default view direction.
#include "manipulators/stroke_input.h"
#include "model/document.h"
#include "ui/main_window.h"
#include "ui/sketch_document.h"

#include <Inventor/Qt/SoQt.h>

#include <QAction>
#include <QApplication>
#include <QStatusBar>
#include <QUndoStack>
#include <gtest/gtest.h>

namespace sculptline::ui {
namespace {

void startApplication()
{
    static int argc = 1;
    static char name[] = "resketch_window_test";
    static char* argv[] = {name, nullptr};
    static QApplication* app = nullptr;
    if (app) return;
    app = new QApplication(argc, argv);
    SoQt::init(static_cast<QWidget*>(nullptr));
}

/// The window's default view direction (ui/main_window.cpp), unit.
const Eigen::Vector3d kView = Eigen::Vector3d(-1.0, 1.6, -0.9).normalized();

/// A stroke through world points, each with its ray from 300 mm back along the view.
manipulators::FinishedStroke strokeThrough(const std::vector<Eigen::Vector3d>& points)
{
    manipulators::FinishedStroke stroke;
    stroke.frame = model::PlaneFrame::fromNormal(points.front(), -kView, 100.0);
    for (size_t i = 0; i < points.size(); ++i) {
        stroke.points.push_back(stroke.frame.toLocal(points[i]));
        stroke.times.push_back(0.01 * static_cast<double>(i));
        stroke.rayTimes.push_back(0.01 * static_cast<double>(i));
        stroke.rayOrigins.push_back(points[i] - 300.0 * kView);
        stroke.rayDirections.push_back(kView);
    }
    return stroke;
}

TEST(ResketchWindow, TheJugsRimIsMarkedRedrawnOverItsStripAndUndone)
{
    // Given the jug (surface 1, u around in [0, 10], v up in [0, 3]) selected, Sculpt mode, Alt+R
    startApplication();
    MainWindow window;
    window.showDocument(model::loadDocument(SCULPTLINE_DATA_DIR "/models/jug_start.json"), QString());
    window.show();
    SketchDocument& doc = window.document();
    const solvers::Surface3d jug = *doc.model().find(1)->surface;
    doc.select(1);
    window.action(QStringLiteral("mode.sculpt"))->trigger();
    window.action(QStringLiteral("sculpt.resketch"))->trigger();
    EXPECT_TRUE(window.statusBar()->currentMessage().contains(QStringLiteral("Re-sketch surface 1"))) << window.statusBar()->currentMessage().toStdString();

    // When a marking runs along the front just below the rim
    std::vector<Eigen::Vector3d> marking;
    for (int k = 0; k <= 20; ++k) marking.push_back(jug.evaluate(4.0 + 2.0 * k / 20, 2.9));
    doc.addStroke(strokeThrough(marking));
    // Then the rim is picked
    EXPECT_TRUE(doc.lastStroke().message.contains(QStringLiteral("picked its u-curve at v = 3.000"))) << doc.lastStroke().message.toStdString();

    // When the strip is turned across the rim (Alt+A) and a stroke over it raises the front 10 mm
    window.action(QStringLiteral("sculpt.resketchRulings"))->trigger();
    EXPECT_TRUE(doc.lastStroke().message.contains(QStringLiteral("across"))) << doc.lastStroke().message.toStdString();
    std::vector<Eigen::Vector3d> lip;
    for (int k = 0; k <= 40; ++k) {
        const double u = 3.5 + 3.0 * k / 40, h = 10.0 * std::pow(std::sin(3.14159265358979 * k / 40), 2);
        const Eigen::Vector3d top = jug.evaluate(u, 3.0), across = (top - jug.evaluate(u, 2.94)).normalized();
        lip.push_back(top + h * across);
    }
    const int steps = doc.undoStack()->count();
    doc.addStroke(strokeThrough(lip));
    // Then the jug followed in one undo step: its rim row moved, every other row kept its points
    EXPECT_EQ(doc.undoStack()->count(), steps + 1);
    EXPECT_TRUE(doc.lastStroke().message.contains(QStringLiteral("follows its re-sketched"))) << doc.lastStroke().message.toStdString();
    const solvers::Surface3d& after = *doc.model().find(1)->surface;
    const int rim = jug.countV() - 1;
    for (int i = 0; i < jug.countU(); ++i)
        for (int j = 0; j < rim; ++j) EXPECT_EQ(after.point(i, j), jug.point(i, j));
    EXPECT_GT(after.evaluate(5.0, 3.0).z(), jug.evaluate(5.0, 3.0).z() + 8.0);

    // When it is undone: the jug as it was
    doc.undoStack()->undo();
    EXPECT_EQ(doc.model().find(1)->surface->points(), jug.points());

    // When Alt+A turns the rulings on to the view direction (the camera's, looking down at the rim)
    window.action(QStringLiteral("sculpt.resketchRulings"))->trigger();
    // Then the strip is made along it, and the status says what to draw next
    EXPECT_TRUE(doc.lastStroke().message.contains(QStringLiteral("the view direction"))) << doc.lastStroke().message.toStdString();
    EXPECT_TRUE(doc.lastStroke().message.contains(QStringLiteral("new shape over the strip"))) << doc.lastStroke().message.toStdString();
}

TEST(ResketchWindow, ASurfaceBuiltFromCurvesIsRefusedWithTheReason)
{
    // Given a loft through two curves, selected, Sculpt mode's Re-sketch tool
    startApplication();
    MainWindow window;
    window.showDocument(model::loadDocument(SCULPTLINE_DATA_DIR "/models/jug_start.json"), QString());
    window.show();
    SketchDocument& doc = window.document();
    auto line = [](double z) { return solvers::Curve3d(1, {0, 0, 1, 1}, {Eigen::Vector3d(-40, -60, z), Eigen::Vector3d(40, -60, z)}); };
    const model::EntityId a = doc.model().addCurve(0, line(0)), b = doc.model().addCurve(0, line(40));
    model::SurfaceRecipe loft;
    loft.mode = model::Construction::Loft;
    const model::EntityId surface = doc.model().addSurface({a, b}, loft);
    const std::vector<Eigen::Vector3d> before = doc.model().find(surface)->surface->points();
    doc.select(surface);
    window.action(QStringLiteral("mode.sculpt"))->trigger();
    window.action(QStringLiteral("sculpt.resketch"))->trigger();
    // When a marking is drawn over it
    doc.addStroke(strokeThrough({Eigen::Vector3d(-20, -60, 20), Eigen::Vector3d(0, -60, 20), Eigen::Vector3d(20, -60, 20)}));
    // Then nothing changes and the status says why
    EXPECT_TRUE(doc.lastStroke().message.contains(QStringLiteral("is built from curves (its loft)"))) << doc.lastStroke().message.toStdString();
    EXPECT_EQ(doc.model().find(surface)->surface->points(), before);
}

}  // namespace
}  // namespace sculptline::ui
