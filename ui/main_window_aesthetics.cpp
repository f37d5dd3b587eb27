// MainWindow: the Aesthetics menu (thesis §7.4, issue 16 §3): each operator applied to the selected
// curve at once (one undo step), and the handle that sets an operator's amount by dragging it on the
// curve's operated point.
#include "ui/main_window.h"
#include "ui/sketch_document.h"

#include <QAction>
#include <QActionGroup>
#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>

namespace sculptline::ui {

namespace aes = solvers::aesthetics;

void MainWindow::createAestheticsMenu()
{
    QMenu* menu = menuBar()->addMenu(tr("&Aesthetics"));
    const auto add = [this](QMenu* m, const QString& name, const QString& text, auto slot) {
        auto* a = new QAction(text, this);
        a->setObjectName(name);
        connect(a, &QAction::triggered, this, slot);
        m->addAction(a);
        return a;
    };
    struct Entry {
        aes::Operator op;
        QString text;
    };
    const Entry entries[] = {
        {aes::Operator::Straighten, tr("&Straighten (remove undulations, then redundant extrema)")},
        {aes::Operator::Soften, tr("S&often the sharpest bend")},
        {aes::Operator::Sharpen, tr("S&harpen the sharpest bend")},
        {aes::Operator::Convex, tr("More con&vex")},
        {aes::Operator::Concave, tr("More conc&ave")},
        {aes::Operator::Tension, tr("More &tension")},
        {aes::Operator::Accelerate, tr("Acce&lerate toward the end")},
    };
    for (const Entry& e : entries) {
        const QString name = QStringLiteral("aesthetic.") + QString::fromLatin1(aes::operatorName(e.op));
        add(menu, name, e.text, [this, op = e.op]() {
            // A menu has no amount to set: a fiftieth of the curve's length (the dock and the handle set any).
            document_->applyAesthetic(op, document_->defaultAestheticAmount());
        });
    }
    menu->addSeparator();
    QMenu* handles = menu->addMenu(tr("&Handle on the curve (drag to set the amount)"));
    auto* group = new QActionGroup(this);
    QAction* none = add(handles, QStringLiteral("aesthetic.handle.none"), tr("&None"), [this]() { document_->showAestheticHandle(std::nullopt); });
    none->setCheckable(true);
    none->setChecked(true);
    group->addAction(none);
    for (const Entry& e : entries) {
        if (e.op == aes::Operator::Straighten) continue;  // straighten finds its own amounts
        const QString name = QStringLiteral("aesthetic.handle.") + QString::fromLatin1(aes::operatorName(e.op));
        QAction* a = add(handles, name, e.text, [this, op = e.op]() {
            const QString why = document_->showAestheticHandle(op);
            statusBar()->showMessage(why.isEmpty() ? tr("Drag the arrow on the curve to set the amount") : why, 10000);
        });
        a->setCheckable(true);
        group->addAction(a);
    }
    connect(document_, &SketchDocument::aestheticApplied, this, [this](const QString& message) {
        if (!message.isEmpty()) statusBar()->showMessage(message, 10000);
    });
}

}  // namespace sculptline::ui
