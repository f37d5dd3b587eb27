#pragma once
// Aesthetic curve operators (thesis §7.2, §7.4, §7.5): Leyton's process-grammar rules and the
// designers' operators (straighten, soften, sharpen, convex, concave, tension, accelerate), each a
// set of linear constraints on the characteristic points — a displacement of amount lambda along the
// principal normal, blocked points, fixed tangents — on the curve constraint rows of
// solvers/editing/curve_manipulation.h. The constraints'
// targets are affine in lambda, so a drag factors once and re-solves per event (OperatorDrag). The
// change solved for is the fairest one (least bending of the control points' displacement, the
// thesis's bar network) rather than the least control-point change of curve_manipulation.h, which
// moves only the control points under each constraint.
#include "solvers/aesthetics/curve_analysis.h"
#include "solvers/editing/curve_manipulation.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sculptline::solvers::aesthetics {

/// Leyton's six rules (the continuations that grow a pair of inflections, the bifurcations that
/// split an extremum into three):
///   Cm+ : m+ -> 0m-0      CM- : M- -> 0M+0
///   BM+ : M+ -> M+m+M+    Bm- : m- -> m-M-m-
///   Bm+ : m+ -> m+M+m+    BM- : M- -> M-m-M-
enum class Rule { CmPlus, CMMinus, BMPlus, BmMinus, BmPlus, BMMinus };

enum class Operator { Straighten, Soften, Sharpen, Convex, Concave, Tension, Accelerate };

/// The most control points an operator or rule takes: searching an amount analyses the curve a few
/// hundred times (about 1 ms each at 200 points), and straighten repeats that per step, so a bigger
/// curve could hold the window for seconds. Sketched curves have tens.
constexpr int kMaxOperatorPoints = 200;
/// Straighten's steps at most (each removes two characteristic points).
constexpr int kMaxStraightenSteps = 16;

/// "Cm+", "CM-", ... / "straighten", "soften", ...; parse returns nullopt for an unknown name.
const char* ruleName(Rule r);
std::optional<Rule> parseRule(const std::string& name);
const char* operatorName(Operator o);
std::optional<Operator> parseOperator(const std::string& name);
/// The kind a rule applies to (Cm+ and Bm+ to an m+, ...).
PointKind ruleKind(Rule r);

/// The constraints of one operator step, before lambda is chosen: targets = base + lambda * direction.
struct OperatorSetup {
    Curve2d curve;  ///< the curve the constraints refer to (with the knots inserted for freedom)
    std::vector<editing::CurveConstraint<2>> constraints;
    std::vector<Eigen::Vector2d> base;       ///< the constraint values at lambda = 0 (the curve's own)
    std::vector<Eigen::Vector2d> direction;  ///< d target / d lambda
    std::vector<int> blocked;                ///< control points outside the operated segment
    int insertedKnots = 0;                   ///< §7.5: knots inserted (no shape change) for freedom
    int point = -1;                          ///< the characteristic point operated on (analysis index)
    double u0 = 0.0, u1 = 0.0;               ///< the operated segment: nothing outside it moves
};

/// A drag of an operator's amount: the fairest change that meets the constraints (least bending of
/// the control points' displacement, operators.cpp) is factored once (constructor), each event is
/// one product (at). The per-event cost is O(free points x constraints).
class OperatorDrag {
public:
    explicit OperatorDrag(OperatorSetup setup);
    /// The curve for amount lambda (model units).
    Curve2d at(double lambda, editing::ManipulationReport* report = nullptr) const;
    const OperatorSetup& setup() const { return setup_; }

private:
    OperatorSetup setup_;
    std::vector<int> free_;  // unique indices of the control points that move
    Eigen::MatrixXd G_;      // free x rows: displacement per unit constraint change
    Eigen::MatrixXd F_;      // rows x free: the constraint rows, for the residual report
};

/// The constraints of a rule (or its inverse) at characteristic point `at` of `analysis`:
/// a displacement along the principal normal N (toward the centre of curvature) at the point —
/// +lambda N for the continuations and for the bifurcations that flatten a |kappa| maximum (BM+, Bm-),
/// -lambda N for those that sharpen a |kappa| minimum (Bm+, BM-); inverses go the other way, except
/// an inverse continuation, which flattens the point the continuation made (toward its own centre) —
/// and the neighbouring characteristic points (or the ends) blocked. Control points whose support
/// lies outside the neighbours' segment do not move.
/// @throws GeometryError "at: ..." when the point is not of the rule's kind (inverse: of the kind the
///         rule produces in the middle) or out of range.
OperatorSetup ruleSetup(const Curve2d& curve, const CurveAnalysis& analysis, Rule rule, int at, bool inverse);

/// The smallest amount at which the rule (or its inverse) gives its announced name (the point
/// replaced by the rule's triple, or the triple by the one point), or nullopt when no amount up to
/// the curve's length does.
std::optional<double> ruleAmount(const Curve2d& curve, Rule rule, int at, bool inverse, const Thresholds& thresholds = {});

/// The name a rule announces at point `at` of the analysis.
std::string announcedName(const CurveAnalysis& analysis, Rule rule, int at, bool inverse);

/// What an operator or rule did.
struct OperatorResult {
    Curve2d curve;
    std::string nameBefore, nameAfter;
    Measures measuresBefore, measuresAfter;
    int insertedKnots = 0;
    double amount = 0.0;     ///< the displacement used (straighten: the sum over its steps)
    std::vector<std::string> names;  ///< straighten: the name after each step (Fig. 7-17's sequence)
    std::string message;     ///< what could not be done (empty when all of it was)
};

struct OperatorOptions {
    std::optional<int> at;      ///< characteristic point (index into the analysis's points)
    bool atEnd = true;          ///< accelerate: the end whose tangent is raised (else the start)
    Thresholds thresholds;
};

/// Applies a rule with amount lambda (>= 0, model units).
OperatorResult applyRule(const Curve2d& curve, Rule rule, int at, double lambda, bool inverse,
                         const Thresholds& thresholds = {});

/// Applies an operator (§7.4). `amount` >= 0 in model units: the displacement of the operated point
/// (soften, sharpen, convex, concave, tension) or of the raised end tangent's handle (accelerate:
/// the second control point from that end, along the tangent); straighten finds its own amounts
/// (each step moves until the codon it removes is gone) and `amount`, when positive, caps each step.
/// Every operator keeps the end points; accelerate also the static end's tangent. All but straighten
/// keep the name: an amount that would change it is limited to the largest that does not (the
/// message says so).
OperatorResult applyOperator(const Curve2d& curve, Operator op, double amount, const OperatorOptions& options = {});

/// The setup behind applyOperator for the operators driven by one amount (all but straighten), for
/// a drag: OperatorDrag(operatorSetup(...)).at(lambda) is applyOperator's curve.
OperatorSetup operatorSetup(const Curve2d& curve, const CurveAnalysis& analysis, Operator op, const OperatorOptions& options);

}  // namespace sculptline::solvers::aesthetics
