// The main window's docks and actions with a real display (run under Xvfb by ctest): every action
// is named, the entity list and the inspector show the selected entity, the curvature plot samples
// the selected curve, and modes switch the viewer between viewing and interaction. Writes the whole
// window to $SCULPTLINE_WINDOW_SHOT (when set) so a person can look at the docks.
#include "scene/scene_document.h"
#include "ui/curvature_plot.h"
#include "ui/inspector_dock.h"
#include "ui/main_window.h"
#include "ui/sketch_document.h"

#include <Inventor/Qt/SoQt.h>
#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>

#include <QAction>
#include <QApplication>
#include <gtest/gtest.h>

#include <cstdlib>

namespace sculptline::ui {
namespace {

TEST(MainWindow, DocksShowTheSelectionAndModesSwitchTheViewer)
{
    int argc = 1;
    char name[] = "main_window_test";
    char* argv[] = {name, nullptr};
    QApplication app(argc, argv);
    SoQt::init(static_cast<QWidget*>(nullptr));
    MainWindow window;
    window.showDocument(scene::loadDocument(SCULPTLINE_DATA_DIR "/default_scene.json"), QString());
    window.show();
    window.resize(1200, 800);
    QApplication::processEvents();

    // Every action has a layer.name object name
    const QList<QAction*> actions = window.namedActions();
    EXPECT_GE(actions.size(), 15);
    for (const char* expected : {"mode.sketch", "mode.select", "mode.oversketch", "plane.add", "edit.undo", "edit.redo",
                                 "edit.delete", "file.save", "file.exportIv", "view.controlPolygons"}) {
        EXPECT_NE(window.action(QString::fromLatin1(expected)), nullptr) << expected;
    }

    // Selecting the default curve (id 2) fills the inspector and the curvature plot
    window.document().select(2);
    QApplication::processEvents();
    auto* inspector = window.findChild<InspectorDock*>();
    ASSERT_NE(inspector, nullptr);
    EXPECT_TRUE(inspector->text().contains(QStringLiteral("Degree: 3"))) << inspector->text().toStdString();
    EXPECT_TRUE(inspector->text().contains(QStringLiteral("Control points (6)")));
    EXPECT_TRUE(inspector->text().contains(QStringLiteral("Knots (10)")));
    auto* plot = window.findChild<CurvaturePlot*>();
    ASSERT_NE(plot, nullptr);
    ASSERT_FALSE(plot->samples().empty());
    EXPECT_GT(*std::max_element(plot->samples().begin(), plot->samples().end()), 0.0);

    // Modes: sketching needs the viewer in interaction mode, viewing gives the mouse to the camera
    window.action(QStringLiteral("mode.sketch"))->trigger();
    EXPECT_FALSE(window.viewer()->isViewing());
    window.action(QStringLiteral("mode.view"))->trigger();
    EXPECT_TRUE(window.viewer()->isViewing());

    if (const char* shot = std::getenv("SCULPTLINE_WINDOW_SHOT")) window.grab().save(QString::fromLocal8Bit(shot));
}

}  // namespace
}  // namespace sculptline::ui
