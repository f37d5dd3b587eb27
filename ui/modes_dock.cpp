#include "ui/modes_dock.h"

#include <QAction>
#include <QGridLayout>
#include <QToolButton>

namespace sculptline::ui {
namespace {

constexpr int kColumns = 2;

}  // namespace

ModesDock::ModesDock(const QList<QAction*>& actions, QWidget* parent) : QDockWidget(tr("Modes"), parent)
{
    setObjectName(QStringLiteral("dock.modes"));
    auto* box = new QWidget(this);
    // Two columns: the sketching and surface modes together stay short enough that the docks
    // never make the window taller than a small screen.
    auto* layout = new QGridLayout(box);
    for (int i = 0; i < actions.size(); ++i) {
        auto* button = new QToolButton(box);
        button->setDefaultAction(actions[i]);
        button->setToolButtonStyle(Qt::ToolButtonTextOnly);
        button->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        button->setToolTip(actions[i]->text() + QStringLiteral(" (") + actions[i]->shortcut().toString() + QStringLiteral(")"));
        layout->addWidget(button, i / kColumns, i % kColumns);
    }
    layout->setRowStretch(static_cast<int>((actions.size() + kColumns - 1) / kColumns), 1);
    setWidget(box);
}

}  // namespace sculptline::ui
