// Extrude: along a direction and along a path (translational sweep), exact; zero extents refused.
#include "solvers/bspline/geometry_error.h"
#include "solvers/surfaces/extrude.h"
#include "surface_checks.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::surfaces;
using namespace sculptline::surfaces_test;

TEST(Extrude, GivenDirection_WhenExtruded_ThenProfileTranslated)
{
    const Curve3d profile = cubic({{0, 0, 0}, {1, 2, 0}, {2, -1, 0}, {3, 0, 0}, {4, 1, 0}});
    const Vec3 d(0.5, 0.2, 3.0);
    const Surface3d s = extrude(profile, d);
    for (int i = 0; i <= 20; ++i)
        for (int j = 0; j <= 10; ++j) {
            const double u = i / 20.0, v = j / 10.0;
            EXPECT_LT((s.evaluate(u, v) - (profile.evaluate(u) + v * d)).norm(), kExact);
        }
    EXPECT_GT(minNeighbourNormalDot(s), 0.0);
}

TEST(Extrude, GivenRationalProfileAndPath_WhenExtruded_ThenSumOfCurves)
{
    const double w = std::sqrt(0.5);
    const Curve3d arc(2, {0, 0, 0, 1, 1, 1}, {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {1, w, 1});
    const Curve3d path(2, {0, 0, 0, 1, 1, 1}, {{0, 0, 0}, {0, 1, 1}, {0, 0, 2}}, {1, 0.5, 1});
    const Surface3d s = extrude(arc, path);
    for (int i = 0; i <= 20; ++i)
        for (int j = 0; j <= 20; ++j) {
            const double u = i / 20.0, v = j / 20.0;
            EXPECT_LT((s.evaluate(u, v) - (arc.evaluate(u) + path.evaluate(v) - path.evaluate(0))).norm(), kExact);
        }
}

TEST(Extrude, GivenZeroExtent_WhenExtruded_ThenClearError)
{
    const Curve3d profile = cubic({{0, 0, 0}, {1, 2, 0}, {2, -1, 0}, {3, 0, 0}});
    EXPECT_THROW(extrude(profile, Vec3::Zero()), GeometryError);
    const Curve3d point = cubic({{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}});
    EXPECT_THROW(extrude(profile, point), GeometryError);
}

TEST(Extrude, GivenPointProfile_WhenExtruded_ThenClearError)
{
    const Curve3d point = cubic({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}});
    EXPECT_THROW(extrude(point, Vec3(0, 0, 1)), GeometryError);
    EXPECT_THROW(extrude(point, cubic({{0, 0, 0}, {0, 1, 0}, {0, 2, 1}, {0, 3, 1}})), GeometryError);
}
