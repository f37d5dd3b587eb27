#include "ui/reference_set.h"

#include "scene/iv_import.h"

#include <Inventor/nodes/SoSeparator.h>

#include <QDir>
#include <QFileInfo>

#include <algorithm>

#include <nlohmann/json.hpp>

namespace sculptline::ui {

void ReferenceSet::set(std::vector<Reference> references)
{
    references_ = std::move(references);
    std::vector<std::shared_ptr<SoSeparator>> graphs;
    for (const Reference& r : references_) graphs.push_back(r.graph);
    layer_.setGraphs(graphs);
}

Reference ReferenceSet::load(const QString& path)
{
    const QString absolute = QFileInfo(path).absoluteFilePath();
    const scene::ImportedIv imported = scene::importIvFile(absolute.toStdString());
    return {absolute, imported.root, QString::fromStdString(scene::describe(imported)), QString(), QString()};
}

QStringList ReferenceSet::restore(const std::vector<model::ReferenceSpec>& specs, const QString& documentFolder)
{
    QStringList problems;
    std::vector<Reference> restored;
    for (const model::ReferenceSpec& spec : specs) {
        QString path = QString::fromStdString(spec.path);
        // The relative path first: a folder moved or copied with its reference files.
        if (!spec.relative.empty() && !documentFolder.isEmpty()) {
            const QString relative = QDir(documentFolder).absoluteFilePath(QString::fromStdString(spec.relative));
            if (QFileInfo::exists(relative)) path = relative;
        } else if (QFileInfo(path).isRelative() && !documentFolder.isEmpty()) {
            path = QDir(documentFolder).absoluteFilePath(path);
        }
        path = QFileInfo(path).absoluteFilePath();
        const auto same = std::find_if(references_.begin(), references_.end(), [&](const Reference& r) { return r.path == path && r.graph; });
        if (same != references_.end()) {
            restored.push_back(*same);
            continue;
        }
        try {
            restored.push_back(load(path));
        } catch (const std::exception& e) {
            const QString why = QString::fromStdString(e.what());
            problems << QStringLiteral("reference %1 not shown (kept in the document): %2").arg(QString::fromStdString(spec.path), why);
            restored.push_back({QString::fromStdString(spec.path), nullptr, QString(), why, QString::fromStdString(spec.relative)});
        }
    }
    set(std::move(restored));
    return problems;
}

nlohmann::json ReferenceSet::toJson(const QString& documentFolder) const
{
    nlohmann::json out = nlohmann::json::array();
    for (const Reference& r : references_) {
        nlohmann::json entry = {{"path", r.path.toStdString()}};
        if (!r.graph && !r.savedRelative.isEmpty()) entry["relative"] = r.savedRelative.toStdString();
        else if (!documentFolder.isEmpty()) entry["relative"] = QDir(documentFolder).relativeFilePath(r.path).toStdString();
        out.push_back(std::move(entry));
    }
    return out;
}

}  // namespace sculptline::ui
