// Revolve: profile met, every point at the profile's distance from the axis, angle option, errors.
#include "solvers/bspline/geometry_error.h"
#include "solvers/surfaces/revolve.h"
#include "surface_checks.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::surfaces;
using namespace sculptline::surfaces_test;

namespace {

// A bottle-like profile in the xz plane, off a tilted axis to test the general case.
Curve3d bottleProfile()
{
    return cubic({{1.0, 0, 0}, {1.5, 0, 0.5}, {1.4, 0, 2.0}, {0.6, 0, 2.6}, {0.5, 0, 3.5}, {0.5, 0, 4.0}});
}

double axialCoordinate(const Axis& a, const Vec3& x) { return (x - a.point).dot(a.direction.normalized()); }

}  // namespace

TEST(Revolve, GivenProfileAndAxis_WhenRevolved_ThenExactCirclesThroughTheProfile)
{
    const Curve3d profile = bottleProfile();
    const Axis axis{Vec3(0.1, -0.2, 0.0), Vec3(0.05, 0.1, 1.0)};
    const Surface3d s = revolve(profile, axis);
    EXPECT_LT(isoDeviation(s, true, 0.0, profile), kExact);
    EXPECT_LT(isoDeviation(s, true, 1.0, profile), kExact);  // full turn closes onto the profile
    for (int i = 0; i <= 30; ++i) {
        const double u = i / 30.0;
        const Vec3 c = profile.evaluate(u);
        for (int j = 0; j <= 47; ++j) {
            const Vec3 p = s.evaluate(u, j / 47.0);
            EXPECT_NEAR(distanceFromAxis(axis, p), distanceFromAxis(axis, c), kExact);
            EXPECT_NEAR(axialCoordinate(axis, p), axialCoordinate(axis, c), kExact);
        }
    }
    EXPECT_GT(minNeighbourNormalDot(s), 0.0);
}

TEST(Revolve, GivenQuarterTurn_WhenRevolved_ThenEndsAtNinetyDegrees)
{
    const Curve3d profile = bottleProfile();
    const Axis axis{Vec3::Zero(), Vec3::UnitZ()};
    const Surface3d s = revolve(profile, axis, 90.0);
    EXPECT_EQ(s.countV(), 3);  // one arc
    // Rotating (x, 0, z) by +90 degrees about z gives (0, x, z).
    for (int i = 0; i <= 20; ++i) {
        const Vec3 c = profile.evaluate(i / 20.0);
        EXPECT_LT((s.evaluate(i / 20.0, 1.0) - Vec3(0.0, c.x(), c.z())).norm(), kExact);
    }
}

TEST(Revolve, GivenRationalProfile_WhenRevolved_ThenSphereExact)
{
    // A rational half circle of radius 2 in the xz plane (two quarter arcs) revolved into a sphere.
    const double w = std::sqrt(0.5);
    const Curve3d half(2, {0, 0, 0, 0.5, 0.5, 1, 1, 1}, {{0, 0, -2}, {2, 0, -2}, {2, 0, 0}, {2, 0, 2}, {0, 0, 2}},
                       {1, w, 1, w, 1});
    const Surface3d s = revolve(half, Axis{}, 270.0);
    for (int i = 0; i <= 20; ++i)
        for (int j = 0; j <= 20; ++j) EXPECT_NEAR(s.evaluate(i / 20.0, j / 20.0).norm(), 2.0, kExact);
}

TEST(Revolve, GivenDegenerateInput_WhenRevolved_ThenClearErrors)
{
    const Curve3d profile = bottleProfile();
    EXPECT_THROW(revolve(profile, Axis{Vec3::Zero(), Vec3::Zero()}), GeometryError);
    EXPECT_THROW(revolve(profile, Axis{}, 0.0), GeometryError);
    EXPECT_THROW(revolve(profile, Axis{}, 400.0), GeometryError);
    const Curve3d onAxis = cubic({{0, 0, 0}, {0, 0, 1}, {0, 0, 2}, {0, 0, 3}});
    EXPECT_THROW(revolve(onAxis, Axis{}), GeometryError);
}

TEST(Revolve, GivenProfileCrossingTheAxisOrAPoint_WhenRevolved_ThenClearErrors)
{
    // Given: a profile in the xz-plane from x = 1 to x = -1 (through the z axis), and a point.
    const Curve3d crossing = cubic({{1, 0, 0}, {0.5, 0, 1}, {-0.5, 0, 1}, {-1, 0, 2}});
    const Curve3d point = cubic({{1, 0, 1}, {1, 0, 1}, {1, 0, 1}, {1, 0, 1}});
    // When / Then
    try {
        revolve(crossing, Axis{});
        FAIL() << "expected GeometryError";
    } catch (const GeometryError& e) {
        EXPECT_NE(std::string(e.what()).find("crosses the axis"), std::string::npos) << e.what();
    }
    EXPECT_THROW(revolve(point, Axis{}), GeometryError);
    // And: a profile that ends on the axis (a pole), or comes near it and turns back, is revolved.
    EXPECT_NO_THROW(revolve(cubic({{0, 0, 0}, {1, 0, 0.5}, {1, 0, 1.5}, {0, 0, 2}}), Axis{}));
    EXPECT_NO_THROW(revolve(cubic({{1, 0, 0}, {0, 0, 1}, {0, 0, 1}, {1, 0, 2}}), Axis{}));
}
