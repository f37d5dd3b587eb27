// Boundary-based rotation (thesis §5.2.1): outlines met exactly, circles through them within the
// reported deviation, creases kept, degenerate outlines refused.
#include "solvers/bspline/geometry_error.h"
#include "solvers/surfaces/boundary_rotation.h"
#include "solvers/surfaces/compatible_curves.h"
#include "surface_checks.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::surfaces;
using namespace sculptline::surfaces_test;

namespace {

// A fish-like body seen from the side (xz plane): two outlines meeting at nose and tail.
Curve3d upper() { return cubic({{0, 0, 0}, {1, 0, 1.2}, {3, 0, 1.5}, {5, 0, 0.8}, {6, 0, 0}}); }
Curve3d lower() { return cubic({{0, 0, 0}, {1.5, 0, -0.8}, {3.5, 0, -1.0}, {5, 0, -0.4}, {6, 0, 0}}); }

}  // namespace

TEST(BoundaryRotation, GivenTwoOutlines_WhenRotated_ThenOutlinesMetAndPointsOnTheCircles)
{
    const Curve3d l = upper();
    const Curve3d r = lower();
    const ApproximatedSurface s = boundaryRotation(l, r);
    EXPECT_LE(s.maxDeviation, s.tolerance);
    EXPECT_LT(isoDeviation(s.surface, true, 0.0, l), kExact);
    EXPECT_LT(isoDeviation(s.surface, true, 0.5, r), kExact);
    const Vec3 n = Vec3::UnitY();  // the outlines' plane is xz
    for (int i = 0; i <= 40; ++i) {
        const double u = i / 40.0;
        const Vec3 q = 0.5 * (l.evaluate(u) + r.evaluate(u));
        const Vec3 d = 0.5 * (l.evaluate(u) - r.evaluate(u));
        for (int j = 0; j <= 40; ++j) {
            const Vec3 p = s.surface.evaluate(u, j / 40.0);
            EXPECT_NEAR((p - q).norm(), d.norm(), s.maxDeviation + kExact);  // eq. 5-4: radius |Cl - Q|
            if (d.norm() > 0.0) {  // in the plane through Q spanned by D and the normal of A
                EXPECT_NEAR((p - q).dot(d.cross(n).normalized()), 0.0, s.maxDeviation + kExact);
            }
        }
    }
    EXPECT_GT(minNeighbourNormalDot(s.surface), 0.0);
}

TEST(BoundaryRotation, GivenOutlineDrawnBackwards_WhenRotated_ThenSameSurface)
{
    const ApproximatedSurface a = boundaryRotation(upper(), lower());
    const ApproximatedSurface b = boundaryRotation(upper(), reversedCurve(normalizedCurve(lower())));
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 10; ++j)
            EXPECT_LT((a.surface.evaluate(i / 10.0, j / 10.0) - b.surface.evaluate(i / 10.0, j / 10.0)).norm(), 1e-6);
}

TEST(BoundaryRotation, GivenOutlineWithCorner_WhenRotated_ThenCreaseKept)
{
    // Degree 3 with a triple knot at 1/2: a C0 corner (a candle's shoulder).
    const Curve3d cornered(3, {0, 0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1, 1},
                           {{0, 0, 0}, {0.5, 0, 1}, {0.6, 0, 2}, {1, 0, 3}, {2, 0, 3.1}, {2.5, 0, 3.5}, {3, 0, 4}});
    const Curve3d straight = cubic({{0, 0, -1}, {1, 0, -1}, {2, 0, -1}, {3, 0, -1}});
    const ApproximatedSurface s = boundaryRotation(cornered, straight);
    EXPECT_GE(knotMultiplicity(s.surface.knotsU(), 0.5), s.surface.degreeU());
    EXPECT_LT(isoDeviation(s.surface, true, 0.0, cornered), kExact);
}

TEST(BoundaryRotation, GivenTighterTolerance_WhenRotated_ThenDeviationFollows)
{
    // Outlines that do not meet (|D| never vanishes) but change width quickly.
    const Curve3d l = cubic({{0, 0, 1}, {1, 0, 3}, {2, 0, 0.5}, {3, 0, 2}});
    const Curve3d r = cubic({{0.5, 0, -1}, {1.5, 0, -0.2}, {1.8, 0, -2}, {3.5, 0, -1}});
    const ApproximatedSurface coarse = boundaryRotation(l, r, ApproximationOptions{1e-2, 2049});
    const ApproximatedSurface fine = boundaryRotation(l, r, ApproximationOptions{1e-7, 2049});
    EXPECT_LE(coarse.maxDeviation, 1e-2);
    EXPECT_LE(fine.maxDeviation, 1e-7);
    EXPECT_GT(fine.surface.countU(), coarse.surface.countU());
}

TEST(BoundaryRotation, GivenDegenerateOutlines_WhenRotated_ThenClearErrors)
{
    EXPECT_THROW(boundaryRotation(upper(), upper()), GeometryError);
    const Curve3d a = cubic({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}});
    const Curve3d b = cubic({{4, 0, 0}, {5, 0, 0}, {6, 0, 0}, {7, 0, 0}});
    EXPECT_THROW(boundaryRotation(a, b), GeometryError);  // on one line: no plane
    const Curve3d arc = fullCircle(Vec3::Zero(), 1.0, Vec3::UnitX(), Vec3::UnitZ());
    EXPECT_THROW(boundaryRotation(arc, upper()), GeometryError);  // rational
}
