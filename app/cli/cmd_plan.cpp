// sculptline-cli plan: a document's construction plan (seed 000 §3.2; model/plan.h).
//
//   {"document": D} or {"path": "doc.json"}
//     -> {"states": {id: "fixed"|"free"|"changed"},
//         "steps": [{"solve": [entity ids], "solver": name, "constraints": [constraint ids]}..],
//         "dof": {id: {"total": n, "consumed": n}},
//         "constraints": {id: {"type": name, "sources": [ids], "targets": [ids]}},
//         "elapsed_ms": t}
//
// The document is opened as the GUI opens it (model/model_document.h); steps come in evaluation
// order. Constraints are numbered apart from entities: the placement of a curve on its plane and the
// construction of a surface are constraints the model derives from the document, the pins and the
// rest are the document's own. "constraints" says what each id is.
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"
#include "model/document.h"
#include "model/model.h"
#include "model/model_document.h"

namespace sculptline::cli {
namespace {

json run(const json& input, const Options&)
{
    const bool inline_ = input.contains("document"), file = input.contains("path");
    if (inline_ == file) throw InputError("document: give either \"document\" (a document object) or \"path\" (its file)");
    if (file && !input["path"].is_string()) throw InputError("path: expected a file name");
    const model::SceneDocument doc = inline_ ? model::documentFromJson(input["document"]) : model::loadDocument(input["path"].get<std::string>());
    const Stopwatch clock;
    model::Model model;
    model::populateModel(doc, model);
    const model::Plan& plan = model.plan();
    const double ms = clock.elapsedMs();

    json states = json::object(), dof = json::object(), steps = json::array(), constraints = json::object();
    for (const auto& [id, e] : model.entities()) {
        const std::string key = std::to_string(id);
        states[key] = model::stateName(model.state(id));
        const model::Dof d = model.dof(id);
        dof[key] = {{"total", d.total}, {"consumed", d.consumed}};
    }
    for (const model::PlanStep& step : plan.steps) {
        steps.push_back({{"solve", step.solve}, {"solver", step.solver}, {"constraints", step.constraints}});
    }
    for (const auto& [id, c] : model.constraints()) {
        constraints[std::to_string(id)] = {{"type", model::constraintTypeName(c.type)}, {"sources", c.sources}, {"targets", c.targets}};
    }
    json out{{"states", states}, {"steps", steps}, {"dof", dof}, {"constraints", constraints}};
    out["elapsed_ms"] = ms;
    return out;
}

const SubcommandRegistrar registrar{
    {"plan", "a document's construction plan: {document: D} or {path} -> {states, steps, dof, constraints}", &run}};

}  // namespace
}  // namespace sculptline::cli
