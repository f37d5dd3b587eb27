// Seed 000's dome (§3.2, Figs. 2, 3 and 8): a closed rim A drawn on a flat-ish bicubic sheet and
// fixed, a curve B across it asking the surface to bulge, then a third curve C across B. Solved by
// solveIncidence (MTSVD at TSVD's corner, the sheet before each step the prior). Given / When / Then.
#include "solvers/incidence/incidence_solve.h"

#include "solvers/bspline/basis.h"
#include "solvers/incidence/curve_crossings.h"
#include "tests/incidence/incidence_fixtures.h"

#include <Eigen/QR>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

namespace sculptline::solvers::incidence {
namespace {

using incidence_test::clampedKnots;

constexpr double kSheetSize = 100.0;  // mm, the sheet spans [0, 100]^2
constexpr double kDomeHeight = 20.0;  // mm, what B and C ask for at the rim's centre
constexpr double kRimRadius = 0.35;   // in the domain [0, 1]^2, centred at (0.5, 0.5)
// The sheets' control nets. Seed 000 Fig. 8 uses 10 x 10, but there (TSVD over all rows) the rim is
// kept only to the truncation's residual. Met exactly, a rim of radius 0.35 fixes every control point
// of a 10 x 10 bicubic whose support it crosses, and every interior one's does (a support is 4/7
// of the domain wide, its half-diagonal 0.40 > 0.35): nothing inside can rise. On 16 x 16 (supports
// 4/13 wide) about a dozen interior control points lie wholly inside the rim, free to bulge.
constexpr int kFigureEightNet = 10;
constexpr int kDomeNet = 20;
// A fixed curve is a hard constraint met by a projection onto its rows' null space: round-off only.
// 1e-9 of the sheet's size (1e-7 mm) leaves three to four orders above double's ε times the sums.
constexpr double kFixedRelative = 1e-9;
// B and C, measured on the 20 x 20 dome (README "The dome"): the exact rim pins every control point
// whose support crosses it, so within about three spans inside the rim (distance 0.17-0.35 from the
// centre) the surface cannot rise as steeply as the cos² request: there B misses by up to 3.1 mm
// (16 % of the height); inside that band, by at most 0.8 mm (4 %), the L-curve's truncation (k = 7
// of 19) trading residual for a smooth net. The seed reports "less than 10^-3" for Fig. 7 (one
// curve, no fixed rim, units not given), which this configuration cannot reach and is not asserted.
constexpr double kWholeCurveTolerance = 0.2 * kDomeHeight;  // 4 mm
constexpr double kInnerRadius = kRimRadius - 3.0 / 17.0;     // the rim's radius less three spans
constexpr double kInnerTolerance = 0.075 * kDomeHeight;     // 1.5 mm
// When C is added, B's points may move by at most this (measured 0.68 mm: C's request agrees with
// B's at the centre, but the few free control points are now shared by both).
constexpr double kBMovesAtMost = 0.05 * kDomeHeight;  // 1 mm

/// n x n bicubic over 100 x 100, gently wavy (±1 mm).
Surface3d flatishSheet(int n)
{
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            points.emplace_back(kSheetSize * i / (n - 1), kSheetSize * j / (n - 1), std::sin(0.6 * i + 0.3 * j));
    return Surface3d(3, 3, clampedKnots(3, n), clampedKnots(3, n), n, n, points);
}

/// The rim A: a closed uniform cubic whose 12-point polygon is scaled so that the curve lies about
/// kRimRadius from the centre (a uniform cubic of n points on a circle sits at (2 + cos(2π/n))/3 of
/// the polygon's radius).
Curve2d rimCurve()
{
    constexpr int n = 12;
    const double polygonRadius = kRimRadius * 3.0 / (2.0 + std::cos(2.0 * M_PI / n));
    std::vector<Curve2d::Point> points;
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * M_PI * i / n;
        points.emplace_back(0.5 + polygonRadius * std::cos(a), 0.5 + polygonRadius * std::sin(a));
    }
    return makeClosedUniform<2>(3, points);
}

/// A straight cubic domain curve from `a` to `b` with 6 points (not along a parameter line).
Curve2d across(const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
    std::vector<Curve2d::Point> points;
    for (int i = 0; i < 6; ++i) points.emplace_back(a + (b - a) * (i / 5.0));
    return Curve2d(3, clampedKnots(3, 6), points);
}

/// The bulge asked for at domain point uv: kDomeHeight cos²(π d / 2R) inside the rim (d the distance
/// from the centre), 0 outside; C1 across the rim, so the request agrees with A where they cross.
double bulge(const Eigen::Vector2d& uv)
{
    const double d = (uv - Eigen::Vector2d(0.5, 0.5)).norm();
    if (d >= kRimRadius) return 0.0;
    const double c = std::cos(M_PI * d / (2.0 * kRimRadius));
    return kDomeHeight * c * c;
}

/// The request for domain curve g on `sheet`: S(G(t)) raised by bulge(G(t)), a cubic with 12 points
/// fitted by least squares to 120 samples.
Curve3d bulgingRequest(const Surface3d& sheet, const Curve2d& g)
{
    constexpr int kPoints = 12, kSamples = 120;
    const KnotVector knots = clampedKnots(3, kPoints);
    Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(kSamples, kPoints), values(kSamples, 3);
    for (int k = 0; k < kSamples; ++k) {
        const double t = static_cast<double>(k) / (kSamples - 1);
        const Eigen::Vector2d uv = g.evaluate(t);
        values.row(k) = (sheet.evaluate(uv.x(), uv.y()) + Eigen::Vector3d(0, 0, bulge(uv))).transpose();
        const int span = findSpan(3, knots, t);
        double nb[4];
        basisFunctions(span, t, 3, knots, nb);
        for (int a = 0; a <= 3; ++a) basis(k, span - 3 + a) = nb[a];
    }
    const Eigen::MatrixXd p = basis.colPivHouseholderQr().solve(values);
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < kPoints; ++i) points.emplace_back(p.row(i).transpose());
    return Curve3d(3, knots, points);
}

/// Largest distance between the surface over g and `curve`, sampled at 201 parameters, of the
/// samples within `radius` of the rim's centre.
double curveOnSurfaceGap(const Surface3d& s, const Curve2d& g, const Curve3d& curve, double radius = 2.0)
{
    double worst = 0.0;
    for (int k = 0; k <= 200; ++k) {
        const double t = k / 200.0;
        const Eigen::Vector2d uv = g.evaluate(g.domainStart() + t * (g.domainEnd() - g.domainStart()));
        if ((uv - Eigen::Vector2d(0.5, 0.5)).norm() > radius) continue;
        worst = std::max(worst, (s.evaluate(uv.x(), uv.y()) - curve.evaluate(t)).norm());
    }
    return worst;
}

/// Largest movement of the surface over g between two surfaces.
double movedAlong(const Surface3d& before, const Surface3d& after, const Curve2d& g)
{
    double worst = 0.0;
    const double t0 = g.domainStart(), t1 = g.domainEnd();
    for (int k = 0; k <= 200; ++k) {
        const Eigen::Vector2d uv = g.evaluate(t0 + (t1 - t0) * k / 200.0);
        worst = std::max(worst, (after.evaluate(uv.x(), uv.y()) - before.evaluate(uv.x(), uv.y())).norm());
    }
    return worst;
}

TEST(IncidenceDome, GivenFigureEightsNetWithAnExactRim_WhenBAsksForABulge_ThenNothingInsideMovesAndNothingBlowsUp)
{
    // Given seed 000 Fig. 8's 10 x 10 sheet, the rim fixed exactly, and B asking for the bulge
    const Surface3d sheet = flatishSheet(kFigureEightNet);
    const Curve2d rim = rimCurve();
    const Curve2d b = across({0.12, 0.30}, {0.88, 0.70});
    // When solved
    const IncidenceResult r = solveIncidence(sheet, {{rim, std::nullopt, true}, {b, bulgingRequest(sheet, b), false}});
    // Then the rim is exact and the inside stays where it was: the rim's rows determine every
    // control point that could raise it. (Before the soft system's rank was cut at the null basis's
    // accuracy, max(m, n) ε κ(C), the corner picked round-off directions of S N: the rim moved 2 µm,
    // the border control points 1e12 mm, and B was "met" to 0.16 mm by amplified noise.)
    EXPECT_LE(r.fixedResidual, kFixedRelative * kSheetSize);
    double insideMoved = 0.0, largestChange = 0.0;
    for (int i = 0; i <= 20; ++i)
        for (int j = 0; j <= 20; ++j) {
            const Eigen::Vector2d uv(i / 20.0, j / 20.0);
            if ((uv - Eigen::Vector2d(0.5, 0.5)).norm() < kRimRadius)
                insideMoved = std::max(insideMoved, (r.surface.evaluate(uv.x(), uv.y()) - sheet.evaluate(uv.x(), uv.y())).norm());
        }
    for (size_t i = 0; i < sheet.points().size(); ++i)
        largestChange = std::max(largestChange, (r.surface.points()[i] - sheet.points()[i]).norm());
    EXPECT_LE(insideMoved, kFixedRelative * kSheetSize);
    // Outside the rim (trimmed away in the seed) B's two ends pull the corner control points
    // (measured 71 mm); the bound says only that they stay on the scale of the request.
    EXPECT_LT(largestChange, 10.0 * kDomeHeight);
    EXPECT_GT(r.residual, 0.9 * kDomeHeight);  // B's bulge is not met: the designer sees it cannot be
}

TEST(IncidenceDome, GivenAFixedRimAndACurveAcrossIt_WhenSolved_ThenTheRimStaysAndTheSurfaceBulges)
{
    // Given the sheet, the rim A fixed (it keeps its present image), and B across it, asking for a
    // bulge of kDomeHeight at the centre
    const Surface3d sheet = flatishSheet(kDomeNet);
    const Curve2d rim = rimCurve();
    const Curve2d b = across({0.12, 0.30}, {0.88, 0.70});
    const Curve3d bRequest = bulgingRequest(sheet, b);
    // (B crosses A twice: seed 000 Fig. 3's P1 and P2, tied by point incidences in the stack)
    ASSERT_EQ(curveCrossings(rim, b).size(), 2u);
    const double centreBefore = sheet.evaluate(0.5, 0.5).z();

    // When solved
    const IncidenceResult ab = solveIncidence(sheet, {{rim, std::nullopt, true}, {b, bRequest, false}});
    std::cout << "Dome A+B: " << ab.rows << " soft rows x " << ab.cols << " (hard " << ab.hardRows << "), k " << ab.k
              << " of " << ab.lcurve.rho.size() << ", A " << ab.fixedResidual << " mm, B " << ab.residual
              << " mm (inside the band " << curveOnSurfaceGap(ab.surface, b, bRequest, kInnerRadius) << "), centre z "
              << ab.surface.evaluate(0.5, 0.5).z() << " (was " << centreBefore << ")\n";

    // Then A is met to round-off, B within the tolerances above, and the surface bulges at the centre
    EXPECT_GT(ab.hardRows, 0);
    EXPECT_LE(ab.fixedResidual, kFixedRelative * kSheetSize);
    EXPECT_LE(movedAlong(sheet, ab.surface, rim), kFixedRelative * kSheetSize);  // A keeps its image
    EXPECT_LE(ab.residual, kWholeCurveTolerance);
    EXPECT_LE(curveOnSurfaceGap(ab.surface, b, bRequest, kInnerRadius), kInnerTolerance);
    EXPECT_NEAR(ab.surface.evaluate(0.5, 0.5).z() - centreBefore, kDomeHeight, kInnerTolerance);

    // When C is added later across B (through the centre, crossing A twice and B once: P5), the
    // bulged sheet the prior, B keeping its request
    const Curve2d c = across({0.30, 0.88}, {0.70, 0.12});
    const Curve3d cRequest = bulgingRequest(sheet, c);
    ASSERT_EQ(curveCrossings(rim, c).size(), 2u);
    ASSERT_EQ(curveCrossings(b, c).size(), 1u);
    const IncidenceResult abc =
        solveIncidence(ab.surface, {{rim, std::nullopt, true}, {b, bRequest, false}, {c, cRequest, false}});
    std::cout << "Dome A+B+C: " << abc.rows << " soft rows x " << abc.cols << " (hard " << abc.hardRows << "), k "
              << abc.k << ", A " << abc.fixedResidual << " mm, B and C " << abc.residual << " mm; B moved "
              << movedAlong(ab.surface, abc.surface, b) << " mm, A moved " << movedAlong(sheet, abc.surface, rim)
              << " mm; inside the band B " << curveOnSurfaceGap(abc.surface, b, bRequest, kInnerRadius) << " C "
              << curveOnSurfaceGap(abc.surface, c, cRequest, kInnerRadius) << " mm, centre rise "
              << abc.surface.evaluate(0.5, 0.5).z() - centreBefore << " mm\n";

    // Then A stays exact (against the original sheet), B stays close, C is met
    EXPECT_LE(abc.fixedResidual, kFixedRelative * kSheetSize);
    EXPECT_LE(movedAlong(sheet, abc.surface, rim), kFixedRelative * kSheetSize);
    EXPECT_LE(abc.residual, kWholeCurveTolerance);
    EXPECT_LE(curveOnSurfaceGap(abc.surface, b, bRequest, kInnerRadius), kInnerTolerance);
    EXPECT_LE(movedAlong(ab.surface, abc.surface, b), kBMovesAtMost);
    EXPECT_LE(curveOnSurfaceGap(abc.surface, c, cRequest, kInnerRadius), kInnerTolerance);
    EXPECT_NEAR(abc.surface.evaluate(0.5, 0.5).z() - centreBefore, kDomeHeight, kInnerTolerance);
}

}  // namespace
}  // namespace sculptline::solvers::incidence
