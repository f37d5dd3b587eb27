#pragma once
// The main window: a SoQt examiner viewer as the central widget, a File menu and a status bar.
#include "scene/scene_document.h"

#include <QMainWindow>
#include <QImage>

#include <memory>
#include <vector>

class SoQtExaminerViewer;
class SoSeparator;
class QWidget;

namespace sculptline::manipulators {
class ProjectionPlaneManipulator;
}

namespace sculptline::ui {

/// Owns the scene graph it shows and the plane manipulators inside it.
/// @note SoQt::init() must have been called before construction.
class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Replaces the scene by the one of `doc` (planes become dragger-carried manipulators) and
    /// frames it: a three-quarter view from the front right, above the ground, then viewAll.
    void showDocument(const scene::SceneDocument& doc, const QString& title);

    /// Resizes the window so that the 3D viewport (the GL area) is width x height pixels.
    void setViewportSize(int width, int height);

    /// Renders the viewport now. Under Xvfb no expose event may come to trigger the first frame
    /// (../shared/NOTES.md), so the program asks for one once the window is shown.
    void renderViewport();

    /// Renders the viewport now and returns its pixels. Reads the GL framebuffer: QWidget::grab()
    /// returns black for a GL area (../shared/NOTES.md).
    QImage grabViewport();

    SoQtExaminerViewer* viewer() const { return viewer_; }
    QWidget* viewport() const;
    SoSeparator* sceneRoot() const { return root_; }

private:
    void createMenus();
    void clearScene();

    SoQtExaminerViewer* viewer_ = nullptr;
    SoSeparator* root_ = nullptr;  ///< ref()ed while shown
    std::vector<std::unique_ptr<manipulators::ProjectionPlaneManipulator>> planes_;
};

}  // namespace sculptline::ui
