#include "ui/recovery_file.h"

#include "solvers/io/geometry_json.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace sculptline::ui {
namespace {

constexpr const char* kRecoveryFormat = "sculptline-recovery";
constexpr int kRecoveryVersion = 1;

}  // namespace

QString recoveryFolder()
{
    // XDG base directories: a relative XDG_DATA_HOME is invalid and ignored.
    QString base = qEnvironmentVariable("XDG_DATA_HOME");
    if (base.isEmpty() || QDir::isRelativePath(base)) base = QDir::homePath() + QStringLiteral("/.local/share");
    return base + QStringLiteral("/sculptline/recovery");
}

QString recoveryLockPath(const QString& recoveryPath)
{
    QString lock = recoveryPath;
    if (lock.endsWith(QStringLiteral(".json"))) lock.chop(5);
    return lock + QStringLiteral(".lock");
}

std::string recoveryText(const RecoveryData& data)
{
    using nlohmann::json;
    const HistorySnapshot& h = data.history;
    json texts = json::array();
    for (const QString& text : h.texts) texts.push_back(text.toStdString());
    const json header{{"format", kRecoveryFormat},
                      {"version", kRecoveryVersion},
                      {"document", data.document.isEmpty() ? json(nullptr) : json(data.document.toStdString())},
                      {"index", h.index},
                      {"clean", h.cleanIndex},
                      {"texts", std::move(texts)}};
    // The states are JSON text already: spliced in, not parsed and printed again.
    std::string text = header.dump();
    text.pop_back();  // the closing brace
    text += ",\"states\":[";
    for (size_t i = 0; i < h.states.size(); ++i) {
        if (i > 0) text += ',';
        text += h.states[i] ? *h.states[i] : std::string("{}");
    }
    text += "]}\n";
    return text;
}

RecoveryData readRecoveryFile(const QString& path)
{
    namespace io = solvers::io;
    const std::string name = path.toStdString();
    std::ifstream in(name, std::ios::binary);
    if (!in) throw io::InputError(name + ": cannot open file");
    std::ostringstream text;
    text << in.rdbuf();
    try {
        const nlohmann::json j = io::parseJson(text.str());
        if (!j.is_object() || j.value("format", std::string()) != kRecoveryFormat) throw io::InputError("not a Sculptline recovery file");
        const int version = io::integerFromJson(io::member(j, "version", "recovery"), "version", 1, 1 << 30);
        if (version > kRecoveryVersion) throw io::InputError("written by a newer Sculptline (version " + std::to_string(version) + ")");
        RecoveryData data;
        const nlohmann::json& document = io::member(j, "document", "recovery");
        if (document.is_string()) data.document = QString::fromStdString(document.get<std::string>());
        const nlohmann::json& texts = io::member(j, "texts", "recovery");
        const nlohmann::json& states = io::member(j, "states", "recovery");
        if (!texts.is_array() || !states.is_array() || states.size() != texts.size() + 1)
            throw io::InputError("states: expected one more than texts");
        const int steps = static_cast<int>(texts.size());
        for (const nlohmann::json& t : texts) data.history.texts.push_back(QString::fromStdString(t.is_string() ? t.get<std::string>() : ""));
        for (const nlohmann::json& s : states) data.history.states.push_back(std::make_shared<const std::string>(s.dump()));
        data.history.index = io::integerFromJson(io::member(j, "index", "recovery"), "index", 0, steps);
        data.history.cleanIndex = io::integerFromJson(io::member(j, "clean", "recovery"), "clean", -1, steps);
        return data;
    } catch (const io::InputError& e) {
        throw io::InputError(name + ": " + e.what());
    }
}

std::optional<OrphanedRecovery> claimOrphanedRecovery(const QString& folder)
{
    const QFileInfoList files = QDir(folder).entryInfoList({QStringLiteral("session-*.json")}, QDir::Files, QDir::Time);
    for (const QFileInfo& file : files) {
        auto lock = std::make_unique<QLockFile>(recoveryLockPath(file.absoluteFilePath()));
        // Only a dead owner makes a lock stale: a live session may go hours without autosaving.
        lock->setStaleLockTime(0);
        if (!lock->tryLock(0)) continue;
        return OrphanedRecovery{file.absoluteFilePath(), std::move(lock)};
    }
    return std::nullopt;
}

void removeOrphan(OrphanedRecovery& orphan)
{
    QFile::remove(orphan.path);
    if (orphan.lock) orphan.lock->unlock();
    orphan.lock.reset();
}

}  // namespace sculptline::ui
