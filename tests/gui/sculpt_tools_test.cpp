// Checks the Sculpt mode's click tools replayed under Xvfb through the real Qt event path
// (tests/gui/CMakeLists.txt runs `sculptline <start> --replay data/sessions/sculpt_*.json --save`
// first; the sessions are written by data/sessions/make_models.py): a handle dropped on the sheet and
// its jack dragged up and turned (the sculpt passes through the point, its normal turned with it;
// undo gives the flat sheet back), the local bump inside a bound (thesis Figs. 6-9, 6-13: control
// points outside stay exactly), a blocked control point (Fig. 6-7) and a distance held. Files are in
// $SCULPTLINE_REPLAY_DIR.
#include "tests/gui/replayed_model.h"
#include "model/model.h"
#include "model/model_document.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace sculptline {
namespace {

/// Handles and distances are met by the solve to round-off.
constexpr double kMet = 1e-6;

model::Model readModel(const std::string& name) { return guitest::readReplayedModel(name); }

const model::Entity* sculptOf(const model::Model& model)
{
    for (const auto& [id, e] : model.entities()) {
        if (e.kind == model::EntityKind::Surface && e.recipe && e.recipe->mode == model::Construction::Sculpt) return &e;
    }
    return nullptr;
}

std::vector<double> greville(const std::vector<double>& knots, int degree, int count)
{
    std::vector<double> out;
    for (int i = 0; i < count; ++i) {
        double sum = 0.0;
        for (int k = 1; k <= degree; ++k) sum += knots[static_cast<size_t>(i + k)];
        out.push_back(sum / degree);
    }
    return out;
}

bool insidePolygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p)
{
    bool inside = false;
    for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Eigen::Vector2d& a = polygon[i];
        const Eigen::Vector2d& b = polygon[j];
        if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) inside = !inside;
    }
    return inside;
}

/// The handle's point and the sculpt surface there.
void expectHandleMet(const model::Model& model, const model::Entity& sculpt)
{
    ASSERT_EQ(sculpt.recipe->handles.size(), 1u);
    const model::SurfaceRecipe::Handle& h = sculpt.recipe->handles.front();
    const model::Entity* point = model.find(h.point);
    ASSERT_NE(point, nullptr);
    EXPECT_EQ(point->kind, model::EntityKind::Point);
    const double miss = (sculpt.surface->evaluate(h.uv.x(), h.uv.y()) - point->position).norm();
    EXPECT_LT(miss, kMet) << "the sculpt misses its handle by " << miss;
}

TEST(SculptTools, AHandleDraggedUpAndTurnedCarriesTheSurface)
{
    // sculpt_handle.json: the sheet (2) selected, Y, Alt+H, a click at (-10, 20, 0), the jack's
    // centre dragged to (-10, 20, 20), then the end of its x axis carried 30 degrees up
    const model::Model model = readModel("sculpt_handle.json");
    const model::Entity* sculpt = sculptOf(model);
    ASSERT_NE(sculpt, nullptr);
    EXPECT_EQ(sculpt->inputs.front(), 2u);
    EXPECT_FALSE(sculpt->failed()) << sculpt->buildError;
    expectHandleMet(model, *sculpt);
    const model::SurfaceRecipe::Handle& h = sculpt->recipe->handles.front();
    const model::Entity& point = *model.find(h.point);
    // The point went up with the jack (the pointer reaches where it aims within a few pixels)
    EXPECT_NEAR(point.position.z(), 20.0, 1.5);
    EXPECT_NEAR(point.position.x(), -10.0, 1.5);
    EXPECT_NEAR(point.position.y(), 20.0, 1.5);
    // And was turned about -y by about 30 degrees (the rotator's sphere under the pointer)
    const Eigen::AngleAxisd turn(point.rotation);
    EXPECT_NEAR(turn.angle() * 180.0 / M_PI, 30.0, 5.0);
    EXPECT_GT(-turn.axis().y(), 0.99);
    // The sculpt's normal there is the base's (flat: +z) turned by the point's rotation (Fig. 6-5 d)
    EXPECT_TRUE(h.holdNormal);
    const Eigen::Vector3d normal = sculpt->surface->normal(h.uv.x(), h.uv.y()).normalized();
    const Eigen::Vector3d expected = point.rotation * model.find(2)->surface->normal(h.uv.x(), h.uv.y()).normalized();
    EXPECT_LT(normal.cross(expected).norm(), kMet) << normal.transpose() << " vs " << expected.transpose();
}

TEST(SculptTools, UndoingTheTurnAndTheDragGivesTheSheetBack)
{
    // sculpt_handle_undo.json: the same, then Ctrl+Z twice
    const model::Model model = readModel("sculpt_handle_undo.json");
    const model::Entity* sculpt = sculptOf(model);
    ASSERT_NE(sculpt, nullptr);
    expectHandleMet(model, *sculpt);
    const model::Entity& point = *model.find(sculpt->recipe->handles.front().point);
    EXPECT_EQ(point.position.z(), 0.0);
    EXPECT_EQ(point.rotation.coeffs(), Eigen::Quaterniond::Identity().coeffs());
    const std::vector<Eigen::Vector3d>& base = model.find(2)->surface->points();
    const std::vector<Eigen::Vector3d>& now = sculpt->surface->points();
    ASSERT_EQ(base.size(), now.size());
    for (size_t k = 0; k < base.size(); ++k) EXPECT_LT((now[k] - base[k]).norm(), 1e-9) << k;
}

TEST(SculptTools, ABumpInsideItsBoundLeavesTheRestOfTheNetExactly)
{
    // sculpt_bump.json (on sculpt_bump_start.json): a loop of radius 38 mm round the sheet's middle
    // drawn with the Bound tool (Alt+B), a handle dropped in its centre (Alt+H), its jack pulled
    // 25 mm up
    const model::Model model = readModel("sculpt_bump.json");
    const model::Entity* sculpt = sculptOf(model);
    ASSERT_NE(sculpt, nullptr);
    EXPECT_FALSE(sculpt->failed()) << sculpt->buildError;
    ASSERT_GE(sculpt->recipe->bound.size(), 16u);
    expectHandleMet(model, *sculpt);
    EXPECT_NEAR(model.find(sculpt->recipe->handles.front().point)->position.z(), 25.0, 1.5);
    const solvers::Surface3d& base = *model.find(2)->surface;
    const solvers::Surface3d& s = *sculpt->surface;
    const std::vector<double> gu = greville(base.knotsU(), base.degreeU(), base.countU());
    const std::vector<double> gv = greville(base.knotsV(), base.degreeV(), base.countV());
    int outside = 0, moved = 0;
    double top = 0.0;
    for (int i = 0; i < base.countU(); ++i) {
        for (int j = 0; j < base.countV(); ++j) {
            const bool in = insidePolygon(sculpt->recipe->bound, Eigen::Vector2d(gu[static_cast<size_t>(i)], gv[static_cast<size_t>(j)]));
            if (!in) {
                ++outside;
                EXPECT_EQ(s.point(i, j), base.point(i, j)) << "control point (" << i << ", " << j << ") outside the bound moved";
            } else if (s.point(i, j) != base.point(i, j)) {
                ++moved;
            }
            top = std::max(top, s.point(i, j).z());
        }
    }
    // The bound holds about a quarter of the 8 x 8 net; the points inside carry the bump
    EXPECT_GT(outside, 40);
    EXPECT_GT(moved, 4);
    EXPECT_GT(top, 20.0);
}

TEST(SculptTools, ABlockedPointStaysAndADistanceIsHeld)
{
    // sculpt_constraints.json: a handle at (-10, -10, 0), control point (4, 4) at (10, 10, 0)
    // blocked (Alt+K), a distance between (-30, -50, 0) and (10, -50, 0) (Alt+D), the handle's
    // jack pulled 20 mm up
    const model::Model model = readModel("sculpt_constraints.json");
    const model::Entity* sculpt = sculptOf(model);
    ASSERT_NE(sculpt, nullptr);
    EXPECT_FALSE(sculpt->failed()) << sculpt->buildError;
    expectHandleMet(model, *sculpt);
    EXPECT_NEAR(model.find(sculpt->recipe->handles.front().point)->position.z(), 20.0, 1.5);
    ASSERT_EQ(sculpt->recipe->blocked.size(), 1u);
    EXPECT_EQ(sculpt->recipe->blocked.front(), (std::array<int, 2>{4, 4}));
    EXPECT_EQ(sculpt->surface->point(4, 4), model.find(2)->surface->point(4, 4));
    // The sheet moved elsewhere
    double top = 0.0;
    for (const Eigen::Vector3d& p : sculpt->surface->points()) top = std::max(top, p.z());
    EXPECT_GT(top, 10.0);
    // The distance picked is the flat sheet's (40 mm within a pixel or two), held after the drag
    ASSERT_EQ(sculpt->recipe->distances.size(), 1u);
    const model::SurfaceRecipe::Distance& d = sculpt->recipe->distances.front();
    EXPECT_NEAR(d.distance, 40.0, 1.5);
    auto apart = [&](const model::Entity& s) {
        return (s.surface->evaluate(d.uv.x(), d.uv.y()) - s.surface->evaluate(d.uv2.x(), d.uv2.y())).norm();
    };
    EXPECT_NEAR(apart(*sculpt), d.distance, kMet);
    // A new value (what the inspector's spin box sets, tested in main_window_test) re-solves to it
    model::Model edited = readModel("sculpt_constraints.json");
    model::SurfaceRecipe recipe = *edited.find(sculpt->id)->recipe;
    recipe.distances.front().distance = d.distance + 8.0;
    edited.setSurfaceRecipe(sculpt->id, recipe);
    edited.update();
    EXPECT_NEAR(apart(*edited.find(sculpt->id)), d.distance + 8.0, kMet);
    EXPECT_EQ(edited.find(sculpt->id)->surface->point(4, 4), model.find(2)->surface->point(4, 4));
}

}  // namespace
}  // namespace sculptline
