// Gaussian and mean curvature (solvers/bspline/surface_curvature.h) against closed forms: an exact
// rational sphere and cylinder (surfaces of revolution), a plane with a non-uniform parameterization,
// and the saddle z = x^2 - y^2 as a polynomial biquadratic (and its bicubic elevation).
#include "solvers/bspline/surface_curvature.h"
#include "solvers/surfaces/revolve.h"
#include "surface_checks.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace sculptline::solvers;
using namespace sculptline::solvers::surfaces;
using namespace sculptline::surfaces_test;

namespace {

/// Curvatures of exact geometry: second derivatives of rational quadratics in double precision
/// keep about 12 digits, the fundamental forms lose at most a few more; 1e-9 relative to 1/r
/// (or 1/r^2) leaves three orders of margin and still catches any wrong term or factor.
constexpr double kCurvatureTolerance = 1e-9;

constexpr double kRadius = 2.5;
const Vec3 kCentre(0.3, -0.4, 1.1);

/// A sphere of radius kRadius about kCentre: the half circle x^2 + z^2 = r^2 (x >= 0) as two exact
/// rational quadratic arcs (The NURBS Book §7.5) revolved 360 degrees about the z axis through
/// kCentre. u runs from the south pole to the north pole; both poles are collapsed edges.
Surface3d sphere()
{
    const double r = kRadius, w = std::sqrt(0.5);
    const std::vector<Vec3> pts{kCentre + Vec3(0, 0, -r), kCentre + Vec3(r, 0, -r), kCentre + Vec3(r, 0, 0),
                                kCentre + Vec3(r, 0, r), kCentre + Vec3(0, 0, r)};
    const Curve3d halfCircle(2, {0, 0, 0, 0.5, 0.5, 1, 1, 1}, pts, {1, w, 1, w, 1});
    return revolve(halfCircle, Axis{kCentre, Vec3::UnitZ()});
}

/// A cylinder of radius kRadius about the z axis through kCentre, 4 units high.
Surface3d cylinder()
{
    const Curve3d line(1, {0, 0, 1, 1}, {kCentre + Vec3(kRadius, 0, 0), kCentre + Vec3(kRadius, 0, 4)});
    return revolve(line, Axis{kCentre, Vec3::UnitZ()});
}

/// z = x^2 - y^2 on [-1, 1]^2 as a biquadratic Bezier patch, x = 2u - 1, y = 2v - 1: the Bernstein
/// coefficients of (2t - 1)^2 are 1, -1, 1 (f(0), f(0) + f'(0)/2, f(1)), so z_ij = c_i - c_j.
Surface3d saddle()
{
    const double x[3] = {-1, 0, 1}, c[3] = {1, -1, 1};
    std::vector<Vec3> pts;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) pts.emplace_back(x[i], x[j], c[i] - c[j]);
    return Surface3d(2, 2, {0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}, 3, 3, pts);
}

/// Monge patch z = f(x, y) = x^2 - y^2 with upward normal (do Carmo §3-3, Example 5).
SurfaceCurvature saddleClosedForm(double x, double y)
{
    const double fx = 2 * x, fy = -2 * y, fxx = 2, fyy = -2, fxy = 0;
    const double g = 1 + fx * fx + fy * fy;
    return {(fxx * fyy - fxy * fxy) / (g * g), ((1 + fy * fy) * fxx - 2 * fx * fy * fxy + (1 + fx * fx) * fyy) / (2 * std::pow(g, 1.5)),
            true};
}

}  // namespace

TEST(SurfaceCurvature, GivenExactRationalSphere_WhenEvaluated_ThenKIsOneOverRSquaredAndHPointsToTheCentre)
{
    const Surface3d s = sphere();
    int checked = 0;
    for (int i = 1; i < 20; ++i) {  // poles excluded: the metric is degenerate there
        for (int j = 0; j <= 24; ++j) {
            const double u = i / 20.0, v = j / 24.0;
            const SurfaceCurvature k = surfaceCurvature(s, u, v);
            ASSERT_TRUE(k.defined) << u << " " << v;
            EXPECT_NEAR(k.gaussian, 1 / (kRadius * kRadius), kCurvatureTolerance / (kRadius * kRadius));
            EXPECT_NEAR(std::abs(k.mean), 1 / kRadius, kCurvatureTolerance / kRadius);
            // The sign convention: H n (n = Su x Sv normalized) is the mean curvature vector, which
            // points to the centre of a sphere whichever way n points.
            const Vec3 n = s.normal(u, v);
            const Vec3 towardsCentre = (kCentre - s.evaluate(u, v)) / (kRadius * kRadius);
            EXPECT_LT((k.mean * n - towardsCentre).norm(), kCurvatureTolerance / kRadius);
            ++checked;
        }
    }
    EXPECT_EQ(checked, 19 * 25);
}

TEST(SurfaceCurvature, GivenSpherePole_WhenEvaluated_ThenUndefined)
{
    const Surface3d s = sphere();
    EXPECT_FALSE(surfaceCurvature(s, 0.0, 0.3).defined);
    EXPECT_FALSE(surfaceCurvature(s, 1.0, 0.7).defined);
}

TEST(SurfaceCurvature, GivenExactRationalCylinder_WhenEvaluated_ThenKIsZeroAndHIsHalfOverR)
{
    const Surface3d s = cylinder();
    for (int i = 0; i <= 10; ++i) {
        for (int j = 0; j <= 24; ++j) {
            const double u = i / 10.0, v = j / 24.0;
            const SurfaceCurvature k = surfaceCurvature(s, u, v);
            ASSERT_TRUE(k.defined);
            EXPECT_NEAR(k.gaussian, 0.0, kCurvatureTolerance / (kRadius * kRadius));
            EXPECT_NEAR(std::abs(k.mean), 1 / (2 * kRadius), kCurvatureTolerance / kRadius);
            const Vec3 p = s.evaluate(u, v);
            Vec3 towardsAxis = kCentre - p;
            towardsAxis.z() = 0;
            EXPECT_LT((k.mean * s.normal(u, v) - towardsAxis / (2 * kRadius * kRadius)).norm(), kCurvatureTolerance / kRadius);
        }
    }
}

TEST(SurfaceCurvature, GivenPlaneWithUnevenParameterization_WhenEvaluated_ThenBothCurvaturesVanish)
{
    // A bicubic patch whose net lies in a tilted plane but is spaced unevenly: Suu, Suv, Svv are
    // non-zero, yet tangent to the plane, so L = M = N = 0.
    const Vec3 o(1, 2, 3), a(1, 0.5, -0.2), b(-0.3, 1, 0.4);
    std::vector<Vec3> pts;
    const double su[4] = {0, 0.2, 1.5, 2}, sv[4] = {0, 1.1, 1.3, 3};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) pts.push_back(o + a * (su[i] + 0.3 * sv[j] * sv[j]) + b * sv[j] * (1 + 0.2 * su[i]));
    const Surface3d s(3, 3, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}, 4, 4, pts);
    for (int i = 0; i <= 8; ++i)
        for (int j = 0; j <= 8; ++j) {
            const SurfaceCurvature k = surfaceCurvature(s, i / 8.0, j / 8.0);
            ASSERT_TRUE(k.defined);
            EXPECT_NEAR(k.gaussian, 0.0, kCurvatureTolerance);
            EXPECT_NEAR(k.mean, 0.0, kCurvatureTolerance);
        }
}

TEST(SurfaceCurvature, GivenSaddle_WhenEvaluatedAtTheOrigin_ThenKIsMinusFourAndHIsZero)
{
    const Surface3d s = saddle();
    const SurfaceCurvature k = surfaceCurvature(s, 0.5, 0.5);
    ASSERT_TRUE(k.defined);
    EXPECT_NEAR(k.gaussian, -4.0, kCurvatureTolerance * 4);
    EXPECT_NEAR(k.mean, 0.0, kCurvatureTolerance);
}

TEST(SurfaceCurvature, GivenSaddleAndItsBicubicElevation_WhenEvaluatedAnywhere_ThenTheMongeFormulasHold)
{
    const Surface3d quadratic = saddle();
    const Surface3d cubic = quadratic.elevate(Direction::U, 1).elevate(Direction::V, 1);
    ASSERT_EQ(cubic.degreeU(), 3);
    ASSERT_EQ(cubic.degreeV(), 3);
    for (const Surface3d* s : {&quadratic, &cubic}) {
        for (int i = 0; i <= 10; ++i)
            for (int j = 0; j <= 10; ++j) {
                const double u = i / 10.0, v = j / 10.0;
                const SurfaceCurvature expected = saddleClosedForm(2 * u - 1, 2 * v - 1);
                const SurfaceCurvature k = surfaceCurvature(*s, u, v);
                ASSERT_TRUE(k.defined);
                EXPECT_NEAR(k.gaussian, expected.gaussian, kCurvatureTolerance * 4);
                EXPECT_NEAR(k.mean, expected.mean, kCurvatureTolerance * 4);
            }
    }
    // The sign relative to Su x Sv, which points up here (x grows with u, y with v): at (0.8, 0)
    // the surface bends down across the x axis (fyy / sqrt(g) = -2 / 1.89) more than up along it
    // (fxx / g^1.5 = 2 / 6.72), so it bends away from the normal on average: H < 0. At (0, 0.8),
    // by symmetry, H > 0.
    EXPECT_LT(surfaceCurvature(quadratic, 0.9, 0.5).mean, 0.0);
    EXPECT_GT(surfaceCurvature(quadratic, 0.5, 0.9).mean, 0.0);
}

TEST(SurfaceCurvature, GivenRationalSurfaceWithInteriorKnots_WhenEvaluatedOnAGrid_ThenTheGridMatchesPointwise)
{
    // Arrange: a rational bicubic x biquadratic patch with interior knots; grid lines on the knots.
    const int nu = 6, nv = 5;
    std::vector<Vec3> pts;
    std::vector<double> w;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            pts.emplace_back(i + 0.1 * j, j, std::sin(1.7 * i) * std::cos(1.3 * j));
            w.push_back(1.0 + 0.3 * ((i + j) % 3));
        }
    const Surface3d s(3, 2, {0, 0, 0, 0, 0.8, 1.5, 2, 2, 2, 2}, {-1, -1, -1, 0.5, 1, 3, 3, 3}, nu, nv, pts, w);
    const std::vector<double> u{0, 0.3, 0.8, 1.2, 1.5, 1.9, 2}, v{-1, 0, 0.5, 0.7, 1, 2.2, 3};
    // Act
    const CurvatureGrid grid(s, u, v);
    std::vector<SurfaceCurvature> out;
    grid.evaluate(s, out);
    // Assert
    ASSERT_TRUE(grid.fits(s));
    ASSERT_EQ(out.size(), u.size() * v.size());
    for (size_t r = 0; r < u.size(); ++r)
        for (size_t c = 0; c < v.size(); ++c) {
            const SurfaceCurvature pointwise = surfaceCurvature(s, u[r], v[c]);
            const SurfaceCurvature& g = out[r * v.size() + c];
            EXPECT_EQ(g.defined, pointwise.defined);
            EXPECT_NEAR(g.gaussian, pointwise.gaussian, kCurvatureTolerance * (1 + std::abs(pointwise.gaussian)));
            EXPECT_NEAR(g.mean, pointwise.mean, kCurvatureTolerance * (1 + std::abs(pointwise.mean)));
        }
    EXPECT_FALSE(grid.fits(s.insertKnot(Direction::U, 1.0)));
}
