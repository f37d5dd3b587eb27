// The curvature comb (scene/curvature_comb.h), headless: its teeth against exact curvature (a rational
// circle, whose kappa N is 1/R towards the centre everywhere: The NURBS Book §7.5, the nine-point
// circle), its default scale, and its nodes following the model's updates of the curve it shows.
#include "model/model.h"
#include "scene/curvature_comb.h"

#include <Inventor/SoDB.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

#include <cmath>

namespace sculptline::scene {
namespace {

/// Curvature of an exact rational circle is exact to round-off of its evaluation.
constexpr double kRoundOff = 1e-12;
/// Points and tooth directions of the circle, relative to its size: its evaluation (a ratio of
/// weighted sums) and a normalization lose a few ulps each.
constexpr double kGeometryRelative = 1e-9;

/// The nine-point quadratic rational circle of radius r about `centre` in the xy plane (NURBS Book
/// Ex. 7.1 / Fig. 7.16): four spans.
solvers::Curve3d circle(double r, const Eigen::Vector3d& centre)
{
    const double w = std::sqrt(0.5);
    std::vector<Eigen::Vector3d> p = {{r, 0, 0}, {r, r, 0}, {0, r, 0}, {-r, r, 0}, {-r, 0, 0}, {-r, -r, 0}, {0, -r, 0}, {r, -r, 0}, {r, 0, 0}};
    for (auto& q : p) q += centre;
    return solvers::Curve3d(2, {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4}, p, {1, w, 1, w, 1, w, 1, w, 1});
}

TEST(CombTeeth, CircleTeethPointToTheCentreWithLengthScaleOverRadius)
{
    // Given a circle of radius 20 about (5, -3, 0)
    const double r = 20.0, scale = 50.0;
    const Eigen::Vector3d centre(5, -3, 0);
    // When its teeth are made at 6 per span
    const std::vector<CombTooth> teeth = combTeeth(circle(r, centre), 6, scale);
    // Then there are 4 spans x 6 + the end, each 1/R long times the scale, towards the centre
    ASSERT_EQ(teeth.size(), 25u);
    for (const CombTooth& t : teeth) {
        EXPECT_NEAR(t.curvatureVector.norm(), 1.0 / r, kRoundOff) << t.u;
        EXPECT_NEAR((t.base - centre).norm(), r, kGeometryRelative * r);
        const Eigen::Vector3d inward = (centre - t.base).normalized();
        EXPECT_NEAR((t.tip - t.base).dot(inward), scale / r, kRoundOff * scale) << t.u;
        EXPECT_NEAR((t.tip - t.base - inward * (scale / r)).norm(), 0.0, kGeometryRelative * scale / r);
    }
    // And the default scale makes the longest tooth 15 % of the circle's box diagonal (2R sqrt 2)
    EXPECT_NEAR(defaultCombScale(teeth) / r, kCombLengthFraction * 2.0 * r * std::sqrt(2.0), kGeometryRelative * r * r);
}

TEST(CombTeeth, AStraightCurveHasZeroTeethAndNoDefaultScale)
{
    const solvers::Curve3d line(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}});
    const std::vector<CombTooth> teeth = combTeeth(line, 8, 10.0);
    ASSERT_EQ(teeth.size(), 9u);
    for (const CombTooth& t : teeth) EXPECT_EQ((t.tip - t.base).norm(), 0.0);
    EXPECT_EQ(defaultCombScale(teeth), 0.0);
}

struct CombModel : ::testing::Test {
    model::Model model;
    model::EntityId curve = 0;
    void SetUp() override
    {
        SoDB::init();
        curve = model.addCurve(0, circle(10.0, Eigen::Vector3d::Zero()));
        model.update();
    }
    static int drawnPoints(const char* part)
    {
        SoSeparator* group = static_cast<SoSeparator*>(SoNode::getByName(part));
        for (int k = 0; group && k < group->getNumChildren(); ++k) {
            if (group->getChild(k)->isOfType(SoCoordinate3::getClassTypeId())) return static_cast<SoCoordinate3*>(group->getChild(k))->point.getNum();
        }
        return -1;
    }
};

TEST_F(CombModel, FollowsTheCurveWhileShownAndClearsWhenItGoes)
{
    CurvatureComb comb(model);
    comb.setCurve(curve);
    // Hidden: nothing computed
    EXPECT_TRUE(comb.teeth().empty());
    EXPECT_EQ(comb.rebuilds(), 0);
    comb.setVisible(true);
    ASSERT_EQ(comb.teeth().size(), static_cast<size_t>(4 * kDefaultCombDensity + 1));
    EXPECT_EQ(drawnPoints("CombTeeth"), 2 * (4 * kDefaultCombDensity + 1));
    EXPECT_EQ(drawnPoints("CombEnvelope"), 4 * kDefaultCombDensity + 1);
    const int rebuilds = comb.rebuilds();
    // The curve grows to twice the radius (an update at rest): rebuilt once, rescaled so the
    // longest tooth is again kCombLengthFraction of its size
    model.setCurveShape(curve, circle(20.0, Eigen::Vector3d::Zero()));
    model.update();
    EXPECT_EQ(comb.rebuilds(), rebuilds + 1);
    EXPECT_NEAR(comb.teeth().front().curvatureVector.norm(), 1.0 / 20.0, kRoundOff);
    EXPECT_NEAR((comb.teeth().front().tip - comb.teeth().front().base).norm(), kCombLengthFraction * 40.0 * std::sqrt(2.0), kGeometryRelative * 40.0);
    // Another entity's update does not touch it
    const model::EntityId other = model.addCurve(0, circle(5.0, Eigen::Vector3d(50, 0, 0)));
    model.update();
    model.setCurveShape(other, circle(6.0, Eigen::Vector3d(50, 0, 0)));
    model.update();
    EXPECT_EQ(comb.rebuilds(), rebuilds + 1);
    // The curve removed: the comb is empty
    model.remove(curve);
    EXPECT_EQ(comb.curve(), 0u);
    EXPECT_TRUE(comb.teeth().empty());
    EXPECT_EQ(drawnPoints("CombTeeth"), 0);
}

}  // namespace
}  // namespace sculptline::scene
