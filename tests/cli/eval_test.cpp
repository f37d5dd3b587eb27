// sculptline-cli eval: reference values from The NURBS Book and closed-form geometry, computed
// independently of the kernel (Given / When / Then).
#include "cli_runner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

using namespace sculptline::cli_test;

namespace {
// Evaluation is a handful of floating-point operations on O(1) values.
constexpr double kExact = 1e-12;

Eigen::Vector3d p(const json& curve, int i)
{
    return pointsOf(curve["points"])[i];
}
}  // namespace

// The NURBS Book (2nd ed.), Ex. 2.3 / Ex. 3.1: p = 2, U = {0,0,0,1,2,3,4,4,5,5,5}. At u = 5/2 the
// non-zero basis functions are N22 = 1/8, N32 = 6/8, N42 = 1/8, so C(5/2) = (P2 + 6 P3 + P4) / 8;
// their derivatives on [2, 3] (from Ex. 2.3's piecewise formulas N22 = (3-u)^2/2,
// N32 = -11/2 + 5u - u^2, N42 = (u-2)^2/2) give C' = (P4 - P2) / 2 and C'' = P2 - 2 P3 + P4.
TEST(CliEval, CurveMatchesNurbsBookExample31)
{
    const json curve = loadData("nurbs_book_ex3_1_curve.json");
    const json out = runOk("eval", {{"curve", curve}, {"params", {2.5}}, {"derivatives", 2}});
    ASSERT_TRUE(out.contains("d2"));
    const Eigen::Vector3d c = pointsOf(out["points"])[0], d1 = pointsOf(out["d1"])[0], d2 = pointsOf(out["d2"])[0];
    EXPECT_LT((c - (p(curve, 2) + 6 * p(curve, 3) + p(curve, 4)) / 8).norm(), kExact);
    EXPECT_LT((d1 - (p(curve, 4) - p(curve, 2)) / 2).norm(), kExact);
    EXPECT_LT((d2 - (p(curve, 2) - 2 * p(curve, 3) + p(curve, 4))).norm(), kExact);
    EXPECT_FALSE(out.contains("d3"));
}

// Clamped ends interpolate the end points; the double knot 4 (multiplicity = degree) interpolates P5.
TEST(CliEval, CurveIsExactAtEndsAndAtAFullMultiplicityKnot)
{
    const json curve = loadData("nurbs_book_ex3_1_curve.json");
    const json out = runOk("eval", {{"curve", curve}, {"params", {0, 4, 5}}});
    const auto pts = pointsOf(out["points"]);
    ASSERT_EQ(pts.size(), 3u);
    EXPECT_EQ(pts[0], p(curve, 0));
    EXPECT_LT((pts[1] - p(curve, 5)).norm(), kExact);
    EXPECT_EQ(pts[2], p(curve, 7));
    EXPECT_FALSE(out.contains("d1"));  // "derivatives" defaults to 0
}

// The rational quadratic with weights 1, sqrt(2)/2, 1 on (1,0), (1,1), (0,1) is exactly the unit
// quarter circle (The NURBS Book, Ex. 7.1): every point has radius 1 and C' is perpendicular to C.
TEST(CliEval, RationalQuarterCircleHasRadiusOne)
{
    const std::vector<double> params = linspace(0, 1, 101);
    const json out = runOk("eval", {{"curve", loadData("quarter_circle.json")}, {"params", params}, {"derivatives", 1}});
    const auto pts = pointsOf(out["points"]), d1 = pointsOf(out["d1"]);
    ASSERT_EQ(pts.size(), params.size());
    for (size_t i = 0; i < pts.size(); ++i) {
        EXPECT_NEAR(pts[i].norm(), 1.0, kExact) << "u = " << params[i];
        EXPECT_EQ(pts[i].z(), 0.0);  // 2D input means z = 0
        EXPECT_NEAR(pts[i].dot(d1[i]) / d1[i].norm(), 0.0, kExact) << "u = " << params[i];
    }
}

// The output is the kernel's result to the last bit: numbers are written in round-trip form.
TEST(CliEval, NumbersRoundTripAtFullPrecision)
{
    const json curveJson = loadData("quarter_circle.json");
    const auto curve = sculptline::solvers::io::curveFromJson(curveJson, "curve");
    const std::vector<double> params{1.0 / 3, 0.1, 2.0 / 7};
    const json out = runOk("eval", {{"curve", curveJson}, {"params", params}});
    const auto pts = pointsOf(out["points"]);
    for (size_t i = 0; i < params.size(); ++i) EXPECT_EQ(pts[i], curve.evaluate(params[i]));
}

// A closed curve's parameter wraps with the period (domain [3, 7], period 4).
TEST(CliEval, ClosedCurveWrapsWithThePeriod)
{
    const json out = runOk("eval", {{"curve", loadData("closed_cubic.json")}, {"params", {3.25, 7.25, -0.75, 5.5, 13.5}}});
    const auto pts = pointsOf(out["points"]);
    EXPECT_LT((pts[0] - pts[1]).norm(), kExact);
    EXPECT_LT((pts[0] - pts[2]).norm(), kExact);
    EXPECT_LT((pts[3] - pts[4]).norm(), kExact);
}

// The biquadratic with control points (a_i, a_j, b_i + b_j), a = (0, 1/2, 1), b = (0, 0, 1) is the
// paraboloid S(u, v) = (u, v, u^2 + v^2): Bernstein coefficients of u and u^2 on [0, 1].
TEST(CliEval, SurfaceDerivativesOfAParaboloid)
{
    const json params = {{0.0, 0.0}, {0.3, 0.7}, {1.0, 0.25}, {0.5, 1.0}};
    const json out = runOk("eval", {{"surface", loadData("paraboloid_surface.json")}, {"params", params}, {"derivatives", 2}});
    for (const char* key : {"points", "du", "dv", "duu", "duv", "dvv"}) ASSERT_TRUE(out.contains(key)) << key;
    EXPECT_FALSE(out.contains("d1"));
    for (size_t i = 0; i < params.size(); ++i) {
        const double u = params[i][0], v = params[i][1];
        EXPECT_LT((pointsOf(out["points"])[i] - Eigen::Vector3d(u, v, u * u + v * v)).norm(), kExact);
        EXPECT_LT((pointsOf(out["du"])[i] - Eigen::Vector3d(1, 0, 2 * u)).norm(), kExact);
        EXPECT_LT((pointsOf(out["dv"])[i] - Eigen::Vector3d(0, 1, 2 * v)).norm(), kExact);
        EXPECT_LT((pointsOf(out["duu"])[i] - Eigen::Vector3d(0, 0, 2)).norm(), kExact);
        EXPECT_LT(pointsOf(out["duv"])[i].norm(), kExact);
        EXPECT_LT((pointsOf(out["dvv"])[i] - Eigen::Vector3d(0, 0, 2)).norm(), kExact);
    }
}

// Order 3 adds four keys, named by how often each direction is differentiated.
TEST(CliEval, SurfaceThirdOrderKeys)
{
    const json out = runOk("eval", {{"surface", loadData("paraboloid_surface.json")}, {"params", {{0.5, 0.5}}}, {"derivatives", 3}});
    for (const char* key : {"duuu", "duuv", "duvv", "dvvv"}) {
        ASSERT_TRUE(out.contains(key)) << key;
        EXPECT_LT(pointsOf(out[key])[0].norm(), kExact) << key;  // a quadratic has no third derivative
    }
}

// A rational surface: the quarter cylinder x^2 + y^2 = 1, z = 2v.
TEST(CliEval, RationalQuarterCylinder)
{
    json params = json::array();
    for (double u : linspace(0, 1, 11))
        for (double v : linspace(0, 1, 5)) params.push_back({u, v});
    const json out = runOk("eval", {{"surface", loadData("quarter_cylinder.json")}, {"params", params}});
    const auto pts = pointsOf(out["points"]);
    ASSERT_EQ(pts.size(), params.size());
    for (size_t i = 0; i < pts.size(); ++i) {
        EXPECT_NEAR(std::hypot(pts[i].x(), pts[i].y()), 1.0, kExact);
        EXPECT_NEAR(pts[i].z(), 2 * params[i][1].get<double>(), kExact);
    }
}

// Reading from a file and from stdin ("-" or no argument) gives the same result.
TEST(CliEval, ReadsFileOrStdin)
{
    const json input = {{"curve", loadData("nurbs_book_ex3_1_curve.json")}, {"params", {0.5, 1.5}}};
    const std::string file = scratchPath("eval_input.json");
    {
        std::ofstream(file) << input.dump();
    }
    const CliResult fromFile = runCli({"eval", file});
    const CliResult fromDash = runCli({"eval", "-"}, input.dump());
    const CliResult fromStdin = runCli({"eval"}, input.dump());
    ASSERT_EQ(fromFile.status, 0) << fromFile.err;
    ASSERT_EQ(fromDash.status, 0) << fromDash.err;
    ASSERT_EQ(fromStdin.status, 0) << fromStdin.err;
    EXPECT_EQ(json::parse(fromFile.out)["points"], json::parse(fromDash.out)["points"]);
    EXPECT_EQ(json::parse(fromFile.out)["points"], json::parse(fromStdin.out)["points"]);
}
