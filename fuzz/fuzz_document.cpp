// The document loader: bytes -> parseJson -> documentFromJson -> populateModel -> modelToJson, what
// `sculptline DOCUMENT` and File > Open do, then the round trip of File > Save: the saved text must
// open again and save to the same JSON (model/model_document.h promises an exact restore).
//
// A document the reader rejects (InputError) is fine. A document it accepts must open: a surface
// whose construction cannot be rebuilt is kept, failed (Model::restoreSurface), so any exception
// from populateModel is a finding, as is anything else that goes wrong.
#include "fuzz/fuzz_target.h"
#include "model/model_document.h"

#include "solvers/io/geometry_json.h"

#include <exception>
#include <nlohmann/json.hpp>

namespace {

using namespace sculptline;
using nlohmann::json;

// Reads, opens and saves; exceptions propagate.
json openAndSave(const std::string& text)
{
    const model::SceneDocument doc = model::documentFromJson(solvers::io::parseJson(text));
    model::Model model;
    try {
        model::populateModel(doc, model);
    } catch (const std::exception& e) {
        fuzz::fuzzFailure("document", std::string("a document the reader accepted does not open: ") + e.what());
    }
    return model::modelToJson(model, doc.grid);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    json saved;
    try {
        saved = openAndSave(std::string(reinterpret_cast<const char*>(data), size));
    } catch (const solvers::io::InputError& e) {
        fuzz::noteRejected(e.what());
        return 0;
    }
    const std::string text = saved.dump();
    json again;
    try {
        again = openAndSave(text);
    } catch (const std::exception& e) {
        fuzz::fuzzFailure("document", std::string("a saved document does not open again: ") + e.what());
    }
    if (again != saved) fuzz::fuzzFailure("document", "saving a reopened document changed it: " + text.substr(0, 300));
    return 0;
}
