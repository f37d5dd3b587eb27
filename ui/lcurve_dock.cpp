#include "ui/lcurve_dock.h"

#include "ui/sketch_document.h"

// QCustomPlot's header uses Qt's `signals` and `foreach` keywords, which QT_NO_KEYWORDS (ui's
// CMakeLists.txt, for the TBB and OpenVDB headers) switches off: spelled out for this one header,
// here only, so that no other file sees them.
#define signals Q_SIGNALS
#define foreach Q_FOREACH
#include <qcustomplot.h>
#undef foreach
#undef signals

#include <QLabel>
#include <QPushButton>
#include <QToolTip>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sculptline::ui {
namespace {

/// A click or a hover within this many pixels of a point is on it.
constexpr double kPickRadius = 10.0;
/// A press and release this many pixels apart are still a click.
constexpr int kClickSlop = 4;
/// Log axes show only positive values: a norm of zero (an exact fit, ρ_r) is drawn this factor
/// below the smallest positive one.
constexpr double kZeroFloorFactor = 0.1;
/// Margin around the points, as a factor on the log axes' ends.
constexpr double kAxisMargin = 1.6;
/// Scatter sizes (pixels): every k, the used k, the corner's ring around it.
constexpr double kPointSize = 5.0;
constexpr double kUsedSize = 11.0;
constexpr double kCornerSize = 17.0;

const QColor kCurveColor(70, 100, 170);
const QColor kUsedColor(230, 80, 30);
const QColor kCornerColor(20, 150, 70);

/// The surface whose L-curve the selection asks for: the surface itself, or the one a selected
/// curve lies on (its curve-on-surface constraint); 0 when none has an incidence report.
model::EntityId reportedSurface(const model::Model& model, model::EntityId selection)
{
    const model::Entity* e = model.find(selection);
    if (!e) return 0;
    if (e->kind == model::EntityKind::Surface) return e->incidence ? e->id : 0;
    if (e->kind != model::EntityKind::Curve) return 0;
    for (model::ConstraintId id : model.constraintsOn(selection)) {
        const model::Constraint& c = model.constraints().at(id);
        if (c.type != model::ConstraintType::CurveOnSurface || c.targets.size() != 2 || c.targets[0] != selection) continue;
        const model::Entity* s = model.find(c.targets[1]);
        if (s && s->incidence) return s->id;
    }
    return 0;
}

/// `values` with every non-positive (or non-finite) entry raised to a floor a log axis can show.
QVector<double> positive(const std::vector<double>& values)
{
    double smallest = std::numeric_limits<double>::infinity();
    for (double v : values) {
        if (v > 0.0 && std::isfinite(v)) smallest = std::min(smallest, v);
    }
    const double floor = std::isfinite(smallest) ? smallest * kZeroFloorFactor : 1e-12;
    QVector<double> out;
    out.reserve(static_cast<int>(values.size()));
    for (double v : values) out.push_back(v > 0.0 && std::isfinite(v) ? v : floor);
    return out;
}

void logAxis(QCPAxis* axis, const QString& label)
{
    axis->setScaleType(QCPAxis::stLogarithmic);
    axis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
    axis->setNumberFormat(QStringLiteral("eb"));  // 10^n
    axis->setNumberPrecision(0);
    axis->setLabel(label);
}

QString millimetres(double value) { return QStringLiteral("%1 mm").arg(value, 0, 'g', 3); }

}  // namespace

LCurveDock::LCurveDock(SketchDocument& document, QWidget* parent) : QDockWidget(tr("L-curve"), parent), document_(document)
{
    setObjectName(QStringLiteral("dock.lcurve"));
    auto* box = new QWidget(this);
    auto* layout = new QVBoxLayout(box);
    plot_ = new QCustomPlot(box);
    plot_->setMinimumSize(240, 200);
    logAxis(plot_->xAxis, tr("residual ρ_k = ‖A F_k − H‖ (mm)"));
    logAxis(plot_->yAxis, tr("change η_k = ‖F_k − F0‖ (mm)"));
    curve_ = new QCPCurve(plot_->xAxis, plot_->yAxis);
    curve_->setName(tr("truncation k = 1..r"));
    curve_->setPen(QPen(kCurveColor, 1.5));
    curve_->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, kPointSize));
    used_ = plot_->addGraph();
    used_->setName(tr("k used"));
    used_->setLineStyle(QCPGraph::lsNone);
    used_->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, QPen(kUsedColor), QBrush(kUsedColor), kUsedSize));
    corner_ = plot_->addGraph();
    corner_->setName(tr("corner"));
    corner_->setLineStyle(QCPGraph::lsNone);
    corner_->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(kCornerColor, 2.0), Qt::NoBrush, kCornerSize));
    plot_->legend->setVisible(true);
    // The legend in a row of its own under the axes, where it hides no point.
    plot_->axisRect()->insetLayout()->take(plot_->legend);
    plot_->plotLayout()->addElement(1, 0, plot_->legend);
    plot_->plotLayout()->setRowStretchFactor(1, 0.001);
    plot_->legend->setFillOrder(QCPLegend::foColumnsFirst);
    usedLabel_ = new QCPItemText(plot_);
    usedLabel_->setColor(kUsedColor);
    connect(plot_, &QCustomPlot::mousePress, this, [this](QMouseEvent* event) { pressedAt_ = event->pos(); });
    connect(plot_, &QCustomPlot::mouseRelease, this, [this](QMouseEvent* event) { released(event); });
    connect(plot_, &QCustomPlot::mouseMove, this, [this](QMouseEvent* event) { hovered(event); });
    layout->addWidget(plot_, 1);
    summary_ = new QLabel(box);
    summary_->setWordWrap(true);
    layout->addWidget(summary_);
    useCorner_ = new QPushButton(tr("Use the corner"), box);
    useCorner_->setToolTip(tr("Solve the surface at the L-curve's corner again (follows the corner as the curves change)"));
    connect(useCorner_, &QPushButton::clicked, this, [this]() {
        if (surface_ != 0) document_.setIncidenceK(surface_, 0);
    });
    layout->addWidget(useCorner_);
    setWidget(box);
    refresh();
}

void LCurveDock::refresh()
{
    const model::Model& model = document_.model();
    const model::EntityId shown = surface_;
    surface_ = reportedSurface(model, document_.selection());
    const model::Entity* s = model.find(surface_);
    // Nothing to show, and nothing shown: no replot (a document's load adds its entities one by one,
    // each a refresh).
    if (!s && shown == 0 && curve_->dataCount() == 0 && !summary_->text().isEmpty()) return;
    curve_->data()->clear();
    used_->data()->clear();
    corner_->data()->clear();
    if (!s) {
        summary_->setText(tr("No L-curve: select a surface that curves lie on (curve-on-surface constraints), or one of "
                             "those curves. Its incidence solve plots here the residual against the surface's change "
                             "for every truncation k; a click on a point solves at that k."));
        useCorner_->setEnabled(false);
        usedLabel_->setVisible(false);
        plot_->replot();
        return;
    }
    const model::Entity::IncidenceReport& r = *s->incidence;
    const QVector<double> rho = positive(r.rho), eta = positive(r.eta);
    const int count = static_cast<int>(std::min(rho.size(), eta.size()));
    for (int i = 0; i < count; ++i) curve_->addData(i + 1, rho[i], eta[i]);
    auto mark = [&](QCPGraph* g, int k) {
        if (k >= 1 && k <= count) g->addData(rho[k - 1], eta[k - 1]);
    };
    mark(used_, r.k);
    if (r.corner != r.k) mark(corner_, r.corner);
    curve_->rescaleAxes();
    for (QCPAxis* axis : {plot_->xAxis, plot_->yAxis}) {
        // Whole decades, at least one: the log ticker labels powers of ten only, and a range inside
        // one decade would crowd its labels.
        const QCPRange range = axis->range();
        axis->setRange(std::pow(10.0, std::floor(std::log10(range.lower / kAxisMargin))),
                       std::pow(10.0, std::ceil(std::log10(range.upper * kAxisMargin))));
    }
    usedLabel_->setVisible(r.k >= 1 && r.k <= count);
    if (usedLabel_->visible()) {
        usedLabel_->position->setCoords(rho[r.k - 1], eta[r.k - 1]);
        // Beside the marker, on the side with room: left of it in the plot's right half.
        const QCPRange x = plot_->xAxis->range();
        const bool right = rho[r.k - 1] > std::sqrt(x.lower * x.upper);
        usedLabel_->setPositionAlignment((right ? Qt::AlignRight : Qt::AlignLeft) | Qt::AlignBottom);
        usedLabel_->setPadding(right ? QMargins(0, 0, 6, 4) : QMargins(6, 0, 0, 4));
        usedLabel_->setText(tr("k = %1").arg(r.k));
    }
    const QString which = s->incidenceK == 0 ? tr("the corner") : tr("chosen; corner %1").arg(r.corner);
    summary_->setText(tr("Surface %1: k = %2 of %3 (%4), residual %5, fixed residual %6; soft system %7 × %8 after %9 hard rows, %10 curve(s).")
                          .arg(surface_)
                          .arg(r.k)
                          .arg(count)
                          .arg(which)
                          .arg(millimetres(r.residual))
                          .arg(millimetres(r.fixedResidual))
                          .arg(r.rows)
                          .arg(r.cols)
                          .arg(r.hardRows)
                          .arg(r.curves));
    useCorner_->setEnabled(s->incidenceK != 0 && !s->fixed);
    plot_->replot();
}

int LCurveDock::pointCount() const { return curve_->dataCount(); }

std::optional<int> LCurveDock::markerAt(const QCPGraph* marker) const
{
    // Read back from what is drawn: the curve's point the marker stands on.
    if (marker->dataCount() == 0) return std::nullopt;
    const QCPGraphData& m = *marker->data()->at(0);
    for (int i = 0; i < curve_->dataCount(); ++i) {
        const QCPCurveData& d = *curve_->data()->at(i);
        if (d.key == m.key && d.value == m.value) return i + 1;
    }
    return std::nullopt;
}

std::optional<int> LCurveDock::usedMarker() const { return markerAt(used_); }
std::optional<int> LCurveDock::cornerMarker() const { return markerAt(corner_); }

QWidget* LCurveDock::plot() const { return plot_; }

QString LCurveDock::summary() const { return summary_->text(); }

QPoint LCurveDock::pixelOf(int k) const
{
    if (k < 1 || k > curve_->dataCount()) return {};
    const QCPCurveData& d = *curve_->data()->at(k - 1);
    return QPoint(static_cast<int>(std::lround(plot_->xAxis->coordToPixel(d.key))),
                  static_cast<int>(std::lround(plot_->yAxis->coordToPixel(d.value))));
}

int LCurveDock::pointNear(const QPoint& position) const
{
    int best = 0;
    double bestDistance = kPickRadius;
    for (int k = 1; k <= pointCount(); ++k) {
        const double d = std::hypot(pixelOf(k).x() - position.x(), pixelOf(k).y() - position.y());
        if (d <= bestDistance) {
            bestDistance = d;
            best = k;
        }
    }
    return best;
}

void LCurveDock::released(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton || (event->pos() - pressedAt_).manhattanLength() > kClickSlop) return;
    const model::Entity* s = document_.model().find(surface_);
    const int k = pointNear(event->pos());
    if (!s || !s->incidence || s->fixed || k == 0) return;  // a fixed surface is not solved again
    // The corner's point: follow the corner again (k = 0), as "Use the corner" does.
    document_.setIncidenceK(surface_, k == s->incidence->corner ? 0 : k);
}

void LCurveDock::hovered(QMouseEvent* event)
{
    const model::Entity* s = document_.model().find(surface_);
    const int k = pointNear(event->pos());
    if (!s || !s->incidence || k == 0) {
        QToolTip::hideText();
        return;
    }
    const model::Entity::IncidenceReport& r = *s->incidence;
    QToolTip::showText(event->globalPos(),
                       tr("k = %1%2\nρ = %3\nη = %4")
                           .arg(k)
                           .arg(k == r.corner ? tr(" (corner)") : k == r.k ? tr(" (used)") : QString())
                           .arg(millimetres(r.rho[static_cast<size_t>(k - 1)]))
                           .arg(millimetres(r.eta[static_cast<size_t>(k - 1)])),
                       plot_);
}

}  // namespace sculptline::ui
