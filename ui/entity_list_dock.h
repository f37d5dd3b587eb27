#pragma once
// The scene's entities in a list (planes, their curves indented under them, surfaces, the designer's
// constraints); picking a row selects the entity. Each row's swatch is its state's colour as the
// viewport draws it (scene/state_colors.h): a designer sees which curves an incidence solve holds
// exactly (fixed) and which softly (free).
#include "model/model.h"

#include <QColor>
#include <QDockWidget>

class QListWidget;

namespace sculptline::ui {

class EntityListDock : public QDockWidget {
    Q_OBJECT

public:
    explicit EntityListDock(QWidget* parent = nullptr);
    void refresh(const model::Model& model, model::EntityId selection);
    void setSelection(model::EntityId id);
    /// The colour of row `row`'s swatch; invalid when it has none.
    QColor swatchColor(int row) const;
    /// The first row whose text (without its indent) starts with `textStart`, or -1.
    int rowOf(const QString& textStart) const;

Q_SIGNALS:
    void entityPicked(model::EntityId id);

private:
    QListWidget* list_ = nullptr;
    bool updating_ = false;
};

}  // namespace sculptline::ui
