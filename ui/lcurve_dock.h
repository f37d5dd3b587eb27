#pragma once
// The L-curve of the selected incidence surface (seed 000 §4.3; Hansen, "Analysis of discrete
// ill-posed problems by means of the L-curve", SIAM Review 34, 1992): the residual norm ρ_k against
// the solution's change η_k for every truncation k of the TSVD, on log-log axes (QCustomPlot), with
// the k the last solve used and the corner marked. A click on a point solves the surface again at
// that k (undoably; a click on the corner goes back to following the corner); a button does the
// same for the corner. A curve selected shows the L-curve of the surface it lies on.
#include "model/model.h"

#include <QDockWidget>
#include <QPoint>

#include <optional>

class QCPCurve;
class QCPGraph;
class QCPItemText;
class QCustomPlot;
class QLabel;
class QMouseEvent;
class QPushButton;

namespace sculptline::ui {

class SketchDocument;

class LCurveDock : public QDockWidget {
    Q_OBJECT

public:
    explicit LCurveDock(SketchDocument& document, QWidget* parent = nullptr);

    /// Shows the L-curve for the document's selection, or why there is none.
    void refresh();

    /// The surface whose L-curve is shown, or 0.
    model::EntityId surface() const { return surface_; }
    /// Points on the plotted L-curve (r: one per truncation k = 1..r).
    int pointCount() const;
    /// The k of the L-curve point the used-k marker and the corner marker stand on, read from the
    /// plot; empty when not drawn (the corner's is drawn only when it differs from the used k).
    std::optional<int> usedMarker() const;
    std::optional<int> cornerMarker() const;
    /// The summary line (k, corner, residuals, system size) or the explanation.
    QString summary() const;
    /// The plot's pixel (plot widget coordinates) of truncation k's point.
    QPoint pixelOf(int k) const;
    /// The plot widget (a QCustomPlot), for clicks.
    QWidget* plot() const;

private:
    /// The k of the curve's point `marker` stands on, if it stands on one.
    std::optional<int> markerAt(const QCPGraph* marker) const;
    /// The truncation whose point lies within kPickRadius pixels of `position`, or 0.
    int pointNear(const QPoint& position) const;
    void released(QMouseEvent* event);
    void hovered(QMouseEvent* event);

    SketchDocument& document_;
    QCustomPlot* plot_ = nullptr;
    QCPCurve* curve_ = nullptr;  ///< parametric in k: ρ need not fall monotonically in floating point
    QCPGraph* used_ = nullptr;
    QCPGraph* corner_ = nullptr;
    QCPItemText* usedLabel_ = nullptr;  ///< "k = .." beside the used k's marker
    QLabel* summary_ = nullptr;
    QPushButton* useCorner_ = nullptr;
    model::EntityId surface_ = 0;
    QPoint pressedAt_;
};

}  // namespace sculptline::ui
