// The solid entity (model/model.h EntityKind::Solid, model/solid_job.h, model/document_solids.h):
// made from surfaces, due again when they change, converted outside update(), saved and read back,
// removed and restored with its surfaces. Given / When / Then.
#include "model/document.h"
#include "model/model.h"
#include "model/model_document.h"
#include "model/solid_job.h"
#include "solvers/io/geometry_json.h"
#include "solvers/math_constants.h"
#include "tests/volume/test_shapes.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

using namespace sculptline;
using model::EntityId;

// The sphere goal of the solids (solvers/volume/solidify.h): within 1 % of 4/3·π·r³ at the default voxel.
constexpr double kSphereVolume = 0.01;

double sphereVolume(double r) { return 4.0 / 3.0 * solvers::kPi * r * r * r; }

model::SolidRecipe closedRecipe() { return {model::SolidMode::Closed, 0.0, 0.0}; }

/// The sphere's control net scaled about the origin (B-splines are affine invariant: a sphere of
/// radius factor·r).
solvers::Surface3d scaled(const solvers::Surface3d& s, double factor)
{
    std::vector<Eigen::Vector3d> points = s.points();
    for (Eigen::Vector3d& p : points) p *= factor;
    return solvers::Surface3d(s.degreeU(), s.degreeV(), s.knotsU(), s.knotsV(), s.countU(), s.countV(), points, s.weights());
}

struct SphereSolid {
    model::Model m;
    EntityId surface = 0, solid = 0;
    SphereSolid()
    {
        surface = m.addSurface(volume_test::sphere(10.0));
        solid = m.addSolid({surface}, closedRecipe());
    }
};

}  // namespace

TEST(SolidEntity, GivenANewSolid_WhenConverted_ThenItIsCurrentWatertightAndHasTheSpheresVolume)
{
    SphereSolid s;
    ASSERT_TRUE(s.m.find(s.solid)->solidStale()) << "added without a result: due";

    const int converted = model::convertStaleSolids(s.m);

    const model::Entity& e = *s.m.find(s.solid);
    EXPECT_EQ(converted, 1);
    EXPECT_FALSE(e.solidStale());
    ASSERT_TRUE(e.solid);
    EXPECT_TRUE(e.solid->watertight);
    EXPECT_NEAR(e.solid->volume, sphereVolume(10.0), kSphereVolume * sphereVolume(10.0));
    EXPECT_TRUE(e.buildError.empty());
}

TEST(SolidEntity, GivenAConvertedSolid_WhenItsSurfaceChanges_ThenUpdateMarksItDueWithoutConvertingAndAnOldResultIsRefused)
{
    SphereSolid s;
    model::convertStaleSolids(s.m);
    const model::SolidJob before = model::solidJob(s.m, s.solid);
    const double oldVolume = s.m.find(s.solid)->solid->volume;

    s.m.setSurfaceShape(s.surface, scaled(volume_test::sphere(10.0), 1.5));
    s.m.update();

    const model::Entity& e = *s.m.find(s.solid);
    EXPECT_TRUE(e.solidStale());
    EXPECT_EQ(e.solid->volume, oldVolume) << "update() does not convert; the last mesh stays shown";
    EXPECT_EQ(s.m.plan().steps.at(s.m.plan().stepOf.at(s.solid)).solver, "solid");
    // A conversion taken before the change arrives late: it is not the present surfaces' solid.
    EXPECT_FALSE(s.m.setSolidResult(s.solid, before.version, model::runSolidJob(before)));
    EXPECT_TRUE(s.m.find(s.solid)->solidStale());

    model::convertStaleSolids(s.m);
    EXPECT_NEAR(s.m.find(s.solid)->solid->volume, sphereVolume(15.0), kSphereVolume * sphereVolume(15.0));
}

TEST(SolidEntity, GivenASolid_WhenSavedAndReadBack_ThenTheRecipeAndTheResultComeBackUnchanged)
{
    SphereSolid s;
    model::convertStaleSolids(s.m);
    const model::Entity& saved = *s.m.find(s.solid);

    const nlohmann::json j = model::modelToJson(s.m, {});
    model::Model read;
    model::populateModel(model::documentFromJson(j), read);

    const model::Entity* e = read.find(s.solid);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->kind, model::EntityKind::Solid);
    EXPECT_EQ(e->inputs, std::vector<EntityId>{s.surface});
    EXPECT_EQ(*e->solidRecipe, *saved.solidRecipe);
    EXPECT_FALSE(e->solidStale()) << "the saved result is current: no conversion on opening";
    ASSERT_TRUE(e->solid);
    EXPECT_EQ(e->solid->mesh.vertices, saved.solid->mesh.vertices);
    EXPECT_EQ(e->solid->mesh.triangles, saved.solid->mesh.triangles);
    EXPECT_EQ(e->solid->volume, saved.solid->volume);
    EXPECT_TRUE(e->solid->watertight);
}

TEST(SolidEntity, GivenAShellRecipeWithoutResult_WhenSavedAndReadBack_ThenItIsDueAndKeepsItsThickness)
{
    model::Model m;
    const EntityId patch = m.addSurface(volume_test::flatPatch(20.0, 20.0));
    const EntityId solid = m.addSolid({patch}, {model::SolidMode::Shell, 1.0, 0.25});

    model::Model read;
    model::populateModel(model::documentFromJson(model::modelToJson(m, {})), read);

    const model::Entity& e = *read.find(solid);
    EXPECT_TRUE(e.solidStale());
    EXPECT_EQ(e.solidRecipe->mode, model::SolidMode::Shell);
    EXPECT_EQ(e.solidRecipe->thickness, 1.0);
    EXPECT_EQ(e.solidRecipe->voxelSize, 0.25);
}

TEST(SolidEntity, GivenBadSolidEntries_WhenRead_ThenEachIsRefusedNamingTheField)
{
    SphereSolid s;
    model::convertStaleSolids(s.m);
    const nlohmann::json good = model::modelToJson(s.m, {});
    const auto errorOf = [](nlohmann::json j) {
        try {
            model::documentFromJson(j);
        } catch (const solvers::io::InputError& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };

    nlohmann::json notASurface = good;
    notASurface["solids"][0]["surfaces"] = {99};
    nlohmann::json badIndex = good;
    badIndex["solids"][0]["result"]["mesh"]["triangles"][0] = {0, 1, 1000000};
    nlohmann::json shellWithoutThickness = good;
    shellWithoutThickness["solids"][0]["mode"] = "shell";
    nlohmann::json badMode = good;
    badMode["solids"][0]["mode"] = "hollow";

    EXPECT_EQ(errorOf(notASurface), "solids[0].surfaces[0]: no surface has id 99");
    EXPECT_EQ(errorOf(badIndex).rfind("solids[0].result.mesh.triangles[0][2]", 0), 0u) << errorOf(badIndex);
    EXPECT_EQ(errorOf(shellWithoutThickness), "solids[0].thickness: a shell needs a thickness > 0");
    EXPECT_EQ(errorOf(badMode), "solids[0].mode: must be \"closed\" or \"shell\"");
}

TEST(SolidEntity, GivenAConvertedSolid_WhenItsSurfaceIsRemovedAndRestored_ThenTheSolidComesBackCurrent)
{
    SphereSolid s;
    model::convertStaleSolids(s.m);
    const double volume = s.m.find(s.solid)->solid->volume;

    const model::Removed removed = s.m.remove(s.surface);
    EXPECT_EQ(s.m.find(s.solid), nullptr) << "a solid goes with its surfaces";
    s.m.restore(removed);

    const model::Entity* e = s.m.find(s.solid);
    ASSERT_TRUE(e);
    EXPECT_FALSE(e->solidStale());
    EXPECT_EQ(e->solid->volume, volume);
}

TEST(SolidEntity, GivenInvalidInputs_WhenAdded_ThenRefused)
{
    model::Model m;
    const EntityId plane = m.addPlane(model::PlaneFrame::fromNormal(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 10.0));
    const EntityId surface = m.addSurface(volume_test::flatPatch(10.0, 10.0));

    EXPECT_THROW(m.addSolid({}, closedRecipe()), std::invalid_argument);
    EXPECT_THROW(m.addSolid({plane}, closedRecipe()), std::invalid_argument);
    EXPECT_THROW(m.addSolid({surface}, {model::SolidMode::Shell, 0.0, 0.0}), std::invalid_argument);
    EXPECT_THROW(m.addSolid({surface}, {model::SolidMode::Closed, 0.0, -1.0}), std::invalid_argument);
    EXPECT_EQ(m.entities().size(), 2u);
}

TEST(SolidEntity, GivenAnOpenPatchAsAClosedSolid_WhenConverted_ThenTheErrorIsRecordedAndTheSolidKept)
{
    model::Model m;
    const EntityId patch = m.addSurface(volume_test::flatPatch(10.0, 10.0));
    const EntityId solid = m.addSolid({patch}, closedRecipe());

    model::convertStaleSolids(m);

    const model::Entity& e = *m.find(solid);
    EXPECT_FALSE(e.solid);
    EXPECT_NE(e.buildError.find("enclose nothing"), std::string::npos) << e.buildError;
}
