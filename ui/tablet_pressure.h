#pragma once
// A tablet pen's pressure for the strokes drawn in the viewport. Qt delivers a pen's motion as
// QTabletEvents and, when the widget does not take them, as mouse events synthesized from them; the
// scene graph sees only the mouse events. This filter on the viewport keeps the last tablet reading
// for the stroke input (manipulators::StrokeInput::setPressure), and forgets it when a real mouse
// moves, so a mouse stroke after a pen stroke carries no stale pressure.
#include <QObject>

#include <optional>

class QEvent;
class QWidget;

namespace sculptline::ui {

class TabletPressure : public QObject {
public:
    /// Watches `viewport`'s events (installed as its event filter; owned by it).
    explicit TabletPressure(QWidget* viewport);
    /// The pen's last pressure as the tablet reported it (0..1), while the pointer is a tablet pen;
    /// none for a mouse.
    std::optional<double> pressure() const { return pressure_; }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    std::optional<double> pressure_;
};

}  // namespace sculptline::ui
