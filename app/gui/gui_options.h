#pragma once
// Command line of the sculptline GUI (../shared/interfaces.md, "sculptline (GUI) automation flags").
// Parsed before Qt starts, so a bad argument is reported without needing a display.
#include <optional>
#include <string>

namespace sculptline::app {

struct GuiOptions {
    std::string document;  ///< empty: the default scene
    int width = 0;  ///< viewport size in pixels; 0 = the window's natural size
    int height = 0;
    std::string screenshot;  ///< PNG of the viewport, written once the scene is shown and rendered
    bool quit = false;  ///< leave after the other flags have acted
};

/// The outcome of parsing: options to run with, or an exit status (0 after --help, 2 after an
/// error) with its message already printed.
struct ParseResult {
    std::optional<GuiOptions> options;
    int exitStatus = 0;
};

/// Parses argv with CLI11. Flags of later issues (--replay, --save, --export-iv, --stats,
/// --list-actions) are recognised and refused with "not implemented yet" (status 2).
ParseResult parseGuiOptions(int argc, const char* const* argv);

/// The default document: $SCULPTLINE_DATA_DIR/default_scene.json when that variable is set, else the
/// data/ directory of the source tree the program was built from.
std::string defaultDocumentPath();

}  // namespace sculptline::app
