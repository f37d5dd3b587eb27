// Documents whose constructed surfaces cannot be rebuilt open anyway: the surface is kept, marked
// failed with the reason, with no geometry when none was saved, and every other entity is intact;
// saving writes the construction back unchanged, so opening such a document loses nothing.
// Headless (the model and its documents, Coin nodes without a window).
#include "model/model.h"
#include "model/model_document.h"
#include "scene/model_view.h"
#include "model/document.h"

#include <Inventor/SoDB.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace sculptline::scene {
namespace {

using nlohmann::json;

json cubicJson(int id, const std::vector<std::vector<double>>& points)
{
    return {{"id", id}, {"degree", 3}, {"knots", {0, 0, 0, 0, 1, 1, 1, 1}}, {"points", points}};
}

/// A closed (periodic) cubic through a square's corners, in the unwrapped convention of
/// ../shared/interfaces.md: 4 unique points, the first 3 repeated, uniform knots.
json closedJson(int id)
{
    return {{"id", id},
            {"degree", 3},
            {"closed", true},
            {"knots", {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10}},
            {"points", {{0, 0, 0}, {40, 0, 0}, {40, 40, 0}, {0, 40, 0}, {0, 0, 0}, {40, 0, 0}, {40, 40, 0}}}};
}

const json kProfile = cubicJson(1, {{10, 0, 0}, {14, 0, 10}, {9, 0, 20}, {12, 0, 30}});
const json kOther = cubicJson(2, {{-30, 5, 0}, {-10, 5, 10}, {10, 5, 10}, {30, 5, 0}});
const json kCollapsed = cubicJson(3, {{7, 7, 7}, {7, 7, 7}, {7, 7, 7}, {7, 7, 7}});

struct BrokenDocument {
    std::string name;
    json curves;  ///< curves with ids 1..; the surface gets id 100
    json construction;
    /// False where the solver may instead meet the request another way (a tolerance below what
    /// double precision can reach is clamped to what it can): the document must open either way.
    bool mustFail = true;
};

void PrintTo(const BrokenDocument& d, std::ostream* out) { *out << d.name; }

std::vector<BrokenDocument> brokenDocuments()
{
    const json lineA = cubicJson(1, {{0, 0, 0}, {10, 0, 0}, {20, 0, 0}, {30, 0, 0}});
    const json lineB = cubicJson(2, {{0, 50, 5}, {10, 50, 5}, {20, 50, 5}, {30, 50, 5}});
    const json lineC = cubicJson(3, {{60, 0, 9}, {60, 10, 9}, {60, 20, 9}, {60, 30, 9}});
    const json lineD = cubicJson(4, {{-60, 0, -9}, {-60, 10, -9}, {-60, 20, -9}, {-60, 30, -9}});
    // A Gordon network whose families lie 50 apart: no curve crosses another.
    const json u0 = cubicJson(1, {{0, 0, 0}, {10, 0, 0}, {20, 0, 0}, {30, 0, 0}});
    const json u1 = cubicJson(2, {{0, 30, 0}, {10, 30, 0}, {20, 30, 0}, {30, 30, 0}});
    const json v0 = cubicJson(3, {{0, 0, 50}, {0, 10, 50}, {0, 20, 50}, {0, 30, 50}});
    const json v1 = cubicJson(4, {{30, 0, 50}, {30, 10, 50}, {30, 20, 50}, {30, 30, 50}});
    return {
        {"revolve_about_a_closed_curve", {kProfile, closedJson(2)}, {{"mode", "revolve"}, {"curves", {1, 2}}}},
        {"fill_of_curves_that_do_not_meet", {lineA, lineB, lineC, lineD}, {{"mode", "fill"}, {"curves", {1, 2, 3, 4}}}},
        {"fill_of_one_curve_four_times", {kProfile}, {{"mode", "fill"}, {"curves", {1, 1, 1, 1}}}},
        {"gordon_of_curves_that_do_not_cross", {u0, u1, v0, v1}, {{"mode", "gordon"}, {"curves", {1, 2, 3, 4}}, {"u_curves", 2}}},
        {"extrude_by_zero", {kProfile}, {{"mode", "extrude"}, {"curves", {1}}, {"direction", {0, 0, 0}}}},
        {"extrude_by_1e_plus_300", {kProfile}, {{"mode", "extrude"}, {"curves", {1}}, {"direction", {0, 1e300, 0}}}},
        {"extrude_by_1e_minus_300", {kProfile}, {{"mode", "extrude"}, {"curves", {1}}, {"direction", {0, 1e-300, 0}}}},
        {"rail_rotation_on_open_rails", {kProfile, kOther, cubicJson(3, {{10, 0, 0}, {0, 3, 10}, {-10, 4, 20}, {-12, 5, 30}})},
         {{"mode", "rail-rotation"}, {"curves", {1, 2, 3}}}},
        {"identical_boundary_rotation_outlines", {kOther, cubicJson(3, {{-30, 5, 0}, {-10, 5, 10}, {10, 5, 10}, {30, 5, 0}})},
         {{"mode", "boundary-rotation"}, {"curves", {2, 3}}}},
        {"sweep_with_tolerance_1e_minus_300", {kProfile, kOther}, {{"mode", "sweep"}, {"curves", {1, 2}}, {"tolerance", 1e-300}}, false},
        {"collapsed_profile", {kCollapsed, kOther}, {{"mode", "sweep"}, {"curves", {3, 2}}}},
        {"network_used_as_a_surface", {kProfile, kOther}, {{"mode", "network"}, {"curves", {1, 2}}}},
    };
}

class BrokenConstruction : public ::testing::TestWithParam<BrokenDocument> {
protected:
    static void SetUpTestSuite() { SoDB::init(); }

    /// The document: its curves, a plane with a curve of its own, the broken surface (id 100).
    json document() const
    {
        json curves = GetParam().curves;
        curves.push_back({{"id", 51}, {"plane", 50}, {"degree", 1}, {"knots", {0, 0, 1, 1}}, {"points", {{0, 0}, {10, 10}}}});
        json planes = json::array({{{"id", 50}, {"origin", {0, 0, 0}}, {"normal", {0, 0, 1}}, {"size", 100}}});
        json surface{{"id", 100}, {"construction", GetParam().construction}};
        return {{"units", "mm"}, {"planes", planes}, {"curves", curves}, {"surfaces", json::array({surface})}};
    }
};

TEST_P(BrokenConstruction, TheDocumentOpensWithTheSurfaceMarkedFailedAndEverythingElseIntact)
{
    // Given a document whose only surface cannot be built from its curves
    const json doc = document();
    const model::SceneDocument read = model::documentFromJson(doc);

    // When it is opened
    model::Model model;
    ASSERT_NO_THROW(model::populateModel(read, model));

    // Then the surface is there, failed, with a reason and no geometry (or, where the request can
    // be met another way, built); the rest is intact
    const model::Entity* surface = model.find(100);
    ASSERT_NE(surface, nullptr);
    if (GetParam().mustFail || surface->failed()) {
        EXPECT_TRUE(surface->failed());
        EXPECT_FALSE(surface->buildError.empty());
        EXPECT_FALSE(surface->surface.has_value());
    }
    ASSERT_NE(model.find(50), nullptr);
    ASSERT_NE(model.find(51), nullptr);
    for (const json& c : doc["curves"]) EXPECT_NE(model.find(c["id"].get<model::EntityId>()), nullptr) << c["id"];
}

TEST_P(BrokenConstruction, SavingWritesTheConstructionBackUnchanged)
{
    // Given the opened document
    model::Model model;
    model::populateModel(model::documentFromJson(document()), model);

    // When it is saved and read again
    const json saved = model::modelToJson(model, model::GridSpec{});
    model::Model reopened;
    model::populateModel(model::documentFromJson(saved), reopened);

    // Then the construction is the one read (nothing lost), still failed
    ASSERT_EQ(saved["surfaces"].size(), 1u);
    const json& construction = saved["surfaces"][0]["construction"];
    EXPECT_EQ(construction["mode"], GetParam().construction["mode"]);
    EXPECT_EQ(construction["curves"], GetParam().construction["curves"]);
    ASSERT_NE(reopened.find(100), nullptr);
    EXPECT_EQ(reopened.find(100)->failed(), model.find(100)->failed());
    EXPECT_EQ(reopened.entities().size(), model.entities().size());
}

TEST_P(BrokenConstruction, TheViewShowsNothingForItAndTheRestAsUsual)
{
    // Given the opened document shown by a Coin view
    model::Model model;
    ModelView view(model);
    model::populateModel(model::documentFromJson(document()), model);

    // Then the failed surface has a node (empty) and the plane's curve is drawn
    SoNode* node = SoNode::getByName(SbName("Surface100"));
    ASSERT_NE(node, nullptr);
    if (GetParam().mustFail || model.find(100)->failed()) {
        EXPECT_EQ(static_cast<SoSeparator*>(node)->getNumChildren(), 0);
    }
    EXPECT_NE(SoNode::getByName(SbName("Curve51")), nullptr);
}

INSTANTIATE_TEST_SUITE_P(Documents, BrokenConstruction, ::testing::ValuesIn(brokenDocuments()),
                         [](const ::testing::TestParamInfo<BrokenDocument>& info) { return info.param.name; });

TEST(FailedSurface, ItBuildsOnceItsCurvesAllowAndItsDependentsFollow)
{
    // Given a fill of four lines that do not meet, opened as a failed surface
    const json doc = {
        {"curves",
         {cubicJson(1, {{0, 0, 0}, {10, 0, 0}, {20, 0, 0}, {30, 0, 0}}), cubicJson(2, {{30, 0, 0}, {30, 10, 0}, {30, 20, 0}, {30, 30, 0}}),
          cubicJson(3, {{30, 30, 0}, {20, 30, 0}, {10, 30, 0}, {0, 30, 0}}), cubicJson(4, {{0, 31, 0}, {0, 20, 0}, {0, 10, 0}, {0, 1, 0}})}},
        {"surfaces", json::array({{{"id", 10}, {"construction", {{"mode", "fill"}, {"curves", {1, 2, 3, 4}}}}}})}};
    model::Model model;
    model::populateModel(model::documentFromJson(doc), model);
    ASSERT_TRUE(model.find(10)->failed());

    // When the last curve is redrawn so that the loop closes
    model.setCurveShape(4, solvers::Curve3d(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 30, 0}, {0, 20, 0}, {0, 10, 0}, {0, 0, 0}}));
    model.update();

    // Then the fill is built
    EXPECT_FALSE(model.find(10)->failed());
    EXPECT_TRUE(model.find(10)->surface.has_value());
}

TEST(FailedSurface, AnExtrusionFarBeyondTheSceneOpensAndWhatItSavesReopens)
{
    // Given an extrusion 2e11 long of a unit line (built: the direction is finite and the solver
    // can use it; its surface reaches far beyond the 1e6 the reader allows for curves)
    const json doc = {{"curves", {cubicJson(1, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}})}},
                      {"surfaces", json::array({{{"id", 2}, {"construction", {{"mode", "extrude"}, {"curves", {1}}, {"direction", {0, 0, 2e11}}}}}})}};
    model::Model model;
    model::populateModel(model::documentFromJson(doc), model);

    // When it is saved and opened again
    model::Model reopened;
    ASSERT_NO_THROW(model::populateModel(model::documentFromJson(model::modelToJson(model, model::GridSpec{})), reopened));

    // Then it is the same surface, in the same state
    ASSERT_NE(reopened.find(2), nullptr);
    EXPECT_EQ(reopened.find(2)->failed(), model.find(2)->failed());
    EXPECT_EQ(reopened.find(2)->surface.has_value(), model.find(2)->surface.has_value());
}

}  // namespace
}  // namespace sculptline::scene
