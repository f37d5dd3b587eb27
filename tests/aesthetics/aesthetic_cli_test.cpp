// sculptline-cli aesthetic, run as the real binary: Fig. 7-17's straightening in a tilted plane (the
// result stays in it), a rule at its announced amount, and clear refusals. Given / When / Then.
#include "solvers/aesthetics/curve_operators.h"
#include "tests/aesthetics/graph_curves.h"
#include "tests/cli/cli_runner.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace sculptline::cli_test;
namespace aes = sculptline::solvers::aesthetics;
using namespace sculptline::solvers;
namespace testcurves = sculptline::testcurves;

namespace {

const std::string kPrefix = "sculptline-cli: ";

// y = x^4 - 0.5 x^2 on [-1.2, 1.2] ("M+0m-0M+", thesis Fig. 7-17's black curve) as an exact quartic,
// 8 spans; placed in the plane through (0, 0, 2) spanned by x and (0, cos 0.4, sin 0.4).
Curve3d tiltedW()
{
    const Curve2d w = testcurves::figure717();
    const aes::PlaneFrame frame{{0, 0, 2}, {1, 0, 0}, {0, std::cos(0.4), std::sin(0.4)}};
    return aes::spaceCurve(w, frame);
}

TEST(AestheticCli, GivenFigure717sCurveInATiltedPlane_WhenStraightened_ThenMplusInThatPlaneWithTheEndsKept)
{
    // Arrange
    const Curve3d w = tiltedW();
    const json input{{"curve", io::toJson(w)}, {"operator", "straighten"}};
    // Act
    const json out = runOk("aesthetic", input);
    // Assert
    EXPECT_EQ(out["name_before"], "M+0m-0M+");
    EXPECT_EQ(out["names"], json({"M+m+M+", "M+"}));
    EXPECT_EQ(out["name_after"], "M+");
    const Curve3d after = io::curveFromJson(out["curve"], "curve");
    constexpr double kSame = 1e-9;  // printed shortest round-trip; the frame's rotation costs round-off
    EXPECT_LT((after.evaluate(after.domainStart()) - w.evaluate(w.domainStart())).norm(), kSame);
    EXPECT_LT((after.evaluate(after.domainEnd()) - w.evaluate(w.domainEnd())).norm(), kSame);
    // Still in the plane: every control point's distance from it is round-off.
    const Eigen::Vector3d n(0, -std::sin(0.4), std::cos(0.4));
    for (const auto& p : after.points()) EXPECT_NEAR((p - Eigen::Vector3d(0, 0, 2)).dot(n), 0.0, kSame);
    EXPECT_FALSE(out["measures_after"]["sharpness"].is_null());
}

TEST(AestheticCli, GivenAnMplus_WhenBMplusWithoutAnAmount_ThenTheSmallestAmountGivingItsName)
{
    // Arrange: the W's first M+ (point 0) after straightening is the lone M+ of a valley.
    const json straight = runOk("aesthetic", {{"curve", io::toJson(tiltedW())}, {"operator", "straighten"}});
    const json input{{"curve", straight["curve"]}, {"rule", "BM+"}, {"at", 0}};
    // Act
    const json out = runOk("aesthetic", input);
    // Assert
    EXPECT_EQ(out["announced"], "M+m+M+");
    EXPECT_EQ(out["name_after"], "M+m+M+");
    EXPECT_GT(out["amount"].get<double>(), 0.0);
}

TEST(AestheticCli, GivenImpossibleInput_WhenApplied_ThenExitTwoWithOneLineNamingTheField)
{
    const json w = io::toJson(tiltedW());
    struct Case {
        json input;
        std::string field;
    };
    json big = w;
    big["knots"] = json::array();
    big["points"] = json::array();
    for (int i = 0; i < 4; ++i) big["knots"].push_back(0.0);
    for (int i = 1; i < 198; ++i) big["knots"].push_back(i / 198.0);
    for (int i = 0; i < 4; ++i) big["knots"].push_back(1.0);
    for (int i = 0; i < 201; ++i) big["points"].push_back({i, std::sin(0.3 * i), 0.0});
    big.erase("degree");
    big["degree"] = 3;
    const Case cases[] = {
        {{{"curve", big}, {"operator", "straighten"}}, "curve.points: 201 control points"},
        {{{"curve", w}, {"operator", "smoothen"}, {"amount", 1}}, "operator: unknown"},
        {{{"curve", w}, {"operator", "soften"}}, "amount: missing"},
        {{{"curve", w}, {"operator", "soften"}, {"amount", -1}}, "amount"},
        {{{"curve", w}, {"rule", "Cm+"}, {"at", 0}, {"amount", 0.1}}, "at: point 0 is M+"},
        {{{"curve", w}, {"rule", "Xm+"}, {"at", 0}}, "rule: unknown"},
        {{{"curve", w}, {"rule", "Cm+"}}, "at: missing"},
        {{{"curve", w}, {"rule", "Cm+"}, {"at", 9}, {"amount", 0.1}}, "at: 9 is not"},
        {{{"curve", w}, {"operator", "accelerate"}, {"amount", 0.1}, {"end", "middle"}}, "end"},
        {{{"curve", w}, {"operator", "soften"}, {"rule", "Cm+"}, {"amount", 1}}, "operator: give exactly one"},
    };
    for (const Case& c : cases) {
        // Act
        const CliResult r = runCli({"aesthetic"}, c.input.dump());
        // Assert
        EXPECT_EQ(r.status, 2) << c.input.dump();
        EXPECT_EQ(r.err.rfind(kPrefix + c.field, 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
}

}  // namespace
