#include "ui/curvature_plot.h"

#include "solvers/bspline/curvature.h"

#include <Eigen/Geometry>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>

namespace sculptline::ui {
namespace {

/// Samples along the parameter: finer than a pixel at the dock's usual width.
constexpr int kSamples = 400;
/// Tangents shorter than this (model units per unit parameter) are corners: curvature undefined.
constexpr double kMinSpeed = 1e-9;

}  // namespace

CurvaturePlot::CurvaturePlot(QWidget* parent) : QWidget(parent) { setMinimumHeight(100); }

void CurvaturePlot::setCurve(const std::optional<solvers::Curve3d>& curve)
{
    kappa_.clear();
    if (curve) kappa_ = solvers::sampleCurvature(*curve, curve->domainStart(), curve->domainEnd(), kSamples, kMinSpeed);
    update();
}

void CurvaturePlot::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.fillRect(rect(), QColor(40, 42, 48));
    const QRectF area = QRectF(rect()).adjusted(8, 18, -8, -8);
    painter.setPen(QColor(150, 155, 165));
    if (kappa_.empty()) {
        painter.drawText(rect(), Qt::AlignCenter, tr("Select a curve to see its curvature"));
        return;
    }
    // Scaled to the 98th percentile, so one corner spike does not flatten the rest of the plot.
    std::vector<double> sorted = kappa_;
    std::sort(sorted.begin(), sorted.end());
    const double top = std::max(sorted[sorted.size() * 98 / 100], 1e-12);
    painter.drawText(QPointF(8, 13), tr("curvature, max %1 /mm").arg(sorted.back(), 0, 'g', 3));
    painter.drawLine(area.bottomLeft(), area.bottomRight());
    QPainterPath path;
    for (size_t i = 0; i < kappa_.size(); ++i) {
        const double x = area.left() + area.width() * static_cast<double>(i) / static_cast<double>(kappa_.size() - 1);
        const double y = area.bottom() - area.height() * std::min(kappa_[i] / top, 1.0);
        if (i == 0) path.moveTo(x, y);
        else path.lineTo(x, y);
    }
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(QColor(255, 140, 40), 1.5));
    painter.drawPath(path);
}

}  // namespace sculptline::ui
