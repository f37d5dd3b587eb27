// Compatibility: different degrees, domains and knots become one layout without changing shape.
#include "solvers/bspline/geometry_error.h"
#include "solvers/surfaces/compatible_curves.h"
#include "surface_checks.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::surfaces;
using namespace sculptline::surfaces_test;

namespace {

// Shape preservation is exact up to round-off of knot insertion and elevation.
constexpr double kShapeTolerance = 1e-12;

Curve3d quadraticOnOddDomain()
{
    // Degree 2, domain [2, 7], a double interior knot at 4.
    return Curve3d(2, {2, 2, 2, 4, 4, 5, 7, 7, 7},
                   {{0, 0, 0}, {1, 2, 0}, {2, -1, 1}, {3, 0, 0}, {4, 1, 2}, {5, 0, 0}});
}

Curve3d rationalQuarterCircle()
{
    const double w = std::sqrt(0.5);
    return Curve3d(2, {0, 0, 0, 1, 1, 1}, {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {1, w, 1});
}

}  // namespace

TEST(CompatibleCurves, GivenMixedDegreesAndDomains_WhenMadeCompatible_ThenOneLayoutSameShapes)
{
    // Arrange
    const std::vector<Curve3d> input{quadraticOnOddDomain(), cubic({{0, 0, 0}, {1, 1, 1}, {2, 0, 3}, {3, 3, 0}, {4, 0, 1}})};
    // Act
    const std::vector<Curve3d> out = makeCompatible(input);
    // Assert
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out[0].degree(), 3);
    EXPECT_EQ(out[0].knots(), out[1].knots());
    EXPECT_EQ(out[0].pointCount(), out[1].pointCount());
    EXPECT_EQ(out[0].knots().front(), 0.0);
    EXPECT_EQ(out[0].knots().back(), 1.0);
    for (size_t k = 0; k < input.size(); ++k)
        for (int s = 0; s <= 200; ++s) {
            const double t = s / 200.0;
            const double u = input[k].domainStart() + t * (input[k].domainEnd() - input[k].domainStart());
            EXPECT_LT((out[k].evaluate(t) - input[k].evaluate(u)).norm(), kShapeTolerance) << k << " " << t;
        }
    // The double knot at 4 (u = 0.4) becomes multiplicity 3 after elevation by one: still C0.
    EXPECT_EQ(knotMultiplicity(out[0].knots(), 0.4), 3);
}

TEST(CompatibleCurves, GivenOneRationalCurve_WhenMadeCompatible_ThenAllRationalAndExact)
{
    const std::vector<Curve3d> input{rationalQuarterCircle(), cubic({{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}})};
    const std::vector<Curve3d> out = makeCompatible(input);
    EXPECT_TRUE(out[0].isRational());
    EXPECT_TRUE(out[1].isRational());
    for (int s = 0; s <= 100; ++s) {
        const double t = s / 100.0;
        EXPECT_NEAR(out[0].evaluate(t).norm(), 1.0, kShapeTolerance);  // still the exact circle
        EXPECT_LT((out[1].evaluate(t) - input[1].evaluate(t)).norm(), kShapeTolerance);
    }
}

TEST(CompatibleCurves, GivenLayout_WhenCurveHasForeignKnot_ThenConformRefuses)
{
    const Curve3d a = normalizedCurve(cubic({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}));
    const Curve3d b = normalizedCurve(cubic({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}}));
    const CurveLayout layout = commonLayout({a});
    EXPECT_FALSE(conformToLayout(b, layout).has_value());  // b has a knot at 0.5 the layout lacks
    const CurveLayout both = commonLayout({a, b});
    EXPECT_TRUE(conformToLayout(a, both).has_value());
}

TEST(CompatibleCurves, GivenNoCurves_WhenMadeCompatible_ThenClearError)
{
    EXPECT_THROW(makeCompatible({}), GeometryError);
}

TEST(CompatibleCurves, GivenCurve_WhenReversed_ThenRunsBackwards)
{
    const Curve3d c = normalizedCurve(quadraticOnOddDomain());
    const Curve3d r = reversedCurve(c);
    for (int s = 0; s <= 50; ++s)
        EXPECT_LT((r.evaluate(s / 50.0) - c.evaluate(1.0 - s / 50.0)).norm(), kShapeTolerance);
}
