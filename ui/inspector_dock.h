#pragma once
// The selected entity in detail: type, plane, degree, control points, knots (curves and surfaces),
// origin and axes (planes); a curve's control points with a check box each, checked = fixed when
// the curve is pulled; below, a selected curve's curvature plot.
#include "model/model.h"

#include <QDockWidget>

#include <vector>

class QCheckBox;
class QDoubleSpinBox;
class QFormLayout;
class QListWidget;
class QWidget;
class QSlider;
class QPlainTextEdit;

namespace sculptline::ui {
class CurvaturePlot;
}

namespace sculptline::ui {

class InspectorDock : public QDockWidget {
    Q_OBJECT

public:
    explicit InspectorDock(QWidget* parent = nullptr);
    void show(const model::Model& model, model::EntityId id);
    /// The selected curve `id` changed shape (a drag's frame): its curvature plot follows, once per
    /// event-loop turn however many updates came, while the plot is visible.
    void followCurve(const model::Model& model, model::EntityId id);
    /// The text shown (tests read it).
    QString text() const;
    /// The control point list (one checkable item per unique point of the selected curve).
    QListWidget* pointList() const { return points_; }
    /// A selected sculpt's stiffness λ in percent (thesis eq. 6-20), hidden for anything else.
    QSlider* stiffnessSlider() const { return stiffness_; }
    /// A selected sculpt with handles: its handles hold their normals (Fig. 6-5 d) when checked.
    QCheckBox* holdNormalsBox() const { return holdNormals_; }
    /// A selected sculpt's distance constraints, one spin box each (model units), in recipe order.
    const std::vector<QDoubleSpinBox*>& distanceBoxes() const { return distances_; }

Q_SIGNALS:
    /// The designer checked or unchecked a control point of `curve`: `fixed` is the new set.
    void fixedPointsEdited(model::EntityId curve, std::vector<int> fixed);
    /// The designer set a sculpt's stiffness λ in (0, 1] (released the slider).
    void stiffnessEdited(model::EntityId surface, double stiffness);
    /// The designer checked or unchecked "Hold normals at handles" of a sculpt.
    void holdNormalsEdited(model::EntityId surface, bool hold);
    /// The designer set distance `index` of a sculpt (finished editing its spin box).
    void distanceEdited(model::EntityId surface, int index, double distance);

private:
    QPlainTextEdit* text_ = nullptr;
    QListWidget* points_ = nullptr;
    model::EntityId curve_ = 0;  ///< the curve whose points the list shows
    QSlider* stiffness_ = nullptr;
    model::EntityId sculpt_ = 0;  ///< the sculpt whose stiffness the slider shows
    QCheckBox* holdNormals_ = nullptr;
    QWidget* distanceBox_ = nullptr;
    QFormLayout* distanceForm_ = nullptr;
    std::vector<QDoubleSpinBox*> distances_;
    bool filling_ = false;
    CurvaturePlot* plot_ = nullptr;
    bool plotPending_ = false;
};

}  // namespace sculptline::ui
