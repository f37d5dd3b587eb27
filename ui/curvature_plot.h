#pragma once
// The curvature of a curve along its parameter, kappa(u) = |C' x C''| / |C'|^3 (do Carmo §1-5),
// drawn as a line plot: where a designer sees the fairness of a fitted stroke (wiggles, flat spots,
// corners as spikes to zero-length tangents). QPainter only, no plotting library.
#include "solvers/bspline/bspline_curve.h"

#include <QWidget>

#include <optional>
#include <vector>

namespace sculptline::ui {

class CurvaturePlot : public QWidget {
    Q_OBJECT

public:
    explicit CurvaturePlot(QWidget* parent = nullptr);
    /// Samples the curve (empty: clears the plot).
    void setCurve(const std::optional<solvers::Curve3d>& curve);
    /// The sampled curvature, 1/model unit (tests read it).
    const std::vector<double>& samples() const { return kappa_; }
    QSize sizeHint() const override { return {260, 140}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    std::vector<double> kappa_;
};

}  // namespace sculptline::ui
