#include "ui/tablet_pressure.h"

#include <QMouseEvent>
#include <QTabletEvent>
#include <QWidget>

namespace sculptline::ui {

TabletPressure::TabletPressure(QWidget* viewport) : QObject(viewport)
{
    viewport->installEventFilter(this);
}

bool TabletPressure::eventFilter(QObject* watched, QEvent* event)
{
    switch (event->type()) {
    case QEvent::TabletPress:
    case QEvent::TabletMove:
    case QEvent::TabletRelease: {
        // (Checked and clamped where the stroke takes it: StrokeInput::addSample.)
        pressure_ = static_cast<QTabletEvent*>(event)->pressure();
        break;  // not taken: Qt synthesizes the mouse event the scene graph draws with
    }
    case QEvent::MouseButtonPress:
    case QEvent::MouseMove:
    case QEvent::MouseButtonRelease:
        if (static_cast<QMouseEvent*>(event)->source() == Qt::MouseEventNotSynthesized) pressure_.reset();
        break;
    default: break;
    }
    return QObject::eventFilter(watched, event);
}

}  // namespace sculptline::ui
