// sculptline-cli surface, run as the real binary (../shared/interfaces.md): every mode returns a
// surface that meets its curves; impossible input exits with status 2 and names the problem.
#include "solvers/io/geometry_json.h"
#include "tests/cli/cli_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <string>

using nlohmann::json;
using namespace sculptline::solvers;

namespace {

constexpr double kExact = 1e-9;

struct CliRun {
    int status = -1;
    std::string out;
    std::string err;
};

// The shared runner (tests/cli): no shell, a private scratch directory per process, so parallel
// ctest processes never share files. err keeps the first line of stderr.
CliRun runCli(const std::string& sub, const json& input)
{
    const sculptline::cli_test::CliResult r = sculptline::cli_test::runCli({sub}, input.dump());
    return {r.status, r.out, r.err.substr(0, r.err.find('\n'))};
}

json curve(const std::vector<std::array<double, 3>>& pts)
{
    const int p = std::min(3, static_cast<int>(pts.size()) - 1);
    json knots = json::array();
    for (int i = 0; i <= p; ++i) knots.push_back(0.0);
    const int inner = static_cast<int>(pts.size()) - p - 1;
    for (int i = 1; i <= inner; ++i) knots.push_back(static_cast<double>(i) / (inner + 1));
    for (int i = 0; i <= p; ++i) knots.push_back(1.0);
    json points = json::array();
    for (const auto& q : pts) points.push_back({q[0], q[1], q[2]});
    return {{"degree", p}, {"knots", knots}, {"points", points}};
}

Surface3d surfaceOf(const CliRun& r)
{
    const json out = json::parse(r.out);
    EXPECT_TRUE(out.contains("elapsed_ms"));
    return io::surfaceFromJson(out.at("surface"), "surface");
}

}  // namespace

TEST(SurfaceCli, GivenEachMode_WhenRun_ThenSurfaceMeetsItsFirstCurve)
{
    const json profile = curve({{1, 0, 0}, {1.5, 0, 1}, {0.8, 0, 2}, {1, 0, 3}});
    const json section2 = curve({{0, 1, 0}, {0.5, 1, 1}, {0, 1.5, 2}, {0.2, 1, 3}});
    const json path = curve({{1, 0, 0}, {1, 1, 0.5}, {2, 2, 0}, {3, 2, 1}});
    const std::vector<json> inputs{
        {{"mode", "revolve"}, {"curves", {profile}}, {"axis", {{"point", {0, 0, 0}}, {"direction", {0, 0, 1}}}}},
        {{"mode", "extrude"}, {"curves", {profile}}, {"direction", {0, 2, 0}}},
        {{"mode", "extrude"}, {"curves", {profile}}, {"path", path}},
        {{"mode", "loft"}, {"curves", {profile, section2}}},
        {{"mode", "sweep"}, {"curves", {curve({{1, 0.2, 0}, {1, 0, 0.2}, {1, -0.2, 0}}), path}}, {"tolerance", 1e-3}},
        {{"mode", "boundary-rotation"}, {"curves", {profile, curve({{-1, 0, 0}, {-1.2, 0, 1}, {-1, 0, 3}})}}},
        {{"mode", "gordon"},
         {"curves", {curve({{0, 0, 0}, {1, 0, 0.5}, {2, 0, 0}}), curve({{0, 2, 0}, {1, 2, -0.5}, {2, 2, 0}})}},
         {"v_curves", {curve({{0, 0, 0}, {0, 1, 0.3}, {0, 2, 0}}), curve({{2, 0, 0}, {2, 1, 0.2}, {2, 2, 0}})}}},
    };
    for (const json& in : inputs) {
        const CliRun r = runCli("surface", in);
        ASSERT_EQ(r.status, 0) << in["mode"] << ": " << r.err;
        const Surface3d s = surfaceOf(r);
        const Curve3d first = io::curveFromJson(in["curves"][0], "c");
        for (int k = 0; k <= 20; ++k) {
            const double t = k / 20.0;
            EXPECT_LT((s.evaluate(t, 0.0) - first.evaluate(t)).norm(), kExact) << in["mode"] << " " << t;
        }
        const json out = json::parse(r.out);
        if (in["mode"] == "sweep" || in["mode"] == "boundary-rotation") {
            EXPECT_LE(out.at("max_deviation").get<double>(), out.at("tolerance").get<double>());
        }
    }
}

TEST(SurfaceCli, GivenFourBoundaries_WhenFilled_ThenCornersOnTheSurface)
{
    const json in{{"mode", "fill"},
                  {"curves",
                   {curve({{0, 0, 0}, {1, 0, 0.5}, {2, 0, 0}}), curve({{2, 2, 0}, {2.2, 1, 0.3}, {2, 0, 0}}),
                    curve({{2, 2, 0}, {1, 2, -0.5}, {0, 2, 0}}), curve({{0, 2, 0}, {0, 1, 0.2}, {0, 0, 0}})}}};
    const CliRun r = runCli("surface", in);
    ASSERT_EQ(r.status, 0) << r.err;
    const Surface3d s = surfaceOf(r);
    EXPECT_LT((s.evaluate(0.5, 0.0) - Eigen::Vector3d(1, 0, 0.25)).norm(), kExact);  // mid of the first boundary
}

TEST(SurfaceCli, GivenFillWithTangentToAdjacentSurface_WhenRun_ThenNormalAcrossTheEdgeIsTheSurfaces)
{
    // Given: a reference strip whose edge y = 0 (from (0,0,0) to (2,0,0)) has the tangent plane
    // z = 0 (it rises only further in), and a fill hanging off that edge whose sides leave it
    // horizontally but whose far side is raised (the plain Coons fill would crease at the edge).
    const std::vector<Eigen::Vector3d> rp{{0, 0, 0}, {0, 0.5, 0}, {0, 1, 0.5}, {2, 0, 0}, {2, 0.5, 0}, {2, 1, 0.5}};
    const Surface3d reference(1, 2, {0, 0, 1, 1}, {0, 0, 0, 1, 1, 1}, 2, 3, rp);
    const json edge = curve({{0, 0, 0}, {2, 0, 0}});
    const json right = curve({{2, 0, 0}, {2, -1, 0}, {2, -2, 1}});
    const json far = curve({{2, -2, 1}, {1, -2, 2}, {0, -2, 1}});
    const json left = curve({{0, -2, 1}, {0, -1, 0}, {0, 0, 0}});
    const json tangents = json::array({{{"curve", 0}, {"surface", io::toJson(reference)}}});
    const json in{{"mode", "fill"}, {"curves", {edge, right, far, left}}, {"tangents", tangents}};

    // When
    const CliRun r = runCli("surface", in);

    // Then: the edge is met, the normal along it is vertical like the reference's, and the angle
    // reached is reported within the default tolerance (0.1 degree).
    ASSERT_EQ(r.status, 0) << r.err;
    const json out = json::parse(r.out);
    const Surface3d s = surfaceOf(r);
    for (double t : {0.1, 0.3, 0.5, 0.7, 0.9}) {
        EXPECT_LT((s.evaluate(t, 0.0) - Eigen::Vector3d(2 * t, 0, 0)).norm(), kExact);
        EXPECT_GT(std::abs(s.normal(t, 0.0).z()), std::cos(0.1 * 3.14159265358979323846 / 180.0)) << t;
    }
    EXPECT_LE(out.at("max_tangent_angle").get<double>(), 0.1);
    EXPECT_EQ(out.at("angle_tolerance").get<double>(), 0.1);

    // And: a side that leaves the edge's end upwards makes G1 impossible there: refused.
    json tilted = in;
    tilted["curves"][3] = curve({{0, -2, 1}, {0, -1, 0.5}, {0, 0, 0}});
    const CliRun bad = runCli("surface", tilted);
    EXPECT_EQ(bad.status, 2);
    EXPECT_NE(bad.err.find("tangents[0]"), std::string::npos) << bad.err;
}

TEST(SurfaceCli, GivenImpossibleInput_WhenRun_ThenExitTwoWithMessage)
{
    const json line = curve({{1, 0, 0}, {1, 0, 2}});
    const std::vector<std::pair<json, std::string>> cases{
        {{{"mode", "loft"}, {"curves", {line}}}, "curves"},
        {{{"mode", "fill"}, {"curves", {line, curve({{5, 0, 0}, {6, 0, 0}})}}}, "curves"},
        {{{"mode", "sweep"}, {"curves", {line, curve({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 0, 0}})}}}, "curves[1]"},
        {{{"mode", "revolve"}, {"curves", {line}}, {"axis", {{"point", {0, 0, 0}}, {"direction", {0, 0, 0}}}}}, "axis"},
        {{{"mode", "revolve"}, {"curves", {line}}}, "axis"},
        {{{"mode", "extrude"}, {"curves", {line}}}, "direction"},
        {{{"mode", "fill"}, {"curves", {line, line}}, {"tangents", json::array()}}, "tangents"},
        {{{"mode", "fill"}, {"curves", {line, line}}, {"tangents", {{{"curve", 2}, {"surface", json::object()}}}}},
         "tangents[0].curve"},
        {{{"mode", "fill"}, {"curves", {line, line}}, {"tangents", {{{"curve", 0}}}}}, "tangents[0].surface"},
        {{{"mode", "fill"}, {"curves", {line, line}}, {"angle_tolerance", 90}}, "angle_tolerance"},
        {{{"mode", "spin"}, {"curves", {line}}}, "mode"},
        {{{"mode", "loft"}}, "curves"},
        {{{"mode", "loft"}, {"curves", {line, line}}, {"degree", 0}}, "degree"},
    };
    for (const auto& [in, fieldName] : cases) {
        const CliRun r = runCli("surface", in);
        EXPECT_EQ(r.status, 2) << in.dump();
        EXPECT_NE(r.err.find(fieldName), std::string::npos) << r.err;
    }
}

TEST(NetworkCli, GivenSquareLoop_WhenMeshed_ThenTrianglesOverTheSquareAndBadLoopsExitTwo)
{
    const json in{{"curves",
                   {curve({{0, 0, 0}, {2, 0, 0}}), curve({{2, 0, 0}, {2, 2, 0}}), curve({{2, 2, 0}, {0, 2, 0}}),
                    curve({{0, 2, 0}, {0, 0, 0}})}},
                  {"loops", {{0, 1, 2, 3}}},
                  {"edge_length", 0.25}};
    const CliRun r = runCli("network", in);
    ASSERT_EQ(r.status, 0) << r.err;
    const json out = json::parse(r.out);
    const json& mesh = out.at("mesh");
    double area = 0.0;
    for (const json& t : mesh.at("triangles")) {
        Eigen::Vector3d p[3];
        for (int k = 0; k < 3; ++k) p[k] = io::pointFromJson(mesh["vertices"][t[k].get<int>()], "v");
        area += 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).z();  // signed: flipped triangles subtract
    }
    EXPECT_NEAR(area, 4.0, 1e-9);  // the triangles tile the square exactly once
    EXPECT_EQ(out.at("boundary_vertices").get<int>(), 32);
    for (const json& bad : {json{{"curves", in["curves"]}, {"loops", {{0, 2}}}},
                            json{{"curves", in["curves"]}, {"loops", {{0, 9}}}}, json{{"curves", in["curves"]}}}) {
        const CliRun e = runCli("network", bad);
        EXPECT_EQ(e.status, 2) << bad.dump();
        EXPECT_NE(e.err.find("loops"), std::string::npos) << e.err;
    }
}
