#include "ui/aesthetics_dock.h"

#include "scene/curvature_comb.h"
#include "solvers/bspline/geometry_error.h"
#include "ui/sketch_document.h"

#include <QAction>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QScrollArea>
#include <QSpinBox>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

#include <string>

namespace sculptline::ui {
namespace {

namespace aes = solvers::aesthetics;

/// Significant digits of the numbers shown: the analysis is exact to far more; four read at a glance.
constexpr int kDigits = 4;
/// The comb's controls: samples per knot span and the factor on the default scale.
constexpr int kMaxDensity = 64;
constexpr double kMinScaleFactor = 0.05;
constexpr double kMaxScaleFactor = 50.0;

QString number(double value) { return QString::number(value, 'g', kDigits); }

/// The measures in the order shown: key, label, unit.
struct MeasureRow {
    const char* key;
    const char* label;
    const char* unit;
};
constexpr MeasureRow kMeasures[] = {
    {"tension", "Tension", ""},
    {"acceleration", "Acceleration", " /mm²"},
    {"sharpness", "Sharpness (max |κ|)", " /mm"},
    {"flatness", "Flatness", ""},
    {"convexity", "Convexity", " mm²"},
    {"crown", "Crown", " mm"},
    {"kappaMin", "κ min", " /mm"},
    {"kappaMax", "κ max", " /mm"},
    {"length", "Length", " mm"},
};

QTableWidget* makeTable(const QStringList& headers, QWidget* parent)
{
    auto* table = new QTableWidget(0, headers.size(), parent);
    table->setHorizontalHeaderLabels(headers);
    table->verticalHeader()->setVisible(false);
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->setSelectionMode(QAbstractItemView::NoSelection);
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table->setMinimumHeight(140);
    return table;
}

void setCell(QTableWidget* table, int row, int column, const QString& text)
{
    auto* item = new QTableWidgetItem(text);
    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    table->setItem(row, column, item);
}

}  // namespace

AestheticsDock::AestheticsDock(SketchDocument& document, QWidget* parent) : QDockWidget(tr("Aesthetics"), parent), document_(document)
{
    setObjectName(QStringLiteral("dock.aesthetics"));
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    auto* box = new QWidget(scroll);
    auto* layout = new QVBoxLayout(box);
    header_ = new QLabel(box);
    header_->setObjectName(QStringLiteral("aesthetics.header"));
    QFont bold = header_->font();
    bold.setBold(true);
    header_->setFont(bold);
    header_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(header_);
    message_ = new QLabel(box);
    message_->setObjectName(QStringLiteral("aesthetics.message"));
    message_->setWordWrap(true);
    message_->setStyleSheet(QStringLiteral("color: #c04020"));
    message_->setVisible(false);
    layout->addWidget(message_);
    operators_ = new QHBoxLayout;
    operators_->setObjectName(QStringLiteral("aesthetics.operators"));
    layout->addLayout(operators_);
    createOperators(box);

    auto* measures = new QGroupBox(tr("Measures"), box);
    auto* form = new QFormLayout(measures);
    for (const MeasureRow& m : kMeasures) {
        auto* value = new QLabel(measures);
        value->setTextInteractionFlags(Qt::TextSelectableByMouse);
        form->addRow(tr(m.label), value);
        measures_[QString::fromLatin1(m.key)] = value;
    }
    layout->addWidget(measures);

    auto* points = new QGroupBox(tr("Characteristic points"), box);
    auto* pointsLayout = new QVBoxLayout(points);
    points_ = makeTable({tr("Codon"), tr("u"), tr("κ (1/mm)"), tr("s (mm)"), tr("Properties")}, points);
    points_->setToolTip(tr("The properties of an extremum (thesis §7.3.2): small visibility (its curvature changes and "
                           "distances to its neighbours below the thresholds), sharp corner, symmetric, redundant"));
    pointsLayout->addWidget(points_);
    layout->addWidget(points);

    auto* lcg = new QGroupBox(tr("Log curvature graph"), box);
    auto* lcgLayout = new QVBoxLayout(lcg);
    lcg_ = makeTable({tr("From u"), tr("To u"), tr("Slope α"), tr("r²")}, lcg);
    lcg_->setToolTip(tr("Slope of log(ρ / |dρ/ds|) against log ρ per monotone-curvature segment: "
                        "clothoid −1, logarithmic spiral 1, circle involute 2"));
    lcgLayout->addWidget(lcg_);
    layout->addWidget(lcg);

    auto* comb = new QGroupBox(tr("Curvature comb"), box);
    auto* combForm = new QFormLayout(comb);
    combAction_ = new QAction(tr("Curvature &comb"), this);
    combAction_->setObjectName(QStringLiteral("view.curvatureComb"));
    combAction_->setShortcut(QKeySequence(QStringLiteral("Shift+C")));
    combAction_->setCheckable(true);
    combAction_->setToolTip(tr("Draw the selected curve's curvature comb in the viewport"));
    combBox_ = new QCheckBox(tr("Show in the viewport (Shift+C)"), comb);
    combBox_->setObjectName(QStringLiteral("aesthetics.comb"));
    combForm->addRow(combBox_);
    connect(combBox_, &QCheckBox::toggled, combAction_, &QAction::setChecked);
    connect(combAction_, &QAction::toggled, this, [this](bool on) {
        combBox_->setChecked(on);
        document_.comb().setVisible(on);
        updateScaleNote();
    });
    density_ = new QSpinBox(comb);
    density_->setObjectName(QStringLiteral("aesthetics.density"));
    density_->setRange(1, kMaxDensity);
    density_->setValue(document_.comb().density());
    density_->setSuffix(tr(" per span"));
    combForm->addRow(tr("Teeth"), density_);
    connect(density_, QOverload<int>::of(&QSpinBox::valueChanged), this, [this](int n) { document_.comb().setDensity(n); });
    scale_ = new QDoubleSpinBox(comb);
    scale_->setObjectName(QStringLiteral("aesthetics.scale"));
    scale_->setRange(kMinScaleFactor, kMaxScaleFactor);
    scale_->setDecimals(2);
    scale_->setSingleStep(0.25);
    scale_->setValue(document_.comb().scaleFactor());
    scale_->setPrefix(QStringLiteral("× "));
    scale_->setToolTip(tr("× 1: the longest tooth is %1 % of the curve's size").arg(100.0 * scene::kCombLengthFraction));
    combForm->addRow(tr("Scale"), scale_);
    connect(scale_, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double f) {
        document_.comb().setScaleFactor(f);
        updateScaleNote();
    });
    scaleNote_ = new QLabel(comb);
    combForm->addRow(scaleNote_);
    layout->addWidget(comb);
    layout->addStretch(1);
    scroll->setWidget(box);
    setWidget(scroll);

    showAction_ = new QAction(tr("&Aesthetics"), this);
    showAction_->setObjectName(QStringLiteral("view.aesthetics"));
    showAction_->setShortcut(QKeySequence(QStringLiteral("Ctrl+Shift+A")));
    connect(showAction_, &QAction::triggered, this, [this]() {
        show();
        raise();
    });

    connect(&document_, &SketchDocument::selectionChanged, this, [this]() { refresh(); });
    connect(&document_, &SketchDocument::entitiesChanged, this, [this]() { scheduleRefresh(); });
    connect(&document_, &SketchDocument::selectionUpdated, this, [this]() {
        const model::Entity* e = document_.model().find(document_.selection());
        if (e && e->kind == model::EntityKind::Curve && !(e->id == curve_ && e->shapeVersion == analysedVersion_)) scheduleRefresh();
    });
    connect(this, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible && stale_) refresh();
    });
    refresh();
}

QString AestheticsDock::header() const { return header_->text(); }
QString AestheticsDock::message() const { return message_->isVisibleTo(this) ? message_->text() : QString(); }

QString AestheticsDock::measureText(const QString& key) const
{
    const auto it = measures_.find(key);
    return it == measures_.end() ? QString() : it->second->text();
}

void AestheticsDock::scheduleRefresh()
{
    if (pending_) return;
    pending_ = true;
    QTimer::singleShot(0, this, [this]() {
        pending_ = false;
        refresh();
    });
}

void AestheticsDock::updateScaleNote()
{
    const scene::CurvatureComb& comb = document_.comb();
    scaleNote_->setText(comb.visible() && comb.scale() > 0.0 ? tr("A tooth is %1 mm² × κ long").arg(number(comb.scale())) : QString());
}

void AestheticsDock::refresh()
{
    // Hidden (closed, or a tab behind another): nothing to read; analysed when shown again.
    if (!isVisible()) {
        stale_ = true;
        return;
    }
    stale_ = false;
    ++refreshes_;
    updateScaleNote();
    const model::Entity* e = document_.model().find(document_.selection());
    analysedVersion_ = -1;
    if (!e || e->kind != model::EntityKind::Curve || !e->world) {
        curve_ = 0;
        clearAnalysis();
        header_->setText(tr("No curve selected"));
        message_->setText(tr("Select a curve (Select mode, E) to see its aesthetic analysis."));
        message_->setVisible(true);
        return;
    }
    if (curve_ != e->id && amount_) amount_->setValue(document_.defaultAestheticAmount());
    curve_ = e->id;
    analysedVersion_ = e->shapeVersion;
    showAnalysis(*e);
}

void AestheticsDock::clearAnalysis()
{
    analysis_.reset();
    for (auto& [key, label] : measures_) label->clear();
    points_->setRowCount(0);
    lcg_->setRowCount(0);
}

void AestheticsDock::showAnalysis(const model::Entity& e)
{
    try {
        if (e.world->degree() < 2) throw solvers::GeometryError("degree 1: a polyline has no curvature; the analysis needs degree 2 or more");
        solvers::Curve2d planar = [&]() {
            try {
                return scene::planarForm(e);
            } catch (const solvers::GeometryError&) {
                throw solvers::GeometryError("not planar — analysis needs a planar curve (the comb shows its Frenet curvature)");
            }
        }();
        analysis_ = aes::analyzeCurve(planar);
    } catch (const solvers::GeometryError& error) {
        clearAnalysis();
        header_->setText(tr("Curve %1").arg(e.id));
        message_->setText(QString::fromStdString(error.what()));
        message_->setVisible(true);
        return;
    }
    const aes::CurveAnalysis& a = *analysis_;
    header_->setText(tr("Curve %1: %2").arg(e.id).arg(a.name.empty() ? tr("(no characteristic points)") : QString::fromStdString(a.name)));
    message_->clear();
    message_->setVisible(false);
    const aes::Measures& m = a.measures;
    const std::map<QString, std::optional<double>> values = {
        {QStringLiteral("tension"), m.tension},
        {QStringLiteral("acceleration"), m.acceleration},
        {QStringLiteral("sharpness"), m.sharpness},
        {QStringLiteral("flatness"), m.flatness},
        {QStringLiteral("convexity"), m.convexity},
        {QStringLiteral("crown"), m.crown},
        {QStringLiteral("kappaMin"), m.curvatureMin},
        {QStringLiteral("kappaMax"), m.curvatureMax},
        {QStringLiteral("length"), a.length},
    };
    for (const MeasureRow& row : kMeasures) {
        const std::optional<double>& v = values.at(QString::fromLatin1(row.key));
        // Tension is undefined where the turns cancel (mean curvature 0).
        measures_.at(QString::fromLatin1(row.key))->setText(v ? number(*v) + QString::fromUtf8(row.unit) : tr("— (mean κ is 0)"));
    }
    points_->setRowCount(static_cast<int>(a.points.size()));
    for (size_t i = 0; i < a.points.size(); ++i) {
        const aes::CharacteristicPoint& p = a.points[i];
        const int r = static_cast<int>(i);
        setCell(points_, r, 0, QString::fromLatin1(aes::codon(p.kind)));
        points_->item(r, 0)->setTextAlignment(Qt::AlignCenter);
        setCell(points_, r, 1, number(p.u));
        setCell(points_, r, 2, number(p.curvature));
        setCell(points_, r, 3, number(p.arcLength));
        setCell(points_, r, 4, QString());  // an inflection has no properties
        points_->item(r, 4)->setTextAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    }
    for (const aes::Characteristics& c : a.characteristics) {
        if (c.point < 0 || c.point >= points_->rowCount()) continue;
        QStringList flags;
        if (c.smallVisibility) flags << tr("small visibility");
        if (c.sharpCorner) flags << tr("sharp corner");
        if (c.symmetric) flags << tr("symmetric");
        if (c.redundant) flags << tr("redundant");
        points_->item(c.point, 4)->setText(flags.isEmpty() ? tr("—") : flags.join(QStringLiteral(", ")));
    }
    lcg_->setRowCount(static_cast<int>(a.lcg.size()));
    for (size_t i = 0; i < a.lcg.size(); ++i) {
        const aes::LcgSegment& s = a.lcg[i];
        const int r = static_cast<int>(i);
        setCell(lcg_, r, 0, number(s.u0));
        setCell(lcg_, r, 1, number(s.u1));
        setCell(lcg_, r, 2, number(s.slope));
        setCell(lcg_, r, 3, number(s.r2));
    }
}

}  // namespace sculptline::ui
