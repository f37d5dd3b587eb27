#include "ui/curvature_plot.h"

#include "scene/curvature_comb.h"
#include "solvers/aesthetics/curve_analysis.h"
#include "solvers/bspline/arc_length.h"
#include "solvers/bspline/curvature.h"
#include "solvers/bspline/geometry_error.h"

// QCustomPlot's header uses Qt's `signals` and `foreach` keywords, which QT_NO_KEYWORDS switches
// off: spelled out for this one header, as in ui/lcurve_dock.cpp.
#define signals Q_SIGNALS
#define foreach Q_FOREACH
#include <qcustomplot.h>
#undef foreach
#undef signals

#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace sculptline::ui {
namespace {

/// Samples along the parameter: finer than a pixel at the dock's usual width.
constexpr int kSamples = 400;
/// Tangents shorter than this (model units per unit parameter) are corners: curvature undefined.
constexpr double kMinSpeed = 1e-9;
/// The vertical range at first holds this share of the samples (by |kappa|), so that one corner's
/// spike does not flatten the rest; wheel zoom and drag reach the rest.
constexpr double kRangeQuantile = 0.98;
/// Margin around the data, as a fraction of the range: room for the codon labels over the extreme
/// points (a label is about a tenth of the plot's usual 150 pixels high).
constexpr double kMargin = 0.22;
/// Codon labels stand this many pixels off their point.
constexpr int kLabelOffset = 4;

const QColor kCurveColor(230, 120, 30);
const QColor kPointColor(70, 100, 170);
const QColor kZeroColor(150, 150, 150);

}  // namespace

CurvaturePlot::CurvaturePlot(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    plot_ = new QCustomPlot(this);
    plot_->setMinimumHeight(220);
    plot_->plotLayout()->insertRow(0);
    title_ = new QCPTextElement(plot_, QString(), QFont(font().family(), font().pointSize(), QFont::Bold));
    plot_->plotLayout()->addElement(0, 0, title_);
    plot_->xAxis->setLabel(tr("arc length s (mm)"));
    plot_->yAxis->setLabel(tr("curvature κ (1/mm)"));
    auto* zero = new QCPItemStraightLine(plot_);
    zero->point1->setCoords(0.0, 0.0);
    zero->point2->setCoords(1.0, 0.0);
    zero->setPen(QPen(kZeroColor, 1.0, Qt::DashLine));
    graph_ = plot_->addGraph();
    graph_->setPen(QPen(kCurveColor, 1.5));
    points_ = plot_->addGraph();
    points_->setLineStyle(QCPGraph::lsNone);
    points_->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, QPen(kPointColor), QBrush(kPointColor), 6.0));
    // Placed by coordinates at the sample read out (attached to the graph it would warn on an empty one).
    tracer_ = new QCPItemTracer(plot_);
    tracer_->setStyle(QCPItemTracer::tsCircle);
    tracer_->setVisible(false);
    plot_->plotLayout()->insertRow(1);
    readout_ = new QCPTextElement(plot_, QString(), QFont(font().family(), font().pointSize() - 1));
    readout_->setTextColor(kPointColor);
    plot_->plotLayout()->addElement(1, 0, readout_);
    plot_->setInteractions(QCP::iRangeZoom | QCP::iRangeDrag);
    connect(plot_, &QCustomPlot::mouseMove, this, [this](QMouseEvent* event) { hovered(event); });
    layout->addWidget(plot_);
    setCurve(nullptr);
}

QWidget* CurvaturePlot::plot() const { return plot_; }
QString CurvaturePlot::title() const { return title_->text(); }
QString CurvaturePlot::readout() const { return readout_->text().trimmed(); }

QStringList CurvaturePlot::codonLabels() const
{
    QStringList out;
    for (const QCPItemText* label : labels_) out << label->text();
    return out;
}

QPoint CurvaturePlot::pixelOfSample(int i) const
{
    if (i < 0 || i >= static_cast<int>(kappa_.size())) return {};
    return QPoint(static_cast<int>(std::lround(plot_->xAxis->coordToPixel(s_[static_cast<size_t>(i)]))),
                  static_cast<int>(std::lround(plot_->yAxis->coordToPixel(kappa_[static_cast<size_t>(i)]))));
}

void CurvaturePlot::setCurve(const model::Entity* e)
{
    kappa_.clear();
    s_.clear();
    signed_ = false;
    for (QCPItemText* label : labels_) plot_->removeItem(label);
    labels_.clear();
    points_->data()->clear();
    readout_->setText(QStringLiteral(" "));  // a space: the row keeps its height
    tracer_->setVisible(false);
    QString title = tr("Select a curve to see its curvature");
    std::vector<solvers::aesthetics::CharacteristicPoint> characteristic;
    if (e && e->kind == model::EntityKind::Curve && e->world) {
        const solvers::Curve3d& world = *e->world;
        const double u0 = world.domainStart(), u1 = world.domainEnd();
        title = tr("Curve %1").arg(e->id);
        if (world.degree() < 2) {
            title += tr(": degree 1, a polyline has no curvature");
        } else {
            try {
                const solvers::Curve2d planar = scene::planarForm(*e);
                signed_ = true;
                const solvers::ArcLengthParameterization<2> arc(planar);
                for (int i = 0; i < kSamples; ++i) {
                    const double u = u0 + (u1 - u0) * i / (kSamples - 1);
                    kappa_.push_back(solvers::aesthetics::signedCurvature(planar, u));
                    s_.push_back(arc.lengthAt(u));
                }
                try {
                    const solvers::aesthetics::CurveAnalysis a = solvers::aesthetics::analyzeCurve(planar);
                    characteristic = a.points;
                    title += tr(": %1").arg(a.name.empty() ? tr("no characteristic points") : QString::fromStdString(a.name));
                } catch (const solvers::GeometryError& error) {
                    title += tr(": %1").arg(QString::fromStdString(error.what()));
                }
            } catch (const solvers::GeometryError&) {
                // A space curve: the unsigned curvature, and no name (the grammar is planar).
                title += tr(": not planar, unsigned curvature");
                const solvers::ArcLengthParameterization<3> arc(world);
                kappa_ = solvers::sampleCurvature(world, u0, u1, kSamples, kMinSpeed);
                for (int i = 0; i < kSamples; ++i) s_.push_back(arc.lengthAt(u0 + (u1 - u0) * i / (kSamples - 1)));
            }
        }
    }
    title_->setText(title);
    graph_->setData(QVector<double>(s_.begin(), s_.end()), QVector<double>(kappa_.begin(), kappa_.end()), true);
    for (const auto& p : characteristic) {
        points_->addData(p.arcLength, p.curvature);
        auto* label = new QCPItemText(plot_);
        label->setText(QString::fromLatin1(solvers::aesthetics::codon(p.kind)));
        label->position->setCoords(p.arcLength, p.curvature);
        const bool above = p.kind == solvers::aesthetics::PointKind::MaxPositive || p.kind == solvers::aesthetics::PointKind::MaxNegative ||
                           (p.kind == solvers::aesthetics::PointKind::Inflection && p.curvature >= 0.0);
        label->setPositionAlignment(Qt::AlignHCenter | (above ? Qt::AlignBottom : Qt::AlignTop));
        label->setPadding(above ? QMargins(0, 0, 0, kLabelOffset) : QMargins(0, kLabelOffset, 0, 0));
        label->setColor(kPointColor);
        label->setClipToAxisRect(false);  // a label over an extreme point may reach into the margin
        labels_.push_back(label);
    }
    if (!kappa_.empty()) {
        std::vector<double> magnitude(kappa_.size());
        std::transform(kappa_.begin(), kappa_.end(), magnitude.begin(), [](double k) { return std::abs(k); });
        std::sort(magnitude.begin(), magnitude.end());
        const double limit = magnitude[static_cast<size_t>(kRangeQuantile * static_cast<double>(magnitude.size() - 1))];
        const auto [low, high] = std::minmax_element(kappa_.begin(), kappa_.end());
        double lower = std::min(0.0, std::max(*low, -limit)), upper = std::max(0.0, std::min(*high, limit));
        if (upper - lower <= 0.0) upper = lower + 1e-3;  // a straight curve: zero in an arbitrary small range
        const double pad = kMargin * (upper - lower);
        plot_->yAxis->setRange(lower - pad, upper + pad);
        plot_->xAxis->setRange(0.0, std::max(s_.back(), 1e-9));
    } else {
        plot_->xAxis->setRange(0.0, 1.0);
        plot_->yAxis->setRange(-1.0, 1.0);
    }
    plot_->replot();
}

void CurvaturePlot::hovered(QMouseEvent* event)
{
    if (s_.empty() || !plot_->axisRect()->rect().contains(event->pos())) {
        if (!readout().isEmpty()) {
            readout_->setText(QStringLiteral(" "));  // a space: the row keeps its height
            tracer_->setVisible(false);
            plot_->replot(QCustomPlot::rpQueuedReplot);
        }
        return;
    }
    const double s = std::clamp(plot_->xAxis->pixelToCoord(event->pos().x()), s_.front(), s_.back());
    // The sample nearest in arc length (the samples are dense: finer than a pixel).
    const auto it = std::lower_bound(s_.begin(), s_.end(), s);
    size_t i = static_cast<size_t>(it - s_.begin());
    if (i == s_.size() || (i > 0 && s - s_[i - 1] < s_[i] - s)) i = i == 0 ? 0 : i - 1;
    tracer_->position->setCoords(s_[i], kappa_[i]);
    tracer_->setVisible(true);
    readout_->setText(tr("s = %1 mm, κ = %2 /mm").arg(s_[i], 0, 'f', 2).arg(kappa_[i], 0, 'g', 4));
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

}  // namespace sculptline::ui
