// Reference geometry in the real window (Xvfb): the box of data/references drawn greyed over the
// default scene, never picked, strokes through it landing on the active plane, View > References,
// Edit > Remove References and undo, and the saved document reopened, moved with its folder and
// with its file gone. Writes the window to $SCULPTLINE_REFERENCE_SHOT (when set) for a person.
#include "model/document.h"
#include "tests/gui/window_shot.h"
#include "ui/main_window.h"
#include "ui/reference_set.h"
#include "ui/sketch_document.h"
#include "ui/undo_history.h"

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>
#include <Inventor/SoPickedPoint.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoRayPickAction.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <QAction>
#include <QDir>
#include <QFile>
#include <QMouseEvent>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QUndoStack>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>

namespace sculptline::ui {
namespace {

const QString kBox = QStringLiteral(SCULPTLINE_DATA_DIR "/references/box.iv");
/// A channel difference below this is the same colour.
constexpr int kChannelTolerance = 12;
/// The box covers well over this many viewport pixels in the default view.
constexpr int kMinBoxPixels = 2000;
/// Pixels that may differ between two renderings of the same scene.
constexpr int kSameScenePixels = 20;
/// The default scene's plane 1 lies in y = 95 (data/default_scene.json).
constexpr double kPlaneY = 95.0;
constexpr double kOnPlane = 1e-6;

QImage shot(MainWindow& window)
{
    window.renderViewport();
    QApplication::processEvents();
    return window.grabViewport().convertToFormat(QImage::Format_RGB32);
}

int differing(const QImage& a, const QImage& b)
{
    if (a.size() != b.size()) return a.width() * a.height();
    int n = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            const QColor p = a.pixelColor(x, y), q = b.pixelColor(x, y);
            if (std::max({std::abs(p.red() - q.red()), std::abs(p.green() - q.green()), std::abs(p.blue() - q.blue())}) > kChannelTolerance) ++n;
        }
    }
    return n;
}

/// What a ray from the camera's position through `world` picks in `root` (the viewer's camera sits
/// above the document's graph, so the ray is given in world space): how many points, and whether
/// any of their paths passes through `node`.
struct Picks {
    int count = 0;
    bool through = false;
};

Picks pickAlong(MainWindow& window, SoNode* root, const Eigen::Vector3d& world, const SoNode* node)
{
    SoRayPickAction pick(window.viewer()->getViewportRegion());
    const SbVec3f eye = window.viewer()->getCamera()->position.getValue();
    SbVec3f direction = SbVec3f(static_cast<float>(world.x()), static_cast<float>(world.y()), static_cast<float>(world.z())) - eye;
    direction.normalize();
    pick.setRay(eye, direction);
    pick.setPickAll(TRUE);
    pick.apply(root);
    Picks result;
    const SoPickedPointList& points = pick.getPickedPointList();
    result.count = points.getLength();
    for (int i = 0; i < points.getLength(); ++i) {
        const SoPath* path = points[i]->getPath();
        for (int k = 0; k < path->getLength(); ++k) result.through = result.through || path->getNode(k) == node;
    }
    return result;
}

void mouse(MainWindow& window, QEvent::Type type, const QPoint& at, Qt::MouseButton button, Qt::MouseButtons held)
{
    QWidget* gl = window.viewport();
    QMouseEvent event(type, QPointF(at), QPointF(at), QPointF(gl->mapToGlobal(at)), button, held, Qt::NoModifier);
    QApplication::sendEvent(gl, &event);
}

/// QApplication and SoQt before any widget: a base constructed before Window's members.
struct Application {
    Application() { guitest::startApplication("reference_window_test"); }
};

struct Window : Application {
    MainWindow window;
    Window()
    {
        window.showDocument(model::loadDocument(SCULPTLINE_DATA_DIR "/default_scene.json"), QString());
        window.show();
        window.setViewportSize(800, 600);
        QElapsedTimer waited;
        waited.start();
        while (!(window.windowHandle() && window.windowHandle()->isExposed()) && waited.elapsed() < guitest::kExposeDeadlineMs)
            QApplication::processEvents(QEventLoop::AllEvents, 50);
    }
    SketchDocument& doc() { return window.document(); }
};

TEST(ReferenceWindow, GivenTheBoxImported_ThenDrawnUnpickableHiddenRemovedAndUndone)
{
    Window w;
    const QImage none = shot(w.window);
    const int steps = w.doc().undoStack()->count();

    // When the box is imported
    const QString summary = w.doc().importReference(kBox);
    const QImage with = shot(w.window);
    if (const char* path = std::getenv("SCULPTLINE_REFERENCE_SHOT")) guitest::saveWindowShot(w.window, QString::fromLocal8Bit(path));

    // Then it is one undo step, drawn, and counted
    EXPECT_TRUE(summary.contains(QStringLiteral("12 triangles"))) << summary.toStdString();
    EXPECT_EQ(w.doc().undoStack()->count(), steps + 1);
    EXPECT_GT(differing(none, with), kMinBoxPixels);
    // And the undo history (autosave, recovery) holds it
    EXPECT_NE(w.window.history().snapshot().states.back()->find("\"references\""), std::string::npos);

    // And a ray through its middle crosses it (a pick on its graph alone hits), yet a pick on the
    // scene never returns a path into the reference layer
    const Eigen::Vector3d centre(0.0, 0.0, 25.0);
    const QPoint middle = w.window.pixelOf(centre);
    SoSeparator* graph = w.doc().references().references().front().graph.get();
    EXPECT_GT(pickAlong(w.window, graph, centre, graph).count, 0);
    const Picks scene = pickAlong(w.window, w.window.sceneRoot(), centre, w.doc().references().root());
    EXPECT_GT(scene.count, 0);  // the plane behind it, at least
    EXPECT_FALSE(scene.through) << "picked the reference";

    // When View > References is turned off and on
    QAction* show = w.window.action(QStringLiteral("view.references"));
    ASSERT_NE(show, nullptr);
    show->trigger();
    EXPECT_LE(differing(none, shot(w.window)), kSameScenePixels);
    show->trigger();
    EXPECT_LE(differing(with, shot(w.window)), kSameScenePixels);
    EXPECT_EQ(w.doc().undoStack()->count(), steps + 1);  // a view setting, not an edit

    // When Edit > Remove References, then undo, then undo the import, then redo
    w.window.action(QStringLiteral("edit.removeReferences"))->trigger();
    EXPECT_EQ(w.doc().references().drawn(), 0);
    EXPECT_LE(differing(none, shot(w.window)), kSameScenePixels);
    w.doc().undoStack()->undo();
    EXPECT_LE(differing(with, shot(w.window)), kSameScenePixels);
    w.doc().undoStack()->undo();
    EXPECT_TRUE(w.doc().references().references().empty());
    EXPECT_LE(differing(none, shot(w.window)), kSameScenePixels);
    w.doc().undoStack()->redo();
    EXPECT_LE(differing(with, shot(w.window)), kSameScenePixels);

    // When a stroke is drawn across the reference in Sketch mode
    w.window.action(QStringLiteral("mode.sketch"))->trigger();
    std::set<model::EntityId> before;
    for (const auto& [id, e] : w.doc().model().entities()) before.insert(id);
    const QPoint from = middle - QPoint(90, 10);
    mouse(w.window, QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    for (int k = 1; k <= 20; ++k) mouse(w.window, QEvent::MouseMove, from + QPoint(9 * k, k), Qt::NoButton, Qt::LeftButton);
    mouse(w.window, QEvent::MouseButtonRelease, from + QPoint(180, 20), Qt::LeftButton, Qt::NoButton);
    QApplication::processEvents();

    // Then it became a curve on the active plane (y = 95), behind the reference, as without it
    const model::Entity* curve = nullptr;
    for (const auto& [id, e] : w.doc().model().entities())
        if (!before.count(id) && e.kind == model::EntityKind::Curve) curve = &e;
    ASSERT_NE(curve, nullptr) << w.doc().lastStroke().message.toStdString();
    ASSERT_TRUE(curve->world.has_value());
    for (const auto& p : curve->world->points()) EXPECT_NEAR(p.y(), kPlaneY, kOnPlane);

    // And File > Import Reference in an automated run opens no dialog and changes nothing
    const int count = w.doc().undoStack()->count();
    w.window.setAutomated(true);
    w.window.action(QStringLiteral("file.importReference"))->trigger();
    EXPECT_EQ(w.doc().undoStack()->count(), count);
}

TEST(ReferenceWindow, GivenASavedDocument_WhenReopenedMovedOrItsFileIsGone_ThenShownOrReportedAndKept)
{
    Window w;
    QTemporaryDir tmp;
    ASSERT_TRUE(tmp.isValid());
    const QDir root(tmp.path());
    ASSERT_TRUE(root.mkpath(QStringLiteral("a")));
    ASSERT_TRUE(QFile::copy(kBox, root.filePath(QStringLiteral("a/box.iv"))));
    w.doc().importReference(root.filePath(QStringLiteral("a/box.iv")));
    w.doc().save(root.filePath(QStringLiteral("a/doc.json")));
    {
        std::ifstream in(root.filePath(QStringLiteral("a/doc.json")).toStdString());
        const nlohmann::json saved = nlohmann::json::parse(in);
        EXPECT_EQ(saved["references"][0]["relative"], "box.iv");
        EXPECT_EQ(saved["references"][0]["path"], root.filePath(QStringLiteral("a/box.iv")).toStdString());
    }

    w.window.setAutomated(true);  // no dialog for the missing file below: nobody would close it
    // Reopened: drawn again, nothing to report, nothing modified
    auto reopen = [&](const QString& path) { w.window.showDocument(model::loadDocument(path.toStdString()), path); };
    reopen(root.filePath(QStringLiteral("a/doc.json")));
    EXPECT_EQ(w.doc().references().drawn(), 1);
    EXPECT_TRUE(w.doc().referenceProblems().isEmpty());
    EXPECT_TRUE(w.doc().undoStack()->isClean());

    // Moved with its folder: found by its relative path
    ASSERT_TRUE(QDir().rename(root.filePath(QStringLiteral("a")), root.filePath(QStringLiteral("b"))));
    reopen(root.filePath(QStringLiteral("b/doc.json")));
    EXPECT_EQ(w.doc().references().drawn(), 1);
    EXPECT_EQ(w.doc().references().references().front().path, root.filePath(QStringLiteral("b/box.iv")));

    // Its file gone: reported in one line, kept in the list, and saved again
    ASSERT_TRUE(QFile::remove(root.filePath(QStringLiteral("b/box.iv"))));
    reopen(root.filePath(QStringLiteral("b/doc.json")));
    EXPECT_EQ(w.doc().references().drawn(), 0);
    ASSERT_EQ(w.doc().referenceProblems().size(), 1);
    const std::string problem = w.doc().referenceProblems().front().toStdString();
    EXPECT_NE(problem.find("not shown (kept in the document)"), std::string::npos) << problem;
    EXPECT_NE(problem.find("cannot open file (No such file or directory)"), std::string::npos) << problem;
    QApplication::processEvents();
    EXPECT_NE(w.window.statusBar()->currentMessage().toStdString().find("not shown"), std::string::npos);
    w.doc().save(root.filePath(QStringLiteral("b/again.json")));
    std::ifstream in(root.filePath(QStringLiteral("b/again.json")).toStdString());
    const nlohmann::json again = nlohmann::json::parse(in);
    ASSERT_EQ(again["references"].size(), 1u);
    EXPECT_EQ(again["references"][0]["path"], root.filePath(QStringLiteral("a/box.iv")).toStdString());
    EXPECT_EQ(again["references"][0]["relative"], "box.iv");
}

}  // namespace
}  // namespace sculptline::ui
