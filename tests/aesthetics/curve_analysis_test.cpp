// Aesthetic analysis (thesis ch. 7) on curves whose characteristic points and measures are known in
// closed form: a sine wave, an exact rational ellipse, a clothoid; a symmetric cubic whose extremum
// sits on a knot; and, independently of the Bernstein root finding, dense sampling of the curvature.
#include "solvers/aesthetics/curve_analysis.h"

#include "solvers/bspline/arc_length.h"
#include "solvers/bspline/geometry_error.h"
#include "solvers/math_constants.h"
#include "solvers/surfaces/interpolation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

namespace {

using namespace sculptline::solvers;
using namespace sculptline::solvers::aesthetics;

// A cubic interpolating `pts` at uniform parameters (The NURBS Book A9.1). The points are samples
// at uniform steps of a smooth parameter of the analytic curve (x for the sine, arc length for the
// clothoid): chord-length parameters would differ from it by O(h^3) per step, and that noise in the
// parameter makes O(h) wiggles in the curvature (3 % at h = 0.03 on the sine), which are real extrema.
Curve2d interpolate(const std::vector<Eigen::Vector2d>& pts)
{
    ControlMatrix data(pts.size(), 2);
    std::vector<double> params;
    for (size_t i = 0; i < pts.size(); ++i) {
        data.row(i) = pts[i].transpose();
        params.push_back(double(i) / (pts.size() - 1));
    }
    const surfaces::CurveInterpolator interp(params, 3);
    const ControlMatrix rows = interp.solve(data);
    std::vector<Eigen::Vector2d> cps;
    for (int i = 0; i < rows.rows(); ++i) cps.emplace_back(rows(i, 0), rows(i, 1));
    return Curve2d(3, interp.knots(), cps);
}

// y = sin x on [x0, x1], interpolated at `count` points.
Curve2d sineWave(double x0, double x1, int count)
{
    std::vector<Eigen::Vector2d> pts;
    for (int i = 0; i < count; ++i) {
        const double x = x0 + (x1 - x0) * i / (count - 1);
        pts.emplace_back(x, std::sin(x));
    }
    return interpolate(pts);
}

// The ellipse x = a cos t, y = b sin t as an exact closed rational quadratic: the affine image of
// the nine-point circle (The NURBS Book Ex. 7.1), in the kernel's unwrapped periodic form.
Curve2d ellipse(double a, double b, const Eigen::Vector2d& centre = Eigen::Vector2d::Zero())
{
    const double w = std::sqrt(0.5);
    const double unit[8][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
    std::vector<Eigen::Vector2d> pts;
    std::vector<double> weights;
    for (int i = 0; i < 10; ++i) {
        pts.push_back(centre + Eigen::Vector2d(a * unit[i % 8][0], b * unit[i % 8][1]));
        weights.push_back(i % 2 ? w : 1.0);
    }
    const KnotVector knots{-0.25, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1.25, 1.25};
    return Curve2d(2, knots, pts, weights, true);
}

// A clothoid with kappa = s / a^2 for s in [s0, s1], from its Fresnel integrals (composite Simpson,
// 2000 steps per sample: error far below the interpolation's), interpolated at `count` points.
Curve2d clothoid(double a, double s0, double s1, int count)
{
    const auto point = [a](double s) {
        constexpr int kSteps = 2000;
        double x = 0.0, y = 0.0;
        const double h = s / kSteps;
        for (int k = 0; k <= kSteps; ++k) {
            const double t = k * h, f = (k == 0 || k == kSteps) ? 1.0 : (k % 2 ? 4.0 : 2.0);
            x += f * std::cos(t * t / (2 * a * a));
            y += f * std::sin(t * t / (2 * a * a));
        }
        return Eigen::Vector2d(x * h / 3, y * h / 3);
    };
    std::vector<Eigen::Vector2d> pts;
    for (int i = 0; i < count; ++i) pts.push_back(point(s0 + (s1 - s0) * i / (count - 1)));
    return interpolate(pts);
}

std::string kinds(const CurveAnalysis& a)
{
    std::string s;
    for (const auto& p : a.points) s += codon(p.kind);
    return s;
}

TEST(CurveAnalysis, GivenASineWave_WhenAnalyzed_ThenExtremaAtThePeaksAndInflectionsAtTheZeros)
{
    // Arrange: y = sin x on [0.3, 4 pi - 0.3]. kappa = -sin x / (1 + cos^2 x)^(3/2) has its extrema at
    // x = pi/2 + k pi only (kappa' = -cos x (4 - 2 cos^2 x)/(1 + cos^2 x)^(5/2)), kappa = -1 at pi/2 (m-),
    // +1 at 3 pi/2 (M+), and changes sign at x = k pi.
    const Curve2d c = sineWave(0.3, 4 * kPi - 0.3, 401);
    // Act
    const CurveAnalysis a = analyzeCurve(c);
    // Assert
    ASSERT_EQ(a.name, "m-0M+0m-0M+");
    // The interpolant (h = 0.03, no end conditions) places them within its own error of the analytic
    // curve's: at an extremum kappa' is flat, so an O(h^2) error in kappa' moves it by O(h^2) / kappa''
    // (2e-4 at the first and last peak, which feel the ends; 1e-5 inside).
    constexpr double kPlace = 5e-4, kCurvature = 1e-4;
    for (int i = 0; i < 7; ++i) {
        const auto& p = a.points[i];
        const double expected = kPi / 2 * (i + 1);
        EXPECT_NEAR(c.evaluate(p.u).x(), expected, kPlace) << i;
        if (p.kind == PointKind::Inflection) {
            EXPECT_NEAR(p.curvature, 0.0, kCurvature) << i;
        } else {
            EXPECT_NEAR(p.curvature, p.kind == PointKind::MaxPositive ? 1.0 : -1.0, kCurvature) << i;
        }
        EXPECT_NEAR(p.arcLength, arcLength(c, c.domainStart(), p.u), 1e-9);
    }
    // The interior extrema have inflections on both sides, a quarter period of arc away.
    ASSERT_EQ(a.characteristics.size(), 4u);
    const auto& inner = a.characteristics[1];  // M+ at 3 pi / 2
    EXPECT_NEAR(inner.dkLeft, 1.0, kCurvature);
    EXPECT_NEAR(inner.dkRight, 1.0, kCurvature);
    EXPECT_NEAR(inner.dLeft, inner.dRight, 2 * kPlace);
    EXPECT_TRUE(inner.symmetric);
    EXPECT_FALSE(inner.redundant);
    EXPECT_FALSE(inner.sharpCorner);
    // The left range ends where kappa is halfway to the neighbour's: found there, inside D_L.
    const ArcLengthParameterization<2> arc(c);
    const auto& m = a.points[inner.point];
    const double uL = arc.parameterAt(m.arcLength - inner.rangeLeft), uR = arc.parameterAt(m.arcLength + inner.rangeRight);
    EXPECT_NEAR(signedCurvature(c, uL), m.curvature - inner.dkLeft / 2, 1e-9);
    EXPECT_NEAR(signedCurvature(c, uR), m.curvature - inner.dkRight / 2, 1e-9);
    EXPECT_LT(inner.rangeLeft, inner.dLeft);
    // Measures: kappa in [-1, 1]; the two turns cancel over the two periods only approximately (the
    // ends are symmetric about 2 pi, so the average is ~0 and tension is undefined).
    EXPECT_NEAR(a.measures.curvatureMax, 1.0, kCurvature);
    EXPECT_NEAR(a.measures.curvatureMin, -1.0, kCurvature);
    EXPECT_NEAR(a.measures.sharpness, 1.0, kCurvature);
    EXPECT_FALSE(a.measures.tension.has_value());
}

TEST(CurveAnalysis, GivenAnExactEllipse_WhenAnalyzed_ThenVerticesAtTheKnotsAndTheMeasuresInClosedForm)
{
    // Arrange: a = 3, b = 2, far from the origin (the rational determinant must not lose it).
    constexpr double ax = 3.0, bx = 2.0;
    const Curve2d c = ellipse(ax, bx, Eigen::Vector2d(1e4, -2e4));
    // Act
    const CurveAnalysis a = analyzeCurve(c);
    // Assert: the vertices (a, 0), (0, b), (-a, 0), (0, -b) are at the double knots 0, 1/4, 1/2, 3/4;
    // kappa = a / b^2 on the major axis (maxima), b / a^2 on the minor (minima).
    ASSERT_EQ(kinds(a), "M+m+M+m+");
    EXPECT_EQ(a.name, "M+m+M+m+");
    constexpr double kExact = 1e-9;
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(a.points[i].u, 0.25 * i, kExact);
        EXPECT_NEAR(a.points[i].curvature, i % 2 ? bx / (ax * ax) : ax / (bx * bx), kExact);
    }
    // Closed: every extremum has extrema of the other type on both sides, a quarter perimeter away.
    const double L = arcLength(c);
    ASSERT_EQ(a.characteristics.size(), 4u);
    for (const auto& ch : a.characteristics) {
        EXPECT_NEAR(ch.dLeft, L / 4, 1e-9 * L);
        EXPECT_NEAR(ch.dRight, L / 4, 1e-9 * L);
        EXPECT_TRUE(ch.symmetric);
    }
    const Measures& m = a.measures;
    EXPECT_NEAR(m.curvatureMax, ax / (bx * bx), kExact);
    EXPECT_NEAR(m.curvatureMin, bx / (ax * ax), kExact);
    EXPECT_NEAR(m.curvatureAverage, 2 * kPi / L, 1e-12);
    ASSERT_TRUE(m.tension.has_value());
    EXPECT_NEAR(*m.tension, (ax / (bx * bx) - bx / (ax * ax)) / (2 * kPi / L), 1e-9);
    EXPECT_NEAR(m.acceleration, (ax / (bx * bx) - bx / (ax * ax)) / (L / 4), 1e-9);
    // The enclosing rectangle is 2a x 2b (within the sampling's chord error: 32 samples per quarter).
    EXPECT_NEAR(m.flatness, 1.0 - bx / ax, 1e-3);
    // No chord on a closed curve: the signed area is the ellipse's, pi a b (Gauss-Legendre on a
    // rational integrand: to 1e-9 relative).
    EXPECT_NEAR(m.convexity, kPi * ax * bx * (bx / ax), 1e-6);
}

TEST(CurveAnalysis, GivenACircle_WhenAnalyzed_ThenNoCharacteristicPointsAndConstantCurvature)
{
    // Arrange: kappa' of an exact circle is zero to round-off everywhere.
    const Curve2d c = ellipse(5.0, 5.0);
    // Act
    const CurveAnalysis a = analyzeCurve(c);
    // Assert
    EXPECT_TRUE(a.points.empty());
    EXPECT_EQ(a.name, "");
    EXPECT_NEAR(a.measures.curvatureMax, 0.2, 1e-12);
    EXPECT_NEAR(a.measures.acceleration, 0.0, 1e-12);
    EXPECT_NEAR(a.measures.flatness, 0.0, 1e-3);
}

TEST(CurveAnalysis, GivenAClothoid_WhenAnalyzed_ThenNoInteriorPointsAndItsLogCurvatureGraphHasSlopeMinusOne)
{
    // Arrange: kappa = s on s in [0.2, 2] (a = 1), interpolated at 120 points.
    const Curve2d c = clothoid(1.0, 0.2, 2.0, 120);
    // Act
    const CurveAnalysis a = analyzeCurve(c);
    // Assert: kappa increases monotonically: no extremum inside, no inflection.
    EXPECT_EQ(a.name, "");
    EXPECT_NEAR(a.length, 1.8, 1e-6);
    // The extremes are the curve's own end curvatures, exactly.
    const Measures& m = a.measures;
    EXPECT_EQ(m.curvatureMin, signedCurvature(c, c.domainStart()));
    EXPECT_EQ(m.curvatureMax, signedCurvature(c, c.domainEnd()));
    // Against the clothoid: the interpolant has no end conditions, so its curvature is O(h) off at
    // the ends (1.2e-3 at h = 0.015), O(h^4) inside.
    constexpr double kEnd = 2e-3;
    EXPECT_NEAR(m.curvatureMin, 0.2, kEnd);
    EXPECT_NEAR(m.curvatureMax, 2.0, kEnd);
    EXPECT_NEAR(m.acceleration, 1.0, kEnd);  // d kappa / ds = 1 / a^2
    // kappa_avg = (s1^2 - s0^2) / 2 / L = 1.1: the total turning, off only by the end tangents' error
    // (O(h^3) = 3e-6 rad).
    EXPECT_NEAR(m.curvatureAverage, 1.1, 1e-5);
    ASSERT_TRUE(m.tension.has_value());
    EXPECT_NEAR(*m.tension, 1.8 / 1.1, kEnd);
    // Log-aesthetic: rho / |d rho / ds| = s, log-linear in rho = 1 / s with slope -1 (Yoshida & Saito).
    // The interpolant's kappa' is piecewise smooth with O(h^2) jumps at the knots: 0.3 % in the slope.
    ASSERT_EQ(a.lcg.size(), 1u);
    EXPECT_NEAR(a.lcg[0].slope, -1.0, 5e-3);
    EXPECT_GT(a.lcg[0].r2, 0.999);
}

TEST(CurveAnalysis, GivenASymmetricArch_WhenAnalyzed_ThenItsExtremumIsAtTheMiddleKnot)
{
    // Arrange: a uniform cubic whose control polygon is symmetric about the middle knot u = 1/2:
    // kappa' jumps there from -c to +c (a cubic's kappa' is discontinuous at knots), never zero.
    const Curve2d c = makeClampedUniform<2>(3, {{-3, 0}, {-2, 1}, {-1, 1.6}, {0, 1.8}, {1, 1.6}, {2, 1}, {3, 0}});
    // Act
    const auto pts = characteristicPoints(c);
    // Assert: an extremum exactly at the knot; kappa < 0 (the arch turns right, clockwise).
    ASSERT_GE(pts.size(), 1u);
    int at = -1;
    for (size_t i = 0; i < pts.size(); ++i) {
        if (std::abs(pts[i].u - 0.5) < 1e-12) at = static_cast<int>(i);
    }
    ASSERT_GE(at, 0);
    // The polygon is flattest at its middle: |kappa| is least there, a maximum of the negative kappa.
    EXPECT_EQ(pts[at].kind, PointKind::MaxNegative);
    const double du = 1e-4;
    EXPECT_LT(signedCurvature(c, 0.5 - du), pts[at].curvature);
    EXPECT_LT(signedCurvature(c, 0.5 + du), pts[at].curvature);
}

// Independent check: the local extrema of kappa sampled at 20,000 parameters (no polynomial algebra)
// match the exact ones in number and place, on random smooth curves, rational or not.
TEST(CurveAnalysis, GivenRandomCurves_WhenAnalyzed_ThenTheExtremaMatchDenseSampling)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jitter(-0.6, 0.6), weight(0.5, 2.0);
    for (int trial = 0; trial < 20; ++trial) {
        // Arrange: 9 control points along x with random heights; half of them rational.
        std::vector<Eigen::Vector2d> pts;
        std::vector<double> w;
        for (int i = 0; i < 9; ++i) {
            pts.emplace_back(i + 0.3 * jitter(rng), jitter(rng) * 2);
            w.push_back(trial % 2 ? weight(rng) : 1.0);
        }
        const Curve2d c = makeClampedUniform<2>(3, pts, trial % 2 ? w : std::vector<double>{});
        // Act
        const auto exact = characteristicPoints(c);
        // Assert
        constexpr int kSamples = 20000;
        std::vector<double> k(kSamples + 1);
        for (int i = 0; i <= kSamples; ++i) k[i] = signedCurvature(c, double(i) / kSamples);
        std::vector<double> sampledExtrema, sampledInflections;
        for (int i = 1; i < kSamples; ++i) {
            if ((k[i] - k[i - 1]) * (k[i + 1] - k[i]) < 0.0) sampledExtrema.push_back(double(i) / kSamples);
            if (k[i] * k[i + 1] < 0.0) sampledInflections.push_back((i + 0.5) / kSamples);
        }
        std::vector<double> exactExtrema, exactInflections;
        for (const auto& p : exact) (p.kind == PointKind::Inflection ? exactInflections : exactExtrema).push_back(p.u);
        ASSERT_EQ(exactExtrema.size(), sampledExtrema.size()) << "trial " << trial;
        ASSERT_EQ(exactInflections.size(), sampledInflections.size()) << "trial " << trial;
        for (size_t i = 0; i < exactExtrema.size(); ++i) EXPECT_NEAR(exactExtrema[i], sampledExtrema[i], 2.0 / kSamples);
        for (size_t i = 0; i < exactInflections.size(); ++i) EXPECT_NEAR(exactInflections[i], sampledInflections[i], 1.0 / kSamples);
        // Where an extremum is not on a knot, d kappa / du vanishes there (to the bisection's round-off).
        for (const auto& p : exact) {
            if (p.kind == PointKind::Inflection) {
                EXPECT_NEAR(signedCurvature(c, p.u), 0.0, 1e-9);
            }
        }
    }
}

TEST(CurveAnalysis, GivenClosedNames_WhenRotatedOrReversed_ThenTheSameName)
{
    using K = PointKind;
    const std::vector<K> a{K::MaxPositive, K::Inflection, K::MinNegative, K::Inflection};
    const std::vector<K> rotated{K::MinNegative, K::Inflection, K::MaxPositive, K::Inflection};
    // Reversed: order reversed and M+ <-> m-.
    const std::vector<K> back{K::Inflection, K::MaxPositive, K::Inflection, K::MinNegative};
    EXPECT_EQ(curveName(a, true), curveName(rotated, true));
    EXPECT_EQ(curveName(a, true), curveName(back, true));
    EXPECT_EQ(curveName(a, false), "M+0m-0");
    EXPECT_NE(curveName({K::MaxPositive, K::MinPositive}, true), curveName({K::MaxPositive, K::MinNegative}, true));
}

TEST(CurveAnalysis, GivenASpaceCurveInATiltedPlane_WhenFlattened_ThenTheSameAnalysis)
{
    // Arrange: the sine wave turned into the plane through the x axis tilted 30 degrees about it.
    const Curve2d flat = sineWave(0.3, 2 * kPi - 0.3, 101);
    std::vector<Eigen::Vector3d> pts;
    for (const auto& p : flat.points()) pts.emplace_back(p.x(), p.y() * std::cos(0.5), p.y() * std::sin(0.5) + 7.0);
    const Curve3d tilted(3, flat.knots(), pts);
    // Act
    const CurveAnalysis a = analyzeCurve(planarCurve(tilted)), b = analyzeCurve(flat);
    // Assert
    EXPECT_EQ(a.name, b.name);
    ASSERT_EQ(a.points.size(), b.points.size());
    for (size_t i = 0; i < a.points.size(); ++i) EXPECT_NEAR(a.points[i].curvature, b.points[i].curvature, 1e-9);
}

TEST(CurveAnalysis, GivenBadInput_WhenAnalyzed_ThenAClearError)
{
    // A helix is not planar.
    std::vector<Eigen::Vector3d> helix;
    for (int i = 0; i < 12; ++i) helix.emplace_back(std::cos(0.7 * i), std::sin(0.7 * i), 0.3 * i);
    EXPECT_THROW(planarCurve(makeClampedUniform<3>(3, helix)), GeometryError);
    // A polyline has no curvature; a collapsed curve none either.
    EXPECT_THROW(analyzeCurve(makeClampedUniform<2>(1, {{0, 0}, {1, 0}, {1, 1}})), GeometryError);
    EXPECT_THROW(analyzeCurve(makeClampedUniform<2>(3, {{1, 1}, {1, 1}, {1, 1}, {1, 1}})), GeometryError);
    // More control points than the analysis takes (it would hold its caller for long).
    std::vector<Eigen::Vector2d> many;
    for (int i = 0; i <= kMaxAnalysisPoints; ++i) many.emplace_back(i, std::sin(0.1 * i));
    EXPECT_THROW(analyzeCurve(makeClampedUniform<2>(3, many)), GeometryError);
    // Thresholds must be positive.
    Thresholds t;
    t.distance = -1.0;
    EXPECT_THROW(analyzeCurve(sineWave(0, 3, 20), t), GeometryError);
}

}  // namespace
