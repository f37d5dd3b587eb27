// Rail-based rotation (thesis §5.2.2): the profile starts the surface exactly, the rails are
// followed within the reported deviation, circular rails give a surface of revolution.
#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/periodic.h"
#include "solvers/bspline/projection.h"
#include "solvers/surfaces/rail_rotation.h"
#include "surface_checks.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::surfaces;
using namespace sculptline::surfaces_test;

namespace {

Curve3d ellipse(double a, double b, double z)
{
    // An ellipse is an affine image of the rational circle (weights unchanged).
    const Curve3d c = fullCircle(Vec3(0, 0, z), 1.0, Vec3::UnitX(), Vec3::UnitY());
    std::vector<Vec3> pts = c.points();
    for (Vec3& p : pts) p = Vec3(a * p.x(), b * p.y(), p.z());
    return Curve3d(c.degree(), c.knots(), pts, c.weights());
}

}  // namespace

TEST(RailRotation, GivenCoaxialCircles_WhenRotated_ThenSurfaceOfRevolutionThroughProfile)
{
    const Curve3d rail1 = ellipse(1.0, 1.0, 0.0);
    const Curve3d rail2 = ellipse(0.6, 0.6, 2.0);
    const Curve3d profile = cubic({{1, 0, 0}, {1.6, 0, 0.7}, {0.3, 0, 1.4}, {0.6, 0, 2}});
    const ApproximatedSurface s = railRotation(rail1, rail2, profile);
    EXPECT_LE(s.maxDeviation, s.tolerance);
    EXPECT_LT(isoDeviation(s.surface, true, 0.0, profile), kExact);
    // maxDeviation is measured on samples (quarter points between sections); elsewhere the error may
    // exceed it by a few percent, hence kSampledBound.
    constexpr double kSampledBound = 1.1;
    for (int i = 0; i <= 20; ++i) {
        const Vec3 c = profile.evaluate(i / 20.0);
        for (int j = 0; j <= 50; ++j) {
            const Vec3 p = s.surface.evaluate(i / 20.0, j / 50.0);
            EXPECT_NEAR(p.head<2>().norm(), c.head<2>().norm(), kSampledBound * s.maxDeviation + kExact);
            EXPECT_NEAR(p.z(), c.z(), kSampledBound * s.maxDeviation + kExact);
        }
    }
    EXPECT_GT(minNeighbourNormalDot(s.surface), 0.0);
    // Closed and C2 across the seam v = 0 = 1 (periodic interpolation).
    for (int i = 0; i <= 10; ++i) {
        const auto a = s.surface.derivatives(i / 10.0, 0.0, 2);
        const auto b = s.surface.derivatives(i / 10.0, 1.0, 2);
        for (int k = 0; k <= 2; ++k) EXPECT_LT((a[0][k] - b[0][k]).norm(), 1e-9 * (1.0 + a[0][k].norm())) << i << " " << k;
    }
}

TEST(RailRotation, GivenEllipticRailsAndReversedProfile_WhenRotated_ThenRailsFollowed)
{
    const Curve3d rail1 = ellipse(2.0, 1.0, 0.0);
    const Curve3d rail2 = ellipse(1.2, 0.8, 3.0);
    // Drawn from the top rail down, and not in a plane through the axis.
    const Curve3d profile = cubic({{1.2, 0, 3}, {1.8, 0.3, 2}, {2.4, 0.2, 1}, {2, 0, 0}});
    const ApproximatedSurface s = railRotation(rail1, rail2, profile, ApproximationOptions{1e-4, 2049});
    EXPECT_LE(s.maxDeviation, 1e-4);
    const CurveProjector<3> on1(rail1), on2(rail2);
    for (int j = 0; j <= 200; ++j) {
        EXPECT_LT(on1.project(s.surface.evaluate(0.0, j / 200.0)).distance, 1e-4 + kExact) << j;
        EXPECT_LT(on2.project(s.surface.evaluate(1.0, j / 200.0)).distance, 1e-4 + kExact) << j;
    }
    EXPECT_GT(minNeighbourNormalDot(s.surface), 0.0);
}

TEST(RailRotation, GivenBadInput_WhenRotated_ThenClearErrors)
{
    const Curve3d rail1 = ellipse(1.0, 1.0, 0.0);
    const Curve3d rail2 = ellipse(0.6, 0.6, 2.0);
    const Curve3d profile = cubic({{1, 0, 0}, {1.6, 0, 0.7}, {0.3, 0, 1.4}, {0.6, 0, 2}});
    const Curve3d open = cubic({{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}});
    EXPECT_THROW(railRotation(open, rail2, profile), GeometryError);
    const Curve3d short_ = cubic({{1, 0, 0}, {1.6, 0, 0.7}, {0.3, 0, 1.4}, {0.6, 0, 1.5}});
    try {
        railRotation(rail1, rail2, short_);
        FAIL() << "expected GeometryError";
    } catch (const GeometryError& e) {
        EXPECT_NE(std::string(e.what()).find("profile"), std::string::npos) << e.what();
    }
}

TEST(PeriodicCubicInterpolation, GivenDataRows_WhenInterpolated_ThenClosedCurvePassesThroughEachRowAtItsParameter)
{
    // Given: K rows of pseudo-random points (K from the minimum 3 up to a large count).
    for (int K : {3, 4, 7, 16, 53}) {
        ControlMatrix data(K, 3);
        for (int k = 0; k < K; ++k) data.row(k) << std::sin(1.3 * k + 0.2), std::cos(0.7 * k * k), 0.1 * k;

        // When
        const ControlMatrix net = periodicCubicInterpolation(data);

        // Then: the closed uniform cubic on those rows meets row k at v = k/K, and is periodic.
        ASSERT_EQ(net.rows(), K + 3);
        std::vector<Vec3> pts;
        for (int r = 0; r < net.rows(); ++r) pts.emplace_back(net(r, 0), net(r, 1), net(r, 2));
        // (Evaluated as an unclamped open curve on the same knots: the same function on [0, 1],
        // and it admits K = 3, which the kernel's closed convention does not.)
        const Curve3d closed(3, periodicUniformKnots(3, K), pts);
        for (int k = 0; k < K; ++k)
            EXPECT_LT((closed.evaluate(static_cast<double>(k) / K) - Vec3(data.row(k).transpose())).norm(), kExact)
                << "K = " << K << ", k = " << k;
    }
    EXPECT_THROW(periodicCubicInterpolation(ControlMatrix::Zero(2, 3)), GeometryError);
}
