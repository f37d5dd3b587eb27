#pragma once
// The document's reference geometry: .iv files imported to sketch over (File > Import Reference),
// validated by scene/iv_import.h, drawn by scene/reference_layer.h. A reference is not a model
// entity: it cannot be picked or edited, strokes go through it onto the active plane. Importing and
// removing are undo steps (ReferencesCommand); hiding is a view setting. The document saves each
// reference as its path (absolute, and relative to the document's folder) and reads the file again
// when it is opened: a file that is gone or no longer passes is reported and kept in the list, so
// the next save does not lose it.
#include "model/document.h"
#include "scene/reference_layer.h"

#include <QString>
#include <QStringList>
#include <QUndoCommand>

#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <vector>

class SoSeparator;

namespace sculptline::ui {

struct Reference {
    QString path;  ///< absolute
    std::shared_ptr<SoSeparator> graph;  ///< null: the file could not be read (problem says why)
    QString summary;  ///< what it draws ("8 coordinates, 12 triangles; box ..")
    QString problem;
    /// A reference that could not be read keeps the relative path it was saved with.
    QString savedRelative;
};

class ReferenceSet {
public:
    SoSeparator* root() const { return layer_.root(); }
    const std::vector<Reference>& references() const { return references_; }
    /// Replaces the list (an undo step's before or after); the graphs are shared, nothing is read.
    void set(std::vector<Reference> references);
    void setVisible(bool visible) { layer_.setVisible(visible); }
    bool visible() const { return layer_.visible(); }
    /// References drawn now (those whose file was read).
    int drawn() const { return layer_.count(); }

    /// Reads and validates `path` (scene::importIvFile).
    /// @throws solvers::io::InputError "path: problem".
    static Reference load(const QString& path);
    /// The references of a document opened from `documentFolder` (empty: untitled; then only
    /// absolute paths are tried). A graph already loaded for the same path is reused. Returns one
    /// line per reference that could not be read.
    QStringList restore(const std::vector<model::ReferenceSpec>& specs, const QString& documentFolder);
    /// "references" as documentFromJson reads them; "relative" only with a documentFolder.
    nlohmann::json toJson(const QString& documentFolder) const;

private:
    scene::ReferenceLayer layer_;
    std::vector<Reference> references_;
};

/// Sets the document's references from `before` to `after` (import: one more; remove: none).
class ReferencesCommand : public QUndoCommand {
public:
    ReferencesCommand(ReferenceSet& set, std::vector<Reference> before, std::vector<Reference> after, const QString& text)
        : QUndoCommand(text), set_(set), before_(std::move(before)), after_(std::move(after))
    {
    }
    void redo() override { set_.set(after_); }
    void undo() override { set_.set(before_); }

private:
    ReferenceSet& set_;
    std::vector<Reference> before_, after_;
};

}  // namespace sculptline::ui
