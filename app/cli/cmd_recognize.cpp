// sculptline-cli recognize: shape recognition of one stroke, or of strokes drawn one after another
// with composite reasoning and the adaptive user model (issue 3; thesis §3.1.1, Tables 3-1, 3-2).
//
//   {"stroke": K}  -> {"shape": kind, "candidates": [{"kind", "score"}..], "regularized": C, "elapsed_ms": t}
//   {"strokes": [K..], "user_model": M or "path.json"}
//     -> the fields above for the last stroke, plus "strokes": [per stroke: shape, candidates,
//        regularized, relations (to the previous stroke), composite, node, composite_node,
//        pre_node (the previous stroke's node, or its composite's for a three-stroke object such
//        as Fig. 3-4 d's polygon_volume), learned, offered], "composite": the last stroke's object,
//        "user_model": the updated model.
//   Optional: "tolerance" (fitting, model units), "resolution" (the pitch the samples are quantized
//   to, as for fit: the default tolerance is at least kResolutionTolerance times it; the window
//   passes one pixel's footprint on the sketch plane), "regularize": false to keep the fitted curves.
// A "user_model" path is read if it exists (else the predefined Table 3-2 is used) and written back
// with what was learned: one file per user.
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"
#include "solvers/stroke/stroke_json.h"

#include <fstream>
#include <sstream>

namespace sculptline::cli {
namespace {

namespace stroke = solvers::stroke;

stroke::FitResult fitOne(const stroke::Stroke& k, double tolerance, double resolution)
{
    stroke::FitOptions o;
    o.tolerance = tolerance;
    o.resolution = resolution;
    try {
        // The fit recognition reads: a self-crossing stroke refitted open, a nearly closed loop
        // refitted closed (recognizeStroke; issue 15 §1, real pen data).
        return stroke::recognizeStroke(k, o).fit;
    } catch (const solvers::GeometryError& e) {
        throw InputError(e.what());
    }
}

stroke::UserModel loadModel(const json& input, std::string* path)
{
    if (!input.contains("user_model")) return stroke::UserModel::predefined();
    const json& m = input["user_model"];
    if (m.is_object()) return stroke::userModelFromJson(m, "user_model");
    if (!m.is_string()) throw InputError("user_model: must be a model object or a file path");
    *path = m.get<std::string>();
    std::ifstream in(*path);
    if (!in) return stroke::UserModel::predefined();
    std::stringstream text;
    text << in.rdbuf();
    return stroke::userModelFromJson(solvers::io::parseJson(text.str()), "user_model(" + *path + ")");
}

json run(const json& input, const Options&)
{
    const bool one = input.contains("stroke"), many = input.contains("strokes");
    if (one && many) throw InputError("strokes: give either \"stroke\" or \"strokes\", not both");
    if (!one && !many) throw InputError("stroke: missing (give \"stroke\" or \"strokes\")");
    std::vector<stroke::Stroke> strokes;
    if (one) {
        strokes.push_back(stroke::strokeFromJson(input["stroke"], "stroke"));
    } else {
        const json& a = input["strokes"];
        if (!a.is_array()) throw InputError("strokes: must be an array");
        if (a.empty()) throw InputError("strokes: empty, at least one stroke is needed");
        for (size_t i = 0; i < a.size(); ++i) strokes.push_back(stroke::strokeFromJson(a[i], "strokes[" + std::to_string(i) + "]"));
    }
    const double tolerance = optionalLength(input, "tolerance", 0.0, false);
    // The pitch the samples are quantized to (as for fit): the window passes one pixel's footprint.
    const double resolution = optionalLength(input, "resolution", 0.0, true);
    stroke::RecognizeOptions ro;
    if (input.contains("regularize")) {
        if (!input["regularize"].is_boolean()) throw InputError("regularize: must be true or false");
        ro.regularize = input["regularize"].get<bool>();
    }
    std::string modelPath;
    stroke::UserModel model = loadModel(input, &modelPath);

    const Stopwatch clock;
    std::vector<stroke::FitResult> fits;
    for (size_t i = 0; i < strokes.size(); ++i) {
        try {
            fits.push_back(fitOne(strokes[i], tolerance, resolution));
        } catch (const InputError& e) {  // name the stroke in a sequence: "strokes[2].points: ..."
            const std::string msg = e.what();
            throw InputError(one ? msg : "strokes[" + std::to_string(i) + "]" + msg.substr(std::string("stroke").size()));
        }
    }
    const std::vector<stroke::Interpretation> seq = stroke::interpretStrokes(fits, model, ro);
    const double ms = clock.elapsedMs();

    json out = stroke::recognitionToJson(seq.back().recognition, strokes.back().dimension);
    if (many) {
        json items = json::array();
        for (size_t i = 0; i < seq.size(); ++i) {
            json item = stroke::recognitionToJson(seq[i].recognition, strokes[i].dimension);
            json rel = json::array();
            for (auto r : seq[i].relations) rel.push_back(stroke::relationName(r));
            item["relations"] = rel;
            item["composite"] = stroke::compositeName(seq[i].composite);
            item["node"] = seq[i].node;
            item["composite_node"] = seq[i].compositeNode;
            item["pre_node"] = seq[i].preNode;
            item["learned"] = seq[i].learned;
            item["offered"] = seq[i].offered;
            items.push_back(std::move(item));
        }
        out["strokes"] = std::move(items);
        out["composite"] = stroke::compositeName(seq.back().composite);
        out["user_model"] = stroke::toJson(model);
        if (!modelPath.empty()) {
            std::ofstream file(modelPath);
            if (!(file << out["user_model"].dump(2) << '\n')) throw InputError("user_model: cannot write '" + modelPath + "'");
        }
    }
    out["elapsed_ms"] = ms;
    return out;
}

const SubcommandRegistrar registrar{
    {"recognize", "shape recognition: {stroke} or {strokes, user_model?} -> {shape, candidates, regularized}", &run}};

}  // namespace
}  // namespace sculptline::cli
