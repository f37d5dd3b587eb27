#include "ui/recognition_dock.h"

#include "ui/sketch_document.h"

#include <QLabel>
#include <QListWidget>
#include <QAction>
#include <QToolButton>
#include <QVBoxLayout>

namespace sculptline::ui {

RecognitionDock::RecognitionDock(SketchDocument& document, QAction* useShape, QAction* useFreeform, QWidget* parent)
    : QDockWidget(tr("Stroke recognition"), parent), document_(document), useShape_(useShape), useFreeform_(useFreeform)
{
    setObjectName(QStringLiteral("dock.recognition"));
    auto* box = new QWidget(this);
    auto* layout = new QVBoxLayout(box);
    summary_ = new QLabel(box);
    summary_->setWordWrap(true);
    layout->addWidget(summary_);
    habit_ = new QLabel(box);
    habit_->setObjectName(QStringLiteral("recognition.habit"));
    habit_->setWordWrap(true);
    habit_->setStyleSheet(QStringLiteral("QLabel { background: #fff3c4; color: #5a4500; padding: 3px; }"));
    habit_->setToolTip(tr("You corrected a similar stroke before; Edit > Forget recognition habits starts afresh"));
    layout->addWidget(habit_);
    candidates_ = new QListWidget(box);
    candidates_->setSelectionMode(QAbstractItemView::NoSelection);
    candidates_->setToolTip(tr("Click a candidate to use that shape for the last stroke"));
    connect(candidates_, &QListWidget::itemClicked, this,
            [this](QListWidgetItem* item) { document_.chooseCandidate(candidates_->row(item)); });
    layout->addWidget(candidates_, 1);
    for (QAction* action : {useShape_, useFreeform_}) {
        auto* button = new QToolButton(box);
        button->setDefaultAction(action);
        button->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        layout->addWidget(button);
    }
    setWidget(box);
    refresh();
}

void RecognitionDock::refresh()
{
    const StrokeReport& report = document_.lastStroke();
    summary_->setText(report.message.isEmpty() ? tr("Draw a stroke in sketch mode.") : report.message);
    habit_->setText(report.habit);
    habit_->setVisible(!report.habit.isEmpty());
    candidates_->clear();
    for (const auto& [kind, score] : report.candidates) {
        const bool habit = candidates_->count() == 0 && !report.habit.isEmpty();  // moved to the front by it
        candidates_->addItem(QStringLiteral("%1  %2%3").arg(kind, -10).arg(score, 0, 'f', 2).arg(habit ? tr("  (your habit)") : QString()));
    }
    const bool choice = document_.recognitionChoiceAvailable();
    useShape_->setText(report.recognized.isEmpty() ? tr("Use the recognized shape") : tr("Use the recognized %1").arg(report.recognized));
    useShape_->setEnabled(choice);
    useFreeform_->setEnabled(choice);
}

}  // namespace sculptline::ui
