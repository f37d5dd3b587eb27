// sculptline-cli insert-knot: the result has the new knot and, evaluated by the kernel, the same
// shape as the input (Boehm insertion changes the representation only).
#include "cli_runner.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace sculptline::cli_test;
using sculptline::solvers::Curve3d;
using sculptline::solvers::Surface3d;
namespace io = sculptline::solvers::io;

namespace {
constexpr double kSameShape = 1e-12;

double curveDeviation(const Curve3d& a, const Curve3d& b, double u0, double u1)
{
    double worst = 0;
    for (double u : linspace(u0, u1, 257)) worst = std::max(worst, (a.evaluate(u) - b.evaluate(u)).norm());
    return worst;
}
}  // namespace

TEST(CliInsertKnot, CurveKeepsItsShape)
{
    for (const char* name : {"nurbs_book_ex3_1_curve.json", "quarter_circle.json"}) {
        const json in = loadData(name);
        const Curve3d before = io::curveFromJson(in, "curve");
        const double knot = 0.3 * before.domainEnd();
        const json out = runOk("insert-knot", {{"curve", in}, {"knot", knot}, {"times", 2}});
        const Curve3d after = io::curveFromJson(out["curve"], "curve");
        EXPECT_EQ(after.pointCount(), before.pointCount() + 2) << name;
        EXPECT_EQ(std::count(after.knots().begin(), after.knots().end(), knot), 2) << name;
        EXPECT_EQ(after.isRational(), before.isRational()) << name;
        EXPECT_LT(curveDeviation(before, after, before.domainStart(), before.domainEnd()), kSameShape) << name;
    }
}

// "times" defaults to 1.
TEST(CliInsertKnot, TimesDefaultsToOne)
{
    const json in = loadData("nurbs_book_ex3_1_curve.json");
    const json out = runOk("insert-knot", {{"curve", in}, {"knot", 2.5}});
    EXPECT_EQ(out["curve"]["knots"].size(), in["knots"].size() + 1);
}

// A closed curve stays closed and keeps its shape over more than one period.
TEST(CliInsertKnot, ClosedCurveStaysClosed)
{
    const json in = loadData("closed_cubic.json");
    const json out = runOk("insert-knot", {{"curve", in}, {"knot", 4.5}});
    const Curve3d before = io::curveFromJson(in, "curve"), after = io::curveFromJson(out["curve"], "curve");
    EXPECT_TRUE(after.isClosed());
    EXPECT_GT(after.pointCount(), before.pointCount());
    EXPECT_LT(curveDeviation(before, after, 2.0, 9.0), kSameShape);
}

TEST(CliInsertKnot, SurfaceInEitherDirectionKeepsItsShape)
{
    const json in = loadData("quarter_cylinder.json");
    const Surface3d before = io::surfaceFromJson(in, "surface");
    for (const char* direction : {"u", "v"}) {
        const json out = runOk("insert-knot", {{"surface", in}, {"direction", direction}, {"knot", 0.4}, {"times", 1}});
        const Surface3d after = io::surfaceFromJson(out["surface"], "surface");
        const bool u = direction == std::string("u");
        EXPECT_EQ(after.countU(), before.countU() + (u ? 1 : 0));
        EXPECT_EQ(after.countV(), before.countV() + (u ? 0 : 1));
        double worst = 0;
        for (double s : linspace(0, 1, 23))
            for (double t : linspace(0, 1, 23)) worst = std::max(worst, (before.evaluate(s, t) - after.evaluate(s, t)).norm());
        EXPECT_LT(worst, kSameShape) << direction;
    }
}

// Operation preconditions are input errors that name the field.
TEST(CliInsertKnot, RejectsTooManyInsertionsAndKnotsOutsideTheDomain)
{
    const json curve = loadData("nurbs_book_ex3_1_curve.json");
    const CliResult tooMany = runCli({"insert-knot"}, json{{"curve", curve}, {"knot", 4}, {"times", 1}}.dump());
    EXPECT_EQ(tooMany.status, 2);
    EXPECT_EQ(tooMany.err.rfind("sculptline-cli: times: ", 0), 0u) << tooMany.err;
    // Closed curves insert a copy per period; the message still names "times", not a copy.
    const CliResult closedTooMany =
        runCli({"insert-knot"}, json{{"curve", loadData("closed_cubic.json")}, {"knot", 8}, {"times", 3}}.dump());
    EXPECT_EQ(closedTooMany.status, 2);
    EXPECT_EQ(closedTooMany.err.rfind("sculptline-cli: times: knot 8 has multiplicity 1", 0), 0u) << closedTooMany.err;
    const CliResult outside = runCli({"insert-knot"}, json{{"curve", curve}, {"knot", 7}}.dump());
    EXPECT_EQ(outside.status, 2);
    EXPECT_EQ(outside.err.rfind("sculptline-cli: knot: ", 0), 0u) << outside.err;
    const CliResult noDirection = runCli({"insert-knot"}, json{{"surface", loadData("quarter_cylinder.json")}, {"knot", 0.5}}.dump());
    EXPECT_EQ(noDirection.status, 2);
    EXPECT_EQ(noDirection.err.rfind("sculptline-cli: direction: missing", 0), 0u) << noDirection.err;
    const CliResult badDirection = runCli(
        {"insert-knot"}, json{{"surface", loadData("quarter_cylinder.json")}, {"knot", 0.5}, {"direction", "w"}}.dump());
    EXPECT_EQ(badDirection.status, 2);
    EXPECT_EQ(badDirection.err.rfind("sculptline-cli: direction: must be \"u\" or \"v\"", 0), 0u) << badDirection.err;
}
