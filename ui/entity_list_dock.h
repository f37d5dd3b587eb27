#pragma once
// The scene's entities in a list (planes, their curves indented under them, surfaces); picking a
// row selects the entity.
#include "scene/model/model.h"

#include <QDockWidget>

class QListWidget;

namespace sculptline::ui {

class EntityListDock : public QDockWidget {
    Q_OBJECT

public:
    explicit EntityListDock(QWidget* parent = nullptr);
    void refresh(const scene::Model& model, scene::EntityId selection);
    void setSelection(scene::EntityId id);

Q_SIGNALS:
    void entityPicked(scene::EntityId id);

private:
    QListWidget* list_ = nullptr;
    bool updating_ = false;
};

}  // namespace sculptline::ui
