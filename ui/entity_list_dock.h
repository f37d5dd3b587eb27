#pragma once
// The scene's entities in a list (planes, their curves indented under them, surfaces); picking a
// row selects the entity.
#include "model/model.h"

#include <QDockWidget>

class QListWidget;

namespace sculptline::ui {

class EntityListDock : public QDockWidget {
    Q_OBJECT

public:
    explicit EntityListDock(QWidget* parent = nullptr);
    void refresh(const model::Model& model, model::EntityId selection);
    void setSelection(model::EntityId id);

Q_SIGNALS:
    void entityPicked(model::EntityId id);

private:
    QListWidget* list_ = nullptr;
    bool updating_ = false;
};

}  // namespace sculptline::ui
