// Several curve constraints on one surface stacked into one system (seed 000 §4.1, Fig. 8).
#include "solvers/incidence/incidence_system.h"

#include "tests/incidence/incidence_fixtures.h"

#include <gtest/gtest.h>

using namespace sculptline::solvers;
using namespace sculptline::solvers::incidence;
using namespace sculptline::incidence_test;

namespace {

constexpr double kRoundOff = 1e-12;

}  // namespace

TEST(IncidenceSystem, TheSurfacesOwnCurvesSatisfyEveryRow)
{
    // Given a surface and two crossing domain curves whose requests are the surface's own curves
    const Surface3d f = figureFourSurface();
    const SurfaceStructure s = SurfaceStructure::of(f);
    const Curve2d g1 = diagonalCurve(8), g2 = curvedCurve(9);
    const std::vector<CurveRequest> curves{{g1, applyComposition(compose(s, g1), f), true},
                                           {g2, applyComposition(compose(s, g2), f), false}};
    // When stacked
    const IncidenceSystem system = stackIncidences(s, curves);
    // Then the blocks are the two curves and their crossings, the rows add up, and F itself meets
    // every row (the curves' and the crossings') to round-off
    ASSERT_GE(system.blocks.size(), 3u);
    EXPECT_EQ(system.blocks[0].kind, RowBlock::Kind::Curve);
    EXPECT_EQ(system.blocks[1].kind, RowBlock::Kind::Curve);
    const int crossings = static_cast<int>(system.blocks.size()) - 2;
    EXPECT_GE(crossings, 1);
    const int rows1 = static_cast<int>(system.compositions[0].matrix.rows());
    const int rows2 = static_cast<int>(system.compositions[1].matrix.rows());
    EXPECT_EQ(system.matrix.rows(), rows1 + rows2 + crossings);
    EXPECT_EQ(system.rhs.rows(), system.matrix.rows());
    const ControlMatrix residual = system.matrix * surfacePointRows(f) - system.rhs;
    EXPECT_LT(residual.cwiseAbs().maxCoeff(), kRoundOff * 100.0);
    for (size_t b = 2; b < system.blocks.size(); ++b) EXPECT_LT(system.blocks[b].mismatch, kRoundOff * 100.0);
    // The fixed curve's rows and its crossings are hard, the free curve's rows soft
    EXPECT_EQ(static_cast<int>(system.hardRows().size()), rows1 + crossings);
    EXPECT_EQ(static_cast<int>(system.softRows().size()), rows2);
    EXPECT_TRUE(system.hard[0]);
    EXPECT_FALSE(system.hard[static_cast<size_t>(rows1)]);
}

TEST(IncidenceSystem, LowDegreeRequestsAreBroughtIntoTheirCurvesSpaces)
{
    // Given a cubic request on its own knots (not breakpoints of the plain composition)
    const Surface3d f = figureFourSurface();
    const SurfaceStructure s = SurfaceStructure::of(f);
    const Curve2d g = diagonalCurve(8);
    std::vector<Curve3d::Point> points;
    for (int i = 0; i < 6; ++i) points.emplace_back(15.0 * i, 12.0 * i, 4.0 * std::sin(double(i)));
    const Curve3d request(3, {0, 0, 0, 0, 0.3, 0.6, 1, 1, 1, 1}, points);
    for (const bool reduce : {false, true}) {
        // When stacked alone, in Bezier form and in the reduced space
        StackOptions options;
        options.reduceMultiplicities = reduce;
        const IncidenceSystem system = stackIncidences(s, {{g, request, false}}, options);
        // Then its knots are breakpoints, and the right-hand side is the request, in H's space
        const CompositionSpace& space = system.compositions[0].space;
        for (double knot : {0.3, 0.6})
            EXPECT_TRUE(std::find(space.breakpoints.begin(), space.breakpoints.end(), knot) != space.breakpoints.end());
        const Curve3d rhsCurve(space.degree, space.knots, [&] {
            std::vector<Curve3d::Point> p;
            for (Eigen::Index i = 0; i < system.rhs.rows(); ++i) p.emplace_back(system.rhs.row(i).transpose());
            return p;
        }());
        for (int k = 0; k <= 200; ++k) EXPECT_LT((rhsCurve.evaluate(k / 200.0) - request.evaluate(k / 200.0)).norm(), 1e-11);
        EXPECT_TRUE(system.hardRows().empty());
        // and the reduced space has fewer rows than the Bezier form
        EXPECT_EQ(system.matrix.rows() < compose(s, g, {0.3, 0.6}).matrix.rows(), reduce);
    }
}

TEST(IncidenceSystem, DisagreeingRequestsMeetHalfwayAtTheirCrossing)
{
    // Given two straight domain curves crossing at (0.5, 0.5), with requests 2 units apart there
    const SurfaceStructure s = SurfaceStructure::of(figureFourSurface());
    const Curve2d a(1, {0, 0, 1, 1}, {Eigen::Vector2d(0.1, 0.1), Eigen::Vector2d(0.9, 0.9)});
    const Curve2d b(1, {0, 0, 1, 1}, {Eigen::Vector2d(0.1, 0.9), Eigen::Vector2d(0.9, 0.1)});
    const Curve3d ha(1, {0, 0, 1, 1}, {Curve3d::Point(0, 0, 0), Curve3d::Point(10, 0, 0)});
    const Curve3d hb(1, {0, 0, 1, 1}, {Curve3d::Point(5, -5, 2), Curve3d::Point(5, 5, 2)});
    // When stacked
    const IncidenceSystem system = stackIncidences(s, {{a, ha, false}, {b, hb, false}});
    // Then one crossing row, its target the mean of the requests there, its mismatch their distance
    ASSERT_EQ(system.blocks.size(), 3u);
    const RowBlock& x = system.blocks[2];
    EXPECT_EQ(x.kind, RowBlock::Kind::Crossing);
    EXPECT_NEAR(x.t, 0.5, 1e-12);
    EXPECT_NEAR(x.tOther, 0.5, 1e-12);
    EXPECT_NEAR(x.mismatch, 2.0, 1e-12);
    EXPECT_LT((system.rhs.row(x.firstRow) - Eigen::RowVector3d(5, 0, 1)).norm(), 1e-12);
    // and with the first fixed, the fixed request wins
    const IncidenceSystem fixed = stackIncidences(s, {{a, ha, true}, {b, hb, false}});
    EXPECT_LT((fixed.rhs.row(fixed.blocks[2].firstRow) - Eigen::RowVector3d(5, 0, 0)).norm(), 1e-12);
    EXPECT_TRUE(fixed.hard[static_cast<size_t>(fixed.blocks[2].firstRow)]);
}
