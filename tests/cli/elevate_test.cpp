// sculptline-cli elevate: degree elevation keeps the shape (evaluated by the kernel).
#include "cli_runner.h"

#include <gtest/gtest.h>

using namespace sculptline::cli_test;
using sculptline::solvers::Curve3d;
using sculptline::solvers::Surface3d;
namespace io = sculptline::solvers::io;

namespace {
constexpr double kSameShape = 1e-12;
}  // namespace

TEST(CliElevate, CurveKeepsItsShape)
{
    for (const char* name : {"nurbs_book_ex3_1_curve.json", "quarter_circle.json", "closed_cubic.json"}) {
        const json in = loadData(name);
        const Curve3d before = io::curveFromJson(in, "curve");
        const json out = runOk("elevate", {{"curve", in}, {"times", 2}});
        const Curve3d after = io::curveFromJson(out["curve"], "curve");
        EXPECT_EQ(after.degree(), before.degree() + 2) << name;
        EXPECT_EQ(after.isClosed(), before.isClosed()) << name;
        double worst = 0;
        // Beyond one period for the closed curve: both wrap.
        const double a = before.domainStart(), b = before.domainEnd() + (before.isClosed() ? 1.5 : 0.0);
        for (double u : linspace(a, b, 257)) worst = std::max(worst, (before.evaluate(u) - after.evaluate(u)).norm());
        EXPECT_LT(worst, kSameShape) << name;
    }
}

// "times" defaults to 1.
TEST(CliElevate, TimesDefaultsToOne)
{
    const json out = runOk("elevate", {{"curve", loadData("quarter_circle.json")}});
    EXPECT_EQ(out["curve"]["degree"], 3);
}

TEST(CliElevate, SurfaceKeepsItsShape)
{
    const json in = loadData("quarter_cylinder.json");
    const Surface3d before = io::surfaceFromJson(in, "surface");
    const json out = runOk("elevate", {{"surface", in}, {"direction", "v"}, {"times", 1}});
    const Surface3d after = io::surfaceFromJson(out["surface"], "surface");
    EXPECT_EQ(after.degreeU(), 2);
    EXPECT_EQ(after.degreeV(), 2);
    double worst = 0;
    for (double s : linspace(0, 1, 23))
        for (double t : linspace(0, 1, 23)) worst = std::max(worst, (before.evaluate(s, t) - after.evaluate(s, t)).norm());
    EXPECT_LT(worst, kSameShape);
}

TEST(CliElevate, RejectsDegreesAboveTheMaximum)
{
    const CliResult r = runCli({"elevate"}, json{{"curve", loadData("quarter_circle.json")}, {"times", 29}}.dump());
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err.rfind("sculptline-cli: times: ", 0), 0u) << r.err;
    EXPECT_EQ(r.out, "");
}
