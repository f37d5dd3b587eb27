// The designer's recognition habits in the window (thesis 002 §3.1.3, Table 3-2: the user model
// adapts to its user): corrections are learned from the recognition dock's choices, applied to every
// recognition, and kept in a JSON file between sessions (solvers/stroke/stroke_json.h, "habits").
#include "ui/sketch_document.h"

#include "solvers/io/geometry_json.h"
#include "solvers/stroke/stroke_json.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>
#include <QStandardPaths>
#include <nlohmann/json.hpp>

#include <algorithm>

namespace sculptline::ui {

namespace {

// A habits file is a few kilobytes per correction (32 points each); anything far larger is not ours.
constexpr qint64 kMaxUserModelBytes = 64 * 1024 * 1024;

QString systemUser()
{
    const QString user = qEnvironmentVariable("USER", qEnvironmentVariable("USERNAME"));
    return user.isEmpty() ? QStringLiteral("default") : user;
}

// The model with its table (nodes) and its habits but the last `drop` (UserModel keeps no way to
// remove one; the table and the remaining habits are copied over).
solvers::stroke::UserModel withoutLastHabits(const solvers::stroke::UserModel& m, size_t drop)
{
    solvers::stroke::UserModel out;
    out.setUser(m.user());
    out.setNodes(m.nodes());
    const size_t keep = m.habits().size() - std::min(drop, m.habits().size());
    for (size_t i = 0; i < keep; ++i) out.addHabit(m.habits()[i]);
    return out;
}

}  // namespace

QString SketchDocument::defaultUserModelPath()
{
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppConfigLocation))
        .filePath(QStringLiteral("recognition_habits.json"));
}

QString SketchDocument::openUserModel(const QString& path)
{
    userModel_ = solvers::stroke::UserModel::predefined(systemUser().toStdString());
    userModelPath_ = path;
    if (path.isEmpty() || !QFileInfo::exists(path)) return {};
    const QString why = [&]() -> QString {
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly)) return file.errorString();
        if (file.size() > kMaxUserModelBytes) return tr("%1 bytes, not a habits file").arg(file.size());
        try {
            const nlohmann::json j = solvers::io::parseJson(file.readAll().toStdString());
            solvers::stroke::UserModel loaded = solvers::stroke::userModelFromJson(j, "habits file");
            if (loaded.user().empty()) loaded.setUser(userModel_.user());
            userModel_ = std::move(loaded);
            return {};
        } catch (const std::exception& e) {
            return QString::fromStdString(e.what());
        }
    }();
    if (why.isEmpty()) return {};
    userModel_ = solvers::stroke::UserModel::predefined(systemUser().toStdString());
    const QString message = tr("Recognition habits not read from %1 (%2); starting without habits. "
                               "Edit > Forget recognition habits replaces the file.")
                                .arg(QDir::toNativeSeparators(path), why);
    Q_EMIT habitsChanged(message);
    return message;
}

QString SketchDocument::saveUserModel() const
{
    if (userModelPath_.isEmpty()) return {};
    const QFileInfo info(userModelPath_);
    if (!QDir().mkpath(info.absolutePath())) return tr("cannot create the folder %1").arg(info.absolutePath());
    QSaveFile file(userModelPath_);  // atomic: a crash mid-write leaves the previous habits
    const std::string text = solvers::stroke::toJson(userModel_).dump(1) + "\n";
    if (!file.open(QIODevice::WriteOnly) || file.write(text.data(), static_cast<qint64>(text.size())) < 0 || !file.commit()) {
        return file.errorString();
    }
    return {};
}

void SketchDocument::learnChoice(solvers::stroke::ShapeKind intended)
{
    if (!recognition_) return;
    // One stroke teaches one habit: trying candidates one after another (the N key) keeps only the
    // last choice, and going back to the shape the window offered makes the lesson a confirmation
    // (UserModel::learnShape: confirmations keep a correction off the similar strokes read right).
    const bool hadLesson = habitFromLastStroke_;
    if (habitFromLastStroke_) {
        userModel_ = withoutLastHabits(userModel_, 1);
        habitFromLastStroke_ = false;
    }
    const size_t before = userModel_.habits().size();
    userModel_.learnShape(*recognition_, intended);
    habitFromLastStroke_ = userModel_.habits().size() > before;
    if (!habitFromLastStroke_ && !hadLesson) return;
    const QString error = saveUserModel();
    if (!habitFromLastStroke_) {
        Q_EMIT habitsChanged(tr("Habit from the last stroke taken back (%1 habits)").arg(userModel_.habits().size()));
        return;
    }
    const QString shape = QString::fromLatin1(solvers::stroke::shapeName(intended));
    const QString asOffered = intended == recognition_->kind ? tr(", as offered") : QString();
    Q_EMIT habitsChanged(error.isEmpty() ? tr("Learned: strokes like this one are a %1%2 (%3 habits)").arg(shape, asOffered).arg(userModel_.habits().size())
                                         : tr("Learned: strokes like this one are a %1, but the habits were not saved: %2").arg(shape, error));
}

int SketchDocument::forgetHabits()
{
    const int count = static_cast<int>(userModel_.habits().size());
    userModel_ = withoutLastHabits(userModel_, userModel_.habits().size());
    habitFromLastStroke_ = false;
    const QString error = saveUserModel();
    Q_EMIT habitsChanged(error.isEmpty() ? tr("Forgot %1 recognition habits").arg(count)
                                         : tr("Forgot %1 recognition habits (the file was not rewritten: %2)").arg(count).arg(error));
    return count;
}

}  // namespace sculptline::ui
