#pragma once
// Camera navigation with the buttons that do not draw, in every mode: a designer sketches with
// the left button and moves the view with the others, as in SketchBook and Blender's Grease Pencil
// (middle-drag turns, Shift+middle pans, Ctrl+middle and the wheel zoom) or with Alt and a button,
// as in Maya and Alias (Alt+left turns, Alt+middle pans, Alt+right zooms). A right-drag pans; a
// right click without a drag is left to the caller (the context menu).
//
// The turn is a turntable about the model's Z (up) through the point the camera looks at, so the
// horizon stays level; no inertia: the view stops when the pointer does.
#include <QPoint>

class QMouseEvent;
class QWheelEvent;
class SoCamera;

namespace sculptline::ui {

class ViewNavigation {
public:
    enum class Gesture { None, Turn, Pan, Zoom, RightButton };

    /// The gesture a press starts; None for a press that draws or picks (the plain left button).
    static Gesture gestureFor(const QMouseEvent& press);

    /// @param camera the viewer's camera (may change between calls, e.g. on reload)
    /// @param viewportHeight pixels, > 0: converts pointer motion to model units at the focal plane
    bool press(const QMouseEvent& event);
    /// Moves the camera for a drag in progress; true when the event was the navigation's.
    bool move(const QMouseEvent& event, SoCamera* camera, int viewportHeight);
    /// Ends the gesture; `click` tells whether a right press was released without a drag.
    bool release(const QMouseEvent& event, bool* click);
    /// Zooms about the point looked at: one wheel notch (120) scales the distance by kWheelStep.
    static void wheel(const QWheelEvent& event, SoCamera* camera);

    bool active() const { return gesture_ != Gesture::None; }

    /// One turn step: `dx`, `dy` pixels of pointer motion (right, down).
    static void turn(SoCamera* camera, double dx, double dy);
    /// Moves the camera so the model follows the pointer by `dx`, `dy` pixels.
    static void pan(SoCamera* camera, double dx, double dy, int viewportHeight);
    /// Scales the distance to the point looked at (orthographic: the view height) by `factor`.
    static void zoom(SoCamera* camera, double factor);

private:
    Gesture gesture_ = Gesture::None;
    Qt::MouseButton button_ = Qt::NoButton;
    QPoint start_, last_;
    bool dragged_ = false;
};

}  // namespace sculptline::ui
