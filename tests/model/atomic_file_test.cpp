// Atomic saves (model/atomic_file.h): the new contents replace the old only as a whole, the
// previous version stays in the backup, and a write that fails leaves the old file as it was.
// Failures are provoked for real: a file size limit (RLIMIT_FSIZE, as a full disk would) and a
// folder the writer may not write to (as root, in a child that gave up root first).
#include "model/atomic_file.h"
#include "model/model_document.h"
#include "solvers/io/geometry_json.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <dirent.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace sculptline::scene {
namespace {

/// An unprivileged user and group (Debian's "nobody"/"nogroup") for the read-only folder test.
constexpr uid_t kNobody = 65534;

std::string readFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void writeFile(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

/// A fresh, empty folder for one test.
std::string freshFolder(const std::string& name)
{
    const std::string dir = testing::TempDir() + "sculptline_atomic_" + name + "_" + std::to_string(getpid());
    std::system(("rm -rf '" + dir + "' && mkdir -p '" + dir + "'").c_str());
    return dir;
}

std::vector<std::string> filesIn(const std::string& dir)
{
    std::vector<std::string> names;
    if (DIR* d = opendir(dir.c_str())) {
        while (dirent* e = readdir(d)) {
            const std::string name = e->d_name;
            if (name != "." && name != "..") names.push_back(name);
        }
        closedir(d);
    }
    return names;
}

/// Runs `save` in a child process prepared by `prepare` (limits, identity); returns what the
/// child's save threw ("" when it succeeded).
template <typename Prepare>
std::string saveInChild(Prepare prepare, const std::string& path, const std::string& contents)
{
    int pipeFds[2];
    if (pipe(pipeFds) != 0) return "pipe failed";
    const pid_t child = fork();
    if (child == 0) {
        close(pipeFds[0]);
        prepare();
        std::string message;
        try {
            model::writeFileAtomically(path, contents, true);
        } catch (const std::exception& e) {
            message = e.what();
        }
        if (!message.empty() && ::write(pipeFds[1], message.data(), message.size()) < 0) _exit(3);
        _exit(0);
    }
    close(pipeFds[1]);
    std::string message;
    char buffer[512];
    ssize_t n = 0;
    while ((n = read(pipeFds[0], buffer, sizeof buffer)) > 0) message.append(buffer, static_cast<size_t>(n));
    close(pipeFds[0]);
    int status = 0;
    waitpid(child, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "the child did not finish normally";
    return message;
}

TEST(AtomicFile, ASaveReplacesTheDocumentAndKeepsThePreviousOneAsBackup)
{
    // Given a document saved twice
    const std::string dir = freshFolder("backup");
    const std::string path = dir + "/doc.json";
    model::writeFileAtomically(path, "first\n", true);
    chmod(path.c_str(), 0640);
    model::writeFileAtomically(path, "second\n", true);
    // Then it holds the second version, the backup the first, and nothing else is left over
    EXPECT_EQ(readFile(path), "second\n");
    EXPECT_EQ(model::backupPath(path), path + ".bak");
    EXPECT_EQ(readFile(model::backupPath(path)), "first\n");
    EXPECT_EQ(filesIn(dir).size(), 2u);
    // And the document kept its permissions
    struct stat info {};
    ASSERT_EQ(stat(path.c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 0777, 0640u);
    // When saved a third time, the backup moves on by one version
    model::writeFileAtomically(path, "third\n", true);
    EXPECT_EQ(readFile(path), "third\n");
    EXPECT_EQ(readFile(model::backupPath(path)), "second\n");
}

TEST(AtomicFile, AWriteThatFailsHalfwayLeavesTheOldDocument)
{
    // Given a document and a process that may write only 16 bytes per file (a full disk)
    const std::string dir = freshFolder("full");
    const std::string path = dir + "/doc.json";
    writeFile(path, "the old document\n");
    const std::string message = saveInChild(
        []() {
            std::signal(SIGXFSZ, SIG_IGN);
            const rlimit limit{16, 16};
            setrlimit(RLIMIT_FSIZE, &limit);
        },
        path, std::string(4096, 'x'));
    // Then the save failed with one line naming the file, and the old document is whole
    EXPECT_EQ(message.rfind(path + ": cannot save (", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(readFile(path), "the old document\n");
    // And no temporary file is left behind
    EXPECT_EQ(filesIn(dir), std::vector<std::string>{"doc.json"});
}

TEST(AtomicFile, ASaveIntoAReadOnlyFolderFailsCleanly)
{
    // Given a document the saving user could overwrite in place, in a folder they may not write
    // to (an atomic save needs a new file beside it)
    const std::string dir = freshFolder("readonly");
    const std::string path = dir + "/doc.json";
    writeFile(path, "the original\n");
    chmod(path.c_str(), 0666);
    chmod(dir.c_str(), 0555);
    // When it is saved (root may write anywhere: the child becomes an ordinary user first)
    const bool root = geteuid() == 0;
    const std::string message = saveInChild(
        [root]() {
            if (root && (setgid(kNobody) != 0 || setuid(kNobody) != 0)) _exit(4);
        },
        path, "the new version\n");
    chmod(dir.c_str(), 0755);
    // Then a one-line message says why, and the original is untouched, with no backup made
    EXPECT_NE(message.find("cannot save (Permission denied)"), std::string::npos) << message;
    EXPECT_EQ(readFile(path), "the original\n");
    EXPECT_EQ(filesIn(dir), std::vector<std::string>{"doc.json"});
}

TEST(AtomicFile, SavingThroughASymbolicLinkReplacesTheLinkedDocument)
{
    const std::string dir = freshFolder("link");
    writeFile(dir + "/real.json", "old\n");
    ASSERT_EQ(symlink((dir + "/real.json").c_str(), (dir + "/link.json").c_str()), 0);
    model::writeFileAtomically(dir + "/link.json", "new\n", true);
    struct stat info {};
    ASSERT_EQ(lstat((dir + "/link.json").c_str(), &info), 0);
    EXPECT_TRUE(S_ISLNK(info.st_mode));
    EXPECT_EQ(readFile(dir + "/real.json"), "new\n");
    EXPECT_EQ(readFile(dir + "/real.json.bak"), "old\n");
}

TEST(AtomicFile, SavedDocumentsCarryTheFormatAndVersion)
{
    const nlohmann::json doc = model::modelToJson(model::Model(), model::GridSpec());
    EXPECT_EQ(doc.at("format"), "sculptline");
    EXPECT_EQ(doc.at("version"), model::kDocumentVersion);
    EXPECT_NO_THROW(model::documentFromJson(doc));
}

TEST(AtomicFile, NewerAndForeignDocumentsAreRefusedByVersion)
{
    // A version from the future is named as such, before any field it might have changed
    try {
        model::documentFromJson(nlohmann::json{{"format", "sculptline"}, {"version", 7}, {"planes", "a new kind of planes"}});
        ADD_FAILURE() << "a newer document was accepted";
    } catch (const solvers::io::InputError& e) {
        EXPECT_EQ(std::string(e.what()), "made by a newer Sculptline (version 7); this one reads up to 1");
    }
    EXPECT_THROW(model::documentFromJson(nlohmann::json{{"format", "someone-else"}}), solvers::io::InputError);
    EXPECT_THROW(model::documentFromJson(nlohmann::json{{"version", "one"}}), solvers::io::InputError);
    // Older documents, without the fields, read as before
    EXPECT_NO_THROW(model::documentFromJson(nlohmann::json{{"planes", nlohmann::json::array()}}));
}

}  // namespace
}  // namespace sculptline::scene
