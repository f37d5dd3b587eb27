// The importer of scene/iv_import.h: Coin's reading of validated text, the index checks before
// Coin draws, the census (counts, bounding box, finite coordinates within the limit), the file size
// checked before reading, and the seed files of the fuzz target. Headless (SoDB::init).
#include "scene/iv_import.h"

#include "solvers/io/geometry_json.h"

#include <Inventor/SoDB.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoMaterialBinding.h>
#include <Inventor/nodes/SoNormal.h>
#include <Inventor/nodes/SoSeparator.h>

#include "refusal.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

using sculptline::scene::importIvFile;
using sculptline::scene::importIvText;
using sculptline::scene::IvLimits;
using sculptline::solvers::io::InputError;

const std::string kHeader = "#Inventor V2.1 ascii\n\n";
/// Coin computes in float: coordinates of a few tens of units come back within this.
constexpr double kFloatTolerance = 1e-4;

std::string refusal(const std::string& text, const IvLimits& limits = {})
{
    return sculptline::test::refusal([](const std::string& t, const IvLimits& l) { importIvText(t, l); }, text, limits);
}

void expectRefused(const std::string& text, const std::string& expected, const IvLimits& limits = {})
{
    sculptline::test::expectRefusedBy([](const std::string& t, const IvLimits& l) { importIvText(t, l); }, text, expected, limits);
}

int countOf(SoNode* root, SoType type)
{
    SoSearchAction search;
    search.setType(type);
    search.setInterest(SoSearchAction::ALL);
    search.setSearchingAll(TRUE);
    search.apply(root);
    return search.getPaths().getLength();
}

TEST(IvImport, GivenTheBoxReference_WhenImported_ThenTwelveTrianglesInItsBox)
{
    const auto imported = importIvFile(std::string(SCULPTLINE_DATA_DIR) + "/references/box.iv");
    ASSERT_TRUE(imported.root);
    EXPECT_EQ(imported.geometry.triangles, 12u);
    const double expectedMin[3] = {-30.0, -20.0, 0.0}, expectedMax[3] = {30.0, 20.0, 50.0};
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(imported.geometry.min[k], expectedMin[k], kFloatTolerance);
        EXPECT_NEAR(imported.geometry.max[k], expectedMax[k], kFloatTolerance);
    }
    EXPECT_EQ(sculptline::scene::describe(imported), "0 coordinates, 12 triangles; box 60 x 40 x 50");
}

TEST(IvImport, GivenAMeshWithShading_WhenImported_ThenCountedAndShadingDropped)
{
    const auto imported = importIvFile(std::string(SCULPTLINE_DATA_DIR) + "/references/tetrahedron.iv");
    EXPECT_EQ(imported.text.coordinates, 4u);
    EXPECT_EQ(imported.geometry.triangles, 4u);
    EXPECT_EQ(imported.geometry.segments, 3u);
    const auto sets = importIvFile(std::string(SCULPTLINE_IV_CORPUS) + "/sets.iv");
    EXPECT_EQ(countOf(sets.root.get(), SoNormal::getClassTypeId()), 0);
    EXPECT_EQ(countOf(sets.root.get(), SoMaterialBinding::getClassTypeId()), 0);
    EXPECT_EQ(sets.geometry.points, 2u);
}

TEST(IvImport, GivenUses_WhenImported_ThenEachInstanceIsCountedWhereItIsDrawn)
{
    // One triangle DEF'd, drawn once, then at x + 3, then twice more in a pair, then the pair scaled.
    const auto imported = importIvFile(std::string(SCULPTLINE_IV_CORPUS) + "/instances.iv");
    EXPECT_EQ(imported.geometry.triangles, 1u + 1u + 2u + 2u + 12u);  // + the cube
    EXPECT_NEAR(imported.geometry.max[0], 5.0, kFloatTolerance);  // the scaled pair: 3 + 2 * 1
}

TEST(IvImport, GivenACoordinateIndexPastTheCoordinates_ThenRefusedBeforeCoinDrawsIt)
{
    expectRefused(kHeader + "Separator { Coordinate3 { point [ 0 0 0, 1 0 0, 0 1 0 ] } IndexedFaceSet { coordIndex [ 0, 1, 7, -1 ] } }",
                   "coordIndex 7 of IndexedFaceSet is past its 3 coordinates");
    // The coordinates in effect are those of the shape's own Separator.
    expectRefused(kHeader + "Separator { Separator { Coordinate3 { point [ 0 0 0, 1 0 0, 0 1 0, 1 1 1 ] } } IndexedLineSet { coordIndex [ 0, 3 ] } }",
                   "coordIndex 3 of IndexedLineSet is past its 1 coordinates");
}

TEST(IvImport, GivenFacesAndLinesWithTooFewVertices_ThenRefused)
{
    const std::string coords = "Coordinate3 { point [ 0 0 0, 1 0 0, 0 1 0 ] } ";
    expectRefused(kHeader + "Separator { " + coords + "IndexedFaceSet { coordIndex [ 0, 1, 2, -1, 0, 1, -1 ] } }",
                  "face 2 of IndexedFaceSet has 2 vertices (3 or more needed)");
    expectRefused(kHeader + "Separator { " + coords + "IndexedFaceSet { coordIndex [ -1, 0, 1, 2 ] } }", "face 1 of IndexedFaceSet has 0 vertices");
    expectRefused(kHeader + "Separator { " + coords + "IndexedLineSet { coordIndex [ 0, -1 ] } }", "line 1 of IndexedLineSet has 1 vertices (2 or more needed)");
    EXPECT_EQ(refusal(kHeader + "Separator { " + coords + "IndexedFaceSet { coordIndex [ 0, 1, 2 ] } }"), "");  // no final -1
}

TEST(IvImport, GivenNonIndexedCountsPastTheCoordinates_ThenRefused)
{
    const std::string coords = "Coordinate3 { point [ 0 0 0, 1 0 0, 0 1 0 ] } ";
    expectRefused(kHeader + "Separator { " + coords + "FaceSet { numVertices [ 3, 3 ] } }", "numVertices up to 6 of FaceSet is past its 3 coordinates");
    expectRefused(kHeader + "Separator { " + coords + "LineSet { numVertices [ 1 ] } }", "numVertices 1 of LineSet must be 2 or more");
    // Found by fuzz-iv-import: Coin 4.0.0 dereferences null in SoFaceSet::generatePrimitives.
    expectRefused(kHeader + "Separator { " + coords + "FaceSet { numVertices 1 } }", "numVertices 1 of FaceSet must be 3 or more");
    expectRefused(kHeader + "Separator { " + coords + "FaceSet { startIndex 1 numVertices -1 } }", "the last numVertices (-1) of FaceSet leaves 2 vertices");
    expectRefused(kHeader + "Separator { " + coords + "PointSet { startIndex 2 numPoints 2 } }",
                   "startIndex + numPoints 4 of PointSet is past its 3 coordinates");
    expectRefused(kHeader + "Separator { " + coords + "FaceSet { startIndex -1 } }", "startIndex of FaceSet is negative");
}

TEST(IvImport, GivenCoordinatesBeyondTheLimitAfterTransforms_ThenRefused)
{
    expectRefused(kHeader + "Separator { Coordinate3 { point [ 0 0 0, 1e7 0 0, 0 1 0 ] } FaceSet { numVertices 3 } }",
                   "a vertex at 1e+07 model units is outside +-1e6");
    expectRefused(kHeader + "Separator { Scale { scaleFactor 1e7 1 1 } Cube { } }", "is outside +-1e6 (after the transforms)");
}

TEST(IvImport, GivenTransformsThatOverflow_ThenRefusedAsNotFinite)
{
    expectRefused(kHeader + "Separator { Scale { scaleFactor 3e38 3e38 3e38 } Scale { scaleFactor 3e38 1 1 } Cube { } }",
                   "a vertex is not finite after the transforms");
}

TEST(IvImport, GivenNothingToDraw_ThenRefused)
{
    expectRefused(kHeader + "Separator { Material { diffuseColor 1 0 0 } }", "nothing to draw");
    expectRefused(kHeader + "Separator { Coordinate3 { point [ 0 0 0 ] } PointSet { numPoints 0 } }", "nothing to draw");
}

TEST(IvImport, GivenMorePrimitivesThanTheBudget_ThenRefused)
{
    IvLimits limits;
    limits.maxPrimitives = 5;
    expectRefused(kHeader + "Cube { }", "more than 5 triangles, segments and points to draw", limits);
}

TEST(IvImport, GivenTextTheCheckRefuses_ThenCoinNeverReadsIt)
{
    expectRefused(kHeader + "Separator { File { name \"/etc/passwd\" } }", "line 3: node File is not accepted");
}

TEST(IvImport, GivenAFileOverTheSizeLimit_ThenRefusedBeforeReading)
{
    // A sparse file: its size is what is checked, so 65 MiB of nothing is refused in microseconds.
    const std::string path = std::filesystem::temp_directory_path() / ("iv_import_big_" + std::to_string(::getpid()) + ".iv");
    {
        std::ofstream out(path);
        out << kHeader;
    }
    std::filesystem::resize_file(path, (std::uintmax_t{65} << 20));
    try {
        importIvFile(path);
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), path + ": 68157440 bytes, over the limit of 67108864 bytes");
    }
    std::filesystem::remove(path);
}

TEST(IvImport, GivenAMissingFile_ThenRefusedWithItsPath)
{
    try {
        importIvFile("/nonexistent/x.iv");
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "/nonexistent/x.iv: cannot open file (No such file or directory)");
    }
}

TEST(IvImport, GivenTheSeedCorpus_ThenValidSeedsImportAndBadOnesAreRefused)
{
    int good = 0, bad = 0;
    for (const auto& entry : std::filesystem::directory_iterator(SCULPTLINE_IV_CORPUS)) {
        const std::string name = entry.path().filename();
        bool accepted = true;
        std::string why;
        try {
            importIvFile(entry.path());
        } catch (const InputError& e) {
            accepted = false;
            why = e.what();
        }
        if (name.rfind("bad_", 0) == 0 || name.rfind("crash-", 0) == 0) {
            EXPECT_FALSE(accepted) << name;
            ++bad;
        } else if (name.rfind("timeout-", 0) != 0) {
            EXPECT_TRUE(accepted) << name << ": " << why;
            ++good;
        }
    }
    EXPECT_GE(good, 5);
    EXPECT_GE(bad, 10);
}

}  // namespace
