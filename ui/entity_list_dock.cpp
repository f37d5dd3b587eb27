#include "ui/entity_list_dock.h"

#include <QListWidget>

namespace sculptline::ui {

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
    auto add = [this](const model::Entity& e, const QString& text) {
        auto* item = new QListWidgetItem(e.fixed ? text + tr(" - fixed") : text, list_);
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
    }
    // The designer's constraints (pins and the rest; fixed points show in the inspector): an item
    // selects what the constraint holds.
    for (const auto& [id, c] : model.constraints()) {
        if (model::derivedConstraint(c.type) || c.type == model::ConstraintType::FixedPoints) continue;
        QStringList targets;
        for (model::EntityId t : c.targets) targets << QString::number(t);
        auto* item = new QListWidgetItem(tr("Constraint c%1 (%2 on %3)").arg(id).arg(QString::fromLatin1(model::constraintTypeName(c.type)))
                                             .arg(targets.join(QStringLiteral(", "))),
                                         list_);
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
