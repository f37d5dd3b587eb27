// Kernel B-splines as OpenCASCADE geometry (solvers/exchange/occt_geometry.h): Given a kernel curve
// or surface, When it is converted, Then OCCT evaluates the same points at the same parameters
// (Geom_BSplineCurve::D0 against evaluate) and holds the same degree, knots and weights.
#include "solvers/exchange/exchange.h"
#include "solvers/exchange/occt_geometry.h"
#include "tests/exchange/exchange_test_geometry.h"

#include <gtest/gtest.h>

namespace sculptline::exchange_test {
namespace {

using solvers::exchange::toOcct;

/// The conversion copies numbers; the two evaluators (The NURBS Book A4.1 here, BSplCLib there)
/// round differently, a few ulps of coordinates up to 25 mm: 1e-12 leaves room for that only.
constexpr double kSameGeometry = 1e-12;
constexpr int kSamples = 400;

double maxCurveDeviation(const Curve3d& c, const Handle(Geom_BSplineCurve)& occt)
{
    double worst = 0;
    const double a = c.domainStart(), b = c.domainEnd();
    for (int k = 0; k <= kSamples; ++k) {
        const double u = a + (b - a) * k / kSamples;
        const gp_Pnt q = occt->Value(u);
        worst = std::max(worst, (c.evaluate(u) - Eigen::Vector3d(q.X(), q.Y(), q.Z())).norm());
    }
    return worst;
}

TEST(OcctGeometry, RationalQuarterCircleKeepsItsPolesWeightsAndKnots)
{
    const Curve3d c = quarterCircle();
    const Handle(Geom_BSplineCurve) o = toOcct(c);
    EXPECT_EQ(o->Degree(), 2);
    EXPECT_TRUE(o->IsRational());
    ASSERT_EQ(o->NbPoles(), 3);
    EXPECT_DOUBLE_EQ(o->Weight(2), std::sqrt(0.5));
    ASSERT_EQ(o->NbKnots(), 2);
    EXPECT_EQ(o->Multiplicity(1), 3);
    EXPECT_LT(maxCurveDeviation(c, o), kSameGeometry);
}

TEST(OcctGeometry, ClosedCurvesBecomePeriodicOnTheirUniquePoles)
{
    // Seam knots of multiplicity 2 on either side of the domain start, and an interior double knot.
    for (const Curve3d& c : {closedCubic(), closedRational(), closedRational({0, 0.5, 2, 1, 1.5}),
                             closedRational({1, 0.5, 2, 1, 0}), closedRational().insertKnot(2.5)}) {
        SCOPED_TRACE(::testing::Message() << "knots " << Eigen::Map<const Eigen::VectorXd>(c.knots().data(), c.knots().size()).transpose());
        const Handle(Geom_BSplineCurve) o = toOcct(c);
        EXPECT_TRUE(o->IsPeriodic());
        EXPECT_EQ(o->NbPoles(), c.pointCount() - c.degree());
        EXPECT_DOUBLE_EQ(o->FirstParameter(), c.domainStart());
        EXPECT_DOUBLE_EQ(o->LastParameter(), c.domainEnd());
        EXPECT_LT(maxCurveDeviation(c, o), kSameGeometry);
    }
}

TEST(OcctGeometry, UnclampedOpenCurveKeepsItsDomain)
{
    const Curve3d c = unclampedCubic();
    const Handle(Geom_BSplineCurve) o = toOcct(c);
    EXPECT_DOUBLE_EQ(o->FirstParameter(), 3.0);
    EXPECT_DOUBLE_EQ(o->LastParameter(), 5.0);
    EXPECT_LT(maxCurveDeviation(c, o), kSameGeometry);
}

TEST(OcctGeometry, SurfacesEvaluateAlike)
{
    for (const Surface3d& s : {sphereOctant(), bicubicPatch()}) {
        const Handle(Geom_BSplineSurface) o = toOcct(s);
        EXPECT_EQ(o->UDegree(), s.degreeU());
        EXPECT_EQ(o->VDegree(), s.degreeV());
        EXPECT_EQ(o->IsURational() || o->IsVRational(), s.isRational());
        double worst = 0;
        for (int a = 0; a <= 40; ++a) {
            for (int b = 0; b <= 40; ++b) {
                const double u = s.domainStart(solvers::Direction::U) +
                                 (s.domainEnd(solvers::Direction::U) - s.domainStart(solvers::Direction::U)) * a / 40;
                const double v = s.domainStart(solvers::Direction::V) +
                                 (s.domainEnd(solvers::Direction::V) - s.domainStart(solvers::Direction::V)) * b / 40;
                const gp_Pnt q = o->Value(u, v);
                worst = std::max(worst, (s.evaluate(u, v) - Eigen::Vector3d(q.X(), q.Y(), q.Z())).norm());
            }
        }
        EXPECT_LT(worst, kSameGeometry);
    }
}

}  // namespace
}  // namespace sculptline::exchange_test
