#pragma once
// View > Surface display: Shaded / Zebra / Gaussian curvature / Mean curvature, and the zebra's
// stripe count, acting on the selected surface, or on every surface (present and future) when no
// surface is selected. A colour legend in the status bar says what the curvature colours stand for.
#include "model/entity_kind.h"
#include "scene/surface_analysis_display.h"

#include <QObject>

#include <functional>

class QAction;
class QActionGroup;
class QLabel;
class QMainWindow;
class QMenu;
class SoCamera;

namespace sculptline::ui {

class SketchDocument;

class SurfaceDisplayMenu : public QObject {
    Q_OBJECT

public:
    /// Adds the submenu to `viewMenu` and the legend to `window`'s status bar. `camera` is the
    /// viewer's current camera (the zebra is seen through it), or null without a viewer.
    SurfaceDisplayMenu(QMainWindow* window, QMenu* viewMenu, SketchDocument& document, std::function<SoCamera*()> camera);

    /// Applies `mode` to the selected surface, or to every surface when none is selected.
    void setMode(scene::SurfaceDisplay mode);
    /// Multiplies the zebra's stripe count by `factor` (within the display's limits).
    void scaleStripes(double factor);
    /// The legend's text (plain: no markup), empty when no curvature mode is shown.
    QString legendText() const;

private:
    /// The surface the menu acts on: the selection when it is a surface, else 0 (all of them).
    model::EntityId target() const;
    /// Checks the mode of the target and rewrites the legend.
    void refresh();

    SketchDocument& document_;
    std::function<SoCamera*()> camera_;
    QActionGroup* modes_ = nullptr;
    QLabel* legend_ = nullptr;
    QString legendText_;
};

}  // namespace sculptline::ui
