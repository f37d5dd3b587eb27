#include "ui/main_window.h"

#include "manipulators/projection_plane_manipulator.h"
#include "scene/default_scene.h"
#include "scene/eigen_coin.h"

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <QAction>
#include <QApplication>
#include <QGLWidget>
#include <QMenuBar>
#include <QStatusBar>

namespace sculptline::ui {
namespace {

/// A dark neutral background: the grid's grey lines, the warm curve and the cool surface all keep
/// their contrast against it.
const SbColor kBackground(0.16f, 0.17f, 0.2f);

/// From the front right (-Y, +X) and above: the three-quarter view of a draughtsman.
const Eigen::Vector3d kViewDirection(-1.0, 1.6, -0.9);

/// Share of viewAll's camera distance kept after framing (closer = larger scene on screen).
constexpr float kFramingZoom = 0.9f;

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent)
{
    setWindowTitle(QStringLiteral("Sculptline"));
    auto* central = new QWidget(this);
    setCentralWidget(central);
    viewer_ = new SoQtExaminerViewer(central);
    viewer_->setBackgroundColor(kBackground);
    // Sorted blending draws the translucent planes after, and back to front over, the opaque shapes.
    viewer_->setTransparencyType(SoGLRenderAction::SORTED_OBJECT_BLEND);
    viewer_->setFeedbackVisibility(FALSE);
    createMenus();
    statusBar()->showMessage(tr("Ready"));
}

MainWindow::~MainWindow()
{
    // Detach the graph from the viewer (it holds a ref of its own), drop ours, then let the
    // manipulators release their subgraphs; the viewer goes last.
    viewer_->setSceneGraph(nullptr);
    clearScene();
    delete viewer_;
}

QWidget* MainWindow::viewport() const { return viewer_->getGLWidget(); }

void MainWindow::createMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* quit = file->addAction(tr("&Quit"));
    quit->setShortcut(QKeySequence::Quit);
    connect(quit, &QAction::triggered, qApp, &QApplication::quit);
}

void MainWindow::clearScene()
{
    if (root_) root_->unref();
    root_ = nullptr;
    planes_.clear();
}

void MainWindow::showDocument(const scene::SceneDocument& doc, const QString& title)
{
    viewer_->setSceneGraph(nullptr);
    clearScene();
    std::vector<std::unique_ptr<manipulators::ProjectionPlaneManipulator>> planes;
    auto factory = [&planes](const scene::PlaneSpec& plane, size_t) -> SoNode* {
        planes.push_back(std::make_unique<manipulators::ProjectionPlaneManipulator>(plane));
        return planes.back()->root();
    };
    root_ = scene::buildSceneGraph(doc, factory);
    root_->ref();
    planes_ = std::move(planes);
    viewer_->setSceneGraph(root_);

    // Z is up in the model; look from the front right and above, like a draughtsman's isometric view.
    if (SoCamera* camera = viewer_->getCamera()) {
        camera->orientation = scene::rotationLookingAlong(kViewDirection, Eigen::Vector3d::UnitZ());
        viewer_->viewAll();
        // viewAll frames the bounding sphere, which leaves a wide margin around a flat-ish scene.
        SbVec3f forward;
        camera->orientation.getValue().multVec(SbVec3f(0, 0, -1), forward);
        const float distance = camera->focalDistance.getValue();
        camera->position = camera->position.getValue() + forward * (distance * (1.0f - kFramingZoom));
        camera->focalDistance = distance * kFramingZoom;
    }
    setWindowTitle(QStringLiteral("Sculptline — %1").arg(title));
    // The examiner viewer starts in viewing mode, where the mouse turns the camera and draggers get
    // no events; Esc toggles to interaction mode (SoQt's convention), so say so.
    statusBar()->showMessage(tr("%1: %2 curve(s), %3 surface(s), %4 plane(s). Esc: switch between "
                                "turning the view and dragging the plane.")
                                 .arg(title)
                                 .arg(doc.curves.size())
                                 .arg(doc.surfaces.size())
                                 .arg(doc.planes.size()));
}

void MainWindow::setViewportSize(int width, int height)
{
    // The difference between the window and its GL area is decorations, menu and status bar;
    // they do not change with the window's size, so one correction step is exact.
    QWidget* gl = viewport();
    const QSize extra = size() - gl->size();
    resize(width + extra.width(), height + extra.height());
}

void MainWindow::renderViewport() { viewer_->render(); }

QImage MainWindow::grabViewport()
{
    renderViewport();
    return static_cast<QGLWidget*>(viewer_->getGLWidget())->grabFrameBuffer();
}

}  // namespace sculptline::ui
