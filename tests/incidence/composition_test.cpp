// H = A F by exact composition: A F is the surface curve F(G) (seed 000 §2.1, Fig. 4).
#include "solvers/incidence/composition.h"

#include "solvers/bspline/geometry_error.h"
#include "tests/incidence/incidence_fixtures.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <random>

using namespace sculptline::solvers;
using namespace sculptline::solvers::incidence;
using namespace sculptline::incidence_test;

namespace {

// Exact up to round-off: relative to the surface's control size (about 130 model units here).
constexpr double kExactRelative = 1e-12;
constexpr int kSamples = 2000;

double surfaceSize(const Surface3d& f)
{
    Eigen::AlignedBox3d box;
    for (const auto& p : f.points()) box.extend(p);
    return box.diagonal().norm();
}

// max |H(t) - F(G(t))| over kSamples + 1 parameters, relative to the surface's size.
double compositionError(const Surface3d& f, const Curve2d& g, const Curve3d& h)
{
    double worst = 0.0;
    for (int k = 0; k <= kSamples; ++k) {
        const double t = g.domainStart() + (g.domainEnd() - g.domainStart()) * k / kSamples;
        const Eigen::Vector2d uv = g.evaluate(t);
        worst = std::max(worst, (h.evaluate(t) - f.evaluate(uv.x(), uv.y())).norm());
    }
    return worst / surfaceSize(f);
}

}  // namespace

TEST(IncidenceComposition, DiagonalCurveOfFigureFourIsExact)
{
    // Given Fig. 4's 8x10 bicubic surface and its cubic 8-point diagonal domain curve
    const Surface3d f = figureFourSurface();
    const Curve2d g = diagonalCurve(8);
    // When A is composed and applied to F's control points
    const Composition c = compose(SurfaceStructure::of(f), g);
    const Curve3d h = applyComposition(c, f);
    // Then H has degree (3 + 3) 3 = 18, Bezier pieces, and is F(G) to round-off
    EXPECT_EQ(c.space.degree, 18);
    EXPECT_EQ(c.space.pointCount(), c.space.pieceCount() * 18 + 1);
    EXPECT_EQ(c.matrix.rows(), c.space.pointCount());
    EXPECT_EQ(c.matrix.cols(), 80);
    EXPECT_LT(compositionError(f, g, h), kExactRelative);
    // The diagonal crosses the 4 interior u lines and 6 interior v lines once each
    EXPECT_EQ(c.space.crossings.size(), 10u);
    std::cout << "Fig. 4 exact composition: degree " << c.space.degree << ", " << c.space.pieceCount() << " pieces ("
              << c.space.crossings.size() << " knot-line crossings, " << g.pointCount() - 4 << " knots of G), "
              << c.space.pointCount() << " rows x " << c.matrix.cols() << " columns, " << c.matrix.nonZeros()
              << " non-zeros; error " << compositionError(f, g, h) << " of the surface size\n";
}

TEST(IncidenceComposition, CurvedCurveOnUnevenKnotsIsExact)
{
    const Surface3d f = wavySurface(8, 10, 0.6);
    const Curve2d g = curvedCurve(9);
    const Composition c = compose(SurfaceStructure::of(f), g);
    EXPECT_LT(compositionError(f, g, applyComposition(c, f)), kExactRelative);
    EXPECT_GT(c.space.crossings.size(), 10u);  // the S crosses the v lines several times
}

TEST(IncidenceComposition, CrossingsAreWhereTheLineMeetsTheKnotLines)
{
    // Given a straight domain line of degree 1, G(t) = (0.1 + 0.8 t, 0.15 + 0.7 t)
    const Surface3d f = wavySurface(8, 10, 0.4);
    const Curve2d g(1, {0.0, 0.0, 1.0, 1.0}, {Eigen::Vector2d(0.1, 0.15), Eigen::Vector2d(0.9, 0.85)});
    // When its space is made
    const CompositionSpace space = compositionSpace(SurfaceStructure::of(f), g);
    // Then every interior knot line it meets is a breakpoint, at the parameter solved by hand
    std::vector<double> expected;
    for (double u : interiorBreakpoints(3, f.knotsU()))
        if (u > 0.1 && u < 0.9) expected.push_back((u - 0.1) / 0.8);
    for (double v : interiorBreakpoints(3, f.knotsV()))
        if (v > 0.15 && v < 0.85) expected.push_back((v - 0.15) / 0.7);
    std::sort(expected.begin(), expected.end());
    ASSERT_EQ(space.crossings.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(space.crossings[i], expected[i], 1e-15);
    EXPECT_EQ(space.degree, 6);
}

TEST(IncidenceComposition, IsoparametricCurveIsTheIsoCurve)
{
    const Surface3d f = figureFourSurface();
    const SurfaceStructure s = SurfaceStructure::of(f);
    // Inside a span, and along an interior knot line of F
    for (double u0 : {0.37, interiorBreakpoints(3, f.knotsU())[1]}) {
        const Curve2d g = isoCurveU(u0);
        const Composition c = compose(s, g);
        const Curve3d h = applyComposition(c, f);
        const Curve3d iso = f.isoCurve(Direction::U, u0);  // runs along v: t = v here
        double worst = 0.0;
        for (int k = 0; k <= kSamples; ++k) {
            const double t = static_cast<double>(k) / kSamples;
            worst = std::max(worst, (h.evaluate(t) - iso.evaluate(t)).norm());
        }
        EXPECT_LT(worst / surfaceSize(f), kExactRelative) << "u0 = " << u0;
        // Along the line no u line is crossed: only the v lines break H
        EXPECT_EQ(c.space.crossings.size(), interiorBreakpoints(3, f.knotsV()).size()) << "u0 = " << u0;
    }
}

TEST(IncidenceComposition, TouchingAKnotLineIsExact)
{
    // Given a domain parabola that touches the knot line u = u_2 at t = 0.5 without crossing it
    const Surface3d f = figureFourSurface();
    const double line = interiorBreakpoints(3, f.knotsU())[1];
    // u(t) = line + 0.4 (t - 0.5)^2: Bezier points line + 0.1, line - 0.1, line + 0.1; v(t) = t
    const Curve2d g(2, {0, 0, 0, 1, 1, 1},
                    {Eigen::Vector2d(line + 0.1, 0.05), Eigen::Vector2d(line - 0.1, 0.5), Eigen::Vector2d(line + 0.1, 0.95)});
    const Composition c = compose(SurfaceStructure::of(f), g);
    EXPECT_LT(compositionError(f, g, applyComposition(c, f)), kExactRelative);
    // and the touch is one breakpoint, not a cluster
    const auto atTouch = std::count_if(c.space.crossings.begin(), c.space.crossings.end(),
                                       [](double t) { return std::abs(t - 0.5) < 1e-6; });
    EXPECT_EQ(atTouch, 1);
}

TEST(IncidenceComposition, RowsArePartitionsOfUnity)
{
    // Given any composition, a surface with all control points at one place maps to that place:
    // each row of A sums to 1 (and so A F is affine invariant)
    const Composition c = compose(SurfaceStructure::of(figureFourSurface()), curvedCurve());
    const Eigen::VectorXd sums = c.matrix * Eigen::VectorXd::Ones(c.matrix.cols());
    EXPECT_LT((sums.array() - 1.0).abs().maxCoeff(), 1e-13);
}

TEST(IncidenceComposition, RefusesCurvesLeavingTheDomainAndRationalOnes)
{
    const SurfaceStructure s = SurfaceStructure::of(figureFourSurface());
    const Curve2d outside(1, {0, 0, 1, 1}, {Eigen::Vector2d(0.5, 0.5), Eigen::Vector2d(1.2, 0.5)});
    EXPECT_THROW(compose(s, outside), GeometryError);
    const Curve2d rational(1, {0, 0, 1, 1}, {Eigen::Vector2d(0.2, 0.5), Eigen::Vector2d(0.8, 0.5)}, {1.0, 2.0});
    EXPECT_THROW(compose(s, rational), GeometryError);
    // degree 6 on a bicubic surface: D = 36, beyond the kernel's 30
    std::vector<Curve2d::Point> points;
    for (int i = 0; i < 7; ++i) points.emplace_back(0.1 + 0.1 * i, 0.5);
    EXPECT_THROW(compose(s, Curve2d(6, clampedKnots(6, 7), points)), GeometryError);
}

TEST(IncidenceComposition, ReducedMultiplicitiesKeepTheCurve)
{
    // Given Fig. 4's composition in Bezier form (14 breakpoints, each of multiplicity 18)
    const Surface3d f = figureFourSurface();
    const Curve2d g = diagonalCurve(8);
    const SurfaceStructure s = SurfaceStructure::of(f);
    const Composition full = compose(s, g);
    // When the knots are removed down to H's continuity (C2 everywhere here: simple knots of a
    // cubic G, simple knot lines of a bicubic F)
    const Composition reduced = reduceMultiplicities(full, s, g);
    // Then each breakpoint has multiplicity 16, and A F is still F(G)
    EXPECT_EQ(reduced.space.pointCount(), full.space.pointCount() - 2 * static_cast<int>(full.space.breakpoints.size()));
    EXPECT_EQ(reduced.matrix.rows(), reduced.space.pointCount());
    EXPECT_LT(compositionError(f, g, applyComposition(reduced, f)), kExactRelative);
    std::cout << "Fig. 4 reduced to H's continuity: " << reduced.space.pointCount() << " rows (Bezier form "
              << full.space.pointCount() << "); error " << compositionError(f, g, applyComposition(reduced, f)) << "\n";
}

TEST(IncidenceComposition, ReducedMultiplicityFollowsADoubleKnotLine)
{
    // Given a surface with one interior u line of multiplicity 2 (only C1 across it)
    const Surface3d base = figureFourSurface();
    const double line = interiorBreakpoints(3, base.knotsU())[2];
    const Surface3d f = base.insertKnot(Direction::U, line);
    const Curve2d g = diagonalCurve(8);
    const SurfaceStructure s = SurfaceStructure::of(f);
    const Composition full = compose(s, g);
    // When reduced
    const Composition reduced = reduceMultiplicities(full, s, g);
    // Then the crossing of that line keeps multiplicity D - 1 = 17, every other one D - 2 = 16
    const auto& b = full.space.breakpoints;
    const int count = static_cast<int>(b.size());
    EXPECT_EQ(reduced.space.pointCount(), full.space.pointCount() - 2 * count + 1);
    EXPECT_LT(compositionError(f, g, applyComposition(reduced, f)), kExactRelative);
}

TEST(IncidenceComposition, RandomCurvesOnRandomKnotsAreExact)
{
    // Given 40 random domain curves (degree 1 to 4, 2 to 12 points, uneven knots) on random surfaces
    // (degrees 2 and 3, uneven knots, 6 to 14 points a side)
    std::mt19937 random(20261201);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worstFull = 0.0, worstReduced = 0.0;
    for (int trial = 0; trial < 40; ++trial) {
        const int p = 2 + trial % 2, q = 3 - (trial / 2) % 2;
        const Surface3d f = wavySurface(6 + trial % 9, 14 - trial % 9, 0.3 * unit(random), p, q);
        const int r = 1 + trial % 4;
        const int n = std::max(r + 1, 2 + static_cast<int>(unit(random) * 10));
        std::vector<Curve2d::Point> points;
        for (int i = 0; i < n; ++i) points.emplace_back(0.02 + 0.96 * unit(random), 0.02 + 0.96 * unit(random));
        const Curve2d g(r, clampedKnots(r, n, 0.3 * unit(random)), points);
        const SurfaceStructure s = SurfaceStructure::of(f);
        const Composition full = compose(s, g);
        const Composition reduced = reduceMultiplicities(full, s, g);
        worstFull = std::max(worstFull, compositionError(f, g, applyComposition(full, f)));
        worstReduced = std::max(worstReduced, compositionError(f, g, applyComposition(reduced, f)));
    }
    // Then every composition is F(G) to round-off, in either space
    EXPECT_LT(worstFull, kExactRelative);
    EXPECT_LT(worstReduced, kExactRelative);
    std::cout << "40 random curves: worst error " << worstFull << " (Bezier form), " << worstReduced << " (reduced)\n";
}
