// Solids from surfaces through level sets (solvers/volume/solidify.h), against analytic volumes.
// Given / When / Then.
#include "solvers/volume/solidify.h"
#include "tests/volume/test_shapes.h"

#include "solvers/bspline/geometry_error.h"
#include "solvers/math_constants.h"

#include <gtest/gtest.h>

namespace vol = sculptline::solvers::volume;
using sculptline::solvers::GeometryError;
using sculptline::solvers::kPi;
using namespace sculptline::volume_test;

namespace {

// The goals: a sphere at the default voxel size within 1 % of 4/3πr³; a shell within 2 % of
// area × thickness (a distance-field shell with rounded rims is 7.9 % over on a 20 × 20 × 1 patch:
// perimeter 80 × πt²/8 = 31.4 on 400).
constexpr double kSphereVolume = 0.01;
constexpr double kShellVolume = 0.02;
// Area from LevelSetMeasure: the smeared delta function is exact to O(voxel²); 2 % on a sphere
// resolved by ~115 voxels across.
constexpr double kArea = 0.02;

double sphereVolume(double r) { return 4.0 / 3.0 * kPi * r * r * r; }

template <typename F>
std::string errorOf(F&& f)
{
    try {
        f();
    } catch (const GeometryError& e) {
        return e.what();
    }
    return "(no GeometryError)";
}

}  // namespace

TEST(Solidify, GivenARevolvedSphereOfRadius10_WhenSolidifiedAtTheDefaultVoxel_ThenItsVolumeWithin1Percent)
{
    const double r = 10.0;

    const vol::Solid solid = vol::solidify({sphere(r)});

    EXPECT_NEAR(solid.volume, sphereVolume(r), kSphereVolume * sphereVolume(r));
    EXPECT_NEAR(solid.area, 4.0 * kPi * r * r, kArea * 4.0 * kPi * r * r);
    EXPECT_TRUE(solid.watertight);
    // Default voxel: bounding-box diagonal (20√3) / 200.
    EXPECT_NEAR(solid.voxelSize, 20.0 * std::sqrt(3.0) / vol::kDefaultVoxelsAcrossDiagonal, 1e-9);
    // Every mesh vertex on the sphere to within a voxel.
    for (const Eigen::Vector3d& p : solid.mesh.vertices) ASSERT_NEAR(p.norm(), r, solid.voxelSize);
}

TEST(Solidify, GivenA100mmPatch_WhenThickened1mm_ThenVolumeIsAreaTimesThicknessWithin2Percent)
{
    const double t = 1.0;
    vol::SolidOptions options;
    options.thickness = t;

    const vol::Solid solid = vol::solidify({flatPatch(100, 100)}, options);

    EXPECT_NEAR(solid.volume, 100.0 * 100.0 * t, kShellVolume * 100.0 * 100.0 * t);
    EXPECT_TRUE(solid.watertight);
    EXPECT_NEAR(solid.voxelSize, t / vol::kDefaultVoxelsAcrossThickness, 1e-12);
}

TEST(Solidify, GivenA20mmPatch_WhenThickened1mm_ThenSquareEdgesNotADistanceFieldsRoundedRim)
{
    const double t = 1.0;
    vol::SolidOptions options;
    options.thickness = t;

    const vol::Solid solid = vol::solidify({flatPatch(20, 20)}, options);

    // Square edges: 400 mm³. A rounded rim would be 431.4 mm³, 7.9 % over, outside the tolerance.
    EXPECT_NEAR(solid.volume, 400.0 * t, kShellVolume * 400.0 * t);
    EXPECT_TRUE(solid.watertight);
    // The walls stand on the patch's edges: the mesh spans [0, 20]² (a distance field reaches
    // t/2 = 2 voxels beyond), and its full thickness at them.
    const auto [lo, hi] = vol::bounds(solid.mesh.vertices);
    const double v = solid.voxelSize;
    EXPECT_NEAR(lo.x(), 0.0, 0.5 * v);
    EXPECT_NEAR(hi.y(), 20.0, 0.5 * v);
    EXPECT_NEAR(lo.z(), -0.5 * t, 0.5 * v);
    EXPECT_NEAR(hi.z(), 0.5 * t, 0.5 * v);
    bool fullHeightAtTheEdge = false;
    for (const Eigen::Vector3d& p : solid.mesh.vertices)
        fullHeightAtTheEdge |= p.x() > 20.0 - v && std::abs(p.z()) > 0.5 * t - 0.5 * v;
    EXPECT_TRUE(fullHeightAtTheEdge);
}

TEST(Solidify, GivenTwoOverlappingSpheres_WhenSolidified_ThenTheirUnionsVolumeByTheLensFormula)
{
    const double r = 10.0, d = 12.0;

    const vol::Solid solid = vol::solidify({sphere(r), sphere(r, Eigen::Vector3d(d, 0, 0))});

    EXPECT_NEAR(solid.volume, twoBallUnionVolume(r, d), kSphereVolume * twoBallUnionVolume(r, d));
    EXPECT_TRUE(solid.watertight);
    // No internal faces where the spheres overlap: nothing of the mesh inside both balls.
    for (const Eigen::Vector3d& p : solid.mesh.vertices)
        ASSERT_FALSE(p.norm() < r - solid.voxelSize && (p - Eigen::Vector3d(d, 0, 0)).norm() < r - solid.voxelSize);
}

TEST(Solidify, GivenSixFacesOfACube_WhenSolidifiedWithoutThickness_ThenTheCubeTheyEnclose)
{
    const double a = 10.0;

    const vol::Solid solid = vol::solidify(cubeFaces(a));

    EXPECT_NEAR(solid.volume, a * a * a, kSphereVolume * a * a * a);
    EXPECT_TRUE(solid.watertight);
}

TEST(Solidify, GivenAPatchWithoutThickness_WhenSolidified_ThenItEnclosesNothingAndTheErrorSaysSo)
{
    const std::string message = errorOf([] { vol::solidify({flatPatch(10, 10)}); });
    EXPECT_EQ(message.rfind("surfaces[0]: is open", 0), 0u) << message;
    EXPECT_NE(message.find("thickness"), std::string::npos) << message;
}

TEST(Solidify, GivenFiveFacesOfACube_WhenSolidifiedWithoutThickness_ThenTheOpenFaceIsNamed)
{
    std::vector<sculptline::solvers::Surface3d> faces = cubeFaces(10.0);
    faces.pop_back();  // the face x = a is missing: faces 0..3 have an unmatched edge there, 4 does not
    const std::string message = errorOf([&] { vol::solidify(faces); });
    EXPECT_EQ(message.rfind("surfaces[0]: is open", 0), 0u) << message;
}

TEST(Solidify, GivenNonFiniteOrNegativeOptions_WhenSolidified_ThenTheFieldIsNamed)
{
    vol::SolidOptions nanThickness;
    nanThickness.thickness = std::nan("");
    EXPECT_EQ(errorOf([&] { vol::solidify({flatPatch(10, 10)}, nanThickness); }).rfind("thickness:", 0), 0u);
    vol::SolidOptions negative;
    negative.thickness = -1.0;
    EXPECT_EQ(errorOf([&] { vol::solidify({flatPatch(10, 10)}, negative); }).rfind("thickness:", 0), 0u);
    vol::SolidOptions nanVoxel;
    nanVoxel.voxelSize = std::nan("");
    EXPECT_EQ(errorOf([&] { vol::solidify({sphere(1.0)}, nanVoxel); }).rfind("voxel_size:", 0), 0u);
    vol::SolidOptions infVoxel;
    infVoxel.voxelSize = std::numeric_limits<double>::infinity();
    EXPECT_EQ(errorOf([&] { vol::solidify({sphere(1.0)}, infVoxel); }).rfind("voxel_size:", 0), 0u);
    EXPECT_EQ(errorOf([] { vol::solidify({}); }).rfind("surfaces:", 0), 0u);
}

TEST(Solidify, GivenAVoxelSizeNeedingTooMuchMemory_WhenSolidified_ThenRefusedBeforeAnyConversion)
{
    // A sphere of radius 10 at a micrometre voxel: 1257 mm² / 1e-6 mm² × 6 ≈ 7.5e9 voxels.
    vol::SolidOptions options;
    options.voxelSize = 1e-3;

    const std::string message = errorOf([&] { vol::solidify({sphere(10.0)}, options); });

    EXPECT_EQ(message.rfind("voxel_size: 0.001 would need about", 0), 0u) << message;
    EXPECT_NE(message.find("use a voxel size of at least"), std::string::npos) << message;
}

TEST(Solidify, GivenALimit_WhenTheSuggestedVoxelSizeIsUsed_ThenTheEstimateFits)
{
    // The message's suggestion is the voxel at which the estimate meets the limit.
    const double area = 4.0 * kPi * 100.0;
    const double limit = 64.0 * 1024 * 1024;
    const double voxel = 1e-3;
    const double suggested = voxel * std::sqrt(vol::estimateMemory(area, voxel) / limit);
    EXPECT_NEAR(vol::estimateMemory(area, suggested), limit, 1e-6 * limit);
    EXPECT_LE(vol::defaultMemoryLimit(), 2.0 * 1024 * 1024 * 1024);
    EXPECT_GT(vol::defaultMemoryLimit(), 0.0);
}

TEST(Solidify, GivenAShellThinnerThanTwoVoxels_WhenSolidified_ThenTheErrorAsksForASmallerVoxel)
{
    // Unrefused, a 1e-3 thick shell at voxel 1 measured 59 mm³ instead of 0.1 mm³.
    vol::SolidOptions options;
    options.thickness = 1e-3;
    options.voxelSize = 1.0;
    const std::string message = errorOf([&] { vol::solidify({flatPatch(10, 10)}, options); });
    EXPECT_EQ(message.rfind("thickness: 0.001 is less than 2 voxels", 0), 0u) << message;
    EXPECT_NE(message.find("voxel_size of at most 0.0005"), std::string::npos) << message;
}

TEST(Solidify, GivenASolidSmallerThanTwoVoxels_WhenSolidified_ThenTheErrorNamesItAndAFittingVoxel)
{
    // Unrefused, a sphere of radius 0.01 at voxel 1 came out as a voxel-sized blob.
    vol::SolidOptions options;
    options.voxelSize = 1.0;
    const std::string message = errorOf([&] { vol::solidify({sphere(10.0), sphere(0.01, {30, 0, 0})}, options); });
    EXPECT_EQ(message.rfind("voxel_size: 1 is more than 1/2 of the smallest extent", 0), 0u) << message;
    EXPECT_NE(message.find("of surfaces[1]"), std::string::npos) << message;
}

TEST(Solidify, GivenASphereFarFromTheOriginOrOfHugeSize_WhenSolidified_ThenTheSameRelativeVolume)
{
    // The work is done relative to the model's centre, in voxel units: a float world coordinate at
    // 1e6 would have a resolution of 0.06, a third of the default voxel; 1e100 does not fit a float.
    // (Far from the origin the kernel's tessellation also refined on round-off: 20 s, not 20 ms.)
    const vol::Solid far = vol::solidify({sphere(10.0, {1e6, -2e6, 3e6})});
    EXPECT_NEAR(far.volume, sphereVolume(10.0), kSphereVolume * sphereVolume(10.0));
    EXPECT_TRUE(far.watertight);

    const vol::Solid huge = vol::solidify({sphere(1e100)});
    EXPECT_NEAR(huge.volume / sphereVolume(1e100), 1.0, kSphereVolume);
    EXPECT_TRUE(huge.watertight);

    // A patch of (1e160)² has an area that overflows a double: refused, not reported as infinity.
    vol::SolidOptions shell;
    shell.thickness = 1e159;
    const std::string message = errorOf([&] { vol::solidify({flatPatch(1e160, 1e160)}, shell); });
    EXPECT_EQ(message.rfind("surfaces: the model's area overflows", 0), 0u) << message;
}
