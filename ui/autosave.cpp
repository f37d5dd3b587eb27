#include "ui/autosave.h"

#include "model/atomic_file.h"
#include "ui/recovery_file.h"
#include "ui/sketch_document.h"
#include "ui/undo_history.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QUndoStack>

namespace sculptline::ui {

Autosaver::Autosaver(SketchDocument& doc, UndoHistory& history, const QString& folder, int intervalSeconds, QObject* parent)
    : QObject(parent), doc_(doc), history_(history)
{
    writer_.setMaxThreadCount(1);
    // The process id keeps two sessions started in the same millisecond apart.
    const QString session = QStringLiteral("session-%1-%2")
                                .arg(QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyyMMdd-HHmmss-zzz")))
                                .arg(QCoreApplication::applicationPid());
    path_ = QDir(folder).absoluteFilePath(session + QStringLiteral(".json"));
    if (!QDir().mkpath(folder)) {
        error_ = tr("autosave off: cannot create %1").arg(folder);
        return;
    }
    lock_ = std::make_unique<QLockFile>(recoveryLockPath(path_));
    lock_->setStaleLockTime(0);
    if (!lock_->tryLock(0)) {
        error_ = tr("autosave off: cannot lock %1").arg(recoveryLockPath(path_));
        lock_.reset();
        return;
    }
    QUndoStack* stack = doc.undoStack();
    connect(stack, &QUndoStack::indexChanged, this, [this]() { pending_ = true; });
    connect(stack, &QUndoStack::cleanChanged, this, [this](bool clean) {
        if (clean) discard();
    });
    connect(&doc, &SketchDocument::replaced, this, [this]() { discard(); });
    connect(&timer_, &QTimer::timeout, this, [this]() { autosave(); });
    setInterval(intervalSeconds);
}

void Autosaver::setInterval(int seconds)
{
    interval_ = seconds;
    timer_.stop();
    if (seconds > 0 && lock_) timer_.start(seconds * 1000);
}

Autosaver::~Autosaver()
{
    timer_.stop();
    discard();
}

void Autosaver::autosave(bool wait)
{
    if (!lock_ || !pending_) return;
    if (doc_.undoStack()->isClean()) {
        discard();
        return;
    }
    QElapsedTimer clock;
    clock.start();
    RecoveryData data;
    data.document = doc_.path();
    data.history = history_.snapshot();
    pending_ = false;
    const double guiMs = static_cast<double>(clock.nsecsElapsed()) / 1e6;
    const std::string path = path_.toStdString();
    writer_.start([this, data = std::move(data), path, guiMs]() {
        try {
            const std::string text = recoveryText(data);
            model::writeFileAtomically(path, text, false);
            const auto bytes = static_cast<qint64>(text.size());
            QMetaObject::invokeMethod(this, [this, bytes, guiMs]() { Q_EMIT written(bytes, guiMs); }, Qt::QueuedConnection);
        } catch (const std::exception& e) {
            const QString message = tr("Autosave failed: %1").arg(QString::fromStdString(e.what()));
            QMetaObject::invokeMethod(this, [this, message]() {
                pending_ = true;  // try again at the next interval
                Q_EMIT failed(message);
            }, Qt::QueuedConnection);
        }
    });
    if (wait) writer_.waitForDone();
}

void Autosaver::discard()
{
    // A write still queued would bring the file back after its removal.
    writer_.waitForDone();
    pending_ = false;
    if (lock_) QFile::remove(path_);
}

}  // namespace sculptline::ui
