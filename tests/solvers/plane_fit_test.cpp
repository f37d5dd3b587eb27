// The best-fit plane against planes known exactly: a tilted grid, a line, one point, none.
#include "solvers/bspline/geometry_error.h"
#include "solvers/geometry/plane_fit.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace sculptline::solvers;

namespace {
/// Eigenvectors of a 3x3 symmetric matrix with well separated eigenvalues: a few ulps of the
/// points' spread.
constexpr double kAxisTolerance = 1e-12;
}  // namespace

TEST(PlaneFit, PointsOfATiltedPlaneGiveItsNormalAndCentroid)
{
    // Given a 5 x 3 grid on z = 0.5 x + 0.2 y + 3, longer along x
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 3; ++j) points.emplace_back(10.0 * i, 4.0 * j, 0.5 * 10.0 * i + 0.2 * 4.0 * j + 3.0);

    // When fitted
    const PlaneFit fit = bestFitPlane(points);

    // Then the normal is (-0.5, -0.2, 1) normalized (up to sign), the spread across it is zero,
    // and the centroid is the grid's centre
    const Eigen::Vector3d n = Eigen::Vector3d(-0.5, -0.2, 1.0).normalized();
    EXPECT_NEAR(std::abs(fit.normal.dot(n)), 1.0, kAxisTolerance);
    EXPECT_NEAR(fit.spread(0), 0.0, 1e-9);
    EXPECT_LT((fit.centroid - Eigen::Vector3d(20.0, 4.0, 0.5 * 20.0 + 0.2 * 4.0 + 3.0)).norm(), 1e-12);
    EXPECT_NEAR(std::abs(fit.axisU.dot(Eigen::Vector3d(1, 0, 0.5).normalized())), 1.0, 1e-3);  // the long side
    EXPECT_NEAR(fit.axisU.dot(fit.normal), 0.0, kAxisTolerance);
}

TEST(PlaneFit, CollinearPointsSaySoThroughTheSpread)
{
    const PlaneFit fit = bestFitPlane({{0, 0, 0}, {1, 2, 3}, {2, 4, 6}, {5, 10, 15}});
    EXPECT_NEAR(std::abs(fit.axisU.dot(Eigen::Vector3d(1, 2, 3).normalized())), 1.0, kAxisTolerance);
    EXPECT_NEAR(fit.spread(1), 0.0, 1e-9);
    EXPECT_GT(fit.spread(2), 1.0);
}

TEST(PlaneFit, AnEmptySetIsRefused)
{
    EXPECT_THROW(bestFitPlane({}), GeometryError);
    EXPECT_LT((bestFitPlane({{1, 2, 3}}).centroid - Eigen::Vector3d(1, 2, 3)).norm(), 1e-15);
}
