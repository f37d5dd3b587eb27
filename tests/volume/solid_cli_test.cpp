// sculptline-cli solid, run as the real binary (../shared/interfaces.md). Given / When / Then.
#include "tests/cli/cli_runner.h"
#include "tests/volume/test_shapes.h"

#include "solvers/math_constants.h"

#include <gtest/gtest.h>

using namespace sculptline::cli_test;
using namespace sculptline::volume_test;
namespace io = sculptline::solvers::io;

namespace {

const std::string kPrefix = "sculptline-cli: ";  // main() starts every error line with it
// As in solidify_test.cpp: a sphere within 1 % at the default voxel size, a shell within 2 %.
constexpr double kSphereVolume = 0.01;
constexpr double kShellVolume = 0.02;

json surfaces(const std::vector<sculptline::solvers::Surface3d>& s)
{
    json out = json::array();
    for (const auto& x : s) out.push_back(io::toJson(x));
    return out;
}

bool watertight(const json& triangles)
{
    std::map<std::pair<int, int>, int> uses;
    for (const json& t : triangles)
        for (int k = 0; k < 3; ++k) {
            const int a = t[k].get<int>(), b = t[(k + 1) % 3].get<int>();
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    for (const auto& e : uses)
        if (e.second != 2) return false;
    return !uses.empty();
}

}  // namespace

TEST(SolidCli, GivenARevolvedSphere_WhenSolidWithDefaults_ThenVolumeWithin1PercentAndAWatertightMesh)
{
    const double r = 10.0;
    const json out = runOk("solid", {{"surfaces", surfaces({sphere(r)})}});

    const double exact = 4.0 / 3.0 * sculptline::solvers::kPi * r * r * r;
    EXPECT_NEAR(out["volume"].get<double>(), exact, kSphereVolume * exact);
    EXPECT_NEAR(out["voxel_size"].get<double>(), 20.0 * std::sqrt(3.0) / 200.0, 1e-12);
    EXPECT_TRUE(out["watertight"].get<bool>());
    // The reported flag agrees with the mesh as written.
    EXPECT_TRUE(watertight(out["mesh"]["triangles"]));
    const size_t n = out["mesh"]["vertices"].size();
    for (const json& t : out["mesh"]["triangles"])
        for (const json& i : t) ASSERT_LT(i.get<size_t>(), n);
    EXPECT_TRUE(out.contains("area") && out.contains("elapsed_ms"));
}

TEST(SolidCli, GivenAPatchAndAThickness_WhenSolid_ThenAShellOfAreaTimesThickness)
{
    const json out = runOk("solid", {{"surfaces", surfaces({flatPatch(20, 20)})}, {"thickness", 1.0}, {"voxel_size", 0.25}});

    EXPECT_NEAR(out["volume"].get<double>(), 400.0, kShellVolume * 400.0);
    EXPECT_TRUE(out["watertight"].get<bool>());
    EXPECT_EQ(out["voxel_size"].get<double>(), 0.25);
}

TEST(SolidCli, GivenBadInput_WhenSolid_ThenExit2WithOneLineNamingTheField)
{
    struct Case {
        json input;
        std::string field;
    };
    const json patch = surfaces({flatPatch(10, 10)});
    const json ball = surfaces({sphere(10.0)});
    const std::vector<Case> cases{
        {json::object(), "surfaces: missing"},
        {{{"surfaces", json::array()}}, "surfaces: expected a non-empty array"},
        {{{"surfaces", patch}}, "surfaces[0]: is open"},
        {{{"surfaces", patch}, {"thickness", -1.0}}, "thickness: must be >= 0"},
        {{{"surfaces", patch}, {"thickness", "thick"}}, "thickness:"},
        {{{"surfaces", ball}, {"voxel_size", 0.0}}, "voxel_size: must be positive"},
        {{{"surfaces", ball}, {"voxel_size", 1e-4}}, "voxel_size: 0.0001 would need about"},
        {{{"surfaces", ball}, {"voxel_size", 100.0}}, "voxel_size: 100 is more than 1/2"},
        {{{"surfaces", patch}, {"thickness", 0.01}, {"voxel_size", 1.0}}, "thickness: 0.01 is less than 2 voxels"},
    };
    for (const Case& c : cases) {
        const CliResult r = runCli({"solid"}, c.input.dump());
        EXPECT_EQ(r.status, 2) << c.field;
        EXPECT_EQ(r.err.rfind(kPrefix + c.field, 0), 0u) << r.err;
        EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
        EXPECT_TRUE(r.out.empty());
    }
}

TEST(SolidCli, GivenANonFiniteNumber_WhenSolid_ThenExit2NamingIt)
{
    json input = {{"surfaces", surfaces({sphere(10.0)})}, {"voxel_size", 12345.0}};
    std::string text = input.dump();
    text.replace(text.find("12345.0"), 7, "1e999");
    const CliResult r = runCli({"solid"}, text);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err.rfind(kPrefix + "voxel_size: not a finite number", 0), 0u) << r.err;

    json bad = {{"surfaces", surfaces({flatPatch(10, 10)})}, {"thickness", 1.0}};
    bad["surfaces"][0]["points"][3][0] = 12345.0;
    std::string badText = bad.dump();
    badText.replace(badText.find("12345.0"), 7, "1e999");  // a control point coordinate
    const CliResult r2 = runCli({"solid"}, badText);
    EXPECT_EQ(r2.status, 2);
    EXPECT_EQ(r2.err.rfind(kPrefix + "surfaces[0].points", 0), 0u) << r2.err;
}
