// sculptline-cli aesthetic: an aesthetic operator or a process-grammar rule applied to a planar curve
// (thesis §7.2, §7.4; solvers/aesthetics/curve_operators.h).
//
//   {"curve": C, "operator": "straighten"|"soften"|"sharpen"|"convex"|"concave"|"tension"|"accelerate",
//    "amount": λ >= 0 (straighten: optional, a cap per step), "at"?: index into analyze's points,
//    "end"?: "start"|"end" (accelerate; default "end"), "thresholds"?}
//   {"curve": C, "rule": "Cm+"|"CM-"|"BM+"|"Bm-"|"Bm+"|"BM-", "inverse"?: bool, "at": index,
//    "amount"?: λ (default: the smallest amount that gives the rule's announced name), "thresholds"?}
//     -> {"curve": C' (in the input curve's plane), "name_before", "name_after", "measures_before",
//         "measures_after", "inserted_knots", "amount" (used), "names" (straighten's steps),
//         "announced" (rules), "message"?, "elapsed_ms"}
#include "app/cli/aesthetics_json.h"
#include "app/cli/cli_support.h"
#include "app/cli/subcommand.h"
#include "solvers/aesthetics/curve_operators.h"

namespace sculptline::cli {
namespace {

namespace aes = solvers::aesthetics;

std::string stringOf(const json& input, const std::string& key)
{
    const json& v = input[key];
    if (!v.is_string()) throw InputError(key + ": expected a string, got " + solvers::io::describeValue(v));
    return v.get<std::string>();
}

json run(const json& input, const Options&)
{
    const solvers::Curve3d curve3 = solvers::io::curveFromJson(field(input, "curve"), "curve");
    const aes::Thresholds thresholds = thresholdsFromJson(input);
    const bool isRule = input.contains("rule");
    if (isRule == input.contains("operator")) throw InputError("operator: give exactly one of \"operator\" and \"rule\"");
    std::optional<double> amount;
    if (input.contains("amount")) {
        amount = solvers::io::numberFromJson(input["amount"], "amount");
        if (*amount < 0.0) throw InputError("amount: must be >= 0, got " + std::to_string(*amount));
    }
    std::optional<int> at;
    if (input.contains("at")) at = solvers::io::integerFromJson(input["at"], "at", 0, 1000000);
    aes::PlaneFrame frame;
    const solvers::Curve2d curve = runOperation(input, "curve", [&] { return aes::planarCurve(curve3, 1e-6, &frame); });
    const Stopwatch clock;
    json out;
    aes::OperatorResult r = [&] {
        if (isRule) {
            const std::string name = stringOf(input, "rule");
            const auto rule = aes::parseRule(name);
            if (!rule) throw InputError("rule: unknown \"" + name + "\" (expected Cm+, CM-, BM+, Bm-, Bm+ or BM-)");
            if (!at) throw InputError("at: missing (the characteristic point the rule applies to)");
            bool inverse = false;
            if (input.contains("inverse")) {
                if (!input["inverse"].is_boolean()) throw InputError("inverse: expected true or false");
                inverse = input["inverse"].get<bool>();
            }
            return runOperation(input, "curve", [&] {
                const aes::CurveAnalysis a = aes::analyzeCurve(curve, thresholds);
                out["announced"] = aes::announcedName(a, *rule, *at, inverse);
                double lambda = 0.0;
                if (amount) {
                    lambda = *amount;
                } else {
                    const auto found = aes::ruleAmount(curve, *rule, *at, inverse, thresholds);
                    if (!found) throw InputError("amount: no amount up to the curve's length gives " + out["announced"].get<std::string>());
                    lambda = *found;
                }
                return aes::applyRule(curve, *rule, *at, lambda, inverse, thresholds);
            });
        }
        const std::string name = stringOf(input, "operator");
        const auto op = aes::parseOperator(name);
        if (!op) {
            throw InputError("operator: unknown \"" + name +
                             "\" (expected straighten, soften, sharpen, convex, concave, tension or accelerate)");
        }
        if (!amount && *op != aes::Operator::Straighten) throw InputError("amount: missing (a displacement in model units)");
        aes::OperatorOptions o;
        o.at = at;
        o.thresholds = thresholds;
        if (input.contains("end")) {
            const std::string end = stringOf(input, "end");
            if (end != "start" && end != "end") throw InputError("end: expected \"start\" or \"end\", got \"" + end + "\"");
            o.atEnd = end == "end";
        }
        return runOperation(input, "curve", [&] { return aes::applyOperator(curve, *op, amount.value_or(0.0), o); });
    }();
    const double ms = clock.elapsedMs();
    out["curve"] = solvers::io::toJson(aes::spaceCurve(r.curve, frame));
    out["name_before"] = r.nameBefore;
    out["name_after"] = r.nameAfter;
    out["measures_before"] = measuresJson(r.measuresBefore);
    out["measures_after"] = measuresJson(r.measuresAfter);
    out["inserted_knots"] = r.insertedKnots;
    out["amount"] = r.amount;
    out["names"] = r.names;
    if (!r.message.empty()) out["message"] = r.message;
    out["elapsed_ms"] = ms;
    requireFiniteOutput(out);
    return out;
}

const SubcommandRegistrar registrar{
    {"aesthetic",
     "an aesthetic operator or a process-grammar rule on a planar curve: {curve, operator, amount, at?, end?} or "
     "{curve, rule, at, inverse?, amount?} -> {curve, name_before, name_after, measures_before, measures_after, "
     "inserted_knots}",
     &run}};

}  // namespace
}  // namespace sculptline::cli
