#pragma once
// The undo history as documents: the model's state at every index of the undo stack, kept as
// compact JSON text as the edits happen, so that an autosave can write the whole history without
// replaying it, and a recovered session can undo back through the steps of the one that died.
#include <QObject>
#include <QString>

#include <memory>
#include <string>
#include <vector>

namespace sculptline::ui {

class SketchDocument;

/// The history a recovery file keeps: states[i] is the document (modelToJson) after the first i
/// commands, texts[i] the text of command i + 1 (so states has one entry more than texts).
struct HistorySnapshot {
    std::vector<std::shared_ptr<const std::string>> states;
    std::vector<QString> texts;
    int index = 0;  ///< the undo stack's current index
    int cleanIndex = -1;  ///< the index at which the document was last saved, -1: none
};

class UndoHistory : public QObject {
    Q_OBJECT

public:
    /// Follows `doc`'s undo stack from now on (its current state becomes index 0).
    explicit UndoHistory(SketchDocument& doc, QObject* parent = nullptr);

    /// A copy of the history (shares the state texts; cheap enough for the GUI thread).
    HistorySnapshot snapshot() const;

    /// Rebuilds the undo stack from `history`: one command per step, which restores the whole
    /// document state of its index. The model must already show history.states[history.index].
    /// @throws solvers::io::InputError when the history is inconsistent (no commands are pushed).
    void restore(const HistorySnapshot& history);

private:
    void record(int index);
    void reset();

    SketchDocument& doc_;
    std::vector<std::shared_ptr<const std::string>> states_;
    /// While restore() pushes its commands, they must neither run nor be recorded.
    bool suspended_ = false;
};

}  // namespace sculptline::ui
