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
    candidates_->clear();
    for (const auto& [kind, score] : report.candidates) {
        candidates_->addItem(QStringLiteral("%1  %2").arg(kind, -10).arg(score, 0, 'f', 2));
    }
    const bool choice = document_.recognitionChoiceAvailable();
    useShape_->setText(report.recognized.isEmpty() ? tr("Use the recognized shape") : tr("Use the recognized %1").arg(report.recognized));
    useShape_->setEnabled(choice);
    useFreeform_->setEnabled(choice);
}

}  // namespace sculptline::ui
