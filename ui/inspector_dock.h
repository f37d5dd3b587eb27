#pragma once
// The selected entity in detail: type, plane, degree, control points, knots (curves and surfaces),
// origin and axes (planes); below, a selected curve's curvature plot.
#include "scene/model/model.h"

#include <QDockWidget>

class QPlainTextEdit;

namespace sculptline::ui {
class CurvaturePlot;
}

namespace sculptline::ui {

class InspectorDock : public QDockWidget {
    Q_OBJECT

public:
    explicit InspectorDock(QWidget* parent = nullptr);
    void show(const scene::Model& model, scene::EntityId id);
    /// The text shown (tests read it).
    QString text() const;

private:
    QPlainTextEdit* text_ = nullptr;
    CurvaturePlot* plot_ = nullptr;
};

}  // namespace sculptline::ui
