// The sculptline executable's argument and document errors: status 2 and a message on stderr, no
// crash. These are checked before Qt starts, so the tests run without a display (DISPLAY unset).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace {

struct ProgramRun {
    int status = -1;  ///< exit status, or -1 when the program did not exit normally (a crash)
    std::string output;  ///< stdout and stderr together
};

/// Runs sculptline with `arguments` and extra environment assignments `env` ("NAME=value ...").
ProgramRun runSculptline(const std::string& arguments, const std::string& env = "")
{
    const std::string command = "env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM " + env + " '" SCULPTLINE_EXE "' " + arguments + " 2>&1";
    ProgramRun run;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return run;
    char buffer[4096];
    size_t n = 0;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) run.output.append(buffer, n);
    const int wait = pclose(pipe);
    if (WIFEXITED(wait)) run.status = WEXITSTATUS(wait);
    return run;
}

void expectError(const std::string& arguments, const std::string& expected)
{
    const ProgramRun run = runSculptline(arguments);
    EXPECT_EQ(run.status, 2) << "sculptline " << arguments << "\n" << run.output;
    EXPECT_NE(run.output.find(expected), std::string::npos)
        << "sculptline " << arguments << ": expected \"" << expected << "\" in\n" << run.output;
}

TEST(GuiArguments, HelpListsTheFlags)
{
    const ProgramRun run = runSculptline("--help");
    EXPECT_EQ(run.status, 0);
    for (const char* flag : {"--size", "--screenshot", "--quit", "DOCUMENT", "--replay", "--save", "--export-iv", "--export-step", "--export-iges", "--export-stl", "--export-obj", "--stats", "--list-actions",
                             "--autosave-interval", "--recover", "--import-reference"}) {
        EXPECT_NE(run.output.find(flag), std::string::npos) << flag;
    }
}

TEST(GuiArguments, ActionsAreListedWithoutADisplay)
{
    // Given no display at all, when the actions are listed
    const ProgramRun run = runSculptline("--list-actions");
    // Then every command is there by name, with its hot key
    EXPECT_EQ(run.status, 0) << run.output;
    for (const char* line : {"mode.sketch\tS\t", "mode.revolve\tR\t", "mode.railRotation\tG\t", "edit.undo\tCtrl+Z\t",
                             "file.exportIv\t", "file.exportStep\t", "file.exportIges\t", "file.exportStl\t",
                             "file.exportObj\t", "file.recover\t", "file.autosaveInterval\t", "surface.build\tReturn\t",
                             "file.importReference\t", "edit.removeReferences\t", "view.references\tCtrl+Shift+R\t"}) {
        EXPECT_NE(run.output.find(line), std::string::npos) << line << "\n" << run.output;
    }
}

TEST(GuiArguments, BadSizesAreRefused)
{
    expectError("--size banana", "--size: expected WxH");
    expectError("--size 800x", "--size: expected WxH");
    expectError("--size 0x600", "--size: width and height must be between");
    expectError("--size 99999x600", "--size: width and height must be between");
    expectError("--size", "--size");
}

TEST(GuiArguments, UnknownFlagsAreRefused) { expectError("--no-such-flag", "no-such-flag"); }

TEST(GuiArguments, BadSessionsAreRefusedBeforeAnyWindow)
{
    expectError("--replay /nonexistent/session.json", "/nonexistent/session.json: cannot open file");
    const std::string dir = testing::TempDir();
    const std::pair<const char*, const char*> cases[] = {
        {R"({"events": [{"type": "jump"}]})", "events[0].type: must be press, move, release, key, action, wait or pose"},
        {R"({"events": [{"type": "press", "x": 10}]})", "events[0]"},
        {R"({"events": [{"type": "press", "x": 1, "y": 2, "button": "thumb"}]})", "events[0].button"},
        {R"({"events": [{"type": "key", "key": "Ctrl+Nonsense"}]})", "events[0].key"},
        {R"({"events": [{"type": "wait", "ms": -5}]})", "events[0].ms"},
        {R"({"events": [{"type": "pose", "device": "pointer", "position": [0, 0, 0], "orientation": [0, 0, 0, 3]}]})", "events[0].orientation"},
        {R"({"size": [1, 2], "events": []})", "size[0]"},
        {R"({"events": )", "malformed JSON"},
        {R"([1, 2])", "session: must be a JSON object"},
    };
    for (const auto& [text, expected] : cases) {
        const std::string path = dir + "sculptline_bad_session.json";
        std::ofstream(path) << text;
        expectError("--replay '" + path + "'", expected);
        std::remove(path.c_str());
    }
}

TEST(GuiArguments, UnreadableDocumentsAreRefused)
{
    expectError("/nonexistent/scene.json", "/nonexistent/scene.json: cannot open file");

    const std::string bad = testing::TempDir() + "sculptline_gui_bad_scene.json";
    std::ofstream(bad) << R"({"curves": [{"degree": 3, "knots": [0, 1], "points": [[0, 0], [1, 1]]}]})";
    expectError("'" + bad + "'", "curves[0]");
    std::remove(bad.c_str());

    const std::string broken = testing::TempDir() + "sculptline_gui_broken_scene.json";
    std::ofstream(broken) << "{\"planes\": [";
    expectError("'" + broken + "'", "malformed JSON");
    std::remove(broken.c_str());
}

TEST(GuiArguments, NewerDocumentsAreRefusedByVersion)
{
    const std::string newer = testing::TempDir() + "sculptline_gui_newer_scene.json";
    std::ofstream(newer) << R"({"format": "sculptline", "version": 2, "planes": "in a form to come"})";
    expectError("'" + newer + "'", newer + ": made by a newer Sculptline (version 2); this one reads up to 1");
    std::remove(newer.c_str());
}

TEST(GuiArguments, BadAutosaveIntervalsAreRefused)
{
    expectError("--autosave-interval -5", "--autosave-interval");
    expectError("--autosave-interval soon", "--autosave-interval");
}

TEST(GuiArguments, MissingDefaultDataDirectoryIsAnError)
{
    // SCULPTLINE_DATA_DIR overrides the baked-in data directory
    const ProgramRun run = runSculptline("", "SCULPTLINE_DATA_DIR=/nonexistent/data");
    EXPECT_EQ(run.status, 2);
    EXPECT_NE(run.output.find("/nonexistent/data/default_scene.json: cannot open file"), std::string::npos) << run.output;
}

TEST(GuiArguments, NoOpenGLIsAMessageNotAHang)
{
    // Given Qt's offscreen platform, where SoQt usually finds no GL canvas and by default would
    // open a modal error dialog nobody can close / Then the program ends: status 1 with the reason,
    // or, where the platform does have GL, a normal 0. `timeout` turns a hang into status 124.
    const ProgramRun run = runSculptline("--quit", "QT_QPA_PLATFORM=offscreen timeout 60");
    EXPECT_TRUE(run.status == 0 || run.status == 1) << "status " << run.status << "\n" << run.output;
    if (run.status == 1) {
        EXPECT_NE(run.output.find("OpenGL"), std::string::npos) << run.output;
    }
}

TEST(GuiArguments, NoDisplayIsAMessageNotAnAbort)
{
    // Given valid arguments but no display / Then a message and status 1 (Qt alone would abort)
    const ProgramRun run = runSculptline("--quit");
    EXPECT_EQ(run.status, 1) << run.output;
    EXPECT_NE(run.output.find("no display"), std::string::npos) << run.output;
}

}  // namespace

TEST(GuiArguments, StereoAndVrFlags)
{
    // Given the help, the stereo and VR flags are there
    const ProgramRun help = runSculptline("--help");
    for (const char* flag : {"--stereo", "--vr", "anaglyph", "quad-buffer", "interleaved-rows"})
        EXPECT_NE(help.output.find(flag), std::string::npos) << flag;
    // And an unknown stereo mode is refused before anything starts, naming the flag
    expectError("--stereo sideways --quit", "--stereo");
    // And every stereo mode and the VR session have an action
    const ProgramRun actions = runSculptline("--list-actions");
    for (const char* name : {"view.stereo.off\t", "view.stereo.anaglyph\t", "view.stereo.quadBuffer\t", "view.stereo.interleavedRows\t", "view.vr\t"})
        EXPECT_NE(actions.output.find(name), std::string::npos) << name << "\n" << actions.output;
}
