// The document a session starts on (app/gui/start_document.h): a person at a desktop gets the
// fresh sheet (File > New) and the reason; a script gets status 2, as before.
#include "app/gui/start_document.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace sculptline::app {
namespace {

GuiOptions optionsFor(const std::string& document)
{
    GuiOptions options;
    options.document = document;
    options.documentGiven = true;
    return options;
}

std::string writeDocument(const std::string& name, const std::string& text)
{
    const std::string path = testing::TempDir() + name;
    std::ofstream(path) << text;
    return path;
}

TEST(StartDocument, APersonGetsAFreshSheetAndTheReason)
{
    // Given a document from a newer version, opened from a desktop
    const std::string newer = writeDocument("sculptline_newer.json", R"({"format": "sculptline", "version": 9, "planes": []})");
    const StartDocument start = openStartDocument(optionsFor(newer), true);
    // Then a fresh sheet opens (File > New's), untitled, with the reason for the dialog
    EXPECT_EQ(start.exitStatus, 0);
    EXPECT_EQ(start.error, newer + ": made by a newer Sculptline (version 9); this one reads up to 1");
    EXPECT_TRUE(start.path.empty());
    EXPECT_EQ(start.document.planes.size(), 1u);  // the sheet's plane, nothing drawn
    EXPECT_TRUE(start.document.curves.empty());
    std::remove(newer.c_str());
}

TEST(StartDocument, MalformedAndMissingDocumentsToo)
{
    const std::string broken = writeDocument("sculptline_broken.json", "{\"planes\": [");
    for (const std::string& path : {broken, std::string("/nonexistent/scene.json")}) {
        const StartDocument start = openStartDocument(optionsFor(path), true);
        EXPECT_EQ(start.exitStatus, 0) << path;
        EXPECT_EQ(start.error.rfind(path + ": ", 0), 0u) << start.error;
        EXPECT_TRUE(start.document.curves.empty()) << path;
        EXPECT_EQ(start.document.planes.size(), 1u) << path;
    }
    std::remove(broken.c_str());
}

TEST(StartDocument, AScriptedRunEndsWithStatus2)
{
    const std::string broken = writeDocument("sculptline_broken2.json", "{\"planes\": [");
    GuiOptions options = optionsFor(broken);
    options.quit = true;
    EXPECT_TRUE(options.scripted());
    EXPECT_EQ(openStartDocument(options, false).exitStatus, 2);
    std::remove(broken.c_str());
}

TEST(StartDocument, AGoodDocumentOpensUnderItsName)
{
    const std::string good = writeDocument("sculptline_good.json", R"({"planes": [{"origin": [0, 0, 0], "normal": [0, 0, 1], "size": 10}]})");
    const StartDocument start = openStartDocument(optionsFor(good), true);
    EXPECT_TRUE(start.error.empty());
    EXPECT_EQ(start.path, good);
    EXPECT_EQ(start.document.planes.size(), 1u);
    EXPECT_TRUE(start.document.curves.empty());
    std::remove(good.c_str());
}

TEST(UserModelPath, FlagThenEnvironmentThenThePersonsFolderAndNothingForAScript)
{
    // Given no flag and no SCULPTLINE_USER_MODEL
    unsetenv("SCULPTLINE_USER_MODEL");
    GuiOptions person;
    GuiOptions script;
    script.quit = true;
    // Then a person's window keeps its habits in the config folder, a script keeps none (it must
    // repeat on any machine, and write nothing into a home folder)
    EXPECT_EQ(userModelPath(person, "/home/x/.config/habits.json"), "/home/x/.config/habits.json");
    EXPECT_EQ(userModelPath(script, "/home/x/.config/habits.json"), "");
    // When the environment names a file, both use it; when the flag names one, it wins
    setenv("SCULPTLINE_USER_MODEL", "/tmp/env_habits.json", 1);
    EXPECT_EQ(userModelPath(person, "/home/x/.config/habits.json"), "/tmp/env_habits.json");
    EXPECT_EQ(userModelPath(script, "/home/x/.config/habits.json"), "/tmp/env_habits.json");
    script.userModel = "/tmp/flag_habits.json";
    EXPECT_EQ(userModelPath(script, "/home/x/.config/habits.json"), "/tmp/flag_habits.json");
    unsetenv("SCULPTLINE_USER_MODEL");
}

}  // namespace
}  // namespace sculptline::app
