// Over-sketching a space curve with a space stroke (thesis 002 §4.2 and seed 001 Alg. 1-1 in 3D):
// the stroke replaces the part it covers, the rest of the curve keeps its points and parameters.
#include "solvers/editing/oversketch.h"

#include "solvers/bspline/projection.h"
#include "tests/editing/editing_fixtures.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>

using namespace sculptline::solvers;
using namespace sculptline::solvers::editing;
using sculptline::editing_fixtures::helix;
using sculptline::editing_fixtures::maxJump;

namespace {

/// A stroke over the helix's parameters [u0, u1], raised by h (sin(pi t) + 0.2) along the curve's
/// binormal: out of the curve's osculating plane, so the edit itself bends the curve in space.
std::vector<Eigen::Vector3d> spaceBump(const Curve3d& c, double u0, double u1, double h, int count)
{
    std::vector<Eigen::Vector3d> s;
    for (int i = 0; i < count; ++i) {
        const double t = double(i) / (count - 1);
        const auto d = c.derivatives(u0 + (u1 - u0) * t, 2);
        const Eigen::Vector3d binormal = d[1].cross(d[2]).normalized();
        s.push_back(d[0] + h * (std::sin(M_PI * t) + 0.2) * binormal);
    }
    return s;
}

double polylineLength(const std::vector<Eigen::Vector3d>& pts)
{
    double length = 0.0;
    for (size_t i = 1; i < pts.size(); ++i) length += (pts[i] - pts[i - 1]).norm();
    return length;
}

class Oversketch3d : public ::testing::TestWithParam<OversketchMethod> {};

TEST_P(Oversketch3d, GivenSpaceStrokeOverTheMiddleOfAHelix_WhenOversketched_ThenFarPartsUnchangedAndStrokeFollowed)
{
    // Given a cubic on 50 points of a helix (radius 10, 0.4 rad and 0.8 up per point) and a stroke over
    // the middle fifth of its domain, raised 3 units along the binormal
    const Curve3d curve = helix(50);
    const double a = curve.domainStart(), e = curve.domainEnd();
    const std::vector<Eigen::Vector3d> stroke = spaceBump(curve, a + 0.4 * (e - a), a + 0.6 * (e - a), 3.0, 200);
    OversketchOptions o;
    o.method = GetParam();

    // When over-sketched in space
    std::pair<double, double> span;
    const Curve3d out = oversketch<3>(curve, stroke, o, &span);

    // Then the edit stays near the stroke,
    EXPECT_GT(span.first, a + 0.25 * (e - a));
    EXPECT_LT(span.second, a + 0.75 * (e - a));
    // nothing outside the edited span moves, at the same parameter (1e-9 of a 40-unit curve: far
    // above evaluation round-off, ~1e-13, far below anything a designer sees),
    constexpr double kFar = 1e-9;
    EXPECT_EQ(out.domainStart(), a);
    EXPECT_EQ(out.domainEnd(), e);
    int checked = 0;
    for (int i = 0; i <= 2000; ++i) {
        const double u = a + (e - a) * i / 2000.0;
        if (u <= span.first || u >= span.second) {
            EXPECT_LT((out.evaluate(u) - curve.evaluate(u)).norm(), kFar) << "u = " << u;
            ++checked;
        }
    }
    EXPECT_GT(checked, 1000) << "most of the curve lies outside the edit";
    // the edit is C2 and follows the space stroke within the tolerance (relative to its length),
    EXPECT_LT(maxJump(out, 2), 1e-9);
    const CurveProjector<3> projector(out);
    double worst = 0.0;
    for (const Eigen::Vector3d& p : stroke) worst = std::max(worst, projector.project(p).distance);
    EXPECT_LE(worst, o.tolerance * polylineLength(stroke));
    // and the curve did move off its old path where the stroke was (3 units, not a no-op).
    const double mid = 0.5 * (span.first + span.second);
    EXPECT_GT(projectToCurve(curve, out.evaluate(mid)).distance, 2.0);
    std::printf("%s: span [%.3f, %.3f] of [%.3f, %.3f], stroke followed to %.2g\n", GetParam() == OversketchMethod::Blend ? "blend" : "local-c2",
                span.first, span.second, a, e, worst);
}

INSTANTIATE_TEST_SUITE_P(Methods, Oversketch3d, ::testing::Values(OversketchMethod::LocalC2, OversketchMethod::Blend));

}  // namespace
