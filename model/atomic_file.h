#pragma once
// Writing a file so that a crash, a full disk or a missing permission can never leave it half
// written: the contents go to a temporary file in the same folder, are flushed to the disk
// (fsync), and only then renamed over the target, which POSIX makes atomic. Readers see the old
// file or the new one, never a mixture. Plain POSIX: the scene layer has no Qt.
#include <string>

namespace sculptline::model {

/// Where writeFileAtomically keeps the previous version of `path`: `path` + ".bak".
std::string backupPath(const std::string& path);

/// Replaces the file at `path` by `contents` atomically (temporary file "<path>.XXXXXX" in the same
/// folder, fsync, rename, fsync of the folder). A symbolic link is followed: its target is replaced.
/// The new file keeps the old file's permissions (a new one gets 0666 minus the umask).
/// @param keepBackup when true and `path` exists, its previous contents stay in backupPath(path)
///        (a hard link to the old file, a copy where links are not supported); a backup that
///        cannot be made does not stop the save.
/// @throws solvers::io::InputError "<path>: cannot save (<reason>)" when anything fails; `path`
///         is then untouched and no temporary file is left behind.
void writeFileAtomically(const std::string& path, const std::string& contents, bool keepBackup);

}  // namespace sculptline::model
