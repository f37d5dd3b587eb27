#include "ui/tablet_pressure.h"

#include <QMouseEvent>
#include <QTabletEvent>
#include <QWidget>

#include <algorithm>
#include <cmath>

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
        const double p = static_cast<QTabletEvent*>(event)->pressure();
        pressure_ = std::isfinite(p) ? std::clamp(p, 0.0, 1.0) : 0.0;
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
