#include "ui/entity_list_dock.h"

#include "scene/state_colors.h"

#include <QListWidget>
#include <QPixmap>

namespace sculptline::ui {
namespace {

/// Side of a row's colour swatch, pixels.
constexpr int kSwatchSize = 12;

QColor toQColor(const scene::Rgb& c) { return QColor::fromRgbF(c[0], c[1], c[2]); }

/// The swatch of entity `e` in the viewport's colours (scene/state_colors.h): a curve's colour as
/// drawn; for other entities the fixed or changed colour, none when free (the viewport colours
/// only curves by state).
QIcon swatch(const model::Model& model, const model::Entity& e)
{
    const model::State state = scene::shownState(model, e.id);
    if (e.kind != model::EntityKind::Curve && state == model::State::Free) return {};
    QPixmap pixmap(kSwatchSize, kSwatchSize);
    pixmap.fill(toQColor(scene::curveColor(e.id, state)));
    return QIcon(pixmap);
}

}  // namespace

QColor EntityListDock::swatchColor(int row) const
{
    const QListWidgetItem* item = list_->item(row);
    if (!item || item->icon().isNull()) return {};
    return item->icon().pixmap(kSwatchSize, kSwatchSize).toImage().pixelColor(kSwatchSize / 2, kSwatchSize / 2);
}

int EntityListDock::rowOf(const QString& textStart) const
{
    for (int row = 0; row < list_->count(); ++row) {
        if (list_->item(row)->text().trimmed().startsWith(textStart)) return row;
    }
    return -1;
}

EntityListDock::EntityListDock(QWidget* parent) : QDockWidget(tr("Entities"), parent)
{
    setObjectName(QStringLiteral("dock.entities"));
    list_ = new QListWidget(this);
    setWidget(list_);
    connect(list_, &QListWidget::currentItemChanged, this, [this](QListWidgetItem* item) {
        if (updating_ || !item) return;
        Q_EMIT entityPicked(item->data(Qt::UserRole).toUInt());
    });
}

void EntityListDock::refresh(const model::Model& model, model::EntityId selection)
{
    updating_ = true;
    list_->clear();
    auto add = [this, &model](const model::Entity& e, const QString& text) {
        const model::State state = scene::shownState(model, e.id);
        auto* item = new QListWidgetItem(swatch(model, e), state == model::State::Fixed     ? text + tr(" - fixed")
                                                         : state == model::State::Changed ? text + tr(" - changed")
                                                                                          : text,
                                         list_);
        item->setData(Qt::UserRole, e.id);
    };
    // Planes with their curves under them, then curves on no plane, surfaces and constraints.
    for (const auto& [id, e] : model.entities()) {
        if (e.kind != model::EntityKind::Plane) continue;
        add(e, tr("Plane %1").arg(id));
        for (model::EntityId c : model.dependents(id)) {
            const model::Entity* curve = model.find(c);
            if (curve->kind != model::EntityKind::Curve) continue;
            add(*curve, tr("    Curve %1 (degree %2, %3 points)").arg(c).arg(curve->local->degree()).arg(curve->local->pointCount()));
        }
    }
    for (const auto& [id, e] : model.entities()) {
        if (e.kind == model::EntityKind::Curve && e.plane() == 0) add(e, tr("Curve %1 (in space)").arg(id));
        if (e.kind == model::EntityKind::Surface) {
            QString text = e.recipe ? tr("Surface %1 (%2)").arg(id).arg(QString::fromLatin1(model::constructionName(e.recipe->mode)))
                                    : tr("Surface %1").arg(id);
            if (e.failed()) text += e.surface ? tr(" - not rebuilt") : tr(" - failed");
            add(e, text);
        }
        if (e.kind == model::EntityKind::Mesh) add(e, tr("Mesh %1 (network of %2 curves)").arg(id).arg(e.inputs.size()));
        if (e.kind == model::EntityKind::Solid) {
            QString text = tr("Solid %1 (%2 of %3 surfaces)").arg(id).arg(QString::fromLatin1(model::solidModeName(e.solidRecipe->mode))).arg(e.inputs.size());
            if (e.solidStale()) text += e.failed() ? tr(" - not converted") : tr(" - converting");
            add(e, text);
        }
    }
    // The designer's constraints (pins and the rest; fixed points show in the inspector): an item
    // selects what the constraint holds.
    for (const auto& [id, c] : model.constraints()) {
        if (model::derivedConstraint(c.type) || c.type == model::ConstraintType::FixedPoints) continue;
        QStringList targets;
        for (model::EntityId t : c.targets) targets << QString::number(t);
        QListWidgetItem* item = nullptr;
        const model::Entity* curve = c.type == model::ConstraintType::CurveOnSurface ? model.find(c.targets.front()) : nullptr;
        if (curve && c.targets.size() == 2) {
            // Held exactly when its curve is fixed (the incidence solve's hard rows), else softly:
            // the swatch is the curve's.
            item = new QListWidgetItem(swatch(model, *curve),
                                       tr("Constraint c%1 (curve %2 on surface %3, %4)").arg(id).arg(c.targets[0]).arg(c.targets[1])
                                           .arg(curve->fixed ? tr("exact") : tr("soft")),
                                       list_);
        } else {
            item = new QListWidgetItem(tr("Constraint c%1 (%2 on %3)").arg(id).arg(QString::fromLatin1(model::constraintTypeName(c.type)))
                                           .arg(targets.join(QStringLiteral(", "))),
                                       list_);
        }
        item->setData(Qt::UserRole, c.targets.front());
    }
    updating_ = false;
    setSelection(selection);
}

void EntityListDock::setSelection(model::EntityId id)
{
    updating_ = true;
    list_->setCurrentItem(nullptr);
    for (int row = 0; row < list_->count(); ++row) {
        if (list_->item(row)->data(Qt::UserRole).toUInt() == id) list_->setCurrentRow(row);
    }
    updating_ = false;
}

}  // namespace sculptline::ui
