// Compatibility matrices (seed 000 §4.1): a request curve brought into H's space is the same curve.
#include "solvers/incidence/compatibility.h"

#include "solvers/bspline/geometry_error.h"
#include "tests/incidence/incidence_fixtures.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::incidence;
using namespace sculptline::incidence_test;

namespace {

constexpr double kRoundOff = 1e-12;

// A cubic 3D request over [0, 1] on the given knots (a "sketched" curve with some swing).
Curve3d request(const KnotVector& knots, int degree = 3)
{
    const int count = static_cast<int>(knots.size()) - degree - 1;
    std::vector<Curve3d::Point> points;
    for (int i = 0; i < count; ++i) points.emplace_back(10.0 * i, 5.0 * std::sin(1.1 * i), 3.0 * std::cos(0.7 * i) + i);
    return Curve3d(degree, knots, points);
}

double maxDeviation(const Curve3d& a, const Curve3d& b)
{
    double worst = 0.0;
    for (int k = 0; k <= 1000; ++k) worst = std::max(worst, (a.evaluate(k / 1000.0) - b.evaluate(k / 1000.0)).norm());
    return worst;
}

}  // namespace

TEST(IncidenceCompatibility, RequestOnTheDomainCurvesKnotsIsBroughtExactly)
{
    // Given the Fig. 4 composition and a cubic request on the domain curve's own knots
    const Curve2d g = diagonalCurve(8);
    const Composition c = compose(SurfaceStructure::of(figureFourSurface()), g);
    const Curve3d h = request(g.knots());
    // When brought into H's space
    const Curve3d brought = bringIntoSpace(h, c.space);
    // Then it has H's degree, knots and point count, and is the same curve
    EXPECT_EQ(brought.degree(), c.space.degree);
    EXPECT_EQ(brought.knots(), c.space.knots);
    EXPECT_EQ(brought.pointCount(), c.matrix.rows());
    EXPECT_LT(maxDeviation(brought, h), kRoundOff * 50.0);
}

TEST(IncidenceCompatibility, MatrixFormAppliesTheSameMap)
{
    const Curve2d g = diagonalCurve(8);
    const Composition c = compose(SurfaceStructure::of(figureFourSurface()), g);
    const Curve3d h = request(clampedKnots(2, 3), 2);  // one quadratic Bezier piece
    const SparseRows m = compatibilityMatrix(h.degree(), h.knots(), c.space);
    ControlMatrix p(h.pointCount(), 3);
    for (int i = 0; i < h.pointCount(); ++i) p.row(i) = h.points()[i].transpose();
    const ControlMatrix mapped = m * p;
    const Curve3d brought = bringIntoSpace(h, c.space);
    for (int i = 0; i < brought.pointCount(); ++i) EXPECT_LT((mapped.row(i).transpose() - brought.points()[i]).norm(), 1e-12);
    // rows of a compatibility matrix are partitions of unity (elevation and insertion are affine)
    const Eigen::VectorXd sums = m * Eigen::VectorXd::Ones(m.cols());
    EXPECT_LT((sums.array() - 1.0).abs().maxCoeff(), 1e-13);
}

TEST(IncidenceCompatibility, KnotsOutsideTheSpaceNeedExtraBreakpoints)
{
    // Given a request with a knot at 0.4321, which is no breakpoint of H
    const Curve2d g = diagonalCurve(8);
    const SurfaceStructure s = SurfaceStructure::of(figureFourSurface());
    const Curve3d h = request({0, 0, 0, 0, 0.4321, 1, 1, 1, 1});
    // Then it cannot be brought into the plain space ...
    EXPECT_THROW(bringIntoSpace(h, compose(s, g).space), GeometryError);
    // ... but can into the space composed with its knot as an extra breakpoint
    const Composition c = compose(s, g, {0.4321});
    EXPECT_LT(maxDeviation(bringIntoSpace(h, c.space), h), kRoundOff * 50.0);
}

TEST(IncidenceCompatibility, RefusesTooHighDegreeAndOtherDomains)
{
    const Composition c = compose(SurfaceStructure::of(figureFourSurface()), diagonalCurve(8));
    // degree above D = 18
    KnotVector high(20, 0.0);
    high.insert(high.end(), 20, 1.0);
    EXPECT_THROW(compatibilityMatrix(19, high, c.space), GeometryError);
    // a domain [0, 2] instead of [0, 1]
    EXPECT_THROW(compatibilityMatrix(1, {0, 0, 2, 2}, c.space), GeometryError);
}
