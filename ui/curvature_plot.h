#pragma once
// The curvature of a curve along its arc length, as a designer reads fairness from it (Farin, Curves
// and Surfaces for CAGD, §23.3): a planar curve's signed curvature kappa = (x'y'' - y'x'') / |C'|^3
// (positive where it turns left along its direction, in its plane as scene::planarForm sees it),
// with its characteristic points (curvature extrema and inflections, thesis ch. 7) marked by their
// codons ("M+", "m-", "0", ...) and its name in the title; a space curve's unsigned
// kappa = |C' x C''| / |C'|^3. QCustomPlot: labelled axes, wheel zoom and drag, and a read-out of
// (s, kappa) under the pointer.
#include "model/model.h"

#include <QPoint>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <vector>

class QCPGraph;
class QCPItemText;
class QCPItemTracer;
class QCPTextElement;
class QCustomPlot;
class QMouseEvent;

namespace sculptline::ui {

class CurvaturePlot : public QWidget {
    Q_OBJECT

public:
    explicit CurvaturePlot(QWidget* parent = nullptr);
    /// Plots curve entity `curve` (null, or not a curve: clears the plot).
    void setCurve(const model::Entity* curve);

    /// The plotted curvature, 1 / model unit: signed for a planar curve (tests read it).
    const std::vector<double>& samples() const { return kappa_; }
    /// The arc length of each sample from the curve's start, model units.
    const std::vector<double>& arcLengths() const { return s_; }
    /// True when samples() are signed (the curve is planar).
    bool isSigned() const { return signed_; }
    /// The codon labels drawn at the characteristic points, in order along the curve.
    QStringList codonLabels() const;
    /// The plot's title: the curve, its name, or why there is no analysis.
    QString title() const;
    /// The last hover read-out ("s = .., κ = .."), empty when the pointer is off the curve.
    QString readout() const;
    /// The plot widget (a QCustomPlot), for pointer events.
    QWidget* plot() const;
    /// The plot's pixel (plot widget coordinates) of sample i.
    QPoint pixelOfSample(int i) const;
    QSize sizeHint() const override { return {260, 240}; }

private:
    void hovered(QMouseEvent* event);

    QCustomPlot* plot_ = nullptr;
    QCPTextElement* title_ = nullptr;
    QCPGraph* graph_ = nullptr;
    QCPGraph* points_ = nullptr;  ///< the characteristic points
    std::vector<QCPItemText*> labels_;
    QCPItemTracer* tracer_ = nullptr;
    QCPTextElement* readout_ = nullptr;  ///< a row under the title, off the data
    std::vector<double> kappa_, s_;
    bool signed_ = false;
};

}  // namespace sculptline::ui
