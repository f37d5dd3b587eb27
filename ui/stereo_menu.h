#pragma once
// View > Stereo (Off / Anaglyph red-cyan / Quad-buffer / Interleaved rows, one checked) and
// View > VR session…: the immersive views of the main window. A stereo mode the OpenGL context cannot
// give leaves the view mono, checks Off and says why in the status bar (no dialog).
#include "ui/stereo_viewer.h"

#include <QObject>

class QAction;
class QActionGroup;
class QMainWindow;
class QMenu;

namespace sculptline::ui {

class VrSession;

class StereoMenu : public QObject {
    Q_OBJECT

public:
    /// Adds the submenu and the VR action to `viewMenu`; `viewer` may be null (no display: the
    /// actions exist for --list-actions but do nothing).
    StereoMenu(QMainWindow* window, QMenu* viewMenu, StereoExaminerViewer* viewer);
    ~StereoMenu() override;

    /// The action name of `mode`: view.stereo.off, view.stereo.anaglyph, view.stereo.quadBuffer,
    /// view.stereo.interleavedRows.
    static QString actionName(StereoMode mode);

    /// Switches to `mode` as its menu entry does; returns the status message when the viewer stays
    /// mono (empty when `mode` is on).
    QString select(StereoMode mode);
    /// View > VR session…: starts an OpenXR session (ui/xr_session.h); returns the status-bar line
    /// that says what runs, or plainly why nothing does.
    QString startVr();

private:
    QMainWindow* window_;
    StereoExaminerViewer* viewer_;
    QActionGroup* group_ = nullptr;
    VrSession* xr_ = nullptr;
};

}  // namespace sculptline::ui
