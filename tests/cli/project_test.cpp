// sculptline-cli project: closest points agree with closed-form distances and are never worse than
// dense sampling (the projection must find the global minimum).
#include "cli_runner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace sculptline::cli_test;
using sculptline::solvers::Curve3d;
using sculptline::solvers::Surface3d;
namespace io = sculptline::solvers::io;

namespace {
// Newton converges to round-off; the closed-form distances are a few operations.
constexpr double kConverged = 1e-9;
// Dense sampling can only over-estimate the minimum; allow for round-off in the comparison.
constexpr double kNotWorseThanSampling = 1e-9;

const std::vector<Eigen::Vector3d> kQueries{
    {3, 2.5, 0.5}, {0, 0, 0}, {7.5, 2, 3}, {-1, 5, 2}, {3.5, -1, 0}, {2, 1, -2}, {10, 10, 10}, {4.5, 2, 1}};

json pointsJson(const std::vector<Eigen::Vector3d>& pts)
{
    json a = json::array();
    for (const auto& p : pts) a.push_back({p.x(), p.y(), p.z()});
    return a;
}
}  // namespace

TEST(CliProject, CurveNeverWorseThanDenseSampling)
{
    const json in = loadData("nurbs_book_ex3_1_curve.json");
    const Curve3d curve = io::curveFromJson(in, "curve");
    const json out = runOk("project", {{"curve", in}, {"points", pointsJson(kQueries)}});
    ASSERT_EQ(out["params"].size(), kQueries.size());
    const auto pts = pointsOf(out["points"]);
    std::vector<Eigen::Vector3d> samples;
    for (double u : linspace(curve.domainStart(), curve.domainEnd(), 20001)) samples.push_back(curve.evaluate(u));
    for (size_t i = 0; i < kQueries.size(); ++i) {
        double sampled = std::numeric_limits<double>::infinity();
        for (const auto& s : samples) sampled = std::min(sampled, (s - kQueries[i]).norm());
        const double distance = out["distances"][i];
        EXPECT_LE(distance, sampled + kNotWorseThanSampling) << "query " << i;
        // The three outputs describe one point.
        EXPECT_LT((curve.evaluate(out["params"][i].get<double>()) - pts[i]).norm(), kConverged);
        EXPECT_NEAR((pts[i] - kQueries[i]).norm(), distance, kConverged);
    }
}

// The Ex. 3.1 curve has a corner at its double knot u = 4 (C(4) = P5 = (5, 4, 0)). From x = (5, 4, 0.1)
// the distance has a local minimum on each side of the corner: 0.08456 at u ~ 3.99285 (the global
// one, found by dense sampling) and 0.09716 at u ~ 4.0028.
// Known kernel bug (reported): CurveProjector returns the minimum right of the corner, so this test
// fails until the projector separates the two sides of a C0 knot.
TEST(CliProject, FindsTheGlobalMinimumBesideACornerKnot)
{
    const json in = loadData("nurbs_book_ex3_1_curve.json");
    const Curve3d curve = io::curveFromJson(in, "curve");
    const Eigen::Vector3d x(5, 4, 0.1);
    const json out = runOk("project", {{"curve", in}, {"points", pointsJson({x})}});
    ASSERT_EQ(out["distances"].size(), 1u);
    double sampled = std::numeric_limits<double>::infinity();
    for (double u : linspace(3.9, 4.1, 20001)) sampled = std::min(sampled, (curve.evaluate(u) - x).norm());
    EXPECT_LE(out["distances"][0].get<double>(), sampled + kNotWorseThanSampling);
    EXPECT_LT(out["params"][0].get<double>(), 4.0);
}

// Unit quarter circle: a point at angle t in (0, pi/2), radius r and height z is closest to
// (cos t, sin t, 0) at distance sqrt((r - 1)^2 + z^2).
TEST(CliProject, QuarterCircleClosedForm)
{
    std::vector<Eigen::Vector3d> queries;
    for (double t : {0.1, 0.5, 0.785, 1.2, 1.5})
        for (double r : {0.2, 0.9, 1.0, 1.7}) queries.emplace_back(r * std::cos(t), r * std::sin(t), r - 1);
    const json out = runOk("project", {{"curve", loadData("quarter_circle.json")}, {"points", pointsJson(queries)}});
    const auto pts = pointsOf(out["points"]);
    for (size_t i = 0; i < queries.size(); ++i) {
        const Eigen::Vector3d& q = queries[i];
        const double r = std::hypot(q.x(), q.y());
        EXPECT_NEAR(out["distances"][i].get<double>(), std::hypot(r - 1, q.z()), kConverged) << i;
        EXPECT_LT((pts[i] - Eigen::Vector3d(q.x() / r, q.y() / r, 0)).norm(), kConverged) << i;
    }
}

// Quarter cylinder x^2 + y^2 = 1, 0 <= z <= 2: inside the patch the distance is |r - 1|.
TEST(CliProject, QuarterCylinderClosedForm)
{
    std::vector<Eigen::Vector3d> queries;
    for (double t : {0.2, 0.8, 1.3})
        for (double r : {0.5, 1.25, 3.0})
            for (double z : {0.1, 1.0, 1.9}) queries.emplace_back(r * std::cos(t), r * std::sin(t), z);
    const json in = loadData("quarter_cylinder.json");
    const Surface3d surface = io::surfaceFromJson(in, "surface");
    const json out = runOk("project", {{"surface", in}, {"points", pointsJson(queries)}});
    ASSERT_EQ(out["params"].size(), queries.size());
    for (size_t i = 0; i < queries.size(); ++i) {
        const double r = std::hypot(queries[i].x(), queries[i].y());
        EXPECT_NEAR(out["distances"][i].get<double>(), std::abs(r - 1), kConverged) << i;
        const json& uv = out["params"][i];
        ASSERT_EQ(uv.size(), 2u);
        EXPECT_NEAR(surface.evaluate(uv[0], uv[1]).z(), queries[i].z(), kConverged) << i;
    }
}

TEST(CliProject, SurfaceNeverWorseThanDenseSampling)
{
    const json in = loadData("paraboloid_surface.json");
    const Surface3d surface = io::surfaceFromJson(in, "surface");
    const std::vector<Eigen::Vector3d> queries{{0.5, 0.5, 2}, {0.2, 0.9, -1}, {2, 2, 0}, {0.5, -0.5, 0.5}, {0.1, 0.1, 0.5}};
    const json out = runOk("project", {{"surface", in}, {"points", pointsJson(queries)}});
    std::vector<Eigen::Vector3d> samples;
    for (double u : linspace(0, 1, 301))
        for (double v : linspace(0, 1, 301)) samples.push_back(surface.evaluate(u, v));
    for (size_t i = 0; i < queries.size(); ++i) {
        double sampled = std::numeric_limits<double>::infinity();
        for (const auto& s : samples) sampled = std::min(sampled, (s - queries[i]).norm());
        EXPECT_LE(out["distances"][i].get<double>(), sampled + kNotWorseThanSampling) << "query " << i;
    }
}

TEST(CliProject, EmptyPointListGivesEmptyResults)
{
    const json out = runOk("project", {{"curve", loadData("quarter_circle.json")}, {"points", json::array()}});
    EXPECT_EQ(out["params"], json::array());
    EXPECT_EQ(out["distances"], json::array());
}
