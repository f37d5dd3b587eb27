#pragma once
// The modes as large buttons (each the button of its QAction, so menu, hot key, replay and button
// stay one thing), plus "new plane".
#include <QDockWidget>
#include <QList>

class QAction;

namespace sculptline::ui {

class ModesDock : public QDockWidget {
    Q_OBJECT

public:
    ModesDock(const QList<QAction*>& actions, QWidget* parent = nullptr);
};

}  // namespace sculptline::ui
