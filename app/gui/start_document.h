#pragma once
// The document a session starts on. A document that cannot be opened (missing, unreadable,
// malformed, made by a newer version) ends a scripted run with status 2, as a script needs; a
// person who started the program from a desktop, where stderr goes nowhere, gets a fresh sheet
// (File > New) instead and the reason in a dialog.
#include "app/gui/gui_options.h"
#include "model/document.h"

#include <string>

namespace sculptline::app {

struct StartDocument {
    model::SceneDocument document;
    std::string path;  ///< empty: untitled (the fresh sheet, so that Save asks where)
    std::string error;  ///< why the requested document is not the one opened (for the dialog)
    int exitStatus = 0;  ///< 2: leave now (the message is printed)
};

/// Opens options.document; on failure prints "sculptline: <reason>" to stderr and, when
/// `interactive` (a display, and not scripted()), falls back to model::freshDocument().
StartDocument openStartDocument(const GuiOptions& options, bool interactive);

}  // namespace sculptline::app
