#pragma once
// The autosave: every interval, when the document has changes that are neither saved nor written
// yet, its history (ui/undo_history.h) is taken on the GUI thread and written, atomically, by a
// worker thread to this session's recovery file (ui/recovery_file.h). The file goes away when the
// work is saved, replaced or discarded, and when the session ends normally; a session that is
// killed leaves it behind for the next start to offer.
#include <QLockFile>
#include <QObject>
#include <QString>
#include <QThreadPool>
#include <QTimer>

#include <memory>

namespace sculptline::ui {

class SketchDocument;
class UndoHistory;

class Autosaver : public QObject {
    Q_OBJECT

public:
    /// Default interval between autosaves.
    static constexpr int kDefaultIntervalSeconds = 120;

    /// Takes this session's lock in `folder` (created when missing); autosaves every
    /// `intervalSeconds` (0: only when asked through autosave()). Without the lock (a folder that
    /// cannot be written) nothing is written and error() says why.
    Autosaver(SketchDocument& doc, UndoHistory& history, const QString& folder, int intervalSeconds, QObject* parent = nullptr);
    /// A normal end: waits for a write in progress and removes the recovery file.
    ~Autosaver() override;

    /// This session's recovery file (it exists only while there is unsaved work).
    const QString& recoveryPath() const { return path_; }
    /// Seconds between autosaves; 0 = only when asked.
    int interval() const { return interval_; }
    void setInterval(int seconds);
    /// Why autosaving is off, or empty.
    const QString& error() const { return error_; }

    /// Writes the recovery file now if there are changes it does not have; `wait`: returns once
    /// it is written (used right after a recovery, so the recovered work is safe at once).
    void autosave(bool wait = false);
    /// Removes the recovery file (the work was saved or discarded).
    void discard();

Q_SIGNALS:
    /// A write failed (message of one line, for the status bar).
    void failed(const QString& message);
    /// A recovery file was written: its size, and the GUI thread's share of the time.
    void written(qint64 bytes, double guiMilliseconds);

private:
    SketchDocument& doc_;
    UndoHistory& history_;
    QString path_;
    QString error_;
    std::unique_ptr<QLockFile> lock_;
    QTimer timer_;
    /// One thread, so that writes happen in the order they were queued.
    QThreadPool writer_;
    bool pending_ = false;  ///< changes since the last write
    int interval_ = 0;
};

}  // namespace sculptline::ui
