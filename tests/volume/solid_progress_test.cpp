// Progress, cancellation and bounded work of solidify (solvers/volume/solidify.h, progress.h).
// Given / When / Then.
#include "solvers/volume/solidify.h"
#include "tests/volume/test_shapes.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/io/geometry_json.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <fstream>
#include <sstream>
#include <string>

namespace vol = sculptline::solvers::volume;
using sculptline::solvers::GeometryError;
using namespace sculptline::volume_test;

namespace {

// A voxel fine enough that the sphere's level set takes many interrupter calls (a 0.05 voxel puts
// about three million voxels in the band: seconds of work), so a cancel lands inside it.
constexpr double kFineVoxel = 0.05;

std::string slowInput() { return SCULPTLINE_SOURCE_DIR "/tests/fuzz/slow/solid_tessellation.json"; }

nlohmann::json readJson(const std::string& path)
{
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return sculptline::solvers::io::parseJson(text.str());
}

}  // namespace

TEST(SolidProgress, GivenASphere_WhenSolidified_ThenProgressRisesFromZeroToOneWithoutGoingBack)
{
    std::vector<double> seen;
    vol::SolidOptions options;
    options.progress = [&seen](double f) {
        seen.push_back(f);
        return true;
    };

    const vol::Solid solid = vol::solidify({sphere(10.0)}, options);

    ASSERT_GE(seen.size(), 4u) << "between the stages at least";
    EXPECT_EQ(seen.back(), 1.0);
    EXPECT_GE(seen.front(), 0.0);
    for (size_t i = 1; i < seen.size(); ++i) EXPECT_GE(seen[i], seen[i - 1]) << "step " << i;
    EXPECT_TRUE(solid.watertight);
}

TEST(SolidProgress, GivenACallbackThatCancelsAtOnce_WhenSolidified_ThenCancelledIsThrown)
{
    vol::SolidOptions options;
    options.progress = [](double) { return false; };

    EXPECT_THROW(vol::solidify({sphere(10.0)}, options), vol::Cancelled);
}

TEST(SolidProgress, GivenACancelDuringTheLevelSet_WhenSolidified_ThenItStopsThereWithCancelled)
{
    // Arrange: cancel once the level-set stage has started (past the tessellations' 15 %), and
    // count how often the callback is asked after that.
    std::atomic<int> askedAfterCancel{0};
    std::atomic<bool> cancelled{false};
    vol::SolidOptions options;
    options.voxelSize = kFineVoxel;
    options.progress = [&](double f) {
        if (cancelled) {
            ++askedAfterCancel;
            return false;
        }
        if (f > 0.2) cancelled = true;
        return !cancelled;
    };

    // Act / Assert: the conversion stops with Cancelled, and does not go on asking for long
    // (OpenVDB's passes stop at the first interrupted answer; each pass asks about once per thread).
    EXPECT_THROW(vol::solidify({sphere(10.0)}, options), vol::Cancelled);
    EXPECT_TRUE(cancelled);
    EXPECT_LT(askedAfterCancel.load(), 64);
}

TEST(SolidProgress, GivenTheFuzzersSlowTessellationInput_WhenSolidified_ThenAClearRefusalNamingTheVoxelSize)
{
    // The input the fuzzer found (a degenerate revolve net with one control point pulled 100 times
    // the net's size, voxel_size 1e-5): it used to tessellate for over 5 s before any check.
    const nlohmann::json input = readJson(slowInput());
    const auto surface = sculptline::solvers::io::surfaceFromJson(input.at("surfaces").at(0), "surfaces[0]");
    vol::SolidOptions options;
    options.voxelSize = input.at("voxel_size").get<double>();

    std::string error;
    try {
        vol::solidify({surface}, options);
    } catch (const GeometryError& e) {
        error = e.what();
    }

    EXPECT_EQ(error.rfind("voxel_size: ", 0), 0u) << error;
    EXPECT_NE(error.find("use at least"), std::string::npos) << error;
}

TEST(SolidProgress, GivenTheSlowInputAtTheDefaultVoxel_WhenSolidified_ThenAWatertightSolidOrAClearRefusal)
{
    const nlohmann::json input = readJson(slowInput());
    const auto surface = sculptline::solvers::io::surfaceFromJson(input.at("surfaces").at(0), "surfaces[0]");

    try {
        const vol::Solid solid = vol::solidify({surface});
        EXPECT_TRUE(solid.watertight);
        EXPECT_GT(solid.volume, 0.0);
    } catch (const GeometryError& e) {
        const std::string message = e.what();
        EXPECT_TRUE(message.rfind("surfaces", 0) == 0 || message.rfind("voxel_size", 0) == 0) << message;
    }
}

TEST(SolidProgress, GivenTheSlowInput_WhenTessellatedForSizing_ThenTheCoarseBudgetBoundsItsVertices)
{
    // The work before the checks is the coarse tessellation: its vertex count is bounded by the
    // budget (tessellate() emits at most the bisection's pending halves beyond it).
    const nlohmann::json input = readJson(slowInput());
    const auto surface = sculptline::solvers::io::surfaceFromJson(input.at("surfaces").at(0), "surfaces[0]");
    constexpr double kSizingChord = 1e-3 * 1000.0;  // the coarse pass's relative chord on a ~1000 mm net

    const vol::TriangleMesh mesh = vol::surfaceMesh(surface, kSizingChord, 0.0, vol::kCoarseVertexBudget);

    EXPECT_LE(mesh.vertices.size(), static_cast<size_t>(2 * vol::kCoarseVertexBudget));
    EXPECT_GT(mesh.triangles.size(), 0u);
}
