#pragma once
// The documents the GUI replays save (tests/gui/CMakeLists.txt: --save into SCULPTLINE_REPLAY_DIR),
// read back as models for the checks.
#include "model/document.h"
#include "model/model.h"
#include "model/model_document.h"

#include <cstdlib>
#include <string>

namespace sculptline::guitest {

/// The path of a file a replay wrote: in SCULPTLINE_REPLAY_DIR, else the working directory.
inline std::string replayFile(const std::string& name)
{
    const char* dir = std::getenv("SCULPTLINE_REPLAY_DIR");
    return std::string(dir ? dir : ".") + "/" + name;
}

/// The model of a document a replay saved.
inline model::Model readReplayedModel(const std::string& name)
{
    model::Model model;
    model::populateModel(model::loadDocument(replayFile(name)), model);
    return model;
}

}  // namespace sculptline::guitest
