#include "model/atomic_file.h"

#include "solvers/io/geometry_json.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace sculptline::model {
namespace {

[[noreturn]] void fail(const std::string& path, int error)
{
    throw solvers::io::InputError(path + ": cannot save (" + std::strerror(error) + ")");
}

/// The file a path names, through symbolic links (so that saving through a link replaces the
/// linked document instead of the link); the path itself when it does not exist yet.
std::string resolved(const std::string& path)
{
    struct stat info {};
    if (lstat(path.c_str(), &info) != 0 || !S_ISLNK(info.st_mode)) return path;
    char target[PATH_MAX];
    return realpath(path.c_str(), target) ? std::string(target) : path;
}

std::string folderOf(const std::string& path)
{
    const size_t slash = path.rfind('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

bool writeAll(int fd, const std::string& contents)
{
    const char* data = contents.data();
    size_t left = contents.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, data, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        data += n;
        left -= static_cast<size_t>(n);
    }
    return true;
}

/// Copies `from` to `to` (the fallback for a backup where hard links are not supported).
bool copyFile(const std::string& from, const std::string& to)
{
    const int in = ::open(from.c_str(), O_RDONLY | O_CLOEXEC);
    if (in < 0) return false;
    const int out = ::open(to.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    bool ok = out >= 0;
    std::vector<char> buffer(1 << 16);
    while (ok) {
        const ssize_t n = ::read(in, buffer.data(), buffer.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            ok = n == 0;
            break;
        }
        ok = writeAll(out, std::string(buffer.data(), static_cast<size_t>(n)));
    }
    ::close(in);
    if (out >= 0 && ::close(out) != 0) ok = false;
    return ok;
}

void keepBackupOf(const std::string& path)
{
    const std::string backup = backupPath(path);
    ::unlink(backup.c_str());
    // A hard link costs nothing and is exact; the rename below then leaves it the only name of
    // the old contents.
    if (::link(path.c_str(), backup.c_str()) != 0) copyFile(path, backup);
}

}  // namespace

std::string backupPath(const std::string& path) { return path + ".bak"; }

void writeFileAtomically(const std::string& requested, const std::string& contents, bool keepBackup)
{
    const std::string path = resolved(requested);
    struct stat old {};
    const bool exists = ::stat(path.c_str(), &old) == 0;
    if (exists && !S_ISREG(old.st_mode)) fail(requested, EISDIR);

    std::string temporary = path + ".XXXXXX";
    const int fd = ::mkstemp(temporary.data());
    if (fd < 0) fail(requested, errno);
    int error = 0;
    if (!writeAll(fd, contents)) error = errno ? errno : EIO;
    if (error == 0) {
        // mkstemp makes the file 0600; a document keeps the mode it had, or gets the usual one.
        mode_t mode = 0;
        if (exists) mode = old.st_mode & 07777;
        else {
            const mode_t mask = ::umask(0);
            ::umask(mask);
            mode = 0666 & ~mask;
        }
        if (::fchmod(fd, mode) != 0) error = errno;
    }
    if (error == 0 && ::fsync(fd) != 0) error = errno;
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error == 0 && exists && keepBackup) keepBackupOf(path);
    if (error == 0 && ::rename(temporary.c_str(), path.c_str()) != 0) error = errno;
    if (error != 0) {
        ::unlink(temporary.c_str());
        fail(requested, error);
    }
    // The rename is durable once the folder's entry is on disk too.
    const int folder = ::open(folderOf(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (folder >= 0) {
        ::fsync(folder);
        ::close(folder);
    }
}

}  // namespace sculptline::model
