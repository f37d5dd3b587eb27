// Crossings of two domain curves (the point incidences that tie curve constraints).
#include "solvers/incidence/curve_crossings.h"

#include "tests/incidence/incidence_fixtures.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::incidence;
using namespace sculptline::incidence_test;

namespace {

constexpr double kPrecise = 1e-12;

Curve2d line(Eigen::Vector2d a, Eigen::Vector2d b) { return Curve2d(1, {0, 0, 1, 1}, {a, b}); }

}  // namespace

TEST(IncidenceCrossings, TwoLinesMeetWhereSolvedByHand)
{
    // (0,0)-(1,1) and (0,1)-(1,0.2): 1 - 0.8 s = t with s = t: t = 1 / 1.8
    const auto x = curveCrossings(line({0, 0}, {1, 1}), line({0, 1}, {1, 0.2}));
    ASSERT_EQ(x.size(), 1u);
    EXPECT_NEAR(x[0].t1, 1.0 / 1.8, kPrecise);
    EXPECT_NEAR(x[0].t2, 1.0 / 1.8, kPrecise);
    EXPECT_NEAR(x[0].point.x(), 1.0 / 1.8, kPrecise);
}

TEST(IncidenceCrossings, CurvedCurveCrossesALineAsOftenAsSamplingSays)
{
    // Given the S-shaped curve and a slanted line across it
    const Curve2d s = curvedCurve(9);
    const Curve2d h = line({0.0, 0.55}, {1.0, 0.45});
    // When crossed
    const auto x = curveCrossings(s, h);
    // Then the count is the number of sign changes of y - 0.5 along a dense sampling, and each
    // crossing lies on both curves
    int changes = 0;
    double last = s.evaluate(0.0).y() - (0.55 - 0.1 * s.evaluate(0.0).x());
    for (int k = 1; k <= 10000; ++k) {
        const Eigen::Vector2d p = s.evaluate(k / 10000.0);
        const double now = p.y() - (0.55 - 0.1 * p.x());
        if ((now < 0) != (last < 0)) ++changes;
        last = now;
    }
    EXPECT_EQ(static_cast<int>(x.size()), changes);
    EXPECT_GE(changes, 3);
    for (const Crossing& c : x) {
        EXPECT_LT((s.evaluate(c.t1) - h.evaluate(c.t2)).norm(), kPrecise);
        EXPECT_NEAR(s.evaluate(c.t1).y(), 0.55 - 0.1 * s.evaluate(c.t1).x(), kPrecise);
    }
}

TEST(IncidenceCrossings, DisjointCurvesDoNotCrossAndATouchIsOnePoint)
{
    EXPECT_TRUE(curveCrossings(line({0, 0}, {1, 0}), line({0, 0.1}, {1, 0.2})).empty());
    // A parabola touching the line y = 0 at x = 0.5: Bezier points (0, 0.25), (0.5, -0.25), (1, 0.25)
    const Curve2d parabola(2, {0, 0, 0, 1, 1, 1}, {Eigen::Vector2d(0, 0.25), Eigen::Vector2d(0.5, -0.25), Eigen::Vector2d(1, 0.25)});
    const auto x = curveCrossings(parabola, line({0, 0}, {1, 0}));
    ASSERT_EQ(x.size(), 1u);
    EXPECT_NEAR(x[0].point.x(), 0.5, 1e-6);
}
