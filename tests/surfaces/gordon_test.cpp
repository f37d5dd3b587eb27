// Gordon surfaces: every network curve is an iso-curve of the result (to 1e-9, or to the network's
// gap), in any order and orientation; non-intersecting networks are refused.
#include "solvers/bspline/geometry_error.h"
#include "solvers/bspline/projection.h"
#include "solvers/surfaces/compatible_curves.h"
#include "solvers/surfaces/gordon.h"
#include "surface_checks.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::surfaces;
using namespace sculptline::surfaces_test;

namespace {

// Largest distance from points of `c` to the iso-curve of s at `value` (v fixed if vFixed).
double distanceToIso(const Surface3d& s, bool vFixed, double value, const Curve3d& c)
{
    const CurveProjector<3> iso(s.isoCurve(vFixed ? Direction::V : Direction::U, value));
    double worst = 0.0;
    for (int k = 0; k <= 100; ++k) {
        const double t = c.domainStart() + (c.domainEnd() - c.domainStart()) * k / 100.0;
        worst = std::max(worst, iso.project(c.evaluate(t)).distance);
    }
    return worst;
}

// A curved network on a height field: u-curves in the planes y = y_k, v-curves in x = x_l, polylines
// through the grid points plus extra vertices that differ from curve to curve, so the curves
// intersect exactly but at parameters that differ from curve to curve.
double height(double x, double y) { return 0.3 * std::sin(1.3 * x) * std::cos(0.9 * y) + 0.1 * x * y; }
const std::vector<double> kGridX{0.0, 1.0, 2.2, 3.0};
const std::vector<double> kGridY{0.0, 0.8, 1.3, 2.0};

Curve3d polylineOver(std::vector<double> t, const std::vector<double>& extra, bool alongX, double fixed)
{
    t.insert(t.end(), extra.begin(), extra.end());
    std::sort(t.begin(), t.end());
    std::vector<Vec3> pts;
    for (double s : t) pts.push_back(alongX ? Vec3(s, fixed, height(s, fixed)) : Vec3(fixed, s, height(fixed, s)));
    return makeClampedUniform<3>(1, pts);
}

Curve3d uCurve(double y) { return polylineOver(kGridX, {0.3 + 0.2 * y, 1.5 + 0.1 * y, 2.6}, true, y); }
Curve3d vCurve(double x) { return polylineOver(kGridY, {0.4 + 0.1 * x, 1.7}, false, x); }

}  // namespace

TEST(Gordon, GivenIsoCurvesOfASurface_WhenJoined_ThenEveryCurveIsAnIsoCurve)
{
    // Iso-curves of a bicubic patch intersect at common parameters already.
    std::vector<Vec3> net;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) net.push_back(Vec3(i, j, std::sin(i + 0.5 * j)));
    const Surface3d base(3, 3, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}, 5, 5, net);
    std::vector<Curve3d> us, vs;
    for (double v : {0.0, 0.3, 0.7, 1.0}) us.push_back(base.isoCurve(Direction::V, v));
    for (double u : {0.0, 0.25, 0.6, 1.0}) vs.push_back(base.isoCurve(Direction::U, u));
    const GordonResult g = gordon(us, vs);
    EXPECT_LT(g.maxGap, kExact);
    for (size_t k = 0; k < us.size(); ++k) EXPECT_LT(isoDeviation(g.surface, true, g.vParams[k], us[k]), kExact);
    for (size_t l = 0; l < vs.size(); ++l) EXPECT_LT(isoDeviation(g.surface, false, g.uParams[l], vs[l]), kExact);
    EXPECT_GT(minNeighbourNormalDot(g.surface), 0.0);
}

TEST(Gordon, GivenShuffledReversedNetworkWithUnevenParameters_WhenJoined_ThenCurvesOnTheSurface)
{
    std::vector<Curve3d> us, vs;
    for (double y : kGridY) us.push_back(uCurve(y));
    for (double x : kGridX) vs.push_back(vCurve(x));
    // Shuffle and reverse some.
    std::swap(us[0], us[2]);
    us[1] = reversedCurve(normalizedCurve(us[1]));
    std::swap(vs[1], vs[3]);
    vs[0] = reversedCurve(normalizedCurve(vs[0]));
    const GordonResult g = gordon(us, vs);
    EXPECT_LT(g.maxGap, kExact);
    for (const Curve3d& c : us) {
        double best = 1e300;
        for (double v : g.vParams) best = std::min(best, distanceToIso(g.surface, true, v, c));
        EXPECT_LT(best, kExact);
    }
    for (const Curve3d& c : vs) {
        double best = 1e300;
        for (double u : g.uParams) best = std::min(best, distanceToIso(g.surface, false, u, c));
        EXPECT_LT(best, kExact);
    }
}

TEST(Gordon, GivenCurvesThatDoNotMeet_WhenJoined_ThenClearError)
{
    std::vector<Curve3d> us{uCurve(0.0), uCurve(2.0)};
    std::vector<Curve3d> vs{vCurve(0.0), vCurve(3.0)};
    std::vector<Vec3> lifted = vs[1].points();
    for (Vec3& p : lifted) p.z() += 0.5;
    vs[1] = Curve3d(vs[1].degree(), vs[1].knots(), lifted);
    try {
        gordon(us, vs);
        FAIL() << "expected GeometryError";
    } catch (const GeometryError& e) {
        EXPECT_NE(std::string(e.what()).find("do not intersect"), std::string::npos) << e.what();
    }
    EXPECT_THROW(gordon({us[0]}, vs), GeometryError);
}
