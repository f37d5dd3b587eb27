#include "ui/undo_history.h"

#include "model/model_document.h"
#include "solvers/io/geometry_json.h"
#include "ui/sketch_document.h"
#include "ui/undo_commands.h"

#include <QUndoStack>

#include <nlohmann/json.hpp>

namespace sculptline::ui {

UndoHistory::UndoHistory(SketchDocument& doc, QObject* parent) : QObject(parent), doc_(doc)
{
    reset();
    connect(doc.undoStack(), &QUndoStack::indexChanged, this, [this](int index) { record(index); });
    connect(&doc, &SketchDocument::replaced, this, [this]() { reset(); });
}

void UndoHistory::reset()
{
    states_.clear();
    record(doc_.undoStack()->index());
}

void UndoHistory::record(int index)
{
    if (suspended_) return;
    // Every index was current once (a push lands on the new last one), so keeping the state of
    // the current index, and dropping those past the end of the stack, keeps them all.
    doc_.scheduler().flush();
    states_.resize(static_cast<size_t>(doc_.undoStack()->count()) + 1);
    states_[static_cast<size_t>(index)] = std::make_shared<const std::string>(doc_.documentJson(QString()).dump());
}

HistorySnapshot UndoHistory::snapshot() const
{
    const QUndoStack* stack = doc_.undoStack();
    HistorySnapshot history;
    history.states = states_;
    for (int i = 0; i < stack->count(); ++i) history.texts.push_back(stack->text(i));
    history.index = stack->index();
    history.cleanIndex = stack->cleanIndex();
    return history;
}

void UndoHistory::restore(const HistorySnapshot& history)
{
    const int steps = static_cast<int>(history.texts.size());
    if (history.states.size() != history.texts.size() + 1 || history.index < 0 || history.index > steps ||
        history.cleanIndex < -1 || history.cleanIndex > steps) {
        throw solvers::io::InputError("history: inconsistent undo history");
    }
    QUndoStack* stack = doc_.undoStack();
    suspended_ = true;
    stack->clear();
    for (int i = 0; i < steps; ++i) {
        const size_t k = static_cast<size_t>(i);
        stack->push(new RestoreStateCommand(doc_, history.states[k], history.states[k + 1], history.texts[k], suspended_));
    }
    // The commands do nothing while suspended: the stack's index and clean mark move, the model
    // (already at history.index) does not.
    if (history.cleanIndex >= 0) {
        stack->setIndex(history.cleanIndex);
        stack->setClean();
    } else {
        stack->resetClean();
    }
    stack->setIndex(history.index);
    suspended_ = false;
    states_ = history.states;
}

}  // namespace sculptline::ui
