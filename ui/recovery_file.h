#pragma once
// Recovery files: the unsaved work of a running session, written by the autosave
// (ui/autosave.h) to $XDG_DATA_HOME/sculptline/recovery/session-<time>-<pid>.json beside a lock
// file session-<time>-<pid>.lock that the session holds while it lives. A recovery file whose lock is not held
// (its session was killed or crashed) is an orphan, and the next start offers it.
//
// Format: {"format": "sculptline-recovery", "version": 1, "document": path or null (untitled),
// "index": undo index, "clean": index at which the document was saved or -1, "texts": [command
// texts], "states": [document at each undo index, 0..texts.size()]}.
#include "ui/undo_history.h"

#include <QLockFile>
#include <QString>

#include <memory>
#include <optional>
#include <string>

namespace sculptline::ui {

/// $XDG_DATA_HOME/sculptline/recovery (default ~/.local/share/sculptline/recovery).
QString recoveryFolder();

/// The lock file that marks `recoveryPath` (<session>.json) as the work of a live session.
QString recoveryLockPath(const QString& recoveryPath);

struct RecoveryData {
    QString document;  ///< the document the work belongs to; empty: untitled
    HistorySnapshot history;
};

/// The recovery file's text. Plain data in, text out: safe on a worker thread.
std::string recoveryText(const RecoveryData& data);

/// Reads a recovery file. @throws solvers::io::InputError "<path>: <what is wrong>".
RecoveryData readRecoveryFile(const QString& path);

/// A recovery file whose session is gone, locked by this process while it decides what to do.
struct OrphanedRecovery {
    QString path;
    std::unique_ptr<QLockFile> lock;
};

/// The newest recovery file (session-*.json) in `folder` whose session is no longer alive, locked; nullopt when
/// there is none. A file whose lock a live process holds is never returned.
std::optional<OrphanedRecovery> claimOrphanedRecovery(const QString& folder);

/// Removes an orphan (after it was recovered or discarded) and its lock.
void removeOrphan(OrphanedRecovery& orphan);

}  // namespace sculptline::ui
