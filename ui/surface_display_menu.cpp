#include "ui/surface_display_menu.h"

#include "scene/model_view.h"
#include "ui/sketch_document.h"

#include <QAction>
#include <QActionGroup>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QStatusBar>

#include <cmath>

namespace sculptline::ui {
namespace {

QString hex(const SbColor& c)
{
    return QStringLiteral("#%1%2%3")
        .arg(static_cast<int>(std::lround(c[0] * 255)), 2, 16, QLatin1Char('0'))
        .arg(static_cast<int>(std::lround(c[1] * 255)), 2, 16, QLatin1Char('0'))
        .arg(static_cast<int>(std::lround(c[2] * 255)), 2, 16, QLatin1Char('0'));
}

QString number(double x) { return QString::number(x, 'g', 3); }

}  // namespace

SurfaceDisplayMenu::SurfaceDisplayMenu(QMainWindow* window, QMenu* viewMenu, SketchDocument& document,
                                       std::function<SoCamera*()> camera)
    : QObject(window), document_(document), camera_(std::move(camera))
{
    QMenu* menu = viewMenu->addMenu(tr("Surface &display"));
    modes_ = new QActionGroup(this);
    using scene::SurfaceDisplay;
    // Alt+digit: the letters and their Alt forms are taken by the modes and the sculpt tools.
    auto mode = [&](const char* name, const QString& text, const char* key, SurfaceDisplay m) {
        auto* a = new QAction(text, window);
        a->setObjectName(QString::fromLatin1(name));
        a->setShortcut(QKeySequence(QString::fromLatin1(key)));
        a->setCheckable(true);
        a->setChecked(m == SurfaceDisplay::Shaded);
        connect(a, &QAction::triggered, this, [this, m]() { setMode(m); });
        modes_->addAction(a);
        menu->addAction(a);
    };
    mode("view.surfaceShaded", tr("&Shaded"), "Alt+1", SurfaceDisplay::Shaded);
    mode("view.surfaceZebra", tr("&Zebra stripes"), "Alt+2", SurfaceDisplay::Zebra);
    mode("view.surfaceGaussian", tr("&Gaussian curvature"), "Alt+3", SurfaceDisplay::Gaussian);
    mode("view.surfaceMean", tr("&Mean curvature"), "Alt+4", SurfaceDisplay::Mean);
    menu->addSeparator();
    auto stripes = [&](const char* name, const QString& text, const char* key, double factor) {
        auto* a = new QAction(text, window);
        a->setObjectName(QString::fromLatin1(name));
        a->setShortcut(QKeySequence(QString::fromLatin1(key)));
        connect(a, &QAction::triggered, this, [this, factor]() { scaleStripes(factor); });
        menu->addAction(a);
    };
    // A factor of 1.5 (rounded): from the default 16, 24, 36, ...; or 11, 7, ...
    stripes("view.zebraMoreStripes", tr("&More zebra stripes"), "Alt+]", 1.5);
    stripes("view.zebraFewerStripes", tr("&Fewer zebra stripes"), "Alt+[", 1 / 1.5);
    legend_ = new QLabel(window);
    legend_->setObjectName(QStringLiteral("surfaceLegend"));
    legend_->setTextFormat(Qt::RichText);
    legend_->hide();
    window->statusBar()->addPermanentWidget(legend_);
    // Opening a document gives the viewer a new camera (SoQt makes one for a graph without): once the
    // window has shown the document, the zebra looks through it, and the all-surfaces mode, which
    // stays, is drawn on the new surfaces.
    connect(&document_, &SketchDocument::replaced, this, [this]() {
        QMetaObject::invokeMethod(
            this, [this]() { if (camera_) document_.view().surfaceAnalysis().setCamera(camera_()); }, Qt::QueuedConnection);
    });
    connect(&document_, &SketchDocument::selectionChanged, this, [this]() { refresh(); });
    connect(&document_, &SketchDocument::entitiesChanged, this, [this]() { refresh(); });
}

model::EntityId SurfaceDisplayMenu::target() const
{
    const model::Entity* e = document_.model().find(document_.selection());
    return e && e->kind == model::EntityKind::Surface ? e->id : 0;
}

void SurfaceDisplayMenu::setMode(scene::SurfaceDisplay mode)
{
    scene::ModelView& view = document_.view();
    if (camera_) view.surfaceAnalysis().setCamera(camera_());
    view.setSurfaceDisplay(target(), mode);
    refresh();
}

void SurfaceDisplayMenu::scaleStripes(double factor)
{
    scene::SurfaceAnalysisDisplay& analysis = document_.view().surfaceAnalysis();
    analysis.setStripes(static_cast<int>(std::lround(analysis.stripes() * factor)));
    if (auto* window = qobject_cast<QMainWindow*>(parent()))
        window->statusBar()->showMessage(tr("Zebra: %1 black stripes over the reflected directions.").arg(analysis.stripes()), 5000);
}

QString SurfaceDisplayMenu::legendText() const { return legendText_; }

void SurfaceDisplayMenu::refresh()
{
    scene::ModelView& view = document_.view();
    const model::EntityId id = target();
    const scene::SurfaceDisplay shown = view.surfaceDisplay(id);
    const QList<QAction*> actions = modes_->actions();
    actions.value(static_cast<int>(shown))->setChecked(true);
    // The legend of the target, or (all surfaces) of the first one coloured.
    model::EntityId legendOf = id;
    if (legendOf == 0) {
        for (const auto& [eid, e] : document_.model().entities()) {
            if (view.surfaceAnalysis().legend(eid)) {
                legendOf = eid;
                break;
            }
        }
    }
    const scene::CurvatureLegend* legend = legendOf ? view.surfaceAnalysis().legend(legendOf) : nullptr;
    if (!legend) {
        legendText_.clear();
        legend_->hide();
        return;
    }
    const bool gaussian = legend->mode == scene::SurfaceDisplay::Gaussian;
    const QString what = gaussian ? tr("Gaussian K") : tr("mean H");
    const QString unit = gaussian ? tr("1/unit²") : tr("1/unit");
    legendText_ = tr("Surface %1, %2 (%3): blue -%4, white 0, red +%4 (95% of |value| within; min %5, max %6)")
                      .arg(legendOf)
                      .arg(what, unit, number(legend->range), number(legend->min), number(legend->max));
    legend_->setText(QStringLiteral("%1: <span style='background:%2'>&nbsp;-%5&nbsp;</span><span style='background:%3;color:black'>&nbsp;0&nbsp;</span>"
                                    "<span style='background:%4'>&nbsp;+%5&nbsp;</span> %6")
                         .arg(what, hex(scene::divergingColor(-1)), hex(scene::divergingColor(0)), hex(scene::divergingColor(1)),
                              number(legend->range), unit));
    legend_->setToolTip(legendText_);
    legend_->show();
}

}  // namespace sculptline::ui
