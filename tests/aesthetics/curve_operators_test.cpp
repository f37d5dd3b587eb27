// Aesthetic operators (thesis §7.2, §7.4, §7.5): each rule and operator on curves whose names are
// known exactly (polynomial graphs y = f(x) represented exactly as Bezier curves, then refined), and
// what each promises: the name after, the end points, what must not move.
#include "solvers/aesthetics/curve_operators.h"

#include "solvers/bspline/geometry_error.h"
#include "tests/aesthetics/graph_curves.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace {

using namespace sculptline::solvers;
using namespace sculptline::solvers::aesthetics;
namespace testcurves = sculptline::testcurves;




Curve2d mirrored(const Curve2d& c)
{
    std::vector<Eigen::Vector2d> pts;
    for (const auto& p : c.points()) pts.emplace_back(p.x(), -p.y());
    return Curve2d(c.degree(), c.knots(), pts, c.weights(), c.isClosed());
}

// "M+0m-0M+": a W, two convex valleys and a bump between (Fig. 7-17's black curve).
Curve2d wCurve() { return testcurves::figure717(); }
// "M+m+M+": a flat-bottomed valley.
Curve2d flatValley() { return testcurves::flatValley(); }
// "M+": a parabola, as a cubic (C2 at its knots, as designers' curves are: a quadratic's curvature
// jumps at every knot a change puts into it).
Curve2d parabola() { return testcurves::polynomialGraph([](double x) { return x * x; }, -1.0, 1.0, 3, 8); }

// Evaluations of two curves at the same parameters agree to this (model units): knot insertion
// and unmoved control points reproduce a curve to round-off of its coordinates (about 1).
constexpr double kSame = 1e-12;

double maxDistance(const Curve2d& a, const Curve2d& b, double u0, double u1)
{
    double d = 0.0;
    for (int k = 0; k <= 200; ++k) {
        const double u = u0 + (u1 - u0) * k / 200;
        d = std::max(d, (a.evaluate(u) - b.evaluate(u)).norm());
    }
    return d;
}

void expectEndsKept(const Curve2d& before, const Curve2d& after)
{
    EXPECT_LT((before.evaluate(before.domainStart()) - after.evaluate(after.domainStart())).norm(), kSame);
    EXPECT_LT((before.evaluate(before.domainEnd()) - after.evaluate(after.domainEnd())).norm(), kSame);
}

TEST(CurveOperators, GivenFigure717sCurve_WhenStraightened_ThenItsNamesGoMplus0mminus0MplusToMplusmplusMplusToMplus)
{
    // Arrange
    const Curve2d w = wCurve();
    ASSERT_EQ(analyzeCurve(w).name, "M+0m-0M+");
    // Act
    const OperatorResult r = applyOperator(w, Operator::Straighten, 0.0);
    // Assert: the undulation 0m-0 goes first (inverse continuation), then the redundant extrema
    // (inverse bifurcation), as thesis Fig. 7-17.
    EXPECT_EQ(r.nameBefore, "M+0m-0M+");
    ASSERT_EQ(r.names.size(), 2u);
    EXPECT_EQ(r.names[0], "M+m+M+");
    EXPECT_EQ(r.names[1], "M+");
    EXPECT_EQ(r.nameAfter, "M+");
    expectEndsKept(w, r.curve);
    EXPECT_TRUE(r.message.empty()) << r.message;
    // Straighter: the curvature's spread falls.
    EXPECT_LT(r.measuresAfter.curvatureMax - r.measuresAfter.curvatureMin,
              r.measuresBefore.curvatureMax - r.measuresBefore.curvatureMin);
}

struct RuleCase {
    Rule rule;
    const char* curve;
    int at;
    const char* before;
    const char* after;
};

Curve2d byName(const std::string& n)
{
    if (n == "flatValley") return flatValley();
    if (n == "parabola") return parabola();
    if (n == "-flatValley") return mirrored(flatValley());
    return mirrored(parabola());
}

class RuleTest : public ::testing::TestWithParam<RuleCase> {};

// Each rule, at the smallest amount that gives its announced name, gives it; the blocked neighbours
// (here the ends or the points beyond them) keep their places and nothing outside moves.
TEST_P(RuleTest, GivenItsKind_WhenApplied_ThenTheAnnouncedNameAndTheEndsKept)
{
    // Arrange
    const RuleCase& c = GetParam();
    const Curve2d curve = byName(c.curve);
    const CurveAnalysis a = analyzeCurve(curve);
    ASSERT_EQ(a.name, c.before);
    EXPECT_EQ(announcedName(a, c.rule, c.at, false), c.after);
    // Act
    const std::optional<double> amount = ruleAmount(curve, c.rule, c.at, false);
    ASSERT_TRUE(amount.has_value()) << ruleName(c.rule);
    const OperatorResult r = applyRule(curve, c.rule, c.at, *amount, false);
    // Assert
    EXPECT_EQ(r.nameAfter, c.after) << ruleName(c.rule) << " at " << *amount;
    expectEndsKept(curve, r.curve);
    // The displaced point moved by the amount along the principal normal.
    const OperatorSetup s = ruleSetup(curve, a, c.rule, c.at, false);
    EXPECT_NEAR((r.curve.evaluate(a.points[c.at].u) - curve.evaluate(a.points[c.at].u)).norm(), *amount, 1e-9);
    // Outside the operated segment nothing moves.
    if (s.u0 > curve.domainStart()) {
        EXPECT_LT(maxDistance(curve, r.curve, curve.domainStart(), s.u0), kSame);
    }
    if (s.u1 < curve.domainEnd()) {
        EXPECT_LT(maxDistance(curve, r.curve, s.u1, curve.domainEnd()), kSame);
    }
    // The inverse at the new middle point brings the original name back.
    const CurveAnalysis after = analyzeCurve(r.curve);
    // The name matched: the rule's triple replaced point `at`, its middle is point at + 1.
    const int middle = c.at + 1;
    ASSERT_EQ(after.points.size(), a.points.size() + 2);
    const std::optional<double> back = ruleAmount(r.curve, c.rule, middle, true);
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(applyRule(r.curve, c.rule, middle, *back, true).nameAfter, c.before);
}

INSTANTIATE_TEST_SUITE_P(
    LeytonsRules, RuleTest,
    ::testing::Values(RuleCase{Rule::CmPlus, "flatValley", 1, "M+m+M+", "M+0m-0M+"},
                      RuleCase{Rule::CMMinus, "-flatValley", 1, "m-M-m-", "m-0M+0m-"},
                      RuleCase{Rule::BMPlus, "parabola", 0, "M+", "M+m+M+"},
                      RuleCase{Rule::BmMinus, "-parabola", 0, "m-", "m-M-m-"},
                      RuleCase{Rule::BmPlus, "flatValley", 1, "M+m+M+", "M+m+M+m+M+"},
                      RuleCase{Rule::BMMinus, "-flatValley", 1, "m-M-m-", "m-M-m-M-m-"}),
    [](const ::testing::TestParamInfo<RuleCase>& i) {
        std::string n = ruleName(i.param.rule);
        for (char& ch : n) ch = ch == '+' ? 'P' : ch == '-' ? 'N' : ch;
        return n;
    });

TEST(CurveOperators, GivenAWrongKind_WhenARuleIsApplied_ThenItSaysWhichKindTheRuleNeeds)
{
    const Curve2d c = flatValley();  // M+ m+ M+
    EXPECT_THROW(applyRule(c, Rule::CmPlus, 0, 0.1, false), GeometryError);  // Cm+ needs an m+
    EXPECT_THROW(applyRule(c, Rule::BMPlus, 5, 0.1, false), GeometryError);  // no point 5
    EXPECT_THROW(applyRule(c, Rule::CmPlus, 1, -1.0, false), GeometryError);
    try {
        applyRule(c, Rule::CMMinus, 1, 0.1, false);
        FAIL();
    } catch (const GeometryError& e) {
        EXPECT_NE(std::string(e.what()).find("applies to M-"), std::string::npos) << e.what();
    }
}

// soften / sharpen (C*M+): the M+ with the greatest curvature flattened or sharpened, its neighbours
// (an end and the m+) holding place and tangent: no new characteristic point.
TEST(CurveOperators, GivenAValley_WhenSoftenedOrSharpened_ThenItsCornerCurvatureFallsOrRisesAndTheNameStays)
{
    // Arrange
    const Curve2d c = flatValley();
    const CurveAnalysis a = analyzeCurve(c);
    for (Operator op : {Operator::Soften, Operator::Sharpen}) {
        // Act
        OperatorOptions o;
        o.at = 0;  // the first M+ (both are equally sharp)
        const OperatorResult r = applyOperator(c, op, 0.01, o);
        // Assert
        EXPECT_EQ(r.nameAfter, "M+m+M+") << operatorName(op);
        expectEndsKept(c, r.curve);
        const CurveAnalysis b = analyzeCurve(r.curve);
        ASSERT_EQ(b.points.size(), 3u);
        const double k0 = a.points[0].curvature, k1 = b.points[0].curvature;
        if (op == Operator::Soften) {
            EXPECT_LT(k1, k0);
        } else {
            EXPECT_GT(k1, k0);
        }
        // The neighbours' places and tangents are kept.
        for (double u : {c.domainStart(), a.points[1].u}) {
            EXPECT_LT((r.curve.derivatives(u, 1)[1] - c.derivatives(u, 1)[1]).norm(), 1e-9);
        }
        // The other half of the valley, beyond the m+, does not move.
        EXPECT_LT(maxDistance(c, r.curve, a.points[1].u + 0.13, c.domainEnd()), kSame);
    }
}

TEST(CurveOperators, GivenAnAmountThatWouldChangeTheName_WhenSharpened_ThenTheAmountIsLimitedAndSaid)
{
    const OperatorResult r = applyOperator(flatValley(), Operator::Sharpen, 0.5);
    EXPECT_EQ(r.nameAfter, "M+m+M+");
    EXPECT_LT(r.amount, 0.5);
    EXPECT_GT(r.amount, 0.0);
    EXPECT_NE(r.message.find("limited"), std::string::npos);
}

TEST(CurveOperators, GivenAValley_WhenConvexOrConcave_ThenTheCrownGrowsOrShrinksByTheAmount)
{
    const Curve2d c = flatValley();
    for (Operator op : {Operator::Convex, Operator::Concave}) {
        const OperatorResult r = applyOperator(c, op, 0.1);
        EXPECT_EQ(r.nameAfter, "M+m+M+") << operatorName(op);
        expectEndsKept(c, r.curve);
        // The valley's bottom (the crown point, the m+) moves 0.1 along the chord's perpendicular.
        const double grow = std::abs(r.measuresAfter.crown) - std::abs(r.measuresBefore.crown);
        EXPECT_NEAR(grow, op == Operator::Convex ? 0.1 : -0.1, 1e-3) << operatorName(op);
    }
}

TEST(CurveOperators, GivenAValley_WhenTensioned_ThenItsMiddleFlattensAndTheTensionRises)
{
    const Curve2d c = flatValley();
    const OperatorResult r = applyOperator(c, Operator::Tension, 0.05);
    EXPECT_EQ(r.nameAfter, "M+m+M+");
    expectEndsKept(c, r.curve);
    ASSERT_TRUE(r.measuresBefore.tension && r.measuresAfter.tension);
    EXPECT_GT(*r.measuresAfter.tension, *r.measuresBefore.tension);
    EXPECT_LT(analyzeCurve(r.curve).points[1].curvature, analyzeCurve(c).points[1].curvature);
}

TEST(CurveOperators, GivenACurve_WhenAccelerated_ThenTheEndTangentGrowsByTheHandleAndTheOtherEndIsStatic)
{
    const Curve2d c = flatValley();
    const double lambda = 0.05;
    const OperatorResult r = applyOperator(c, Operator::Accelerate, lambda);
    expectEndsKept(c, r.curve);
    const double u0 = c.domainStart(), u1 = c.domainEnd();
    // The static start keeps its tangent vector.
    EXPECT_LT((r.curve.derivatives(u0, 1)[1] - c.derivatives(u0, 1)[1]).norm(), 1e-9);
    // The end's tangent keeps its direction and grows by lambda times p / (end span's parameter length)
    // (a clamped end: C' = p / dt (P_n - P_{n-1})).
    const Eigen::Vector2d t0 = c.derivatives(u1, 1)[1], t1 = r.curve.derivatives(u1, 1)[1];
    EXPECT_NEAR(t0.normalized().dot(t1.normalized()), 1.0, 1e-12);
    const double dt = c.knots()[c.pointCount()] - c.knots()[c.pointCount() - 1];
    EXPECT_NEAR(t1.norm() - t0.norm(), lambda * c.degree() / dt, 1e-9);
}

TEST(CurveOperators, GivenABezierTooStiffForItsConstraints_WhenSoftened_ThenKnotsAreInsertedAndCounted)
{
    // Arrange: one cubic span (4 control points) cannot take soften's 5 constraints plus freedom.
    const Curve2d c = testcurves::polynomialGraph([](double x) { return x * x * x - x; }, -1.0, 0.2, 3, 1);
    const CurveAnalysis a = analyzeCurve(c);
    ASSERT_FALSE(a.characteristics.empty());
    const OperatorSetup s = operatorSetup(c, a, Operator::Soften, {});
    // Assert: knots inserted (the curve's shape unchanged by it), the segment free enough.
    EXPECT_GT(s.insertedKnots, 0);
    EXPECT_LT(maxDistance(c, s.curve, c.domainStart(), c.domainEnd()), kSame);
    EXPECT_GE(s.curve.pointCount() - static_cast<int>(s.blocked.size()), static_cast<int>(s.constraints.size()) + 2);
    // At amount 0 the drag gives the curve back.
    EXPECT_LT(maxDistance(s.curve, OperatorDrag(s).at(0.0), c.domainStart(), c.domainEnd()), kSame);
}

}  // namespace

namespace {

// A closed uniform cubic around a 16-gon inscribed in a 30 x 15 ellipse, its first vertex on the
// seam: soften acts on the M+ across the seam (the segment wraps) and keeps the name and everything
// beyond the neighbours. (The polygon's corners ripple the curvature: M+m+ eight times.)
TEST(CurveOperators, GivenAClosedCurve_WhenItsVertexAcrossTheSeamIsSoftened_ThenTheNameStaysAndTheFarSideDoesNotMove)
{
    // Arrange
    std::vector<Eigen::Vector2d> polygon;
    for (int i = 0; i < 16; ++i) polygon.emplace_back(30.0 * std::cos(2 * M_PI * i / 16), 15.0 * std::sin(2 * M_PI * i / 16));
    const Curve2d c = makeClosedUniform<2>(3, polygon);
    const CurveAnalysis a = analyzeCurve(c);
    ASSERT_EQ(a.name, "M+m+M+m+M+m+M+m+");
    const auto toSeam = [&](double u) { return std::min(u - c.domainStart(), c.domainEnd() - u); };
    int seamVertex = -1;  // the M+ nearest the seam (u = 0 or the period)
    for (size_t i = 0; i < a.points.size(); ++i) {
        if (a.points[i].kind != PointKind::MaxPositive) continue;
        if (seamVertex < 0 || toSeam(a.points[i].u) < toSeam(a.points[seamVertex].u)) seamVertex = static_cast<int>(i);
    }
    ASSERT_GE(seamVertex, 0);
    // Its neighbours lie on both sides of the seam: the operated segment wraps.
    const int n = static_cast<int>(a.points.size());
    ASSERT_TRUE(seamVertex == 0 || seamVertex == n - 1);
    OperatorOptions o;
    o.at = seamVertex;
    // Act
    const OperatorResult r = applyOperator(c, Operator::Soften, 0.2, o);
    // Assert
    EXPECT_EQ(r.nameAfter, a.name);
    const CurveAnalysis b = analyzeCurve(r.curve);
    ASSERT_EQ(b.points.size(), a.points.size());
    EXPECT_LT(b.points[seamVertex].curvature, a.points[seamVertex].curvature);
    // The opposite vertex (half a period away) and its neighbourhood do not move.
    const double half = 0.5 * (c.domainEnd() - c.domainStart());
    EXPECT_LT(maxDistance(c, r.curve, a.points[seamVertex].u + half - 2.0, a.points[seamVertex].u + half + 2.0), kSame);
    EXPECT_TRUE(r.curve.isClosed());
}

}  // namespace

namespace {

TEST(CurveOperators, GivenACurveAboveTheSizeLimit_WhenOperated_ThenRefusedNamingItsPoints)
{
    std::vector<Eigen::Vector2d> pts;
    for (int i = 0; i <= kMaxOperatorPoints; ++i) pts.emplace_back(i, std::sin(0.3 * i));
    const Curve2d big = makeClampedUniform<2>(3, pts);
    try {
        applyOperator(big, Operator::Straighten, 0.0);
        FAIL() << "a curve of " << pts.size() << " points was operated on";
    } catch (const GeometryError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("points: 201", 0), 0u) << e.what();
    }
    pts.pop_back();  // at the limit: analysed and operated on
    EXPECT_NO_THROW(applyOperator(makeClampedUniform<2>(3, pts), Operator::Soften, 0.01));
}

}  // namespace
