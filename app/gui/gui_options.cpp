#include "app/gui/gui_options.h"

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <iostream>
#include <regex>

namespace sculptline::app {
namespace {

/// Viewport edge limits: below 16 px nothing is visible; above 8192 px GL drivers refuse.
constexpr int kMinEdge = 16;
constexpr int kMaxEdge = 8192;

/// "WxH" -> width, height; an empty string when valid, else CLI11's error message.
std::string parseSize(const std::string& text, int& width, int& height)
{
    static const std::regex pattern("([0-9]{1,5})x([0-9]{1,5})");
    std::smatch m;
    if (!std::regex_match(text, m, pattern)) return "--size: expected WxH (e.g. 800x600), got '" + text + "'";
    width = std::stoi(m[1].str());
    height = std::stoi(m[2].str());
    if (width < kMinEdge || height < kMinEdge || width > kMaxEdge || height > kMaxEdge) {
        return "--size: width and height must be between " + std::to_string(kMinEdge) + " and " +
               std::to_string(kMaxEdge) + ", got '" + text + "'";
    }
    return {};
}

}  // namespace

ParseResult parseGuiOptions(int argc, const char* const* argv)
{
    CLI::App cli{"Sculptline: sketch-based 3D curve and surface modelling.", "sculptline"};
    GuiOptions options;
    std::string size;
    cli.add_option("DOCUMENT", options.document, "Scene document (JSON) to open; default: the default scene");
    cli.add_option("--size", size, "Size of the 3D viewport in pixels, WxH");
    cli.add_option("--screenshot", options.screenshot, "Write the rendered viewport to this PNG file");
    cli.add_flag("--quit", options.quit, "Quit after the other flags have acted");
    cli.add_option("--replay", options.replay, "Play a recorded session (JSON) through the viewer");
    cli.add_option("--save", options.save, "Save the document (JSON) after the replay");
    cli.add_option("--export-iv", options.exportIv, "Export the scene as Open Inventor (.iv) after the replay");
    cli.add_option("--import-reference", options.importReference,
                   "Import an Open Inventor (.iv) file as reference geometry (one undo step) before the replay");
    cli.add_option("--export-step", options.exportStep, "Export the curves and surfaces as STEP AP214 (exact B-splines) after the replay");
    cli.add_option("--export-iges", options.exportIges, "Export the curves and surfaces as IGES (exact B-splines) after the replay");
    cli.add_option("--export-stl", options.exportStl, "Export the surfaces (tessellated) and meshes as binary STL after the replay");
    cli.add_option("--export-obj", options.exportObj, "Export the curves, surfaces and meshes as Wavefront OBJ after the replay");
    cli.add_option("--stats", options.stats, "Write the replay's update latencies (JSON: count, p50, p99, max)");
    cli.add_option("--autosave-interval", options.autosaveInterval,
                   "Seconds between autosaves of unsaved work to the recovery file (default 120; 0 = off)")
        ->check(CLI::Range(0, 24 * 3600));
    cli.add_flag("--recover", options.recover,
                 "Reopen the unsaved work of a session that ended without saving, without asking");
    cli.add_option("--user-model", options.userModel,
                   "Recognition habits file (JSON) to read and update; default $SCULPTLINE_USER_MODEL, else "
                   "recognition_habits.json in the user's config folder (scripted runs: none, habits in memory only)");
    cli.add_option("--stereo", options.stereo,
                   "Stereo view: anaglyph (red/cyan glasses), quad-buffer (stereo OpenGL), interleaved-rows (passive 3D "
                   "display) or off; where the display cannot, a message and the view stays mono")
        ->check(CLI::IsMember({"anaglyph", "quad-buffer", "interleaved-rows", "off"}));
    cli.add_flag("--vr", options.vr,
                 "Start a VR session through OpenXR (View > VR session…); without an OpenXR runtime, a message and the desktop goes on");
    cli.add_flag("--list-actions", options.listActions, "Print the name of every action and leave");
    cli.add_flag("--nurbs-nodes", options.nurbsNodes,
                 "Draw curves and surfaces with SoNurbsCurve/SoNurbsSurface instead of the kernel's tessellation "
                 "(to compare frame times with --stats)");

    ParseResult result;
    try {
        cli.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        std::cout << cli.help();
        return result;
    } catch (const CLI::ParseError& e) {
        std::cerr << "sculptline: " << e.what() << "\nRun 'sculptline --help' for the flags.\n";
        result.exitStatus = 2;
        return result;
    }
    if (!size.empty()) {
        if (const std::string error = parseSize(size, options.width, options.height); !error.empty()) {
            std::cerr << "sculptline: " << error << "\n";
            result.exitStatus = 2;
            return result;
        }
    }
    options.documentGiven = !options.document.empty();
    options.autosaveIntervalGiven = cli.count("--autosave-interval") > 0;
    if (options.document.empty()) options.document = defaultDocumentPath();
    result.options = options;
    return result;
}

std::string defaultDocumentPath()
{
    const char* env = std::getenv("SCULPTLINE_DATA_DIR");
    const std::string dir = (env && *env) ? env : SCULPTLINE_DATA_DIR;
    return dir + "/default_scene.json";
}

std::string userModelPath(const GuiOptions& options, const std::string& personal)
{
    if (!options.userModel.empty()) return options.userModel;
    if (const char* env = std::getenv("SCULPTLINE_USER_MODEL"); env && *env) return env;
    return options.scripted() ? std::string() : personal;
}

}  // namespace sculptline::app
