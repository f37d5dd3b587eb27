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
    std::string replay;  ///< session JSON to play through the viewer's Qt event path
    std::string save;  ///< document JSON written after the replay
    std::string exportIv;  ///< Open Inventor file written after the replay
    std::string importReference;  ///< .iv file imported as reference geometry, before the replay
    std::string exportStep;  ///< STEP AP214 of the world curves and surfaces, after the replay
    std::string exportIges;  ///< IGES of the same
    std::string exportStl;  ///< binary STL of the surfaces (tessellated) and network meshes
    std::string exportObj;  ///< OBJ of everything (curves as polylines)
    std::string stats;  ///< latency statistics of the replay (JSON)
    bool listActions = false;  ///< print every action name and leave
    bool nurbsNodes = false;  ///< draw with SoNurbsCurve/SoNurbsSurface (frame-time comparison only)
    bool documentGiven = false;  ///< DOCUMENT was on the command line (else the default scene)
    int autosaveInterval = 120;  ///< seconds between autosaves to the recovery file; 0 = off
    bool autosaveIntervalGiven = false;  ///< on the command line (else File > Autosave Interval's setting)
    bool recover = false;  ///< reopen the unsaved work of a session that died, without asking
    std::string stereo;  ///< "anaglyph", "quad-buffer", "interleaved-rows" or "off"; empty: not given (mono)
    bool vr = false;  ///< start an OpenXR session at once (View > VR session…)
    /// The recognition habits file (--user-model); empty: $SCULPTLINE_USER_MODEL, else the user's
    /// config folder for a person, nothing (habits in memory only) for a script (userModelPath()).
    std::string userModel;

    /// Run by a script (a replay, an output flag or --quit): nobody is there to answer a dialog.
    bool scripted() const
    {
        return quit || !replay.empty() || !save.empty() || !exportIv.empty() || !exportStep.empty() || !exportIges.empty() ||
               !exportStl.empty() || !exportObj.empty() || !screenshot.empty() || !stats.empty();
    }
};

/// The outcome of parsing: options to run with, or an exit status (0 after --help, 2 after an
/// error) with its message already printed.
struct ParseResult {
    std::optional<GuiOptions> options;
    int exitStatus = 0;
};

/// Parses argv with CLI11; status 2 and a message for a bad flag or value.
ParseResult parseGuiOptions(int argc, const char* const* argv);

/// Where the window keeps the recognition habits: --user-model, else $SCULPTLINE_USER_MODEL, else
/// `personal` (the user's config folder) when nobody scripts the run; empty for a script without
/// either (its habits live in memory only: a replay must repeat whatever the person's habits, and
/// must not write into their home).
std::string userModelPath(const GuiOptions& options, const std::string& personal);

/// The default document: $SCULPTLINE_DATA_DIR/default_scene.json when that variable is set, else the
/// data/ directory of the source tree the program was built from.
std::string defaultDocumentPath();

}  // namespace sculptline::app
