// Recovery after a real kill -9: the test (run under Xvfb by ctest) starts sculptline with a short
// autosave interval and a private XDG_DATA_HOME, replays edits, waits until the recovery file holds
// them, kills the program with SIGKILL, and starts it again with --recover. Also: a live session's
// recovery file is never taken by another, and a normal exit leaves nothing behind. And saving
// through the real program when the disk refuses the write.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

using nlohmann::json;

/// How often to look at the recovery folder while a session runs.
constexpr std::chrono::milliseconds kPoll{50};
/// Undo steps of data/sessions/hundred_edits.json (28 rounds of four edits).
constexpr int kHundredEdits = 112;

std::string readFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// A private data home per test, so that recovery files of other runs or of the user never count.
class Recovery : public testing::Test {
protected:
    void SetUp() override
    {
        // The process id keeps concurrent runs of this test (two build trees, CI beside a developer)
        // out of each other's folders: a shared one showed two recovery files, and a live lock taken.
        home_ = testing::TempDir() + "sculptline_recovery_" + std::to_string(getpid()) + "_" +
                testing::UnitTest::GetInstance()->current_test_info()->name();
        std::system(("rm -rf '" + home_ + "' && mkdir -p '" + home_ + "'").c_str());
    }

    std::string folder() const { return home_ + "/sculptline/recovery"; }
    std::string file(const std::string& name) const { return home_ + "/" + name; }

    /// Starts sculptline with `arguments` (or, with `program`, the program arguments[0] with the
    /// rest); its stderr goes to `log`.
    pid_t start(const std::vector<std::string>& arguments, const std::string& log, bool program = false) const
    {
        const pid_t pid = fork();
        if (pid == 0) {
            setenv("XDG_DATA_HOME", home_.c_str(), 1);
            const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            dup2(fd, 2);
            std::vector<char*> argv;
            if (!program) argv.push_back(const_cast<char*>(SCULPTLINE_EXE));
            for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
            argv.push_back(nullptr);
            execv(argv.front(), argv.data());
            _exit(127);
        }
        return pid;
    }

    /// Runs sculptline to its end; returns its exit status (-1: killed by a signal) and stderr.
    int run(const std::vector<std::string>& arguments, std::string* output = nullptr, bool program = false) const
    {
        const std::string log = file("run.log");
        int status = 0;
        waitpid(start(arguments, log, program), &status, 0);
        if (output) *output = readFile(log);
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }

    std::vector<std::string> filesIn(const std::string& dir, const std::string& suffix) const
    {
        std::vector<std::string> names;
        if (DIR* d = opendir(dir.c_str())) {
            while (dirent* e = readdir(d)) {
                const std::string name = e->d_name;
                if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
                    names.push_back(dir + "/" + name);
            }
            closedir(d);
        }
        return names;
    }

    /// Waits until the session `pid` has autosaved a history of `steps` edits; returns the
    /// recovery file (nullopt when the session ended first). The ctest timeout bounds the wait.
    std::optional<json> waitForAutosave(pid_t pid, int steps) const
    {
        for (;;) {
            for (const std::string& path : filesIn(folder(), ".json")) {
                const json recovery = json::parse(readFile(path), nullptr, false);
                if (recovery.is_object() && recovery["texts"].size() == static_cast<size_t>(steps)) return recovery;
            }
            int status = 0;
            if (waitpid(pid, &status, WNOHANG) == pid) return std::nullopt;
            std::this_thread::sleep_for(kPoll);
        }
    }

    /// Kills the session with SIGKILL and reaps it (a zombie would still look alive to the lock).
    static void killHard(pid_t pid)
    {
        kill(pid, SIGKILL);
        int status = 0;
        waitpid(pid, &status, 0);
        EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
    }

    std::string home_;
};

TEST_F(Recovery, AKilledSessionsStrokesAreRecovered)
{
    // Given a session that sketched two strokes and was killed after autosaving them
    const pid_t session = start({"--replay", SCULPTLINE_DATA_DIR "/sessions/sketch_two_strokes.json", "--autosave-interval", "1"},
                                file("killed.log"));
    const std::optional<json> autosaved = waitForAutosave(session, 2);
    ASSERT_TRUE(autosaved) << readFile(file("killed.log"));
    killHard(session);
    ASSERT_EQ(filesIn(folder(), ".json").size(), 1u);
    EXPECT_TRUE((*autosaved)["document"].is_null());  // it was the untitled default scene
    // When the program starts again and recovers without asking
    std::string log;
    ASSERT_EQ(run({"--recover", "--save", file("out.json"), "--quit"}, &log), 0) << log;
    // Then the saved document has the default curve and both strokes, as autosaved
    const json saved = json::parse(readFile(file("out.json")));
    EXPECT_EQ(saved["curves"].size(), 3u) << log;
    EXPECT_EQ(saved["curves"], (*autosaved)["states"][2]["curves"]);
    // And, that session having ended normally, no recovery file or lock is left
    EXPECT_TRUE(filesIn(folder(), ".json").empty());
    EXPECT_TRUE(filesIn(folder(), ".lock").empty());
}

TEST_F(Recovery, ARecoveredSessionUndoesBackThroughAHundredEdits)
{
    // Given the untouched default scene as saved, and a session of 112 edits of four kinds killed
    // after autosaving them all
    ASSERT_EQ(run({"--save", file("start.json"), "--quit"}), 0);
    const pid_t session = start({"--replay", SCULPTLINE_DATA_DIR "/sessions/hundred_edits.json", "--autosave-interval", "1"},
                                file("killed.log"));
    const std::optional<json> autosaved = waitForAutosave(session, kHundredEdits);
    ASSERT_TRUE(autosaved) << readFile(file("killed.log"));
    killHard(session);
    const std::vector<std::string> files = filesIn(folder(), ".json");
    ASSERT_EQ(files.size(), 1u);
    std::cout << "recovery file of " << kHundredEdits << " edits: " << readFile(files.front()).size() << " bytes\n";
    EXPECT_EQ((*autosaved)["index"], kHundredEdits);
    EXPECT_NE(json::parse(readFile(file("start.json"))), (*autosaved)["states"][kHundredEdits]);
    // When the work is recovered and every recovered step undone
    json undos{{"size", {800, 600}}, {"events", json::array()}};
    for (int k = 0; k < kHundredEdits; ++k) undos["events"].push_back({{"type", "key"}, {"key", "Ctrl+Z"}, {"t", 5 * k}});
    std::ofstream(file("undos.json")) << undos.dump();
    std::string log;
    ASSERT_EQ(run({"--recover", "--replay", file("undos.json"), "--save", file("undone.json"), "--quit"}, &log), 0) << log;
    // Then the document is the default scene again, exactly
    EXPECT_EQ(json::parse(readFile(file("undone.json"))), json::parse(readFile(file("start.json")))) << log;
}

TEST_F(Recovery, ALiveSessionsRecoveryFileIsNotTaken)
{
    // Given a live session with autosaved work
    const pid_t session = start({"--replay", SCULPTLINE_DATA_DIR "/sessions/sketch_two_strokes.json", "--autosave-interval", "1"},
                                file("live.log"));
    ASSERT_TRUE(waitForAutosave(session, 2)) << readFile(file("live.log"));
    // When a second instance starts with --recover
    std::string log;
    EXPECT_EQ(run({"--recover", "--save", file("second.json"), "--quit"}, &log), 0) << log;
    // Then it found nothing to recover, and the first session's file is still there
    EXPECT_NE(log.find("no unsaved work to recover"), std::string::npos) << log;
    EXPECT_EQ(json::parse(readFile(file("second.json")))["curves"].size(), 1u);
    EXPECT_EQ(filesIn(folder(), ".json").size(), 1u);
    killHard(session);
}

TEST_F(Recovery, ANormalExitLeavesNoRecoveryFile)
{
    // Given a session that autosaves (a replay waiting past the interval) and then quits
    json replay = json::parse(readFile(SCULPTLINE_DATA_DIR "/sessions/sketch_two_strokes.json"));
    replay["events"].push_back({{"type", "wait"}, {"ms", 1500}});
    std::ofstream(file("wait.json")) << replay.dump();
    std::string log;
    ASSERT_EQ(run({"--replay", file("wait.json"), "--autosave-interval", "1", "--quit"}, &log), 0) << log;
    // Then its work had been autosaved, and the file and its lock are gone
    EXPECT_NE(log.find("autosaved"), std::string::npos) << log;
    EXPECT_TRUE(filesIn(folder(), ".json").empty());
    EXPECT_TRUE(filesIn(folder(), ".lock").empty());
}

/// Saving through the real program (the same private folder set-up).
class Saving : public Recovery {};

TEST_F(Saving, ASaveThatHitsAFileSizeLimitLeavesTheDocumentWholeAndSaysWhy)
{
    // Given a saved document, then a session that edits it and may write at most 1000 bytes per
    // file (as on a full disk)
    ASSERT_EQ(run({"--save", file("doc.json"), "--quit"}), 0);
    const std::string before = readFile(file("doc.json"));
    ASSERT_GT(before.size(), 1000u);
    std::string log;
    const int status = run({"/usr/bin/prlimit", "--fsize=1000", "--", SCULPTLINE_EXE, file("doc.json"), "--replay",
                            SCULPTLINE_DATA_DIR "/sessions/sketch_two_strokes.json", "--save", file("doc.json"), "--quit"},
                           &log, true);
    // Then the program was not killed by the limit: it said why in one line and exits with 1
    EXPECT_EQ(status, 1) << log;
    EXPECT_NE(log.find("sculptline: --save: " + file("doc.json") + ": cannot save (File too large)\n"), std::string::npos) << log;
    // And the document is the old one, whole, with no temporary file beside it
    EXPECT_EQ(readFile(file("doc.json")), before);
    EXPECT_EQ(filesIn(home_, ".json").size(), 1u);
    EXPECT_TRUE(filesIn(home_, ".bak").empty());
}

TEST_F(Recovery, ABadDocumentEndsAScriptedRunWithStatus2EvenWithADisplay)
{
    // With a display a person would get the default scene and a dialog; a script must not
    std::ofstream(file("broken.json")) << "{\"planes\": [";
    std::string log;
    EXPECT_EQ(run({file("broken.json"), "--save", file("never.json"), "--quit"}, &log), 2) << log;
    EXPECT_NE(log.find(file("broken.json") + ": input: malformed JSON"), std::string::npos) << log;
    EXPECT_FALSE(std::ifstream(file("never.json")).good());
}

}  // namespace
