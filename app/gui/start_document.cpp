#include "app/gui/start_document.h"

#include <exception>
#include <iostream>

namespace sculptline::app {

StartDocument openStartDocument(const GuiOptions& options, bool interactive)
{
    StartDocument start;
    try {
        start.document = model::loadDocument(options.document);
        if (options.documentGiven) start.path = options.document;
        return start;
    } catch (const std::exception& e) {
        std::cerr << "sculptline: " << e.what() << "\n";
        start.error = e.what();
    }
    // Without a document named, the default scene failing is an installation problem: no fallback.
    if (!interactive || !options.documentGiven) {
        start.exitStatus = 2;
        return start;
    }
    start.document = model::freshDocument();
    return start;
}

}  // namespace sculptline::app
