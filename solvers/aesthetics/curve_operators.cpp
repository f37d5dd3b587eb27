#include "solvers/aesthetics/curve_operators.h"

#include "solvers/bspline/arc_length.h"
#include "solvers/bspline/geometry_error.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <Eigen/QR>

namespace sculptline::solvers::aesthetics {
namespace {

using editing::ConstraintType;
using editing::CurveConstraint;
using Vec = Eigen::Vector2d;

// §7.5: an operated segment keeps at least this many free control points more than it has
// constraints, so that the least change has room to spread instead of being forced (with exactly
// as many, the solve is an interpolation through the constraints).
constexpr int kFreedomMargin = 2;
// At most this many rounds of knot insertion (each halves every span of the segment).
constexpr int kMaxRefinementRounds = 4;

int uniqueCount(const Curve2d& c) { return c.isClosed() ? c.pointCount() - c.degree() : c.pointCount(); }

struct Frame {
    Vec point, tangent, normal;  // normal: the principal normal N, toward the centre of curvature
    double kappa = 0.0;
};

Frame frameAt(const Curve2d& c, double u)
{
    const auto d = c.derivatives(c.isClosed() ? c.normalizeParameter(u) : u, 2);
    Frame f;
    f.point = d[0];
    f.tangent = d[1].normalized();
    const Vec left(-f.tangent.y(), f.tangent.x());
    f.kappa = signedCurvature(c, c.isClosed() ? c.normalizeParameter(u) : u);
    f.normal = f.kappa < 0.0 ? Vec(-left) : left;
    return f;
}

// The control points (unique indices) that may move: those whose support lies within [a, b]. The
// displacement is then a spline that vanishes outside [a, b] with its first p - 1 derivatives at a
// and b: nothing outside the operated segment moves, and the change joins the rest C^(p-1).
// Closed curves: b - a is at most a period, a may lie before the domain start.
std::vector<int> blockedOutside(const Curve2d& c, double a, double b)
{
    const auto& t = c.knots();
    const int p = c.degree(), n = c.pointCount(), unique = uniqueCount(c);
    const double period = c.domainEnd() - c.domainStart();
    // Knots computed a period apart, or by insertion at a, agree with a and b to round-off only.
    const double eps = 1e-12 * std::max(1.0, std::abs(period));
    std::vector<bool> free(unique, false);
    for (int j = 0; j < n; ++j) {
        const int i = j % unique;
        for (int k = c.isClosed() ? -2 : 0; k <= (c.isClosed() ? 2 : 0); ++k) {
            if (t[j] + k * period >= a - eps && t[j + p + 1] + k * period <= b + eps) free[i] = true;
        }
    }
    std::vector<int> blocked;
    for (int i = 0; i < unique; ++i) {
        if (!free[i]) blocked.push_back(i);
    }
    return blocked;
}

// Records constraints by parameter; their values are read from the final curve (knot insertion
// does not change the geometry, so they are the same on every refinement).
struct Spec {
    ConstraintType type;
    double u;
    Vec direction;  // d value / d lambda
};

OperatorSetup finish(const Curve2d& curve, const std::vector<Spec>& specs, double a, double b, int point)
{
    OperatorSetup s{curve, {}, {}, {}, {}, 0, point, a, b};
    const int fixedRows = static_cast<int>(specs.size());
    int free = 0;
    // §7.5: more freedom where the constraints would exceed the segment's free control points.
    for (int round = 0;; ++round) {
        s.blocked = blockedOutside(s.curve, a, b);
        free = uniqueCount(s.curve) - static_cast<int>(s.blocked.size());
        if (free >= fixedRows + kFreedomMargin || round == kMaxRefinementRounds) break;
        std::vector<double> mids;
        std::vector<double> breaks{s.curve.domainStart()};
        for (double k : s.curve.knots()) {
            if (k > breaks.back() && k < s.curve.domainEnd()) breaks.push_back(k);
        }
        breaks.push_back(s.curve.domainEnd());
        const double period = s.curve.domainEnd() - s.curve.domainStart();
        for (size_t i = 0; i + 1 < breaks.size(); ++i) {
            const double m = 0.5 * (breaks[i] + breaks[i + 1]);
            bool inside = m > a && m < b;
            if (s.curve.isClosed()) inside = inside || (m - period > a && m - period < b) || (m + period > a && m + period < b);
            if (inside) mids.push_back(m);
        }
        if (mids.empty()) break;
        s.curve = s.curve.refine(mids);
        s.insertedKnots += static_cast<int>(mids.size());
    }
    for (const Spec& sp : specs) {
        CurveConstraint<2> c;
        c.type = sp.type;
        c.u = s.curve.isClosed() ? s.curve.normalizeParameter(sp.u) : sp.u;
        const auto d = s.curve.derivatives(c.u, 1);
        c.value = sp.type == ConstraintType::Tangent ? d[1] : d[0];
        s.constraints.push_back(c);
        s.base.push_back(c.value);
        s.direction.push_back(sp.direction);
    }
    return s;
}

// The neighbour `step` points away (+-1, +-2) from point i, or the curve's end: its parameter,
// unwrapped on closed curves so that left < u < right.
double neighbourParameter(const Curve2d& c, const CurveAnalysis& a, int i, int step, bool* isEnd = nullptr)
{
    const int n = static_cast<int>(a.points.size());
    const double period = c.domainEnd() - c.domainStart();
    if (isEnd) *isEnd = false;
    if (c.isClosed()) {
        if (std::abs(step) >= n) return a.points[i].u + (step < 0 ? -period : period) * 0.999;
        const int j = i + step;
        double u = a.points[((j % n) + n) % n].u;
        if (j < 0) u -= period;
        if (j >= n) u += period;
        return u;
    }
    const int j = i + step;
    if (j < 0 || j >= n) {
        if (isEnd) *isEnd = true;
        return j < 0 ? c.domainStart() : c.domainEnd();
    }
    return a.points[j].u;
}

void checkSize(const Curve2d& c)
{
    if (c.pointCount() > kMaxOperatorPoints) {
        throw GeometryError("points: " + std::to_string(c.pointCount()) + " control points, the operators take at most " +
                            std::to_string(kMaxOperatorPoints) + " (remove knots first)");
    }
}

void checkPoint(const CurveAnalysis& a, int at)
{
    if (at < 0 || at >= static_cast<int>(a.points.size())) {
        throw GeometryError("at: " + std::to_string(at) + " is not a characteristic point (the curve has " +
                            std::to_string(a.points.size()) + ", named \"" + a.name + "\")");
    }
}

bool isContinuation(Rule r) { return r == Rule::CmPlus || r == Rule::CMMinus; }

// The kind in the middle of what a rule makes (where its inverse applies).
PointKind producedKind(Rule r)
{
    switch (r) {
    case Rule::CmPlus: return PointKind::MinNegative;   // 0m-0
    case Rule::CMMinus: return PointKind::MaxPositive;  // 0M+0
    case Rule::BMPlus: return PointKind::MinPositive;   // M+m+M+
    case Rule::BmMinus: return PointKind::MaxNegative;  // m-M-m-
    case Rule::BmPlus: return PointKind::MaxPositive;   // m+M+m+
    case Rule::BMMinus: return PointKind::MinNegative;  // M-m-M-
    }
    return PointKind::Inflection;
}

// The same extremum with kappa of the other sign (m- -> m+: a dent flattened into a bulge).
PointKind signFlipped(PointKind k)
{
    switch (k) {
    case PointKind::MaxPositive: return PointKind::MaxNegative;
    case PointKind::MinPositive: return PointKind::MinNegative;
    case PointKind::MaxNegative: return PointKind::MaxPositive;
    case PointKind::MinNegative: return PointKind::MinPositive;
    case PointKind::Inflection: return k;
    }
    return k;
}

// Drives a setup's lambda up until `done` holds for the result: steps growing by kDriveGrowth from a
// thousandth of the curve's length (a name a rule announces may last only a short range of amounts:
// the inverse continuation of the W's dent gives "M+m+M+" between 0.086 and 0.095 only), bisection
// of the last step to the range's lower edge, then the middle of the range (found in 1 % steps): as
// far as can be from both edges, where a curvature sits at zero and round-off could flip a codon.
constexpr double kDriveGrowth = 1.03;

std::optional<std::pair<Curve2d, double>> driveUntil(const OperatorSetup& setup, double length, double cap,
                                                      const std::function<bool(const Curve2d&)>& done)
{
    const OperatorDrag drag(setup);
    double lo = 0.0, hi = 1e-3 * length;
    const double limit = cap > 0.0 ? cap : length;
    bool found = false;
    while (hi <= limit) {
        if (done(drag.at(hi))) {
            found = true;
            break;
        }
        lo = hi;
        hi *= kDriveGrowth;
    }
    if (!found) return std::nullopt;
    for (int i = 0; i < 30; ++i) {  // 30 halvings: 1e-9 of the step
        const double mid = 0.5 * (lo + hi);
        (done(drag.at(mid)) ? hi : lo) = mid;
    }
    double top = hi;
    while (top < std::min(2.0 * hi, limit) && done(drag.at(top * 1.01))) top *= 1.01;
    const double middle = 0.5 * (hi + top);
    if (done(drag.at(middle))) return std::make_pair(drag.at(middle), middle);
    return std::make_pair(drag.at(hi), hi);
}

std::vector<PointKind> kindsOf(const CurveAnalysis& a)
{
    std::vector<PointKind> k;
    for (const auto& p : a.points) k.push_back(p.kind);
    return k;
}

// The kinds a rule (or its inverse) announces at point i: the point replaced by the rule's triple,
// or the triple around it by the one point the inverse leaves.
std::vector<PointKind> announcedKinds(const CurveAnalysis& a, Rule rule, int i, bool inverse)
{
    const PointKind k = ruleKind(rule), mid = producedKind(rule);
    const bool continuation = isContinuation(rule);
    const std::vector<PointKind> triple = continuation ? std::vector<PointKind>{PointKind::Inflection, mid, PointKind::Inflection}
                                                       : std::vector<PointKind>{k, mid, k};
    std::vector<PointKind> kinds = kindsOf(a);
    const int n = static_cast<int>(kinds.size());
    if (!inverse) {
        kinds.erase(kinds.begin() + i);
        kinds.insert(kinds.begin() + i, triple.begin(), triple.end());
        return kinds;
    }
    // Inverse: i - 1, i, i + 1 (cyclic on closed curves) become k.
    std::vector<PointKind> out;
    for (int j = 0; j < n; ++j) {
        const int d = a.closed ? std::min((j - i + n) % n, (i - j + n) % n) : std::abs(j - i);
        if (d == 0) out.push_back(k);
        else if (d > 1) out.push_back(kinds[j]);
    }
    return out;
}

// The curve's name is `name` (a curve that cannot be analysed, collapsed by a huge amount, has none).
bool named(const Curve2d& c, const std::string& name)
{
    try {
        return nameOf(c) == name;
    } catch (const GeometryError&) {
        return false;
    }
}

double visibility(const Characteristics& ch) { return (ch.dLeft + ch.dRight) * 0.5 * (std::abs(ch.dkLeft) + std::abs(ch.dkRight)); }

// A straightening step's drive: `curve` becomes the setup's curve at the smallest amount that gives
// `expected`; the amount and the knots inserted are added up. False when no amount does.
bool driveToName(const OperatorSetup& s, double length, double cap, const std::string& expected, Curve2d& curve, double& used,
                 int& inserted)
{
    const auto r = driveUntil(s, length, cap, [&](const Curve2d& c) { return named(c, expected); });
    if (!r) return false;
    curve = r->first;
    used += r->second;
    inserted += s.insertedKnots;
    return true;
}

// One straightening step: the extremum between two inflections with the smallest visibility (or,
// with `flaggedOnly`, only one flagged small) flattened by the inverse continuation until its two
// inflections are gone. Returns false when there is none or it cannot be done.
bool removeUndulation(Curve2d& curve, const Thresholds& t, bool flaggedOnly, double cap, double& used, int& inserted)
{
    const CurveAnalysis a = analyzeCurve(curve, t);
    const int n = static_cast<int>(a.points.size());
    const Characteristics* best = nullptr;
    for (const auto& ch : a.characteristics) {
        const int i = ch.point;
        const bool between = (a.closed || (i > 0 && i + 1 < n)) && n >= 3 &&
                             a.points[(i + n - 1) % n].kind == PointKind::Inflection &&
                             a.points[(i + 1) % n].kind == PointKind::Inflection;
        if (!between || (flaggedOnly && !ch.smallVisibility)) continue;
        if (!best || visibility(ch) < visibility(*best)) best = &ch;
    }
    if (!best) return false;
    // The inverse continuation of 0m-0 (Cm+) or 0M+0 (CM-); an m+ or M- between inflections (the
    // neighbours' kinds say the curve turns the other way around it) is flattened toward its own
    // centre with the same constraints.
    const PointKind k = a.points[best->point].kind;
    const auto setup = [&]() {
        if (k == PointKind::MinNegative || k == PointKind::MaxPositive) {
            return ruleSetup(curve, a, k == PointKind::MinNegative ? Rule::CmPlus : Rule::CMMinus, best->point, true);
        }
        const double u = a.points[best->point].u;
        const double uL = neighbourParameter(curve, a, best->point, -2), uR = neighbourParameter(curve, a, best->point, 2);
        return finish(curve,
                      {{ConstraintType::Position, u, frameAt(curve, u).normal},
                       {ConstraintType::Position, uL, Vec::Zero()},
                       {ConstraintType::Position, uR, Vec::Zero()}},
                      uL, uR, best->point);
    };
    const OperatorSetup s = setup();
    // Announced: the 0X0 codon becomes one point of the opposite kind (0m-0 -> m+, 0M+0 -> M-).
    const std::string expected = [&] {
        std::vector<PointKind> k = kindsOf(a);
        const int i = best->point;
        std::vector<PointKind> out;
        for (int j = 0; j < n; ++j) {
            const int d = a.closed ? std::min((j - i + n) % n, (i - j + n) % n) : std::abs(j - i);
            if (d == 0) out.push_back(signFlipped(k[i]));
            else if (d > 1) out.push_back(k[j]);
        }
        return curveName(out, a.closed);
    }();
    return driveToName(s, a.length, cap, expected, curve, used, inserted);
}

// One redundancy step: the middle extremum of "M+m+M+" (or m+M+m+, m-M-m-, M-m-M-) with the
// smallest visibility raised (or lowered) to its neighbours by the inverse bifurcation until two
// extrema are gone.
bool removeRedundant(Curve2d& curve, const Thresholds& t, double cap, double& used, int& inserted)
{
    const CurveAnalysis a = analyzeCurve(curve, t);
    const Characteristics* best = nullptr;
    const int n = static_cast<int>(a.points.size());
    for (const auto& ch : a.characteristics) {
        const int i = ch.point;
        if (!a.closed && (i == 0 || i + 1 >= n)) continue;
        if (n < 3) continue;
        const PointKind l = a.points[(i + n - 1) % n].kind, r = a.points[(i + 1) % n].kind, k = a.points[i].kind;
        const auto positive = [](PointKind x) { return x == PointKind::MaxPositive || x == PointKind::MinPositive; };
        if (l == PointKind::Inflection || r == PointKind::Inflection || positive(l) != positive(k) || positive(r) != positive(k)) continue;
        if (!best || visibility(ch) < visibility(*best)) best = &ch;
    }
    if (!best) return false;
    const PointKind k = a.points[best->point].kind;
    // The inverse of the bifurcation that made this middle point (producedKind).
    Rule rule = Rule::BMPlus;  // an m+ between two M+
    if (k == PointKind::MaxNegative) rule = Rule::BmMinus;
    if (k == PointKind::MaxPositive) rule = Rule::BmPlus;
    if (k == PointKind::MinNegative) rule = Rule::BMMinus;
    const OperatorSetup s = ruleSetup(curve, a, rule, best->point, true);
    const std::string expected = curveName(announcedKinds(a, rule, best->point, true), a.closed);
    return driveToName(s, a.length, cap, expected, curve, used, inserted);
}

}  // namespace

const char* ruleName(Rule r)
{
    switch (r) {
    case Rule::CmPlus: return "Cm+";
    case Rule::CMMinus: return "CM-";
    case Rule::BMPlus: return "BM+";
    case Rule::BmMinus: return "Bm-";
    case Rule::BmPlus: return "Bm+";
    case Rule::BMMinus: return "BM-";
    }
    return "?";
}

std::optional<Rule> parseRule(const std::string& name)
{
    for (Rule r : {Rule::CmPlus, Rule::CMMinus, Rule::BMPlus, Rule::BmMinus, Rule::BmPlus, Rule::BMMinus}) {
        if (name == ruleName(r)) return r;
    }
    return std::nullopt;
}

const char* operatorName(Operator o)
{
    switch (o) {
    case Operator::Straighten: return "straighten";
    case Operator::Soften: return "soften";
    case Operator::Sharpen: return "sharpen";
    case Operator::Convex: return "convex";
    case Operator::Concave: return "concave";
    case Operator::Tension: return "tension";
    case Operator::Accelerate: return "accelerate";
    }
    return "?";
}

std::optional<Operator> parseOperator(const std::string& name)
{
    for (Operator o : {Operator::Straighten, Operator::Soften, Operator::Sharpen, Operator::Convex, Operator::Concave,
                       Operator::Tension, Operator::Accelerate}) {
        if (name == operatorName(o)) return o;
    }
    return std::nullopt;
}

PointKind ruleKind(Rule r)
{
    switch (r) {
    case Rule::CmPlus: return PointKind::MinPositive;
    case Rule::CMMinus: return PointKind::MaxNegative;
    case Rule::BMPlus: return PointKind::MaxPositive;
    case Rule::BmMinus: return PointKind::MinNegative;
    case Rule::BmPlus: return PointKind::MinPositive;
    case Rule::BMMinus: return PointKind::MaxNegative;
    }
    return PointKind::Inflection;
}

OperatorDrag::OperatorDrag(OperatorSetup setup) : setup_(std::move(setup))
{
    // The fairest change (thesis §7.2: the bar network's equilibrium, not the least control-point
    // change, which moves only the p + 1 points under each constraint and raises spikes): minimize the
    // bending of the displacement, sum |d_{i-1} - 2 d_i + d_{i+1}|^2 over the control polygon (cyclic
    // on closed curves; blocked points take part with d = 0, so the change fades smoothly into what
    // does not move), plus kTieBreak |d|^2, subject to F d = target - F p. The KKT matrix
    // [Q F^T; F 0] is factored once by a complete orthogonal decomposition (a dependent or
    // contradictory constraint set gets the least-squares compromise instead of a singular solve),
    // and its solution map G (free x rows) kept: each event is d = G b.
    const Curve2d& c = setup_.curve;
    const int n = uniqueCount(c), rows = static_cast<int>(setup_.constraints.size());
    std::vector<bool> blocked(n, false);
    for (int b : setup_.blocked) blocked[b] = true;
    for (int i = 0; i < n; ++i) {
        if (!blocked[i]) free_.push_back(i);
    }
    const int m = static_cast<int>(free_.size());
    std::vector<int> column(n, -1);
    for (int k = 0; k < m; ++k) column[free_[k]] = k;
    Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(m, m);
    const auto addSecondDifference = [&](int a, int b, int cc) {
        const int idx[3] = {a, b, cc};
        const double w[3] = {1.0, -2.0, 1.0};
        for (int x = 0; x < 3; ++x)
            for (int y = 0; y < 3; ++y)
                if (column[idx[x]] >= 0 && column[idx[y]] >= 0) Q(column[idx[x]], column[idx[y]]) += w[x] * w[y];
    };
    if (c.isClosed()) {
        for (int i = 0; i < n; ++i) addSecondDifference((i + n - 1) % n, i, (i + 1) % n);
    } else {
        for (int i = 1; i + 1 < n; ++i) addSecondDifference(i - 1, i, i + 1);
    }
    // A tie-break far below the bending terms (which are O(1)): it fixes the displacement's
    // otherwise free linear part where no constraint and no blocked point pins it.
    constexpr double kTieBreak = 1e-8;
    Q.diagonal().array() += kTieBreak;
    Eigen::MatrixXd F(rows, m);
    for (int j = 0; j < rows; ++j) {
        const Eigen::VectorXd full = editing::constraintRow(c, setup_.constraints[j]);
        for (int k = 0; k < m; ++k) F(j, k) = full[free_[k]];
    }
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(m + rows, m + rows);
    K.topLeftCorner(m, m) = Q;
    K.topRightCorner(m, rows) = F.transpose();
    K.bottomLeftCorner(rows, m) = F;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(m + rows, rows);
    rhs.bottomRows(rows).setIdentity();
    const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(K);
    G_ = cod.solve(rhs).topRows(m);
    F_ = F;
}

Curve2d OperatorDrag::at(double lambda, editing::ManipulationReport* report) const
{
    const Curve2d& c = setup_.curve;
    const int rows = static_cast<int>(setup_.constraints.size());
    Eigen::MatrixXd b(rows, 2);
    for (int j = 0; j < rows; ++j) b.row(j) = (lambda * setup_.direction[j]).transpose();
    const Eigen::MatrixXd d = G_ * b;
    std::vector<Vec> pts = c.points();
    const int n = uniqueCount(c);
    for (size_t k = 0; k < free_.size(); ++k) pts[free_[k]] += d.row(k).transpose();
    for (int i = n; i < c.pointCount(); ++i) pts[i] = pts[i - n];  // a closed curve's repeated points
    Curve2d out(c.degree(), c.knots(), pts, c.weights(), c.isClosed());
    if (report) {
        const Eigen::MatrixXd residual = F_ * d - b;
        report->constraintRows = rows;
        report->freePoints = static_cast<int>(free_.size());
        report->residuals.clear();
        report->maxResidual = 0.0;
        for (int j = 0; j < rows; ++j) {
            report->residuals.push_back(residual.row(j).norm());
            report->maxResidual = std::max(report->maxResidual, report->residuals.back());
        }
        // Met to round-off of the geometry's size, or a compromise (dependent constraints asking
        // for different things).
        report->compromise = report->maxResidual > 1e-9 * std::max(1.0, c.controlSize());
        report->message = report->compromise ? "the constraints cannot all be met; the closest compromise is shown" : "";
    }
    return out;
}

OperatorSetup ruleSetup(const Curve2d& curve, const CurveAnalysis& a, Rule rule, int at, bool inverse)
{
    checkSize(curve);
    checkPoint(a, at);
    const PointKind want = inverse ? producedKind(rule) : ruleKind(rule);
    if (a.points[at].kind != want) {
        throw GeometryError(std::string("at: point ") + std::to_string(at) + " is " + codon(a.points[at].kind) + "; " +
                            (inverse ? "the inverse of " : "") + ruleName(rule) + " applies to " + codon(want));
    }
    // Toward the centre of curvature for the continuations and the bifurcations of a |kappa|
    // maximum; away for those of a |kappa| minimum. An inverse bifurcation goes the other way; an
    // inverse continuation flattens the point the continuation made, toward its own centre.
    const bool flattens = isContinuation(rule) || rule == Rule::BMPlus || rule == Rule::BmMinus;
    const double sign = (inverse && !isContinuation(rule)) ? (flattens ? -1.0 : 1.0) : (flattens ? 1.0 : -1.0);
    const double u = a.points[at].u;
    // A rule holds the neighbouring characteristic points and moves nothing beyond them. An inverse
    // removes its neighbours (two inflections, or two extrema merged into it): it holds the points
    // beyond those, which survive, and lets the curve move up to the points beyond them in turn.
    const int hold = inverse ? 2 : 1, reach = inverse ? 3 : 1;
    double from = neighbourParameter(curve, a, at, -reach), to = neighbourParameter(curve, a, at, reach);
    double holdL = neighbourParameter(curve, a, at, -hold), holdR = neighbourParameter(curve, a, at, hold);
    if (!inverse && (rule == Rule::BMPlus || rule == Rule::BmMinus) && !curve.isClosed()) {
        // Flattening a |kappa| maximum into two (thesis Fig. 7-6: the points O2, O3 beside M1+ fixed)
        // is local: the point's range of influence (§7.3.2) is held at its edges, so the curvature
        // the flattened tip loses piles up there. Held at the neighbours instead, the fairest change
        // bends the whole segment and the extremum stays one.
        for (const auto& ch : a.characteristics) {
            if (ch.point != at) continue;
            const ArcLengthParameterization<2> arc(curve);
            from = holdL = std::max(from, arc.parameterAt(a.points[at].arcLength - ch.rangeLeft));
            to = holdR = std::min(to, arc.parameterAt(a.points[at].arcLength + ch.rangeRight));
        }
    }
    std::vector<Spec> specs{{ConstraintType::Position, u, sign * frameAt(curve, u).normal},
                            {ConstraintType::Position, holdL, Vec::Zero()},
                            {ConstraintType::Position, holdR, Vec::Zero()}};
    // Where the segment reaches an end of an open curve, the end is held too (inside, its edges
    // hold by themselves: nothing beyond them moves).
    if (from != holdL) specs.push_back({ConstraintType::Position, from, Vec::Zero()});
    if (to != holdR) specs.push_back({ConstraintType::Position, to, Vec::Zero()});
    return finish(curve, specs, from, to, at);
}

std::optional<double> ruleAmount(const Curve2d& curve, Rule rule, int at, bool inverse, const Thresholds& thresholds)
{
    const CurveAnalysis a = analyzeCurve(curve, thresholds);
    const OperatorSetup s = ruleSetup(curve, a, rule, at, inverse);
    Curve2d result = curve;
    double amount = 0.0;
    int inserted = 0;
    if (!driveToName(s, a.length, 0.0, curveName(announcedKinds(a, rule, at, inverse), a.closed), result, amount, inserted)) {
        return std::nullopt;
    }
    return amount;
}

std::string announcedName(const CurveAnalysis& a, Rule rule, int at, bool inverse)
{
    checkPoint(a, at);
    return curveName(announcedKinds(a, rule, at, inverse), a.closed);
}

OperatorResult applyRule(const Curve2d& curve, Rule rule, int at, double lambda, bool inverse, const Thresholds& thresholds)
{
    if (!std::isfinite(lambda) || lambda < 0.0) throw GeometryError("amount: must be a finite number >= 0");
    const CurveAnalysis before = analyzeCurve(curve, thresholds);
    const OperatorSetup s = ruleSetup(curve, before, rule, at, inverse);
    OperatorResult r{OperatorDrag(s).at(lambda), before.name, "", before.measures, {}, s.insertedKnots, lambda, {}, ""};
    const CurveAnalysis after = analyzeCurve(r.curve, thresholds);
    r.nameAfter = after.name;
    r.measuresAfter = after.measures;
    return r;
}

OperatorSetup operatorSetup(const Curve2d& curve, const CurveAnalysis& a, Operator op, const OperatorOptions& o)
{
    checkSize(curve);
    const int n = static_cast<int>(a.points.size());
    const double u0 = curve.domainStart(), u1 = curve.domainEnd();
    const auto extremumWhere = [&](const std::function<bool(const CharacteristicPoint&)>& ok,
                                   const std::function<double(const CharacteristicPoint&)>& score) {
        if (o.at) {
            checkPoint(a, *o.at);
            if (!ok(a.points[*o.at])) {
                throw GeometryError("at: point " + std::to_string(*o.at) + " (" + codon(a.points[*o.at].kind) + ") is not one " +
                                    operatorName(op) + " applies to");
            }
            return *o.at;
        }
        int best = -1;
        for (int i = 0; i < n; ++i) {
            if (ok(a.points[i]) && (best < 0 || score(a.points[i]) > score(a.points[best]))) best = i;
        }
        return best;
    };
    std::vector<Spec> specs;
    const auto fixEnds = [&] {
        if (curve.isClosed()) return;
        specs.push_back({ConstraintType::Position, u0, Vec::Zero()});
        specs.push_back({ConstraintType::Position, u1, Vec::Zero()});
    };
    switch (op) {
    case Operator::Soften:
    case Operator::Sharpen: {
        // C*M+ or C*m- on the |kappa| maximum: toward its centre (soften) or away (sharpen), with the
        // neighbours' positions and tangents fixed: no new extrema (Fig. 7-18).
        const int i = extremumWhere(
            [](const CharacteristicPoint& p) { return p.kind == PointKind::MaxPositive || p.kind == PointKind::MinNegative; },
            [](const CharacteristicPoint& p) { return std::abs(p.curvature); });
        if (i < 0) throw GeometryError(std::string(operatorName(op)) + ": the curve has no M+ or m- extremum (named \"" + a.name + "\")");
        const double u = a.points[i].u;
        bool endL = false, endR = false;
        const double uL = neighbourParameter(curve, a, i, -1, &endL), uR = neighbourParameter(curve, a, i, 1, &endR);
        const double sign = op == Operator::Soften ? 1.0 : -1.0;
        specs = {{ConstraintType::Position, u, sign * frameAt(curve, u).normal},
                 {ConstraintType::Position, uL, Vec::Zero()},
                 {ConstraintType::Tangent, uL, Vec::Zero()},
                 {ConstraintType::Position, uR, Vec::Zero()},
                 {ConstraintType::Tangent, uR, Vec::Zero()}};
        return finish(curve, specs, uL, uR, i);
    }
    case Operator::Convex:
    case Operator::Concave: {
        if (curve.isClosed()) throw GeometryError(std::string(operatorName(op)) + ": needs an open curve (it acts across the chord)");
        // The point farthest from the chord (an extremum when there is one) moves along the chord's
        // perpendicular, out (convex) or in (concave); inflections beside it follow along their normals,
        // D_L / (D_L + D_R) and D_R / (D_L + D_R) of the amount (thesis: lambda_L = D_L, lambda_R = D_R).
        const Vec p0 = curve.evaluate(u0), chord = curve.evaluate(u1) - p0;
        if (chord.norm() <= 1e-12 * a.length) throw GeometryError(std::string(operatorName(op)) + ": the curve's ends coincide (no chord)");
        const Vec perp = Vec(-chord.y(), chord.x()).normalized();
        const auto height = [&](double u) { return perp.dot(curve.evaluate(u) - p0); };
        int i = extremumWhere([](const CharacteristicPoint& p) { return p.kind != PointKind::Inflection; },
                              [&](const CharacteristicPoint& p) { return std::abs(height(p.u)); });
        double u;
        if (i >= 0) {
            u = a.points[i].u;
        } else {
            // No extremum: the crown point, by sampling.
            u = u0;
            for (int k = 0; k <= 256; ++k) {
                const double v = u0 + (u1 - u0) * k / 256;
                if (std::abs(height(v)) > std::abs(height(u))) u = v;
            }
        }
        const double side = height(u) >= 0.0 ? 1.0 : -1.0;
        const Vec out = side * perp * (op == Operator::Convex ? 1.0 : -1.0);
        specs.push_back({ConstraintType::Position, u, out});
        fixEnds();
        if (i >= 0) {
            const bool infL = i > 0 && a.points[i - 1].kind == PointKind::Inflection;
            const bool infR = i + 1 < n && a.points[i + 1].kind == PointKind::Inflection;
            const double dL = infL ? a.points[i].arcLength - a.points[i - 1].arcLength : 0.0;
            const double dR = infR ? a.points[i + 1].arcLength - a.points[i].arcLength : 0.0;
            const auto follow = [&](int j, double weight) {
                const Frame f = frameAt(curve, a.points[j].u);
                Vec nrm(-f.tangent.y(), f.tangent.x());
                if (nrm.dot(out) < 0.0) nrm = -nrm;
                specs.push_back({ConstraintType::Position, a.points[j].u, weight * out.norm() * nrm});
            };
            if (infL) follow(i - 1, dL / (dL + dR));
            if (infR) follow(i + 1, dR / (dL + dR));
        }
        return finish(curve, specs, u0, u1, i);
    }
    case Operator::Tension: {
        // C*m+ (C*M-): the |kappa| minimum between two maxima flattened toward kappa = 0, ends fixed
        // (Fig. 7-20); the maxima around it rise.
        const int i = extremumWhere(
            [&](const CharacteristicPoint& p) { return p.kind == PointKind::MinPositive || p.kind == PointKind::MaxNegative; },
            [](const CharacteristicPoint& p) { return -std::abs(p.curvature); });
        if (i < 0) throw GeometryError("tension: the curve has no m+ or M- (a curvature minimum between maxima; named \"" + a.name + "\")");
        const double period = u1 - u0, u = a.points[i].u;
        specs.push_back({ConstraintType::Position, u, frameAt(curve, u).normal});
        fixEnds();
        return curve.isClosed() ? finish(curve, specs, u - 0.5 * period, u + 0.5 * period, i) : finish(curve, specs, u0, u1, i);
    }
    case Operator::Accelerate: {
        if (curve.isClosed()) throw GeometryError("accelerate: needs an open curve (it raises one end's tangent)");
        // The moving end keeps its point and its tangent's direction; the tangent's handle (the second
        // control point from that end) moves lambda inward along it, so C' grows by lambda times the
        // handle's coefficient in C'; the other end keeps point and tangent (Fig. 7-21).
        const double ue = o.atEnd ? u1 : u0, us = o.atEnd ? u0 : u1;
        const CurveConstraint<2> probe{ConstraintType::Tangent, ue, 0.0, Vec::Zero()};
        const Eigen::VectorXd row = editing::constraintRow(curve, probe);
        const int handle = o.atEnd ? curve.pointCount() - 2 : 1;
        const Vec t = frameAt(curve, ue).tangent;
        const double grow = std::abs(row[handle]);
        specs = {{ConstraintType::Position, ue, Vec::Zero()},
                 {ConstraintType::Tangent, ue, grow * t},
                 {ConstraintType::Position, us, Vec::Zero()},
                 {ConstraintType::Tangent, us, Vec::Zero()}};
        return finish(curve, specs, u0, u1, -1);
    }
    case Operator::Straighten: break;
    }
    throw GeometryError("operator: straighten is a sequence of steps, not one drag (applyOperator)");
}

OperatorResult applyOperator(const Curve2d& curve, Operator op, double amount, const OperatorOptions& o)
{
    if (!std::isfinite(amount) || amount < 0.0) throw GeometryError("amount: must be a finite number >= 0");
    checkSize(curve);
    const CurveAnalysis before = analyzeCurve(curve, o.thresholds);
    OperatorResult r{curve, before.name, before.name, before.measures, before.measures, 0, 0.0, {}, ""};
    Curve2d c = curve;
    if (op == Operator::Straighten) {
        // Fig. 7-17: undulations (0X0 codons, smallest visibility first) by inverse continuations,
        // then redundant extrema (M+m+M+ -> M+) by inverse bifurcations, each step driven until its
        // codons are gone.
        for (int step = 0; step < kMaxStraightenSteps; ++step) {
            if (!removeUndulation(c, o.thresholds, false, amount, r.amount, r.insertedKnots) &&
                !removeRedundant(c, o.thresholds, amount, r.amount, r.insertedKnots)) {
                break;
            }
            r.names.push_back(analyzeCurve(c, o.thresholds).name);
        }
    } else {
        // Convex, concave and tension first remove the undulations flagged small (§7.4).
        if (op == Operator::Convex || op == Operator::Concave || op == Operator::Tension) {
            double unused = 0.0;
            for (int step = 0; step < 8 && removeUndulation(c, o.thresholds, true, 0.0, unused, r.insertedKnots); ++step) {
                r.names.push_back(analyzeCurve(c, o.thresholds).name);
            }
        }
        const CurveAnalysis a = analyzeCurve(c, o.thresholds);
        const OperatorSetup s = operatorSetup(c, a, op, o);
        const OperatorDrag drag(s);
        editing::ManipulationReport report;
        Curve2d moved = drag.at(amount, &report);
        double used = amount;
        // These operators change measures, not names (§7.4: no new characteristic points): beyond the
        // largest amount that keeps the name, the amount is limited to it (bisection, 40 halvings).
        if (!named(moved, a.name)) {
            double lo = 0.0, hi = amount;
            for (int i = 0; i < 40; ++i) {
                const double mid = 0.5 * (lo + hi);
                (named(drag.at(mid), a.name) ? lo : hi) = mid;
            }
            used = lo;
            moved = drag.at(used, &report);
            r.message = std::string(operatorName(op)) + ": amount limited to " + std::to_string(used) + " (of " +
                        std::to_string(amount) + "); more would change the name \"" + a.name + "\"";
        }
        c = moved;
        r.insertedKnots += s.insertedKnots;
        r.amount = used;
        if (report.compromise) r.message += (r.message.empty() ? "" : "; ") + report.message;
    }
    r.curve = c;
    const CurveAnalysis after = analyzeCurve(c, o.thresholds);
    r.nameAfter = after.name;
    r.measuresAfter = after.measures;
    return r;
}

}  // namespace sculptline::solvers::aesthetics
