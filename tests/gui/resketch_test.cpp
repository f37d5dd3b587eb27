// Checks the jug's mouth replayed under Xvfb (seed 001_08db50965017e161 §5.2, Fig. 10): the jug
// (a free-form bicubic surface) selected, Sculpt mode's Re-sketch tool, a marking along the rim's
// front, the strip's rulings turned across the rim, and a stroke over the strip raising the lip
// (tests/gui/CMakeLists.txt runs `sculptline jug_start.json --replay jug_mouth.json --save` first;
// both written by data/sessions/make_models.py), and the same undone. Files are in
// $SCULPTLINE_REPLAY_DIR.
#include "tests/gui/replayed_model.h"

#include "solvers/bspline/projection.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace sculptline {
namespace {

/// The stroke reaches the strip through pixels (a pixel is ~0.3 mm at the jug's distance in the
/// 800 x 600 replay), the over-sketch fits it within 0.002 of its length (~0.2 mm) and the refit in
/// the rim's 13-point knot vector adds what the coarse knots cannot follow: 1.5 mm in all.
constexpr double kFitTolerance = 1.5;
/// The stroke's ends blend into the old rim (the over-sketch's transitions): its middle is checked.
constexpr double kEndFraction = 0.15;

model::Model startModel()
{
    model::Model m;
    model::populateModel(model::loadDocument(std::string(SCULPTLINE_DATA_DIR) + "/models/jug_start.json"), m);
    return m;
}

/// The "at" points of the session's last stroke (press, moves, release).
std::vector<Eigen::Vector3d> lastStroke()
{
    std::ifstream in(std::string(SCULPTLINE_DATA_DIR) + "/sessions/jug_mouth.json");
    const nlohmann::json session = nlohmann::json::parse(in);
    std::vector<Eigen::Vector3d> points;
    for (const auto& e : session.at("events")) {
        if (!e.contains("at")) continue;
        if (e.at("type") == "press") points.clear();
        const auto& a = e.at("at");
        points.emplace_back(a.at(0).get<double>(), a.at(1).get<double>(), a.at(2).get<double>());
    }
    return points;
}

TEST(Resketch, TheJugsRimFollowsTheStrokeAndNothingButTheRimRowMoved)
{
    const model::Model before = startModel();
    const model::Model after = guitest::readReplayedModel("jug_mouth.json");
    const model::Entity* was = before.find(1);
    const model::Entity* jug = after.find(1);
    ASSERT_TRUE(was && was->surface);
    ASSERT_TRUE(jug && jug->surface);
    const solvers::Surface3d& s0 = *was->surface;
    const solvers::Surface3d& s1 = *jug->surface;
    // A free-form surface still, same knots and net size
    EXPECT_FALSE(jug->recipe.has_value());
    EXPECT_EQ(s1.knotsU(), s0.knotsU());
    EXPECT_EQ(s1.knotsV(), s0.knotsV());
    ASSERT_EQ(s1.countU(), s0.countU());
    ASSERT_EQ(s1.countV(), s0.countV());
    // Only the rim's row can move (N_j(v = end) = 0 for every other row): exactly unchanged
    const int rim = s0.countV() - 1;
    int moved = 0;
    for (int i = 0; i < s0.countU(); ++i) {
        for (int j = 0; j < rim; ++j) EXPECT_EQ(s1.point(i, j), s0.point(i, j)) << i << "," << j;
        moved += s1.point(i, rim) != s0.point(i, rim) ? 1 : 0;
    }
    EXPECT_GT(moved, 0) << "the rim did not move";
    // The back of the rim (the seam, far from the stroke) kept its points
    EXPECT_EQ(s1.point(0, rim), s0.point(0, rim));
    EXPECT_EQ(s1.point(s0.countU() - 1, rim), s0.point(s0.countU() - 1, rim));
    // The rim is the re-sketched line: the stroke's middle lies on it within the fit
    const solvers::Curve3d rimCurve = s1.isoCurve(solvers::Direction::V, s1.domainEnd(solvers::Direction::V));
    const solvers::CurveProjector<3> onRim(rimCurve);
    const std::vector<Eigen::Vector3d> stroke = lastStroke();
    ASSERT_GT(stroke.size(), 20u);
    double worst = 0.0;
    const size_t skip = static_cast<size_t>(kEndFraction * static_cast<double>(stroke.size()));
    for (size_t k = skip; k + skip < stroke.size(); ++k) worst = std::max(worst, onRim.project(stroke[k]).distance);
    EXPECT_LT(worst, kFitTolerance) << "the rim misses the stroke by " << worst << " mm";
    std::cout << "rim vs stroke (middle " << 100 * (1 - 2 * kEndFraction) << "%): max " << worst << " mm; rim points moved: " << moved
              << "\n";
    // The lip rose: the front of the rim is ~14 mm higher than the old rim (z = 100)
    double top = 0.0;
    for (int k = 0; k <= 200; ++k) top = std::max(top, rimCurve.evaluate(rimCurve.domainStart() + (rimCurve.domainEnd() - rimCurve.domainStart()) * k / 200.0).z());
    EXPECT_GT(top, 110.0);
}

TEST(Resketch, OneUndoGivesTheJugBack)
{
    // jug_mouth_undo.json: the same session followed by Ctrl+Z
    const model::Model before = startModel();
    const model::Model undone = guitest::readReplayedModel("jug_mouth_undo.json");
    ASSERT_TRUE(undone.find(1) && undone.find(1)->surface);
    EXPECT_EQ(undone.find(1)->surface->points(), before.find(1)->surface->points());
}

}  // namespace
}  // namespace sculptline
