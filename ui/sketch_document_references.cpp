// SketchDocument's reference geometry (ui/reference_set.h): import, removal and the saved form.
#include "ui/sketch_document.h"

#include "model/model_document.h"
#include "ui/reference_set.h"

#include <QFileInfo>

#include <nlohmann/json.hpp>

namespace sculptline::ui {

nlohmann::json SketchDocument::documentJson(const QString& folder) const
{
    nlohmann::json j = model::modelToJson(model_, grid_);
    // Absent when there is none: a document without references reads (and diffs) as before.
    if (!references_->references().empty()) j["references"] = references_->toJson(folder);
    return j;
}

QString SketchDocument::importReference(const QString& path)
{
    const Reference reference = ReferenceSet::load(path);
    addReference(reference);
    return reference.summary;
}

void SketchDocument::addReference(const Reference& reference)
{
    std::vector<Reference> before = references_->references();
    std::vector<Reference> after = before;
    after.push_back(reference);
    undo_.push(new ReferencesCommand(*references_, std::move(before), std::move(after),
                                     tr("Import reference %1").arg(QFileInfo(reference.path).fileName())));
}

bool SketchDocument::removeReferences()
{
    std::vector<Reference> before = references_->references();
    if (before.empty()) return false;
    undo_.push(new ReferencesCommand(*references_, std::move(before), {}, tr("Remove references")));
    return true;
}

}  // namespace sculptline::ui
