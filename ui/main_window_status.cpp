// MainWindow: the status bar's text — what the mode does, what the designer is asked for next, and
// the mode's action name (the mode and status text, apart from picking and the viewer).
#include "ui/main_window.h"
#include "ui/sketch_document.h"

#include <QAction>
#include <QStatusBar>

namespace sculptline::ui {
namespace {

/// How the view moves, in every mode (ui/view_navigation.h).
const QString kNavigationHint = QStringLiteral("View: middle-drag or Alt+left turns, right-drag pans, wheel zooms; right-click: menu.");

}  // namespace

void MainWindow::updateStatus()
{
    const model::EntityId plane = document_->activePlane();
    QString text;
    switch (mode_) {
    case Mode::View: text = tr("View: drag to turn, right-drag to pan, wheel to zoom. S: sketch, E: select."); break;
    case Mode::Sketch:
        text = plane ? tr("Sketch: draw with the left button on plane %1; drag the plane's jack to move or turn it. Ctrl+P: new plane.").arg(plane)
                     : tr("Sketch: there is no plane to draw on; Ctrl+P adds one facing the view.");
        break;
    case Mode::Oversketch:
        text = tr("Over-sketch: draw over a curve (start on it, or near a curve of plane %1) to redraw that part of it.").arg(plane);
        break;
    case Mode::Lift: text = tr("Lift: draw from a point of one curve to a point of another; the stroke becomes a space curve of least curvature between them."); break;
    case Mode::Pull:
        text = tr("Pull: press on a curve and drag; the curve changes as little as it can to follow the point, keeping its pins "
                  "and fixed points. Shift+click pins a point.");
        break;
    case Mode::Select: text = tr("Select: click a curve or a plane's jack; Delete removes the selection."); break;
    case Mode::Sculpt: {
        if (document_->sculptBase() == 0) {
            text = tr("Sculpt: select a surface first (E, then click it or pick it in the list), then press Y.");
            break;
        }
        const model::EntityId s = document_->sculptBase();
        switch (document_->sculptTool()) {
        case SketchDocument::SculptTool::Target:
            text = tr("Sculpt surface %1: draw a target curve on the active plane; the surface's nearest curve moves onto it. Drag the plane to move it live. "
                      "Alt+B bound, Alt+H handles, Alt+K block, Alt+D distance.").arg(s);
            break;
        case SketchDocument::SculptTool::Bound:
            text = tr("Sculpt surface %1: draw a closed loop over the surface; only the region inside deforms (Alt+T: back to targets).").arg(s);
            break;
        case SketchDocument::SculptTool::Handle:
            text = tr("Sculpt surface %1: click the surface to drop a handle; drag its jack to pull the point, turn its axes' ends to tilt the normal.").arg(s);
            break;
        case SketchDocument::SculptTool::Block:
            text = tr("Sculpt surface %1: click near a control point to block it (it never moves) or free it again.").arg(s);
            break;
        case SketchDocument::SculptTool::Distance:
            text = tr("Sculpt surface %1: click two surface points; their distance is held (set it in the inspector).").arg(s);
            break;
        case SketchDocument::SculptTool::Resketch: text = document_->resketchGuidance(); break;
        }
        break;
    }
    case Mode::Surface: text = surfaceGuidance(); break;
    case Mode::Incidence:
        text = document_->incidenceBase() != 0
                   ? tr("Curves on surface %1: draw a curve on the active plane; the surface is solved to pass through it. Drag the plane or "
                        "over-sketch the curve (O) and the surface follows; Ctrl+Shift+F fixes a curve (met exactly). The L-curve dock picks k.")
                         .arg(document_->incidenceBase())
                   : tr("Interpolation: click the curves a surface should pass through, then Enter (select a surface first and press I to draw onto it).");
        if (!document_->surfaceMessage().isEmpty()) text = document_->surfaceMessage() + QStringLiteral("  ") + text;
        break;
    }
    // The view moves the same way in every mode, so every mode's message ends with it.
    if (mode_ != Mode::View) text += QStringLiteral("  ") + kNavigationHint;
    statusBar()->showMessage(text);
}

QString MainWindow::modeActionName() const
{
    switch (mode_) {
    case Mode::View: return QStringLiteral("mode.view");
    case Mode::Sketch: return QStringLiteral("mode.sketch");
    case Mode::Oversketch: return QStringLiteral("mode.oversketch");
    case Mode::Lift: return QStringLiteral("mode.lift");
    case Mode::Pull: return QStringLiteral("mode.pull");
    case Mode::Select: return QStringLiteral("mode.select");
    case Mode::Sculpt: return QStringLiteral("mode.sculpt");
    case Mode::Incidence: return QStringLiteral("mode.incidence");
    case Mode::Surface: break;
    }
    // "boundary-rotation" -> "mode.boundaryRotation"
    QString name = QStringLiteral("mode.");
    bool upper = false;
    for (const char* c = surfaceMode_ ? model::constructionName(*surfaceMode_) : ""; *c; ++c) {
        if (*c == '-') {
            upper = true;
            continue;
        }
        name += upper ? QChar(*c).toUpper() : QChar(*c);
        upper = false;
    }
    return name;
}

QString MainWindow::surfaceGuidance() const
{
    if (!document_->surfaceMessage().isEmpty()) return document_->surfaceMessage();
    if (!surfaceMode_) return QString();
    const QString mode = QString::fromLatin1(model::constructionName(*surfaceMode_));
    if (surfaceMode_ == model::Construction::Extrude) return tr("Extrude: press on a curve and drag; the surface follows the pointer.");
    if (surfaceMode_ == model::Construction::Gordon) {
        return tr("Gordon: click two or more curves of one family, Enter, then the curves crossing them, Enter (%1 picked). Esc forgets.")
            .arg(document_->surfaceInputs().size());
    }
    if (surfaceMode_ == model::Construction::Network) {
        return tr("Network: click the curves of a closed loop in order (or one closed curve), then Enter (%1 picked). Esc forgets.")
            .arg(document_->surfaceInputs().size());
    }
    const model::InputCount count = model::surfaceInputCount(*surfaceMode_);
    const int picked = static_cast<int>(document_->surfaceInputs().size());
    QString text = tr("%1: click the %2").arg(mode, QString::fromStdString(model::surfaceInputRole(*surfaceMode_, picked)));
    text += count.min == count.max ? tr(" (%1 of %2).").arg(picked + 1).arg(count.max)
                                   : tr(" (%1 picked; Enter builds with %2 or more).").arg(picked).arg(count.min);
    return text + tr(" Esc forgets the picks.");
}

}  // namespace sculptline::ui
