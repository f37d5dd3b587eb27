#include "ui/modes_dock.h"

#include <QAction>
#include <QToolButton>
#include <QVBoxLayout>

namespace sculptline::ui {

ModesDock::ModesDock(const QList<QAction*>& actions, QWidget* parent) : QDockWidget(tr("Modes"), parent)
{
    setObjectName(QStringLiteral("dock.modes"));
    auto* box = new QWidget(this);
    auto* layout = new QVBoxLayout(box);
    for (QAction* action : actions) {
        auto* button = new QToolButton(box);
        button->setDefaultAction(action);
        button->setToolButtonStyle(Qt::ToolButtonTextOnly);
        button->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        layout->addWidget(button);
    }
    layout->addStretch(1);
    setWidget(box);
}

}  // namespace sculptline::ui
