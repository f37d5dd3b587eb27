// Re-sketching a parameter line of a surface (seed 001_08db50965017e161 §5.2, Figs. 9-10): the pick,
// the exact iso-curve, the auxiliary ruled strip, the re-sketch in the line's knots and the least
// change of the net. Given / When / Then.
#include "solvers/deformation/parameter_line.h"

#include "solvers/bspline/geometry_error.h"

#include "tests/deformation/deformation_fixtures.h"

#include <gtest/gtest.h>
#include <cmath>
#include <limits>

using namespace sculptline::solvers;
using namespace sculptline::solvers::deformation;
using sculptline::deformtest::wavySurface;

namespace {

// The line after the edit is Σ_i N_i(t)(P_ij + N_i ΔQ_j / ΣN²): a few round-offs of ~10-unit points.
constexpr double kExactTolerance = 1e-9;
// Evaluation of the same polynomial two ways (a control polygon vs the tensor product).
constexpr double kEvalTolerance = 1e-12;
// The over-sketch's default tolerance is 0.002 of the stroke's length; the refit in the line's
// (coarser) knots adds at most as much again on these smooth strokes: 1% of a 2-unit raise.
constexpr double kFitTolerance = 0.02;

/// The flat 8 x 13 sheet z = 0 over [0, 7] x [0, 12] (x depends on u only, y on v only).
Surface3d flatSheet() { return wavySurface(8, 13, 0.0); }

double maxDistance(const Curve3d& a, const Curve3d& b)
{
    double worst = 0.0;
    for (size_t j = 0; j < a.points().size(); ++j) worst = std::max(worst, (a.points()[j] - b.points()[j]).norm());
    return worst;
}

/// Points along the line at u = u0 of the flat sheet, for v in [v0, v1], raised by `height`.
std::vector<Eigen::Vector3d> raisedStroke(const Surface3d& s, double u0, double v0, double v1, double height, int n = 60)
{
    std::vector<Eigen::Vector3d> out;
    for (int k = 0; k < n; ++k) {
        const double v = v0 + (v1 - v0) * k / (n - 1);
        out.push_back(s.evaluate(u0, v) + Eigen::Vector3d(0, 0, height));
    }
    return out;
}

}  // namespace

TEST(ParameterLinePick, MarkingAlongUPicksTheUCurveAtTheMeanV)
{
    // Given a marking running along u at v near 0.3 (with a little wobble)
    const Surface3d s = wavySurface(8, 7);
    const std::vector<Eigen::Vector2d> uv = {{0.2, 0.29}, {0.4, 0.31}, {0.6, 0.30}, {0.8, 0.30}};
    // When the line is picked
    const ParameterLine line = pickParameterLine(s, uv);
    // Then it is the u-curve (v fixed) at the least-squares v, the mean
    EXPECT_EQ(line.fixed, Direction::V);
    EXPECT_NEAR(line.value, 0.30, 1e-15);
}

TEST(ParameterLinePick, MarkingAlongVPicksTheVCurve)
{
    const Surface3d s = wavySurface(8, 7);
    const ParameterLine line = pickParameterLine(s, {{0.52, 0.1}, {0.50, 0.5}, {0.48, 0.9}});
    EXPECT_EQ(line.fixed, Direction::U);
    EXPECT_NEAR(line.value, 0.50, 1e-15);
}

TEST(ParameterLinePick, MarkingNearTheRimSnapsOntoTheBoundary)
{
    const Surface3d s = wavySurface(8, 7);
    const ParameterLine line = pickParameterLine(s, {{0.1, 0.97}, {0.5, 0.98}, {0.9, 0.97}});
    EXPECT_EQ(line.fixed, Direction::V);
    EXPECT_EQ(line.value, 1.0);
}

TEST(ParameterLinePick, RaysOverTheSurfaceGiveThePointsUnderThem)
{
    // Given rays straight down onto the wavy sheet through S(0.3, v) for a few v
    const Surface3d s = wavySurface(8, 7);
    std::vector<Eigen::Vector3d> origins, directions;
    for (double v : {0.2, 0.4, 0.6}) {
        origins.push_back(s.evaluate(0.3, v) + Eigen::Vector3d(0, 0, 50));
        directions.push_back(-Eigen::Vector3d::UnitZ());
    }
    // When the marking is put on the surface
    const auto uv = markingOnSurface(s, origins, directions, 0.1);
    // Then each ray's point is the surface point it passes through
    ASSERT_EQ(uv.size(), 3u);
    EXPECT_NEAR(uv[1].x(), 0.3, 1e-7);
    EXPECT_NEAR(uv[1].y(), 0.4, 1e-7);
    EXPECT_EQ(pickParameterLine(s, uv).fixed, Direction::U);
}

TEST(ParameterLinePick, ARayThroughTwoWallsTakesTheWallNearestTheEye)
{
    // Given a tube (u around, v along x; walls at y = ±5) and rays through both walls at x = 3 and
    // 4, from either side
    std::vector<Eigen::Vector3d> net;
    const int nu = 9, nv = 6;
    for (int i = 0; i < nu; ++i) {
        const double a = 2 * 3.14159265358979 * i / (nu - 1);
        for (int j = 0; j < nv; ++j) net.emplace_back(j * 2.0, 5 * std::sin(a), 5 * std::cos(a));
    }
    const Surface3d tube(3, 3, sculptline::deformtest::clampedUniform(nu, 3), sculptline::deformtest::clampedUniform(nv, 3), nu, nv, net);
    for (const double side : {1.0, -1.0}) {
        const std::vector<Eigen::Vector3d> origins = {{3, 50 * side, 0.5}, {4, 50 * side, 0.5}};
        const std::vector<Eigen::Vector3d> directions(2, -side * Eigen::Vector3d::UnitY());
        // When the marking is put on it
        const auto uv = markingOnSurface(tube, origins, directions, 0.1);
        // Then its points are on the wall nearer the eye
        ASSERT_EQ(uv.size(), 2u);
        for (const auto& p : uv) EXPECT_GT(side * tube.evaluate(p.x(), p.y()).y(), 3.0) << side;
    }
}

TEST(ParameterLineCurve, IsTheExactIsoCurveWithTheSurfacesKnots)
{
    const Surface3d s = wavySurface(8, 7);
    const ParameterLine line{Direction::U, 0.37};
    const Curve3d c = parameterLineCurve(s, line);
    EXPECT_EQ(c.knots(), s.knotsV());
    EXPECT_EQ(c.degree(), s.degreeV());
    for (double v : {0.0, 0.13, 0.5, 0.77, 1.0}) EXPECT_LT((c.evaluate(v) - s.evaluate(0.37, v)).norm(), kEvalTolerance);
}

TEST(ParameterLineFollow, TheSurfacesLineBecomesTheTargetAndOtherRowsStay)
{
    // Given the v-curve at u0 = 0.5 (span [0.4, 0.6): rows 2..5 carry it) and a target moving each
    // of its control points differently
    const Surface3d s = wavySurface(8, 7);
    const ParameterLine line{Direction::U, 0.5};
    const Curve3d before = parameterLineCurve(s, line);
    std::vector<Eigen::Vector3d> q = before.points();
    for (size_t j = 0; j < q.size(); ++j) q[j] += Eigen::Vector3d(0.1 * j, -0.2, 0.3 + 0.05 * j * j);
    const Curve3d target(before.degree(), before.knots(), q);
    // When the surface follows
    const Surface3d after = followParameterLine(s, line, target);
    // Then its line is the target, its knots are the same, and rows 0, 1, 6, 7 did not move at all
    EXPECT_LT(maxDistance(parameterLineCurve(after, line), target), kExactTolerance);
    EXPECT_EQ(after.knotsU(), s.knotsU());
    EXPECT_EQ(after.knotsV(), s.knotsV());
    for (int i : {0, 1, 6, 7})
        for (int j = 0; j < s.countV(); ++j) EXPECT_EQ(after.point(i, j), s.point(i, j)) << i << "," << j;
    for (int i : {2, 3, 4, 5}) EXPECT_NE(after.point(i, 0), s.point(i, 0));
}

TEST(ParameterLineFollow, ABoundaryLineMovesOnlyItsOwnRow)
{
    const Surface3d s = wavySurface(8, 7);
    const ParameterLine rim{Direction::V, 1.0};
    const Curve3d before = parameterLineCurve(s, rim);
    std::vector<Eigen::Vector3d> q = before.points();
    q[3].z() += 2.0;
    const Surface3d after = followParameterLine(s, rim, Curve3d(before.degree(), before.knots(), q));
    for (int i = 0; i < s.countU(); ++i)
        for (int j = 0; j < s.countV(); ++j) {
            if (i == 3 && j == s.countV() - 1) EXPECT_EQ(after.point(i, j), s.point(i, j) + Eigen::Vector3d(0, 0, 2));
            else EXPECT_EQ(after.point(i, j), s.point(i, j));
        }
}

TEST(ParameterLineStrip, RaysMeetTheNormalStripOfAFlatSheetInItsVerticalPlane)
{
    // Given the normal strip of the flat sheet's line at u = 0.5 (the vertical plane x = 3.5) and
    // rays from the side aimed at known points of that plane
    const Surface3d s = flatSheet();
    const ParameterLine line{Direction::U, 0.5};
    const RuledStrip strip = makeRuledStrip(s, line, RulingKind::Normal);
    const double x0 = s.evaluate(0.5, 0.5).x();
    std::vector<Eigen::Vector3d> targets = {{x0, 1.0, 0.5}, {x0, 2.5, 1.5}, {x0, 4.0, -1.0}}, origins, directions;
    for (const auto& t : targets) {
        origins.push_back(t + Eigen::Vector3d(20, -5, 8));
        directions.push_back(t - origins.back());
    }
    // When they are projected
    const auto on = projectRaysOntoStrip(strip, origins, directions, 5.0);
    // Then they are the targets
    ASSERT_EQ(on.size(), 3u);
    for (size_t k = 0; k < 3; ++k) EXPECT_LT((on[k] - targets[k]).norm(), 1e-9) << k;
}

TEST(ParameterLineStrip, AcrossRulingsAtARimPointOutOfTheSurface)
{
    const Surface3d s = flatSheet();
    const RuledStrip atEnd = makeRuledStrip(s, {Direction::V, 1.0}, RulingKind::Across);
    const RuledStrip atStart = makeRuledStrip(s, {Direction::V, 0.0}, RulingKind::Across);
    EXPECT_GT(atEnd.ruling(0.5).y(), 0.99);
    EXPECT_LT(atStart.ruling(0.5).y(), -0.99);
}

TEST(ParameterLineResketch, AStraightRaiseOnAFlatSheetLiftsTheMiddleAndOnlyInZ)
{
    // Given the flat sheet's v-curve at u = 0.5 and a straight stroke 1 above its middle
    const Surface3d s = flatSheet();
    const ParameterLine line{Direction::U, 0.5};
    const Curve3d before = parameterLineCurve(s, line);
    const auto stroke = raisedStroke(s, 0.5, 0.35, 0.65, 1.0);
    // When it is re-sketched and the surface follows
    const ResketchResult r = resketchLine(before, stroke);
    const Surface3d after = followParameterLine(s, line, r.curve);
    // Then the line keeps its knots, the surface's line is the new curve, the middle is raised by 1
    // (within the fit), the ends of the line did not move, and nothing moved out of the strip
    EXPECT_EQ(r.curve.knots(), before.knots());
    EXPECT_LT(maxDistance(parameterLineCurve(after, line), r.curve), kExactTolerance);
    EXPECT_NEAR(after.evaluate(0.5, 0.5).z(), 1.0, kFitTolerance);
    EXPECT_NEAR(after.evaluate(0.5, 0.42).z(), 1.0, kFitTolerance);
    EXPECT_EQ(after.evaluate(0.5, 0.0), s.evaluate(0.5, 0.0));
    EXPECT_EQ(after.evaluate(0.5, 1.0), s.evaluate(0.5, 1.0));
    // The strip is the plane x = 3.5: the line moved in it only.
    for (int j = 0; j < s.countV(); ++j) EXPECT_NEAR(after.point(4, j).x(), s.point(4, j).x(), kEvalTolerance);
    EXPECT_LT(r.knotFitError, kFitTolerance);
    EXPECT_GT(r.movedPoints, 0);
    // The min-norm pattern: row i moves by N_i(u0)/ΣN² of the line's change (The NURBS Book A2.2)
    const int span = findSpan(3, s.knotsU(), 0.5);
    double N[4];
    basisFunctions(span, 0.5, 3, s.knotsU(), N);
    const double n2 = N[0] * N[0] + N[1] * N[1] + N[2] * N[2] + N[3] * N[3];
    const int j = 3;
    const double dq = r.curve.points()[j].z() - before.points()[j].z();
    for (int k = 0; k <= 3; ++k) EXPECT_NEAR(after.point(span - 3 + k, j).z(), N[k] / n2 * dq, 1e-12);
}

TEST(ParameterLineResketch, StrokeFromRaysOntoTheStripEndToEnd)
{
    // Given the wavy 12 x 7 sheet's rim at v = 1, its Across strip (the sheet continued), and a
    // stroke seen from above-front whose points rise 1.5 up the strip over most of the rim
    const Surface3d s = wavySurface(12, 7);
    const ParameterLine rim = pickParameterLine(s, {{0.3, 0.98}, {0.7, 0.99}});
    const RuledStrip strip = makeRuledStrip(s, rim, RulingKind::Across);
    std::vector<Eigen::Vector3d> origins, directions;
    for (int k = 0; k <= 60; ++k) {
        const double t = 0.1 + 0.8 * k / 60.0;
        const Eigen::Vector3d target = strip.at(t, 1.5 * std::sin(3.14159265358979 * k / 60.0));
        origins.push_back(target + Eigen::Vector3d(2, 30, 25));
        directions.push_back(target - origins.back());
    }
    const auto stroke = projectRaysOntoStrip(strip, origins, directions, 10.0);
    ASSERT_EQ(stroke.size(), 61u);
    // When the rim is re-sketched and the sheet follows
    const ResketchResult r = resketchLine(strip.base, stroke);
    const Surface3d after = followParameterLine(s, rim, r.curve);
    // Then the rim reaches out by 1.5 in its middle (within the fits) and only the last row moved
    EXPECT_EQ(rim.fixed, Direction::V);
    EXPECT_EQ(rim.value, 1.0);
    const double reach = (after.evaluate(0.5, 1.0) - s.evaluate(0.5, 1.0)).norm();
    EXPECT_NEAR(reach, 1.5, r.oversketchError + r.knotFitError + kFitTolerance);
    for (int i = 0; i < s.countU(); ++i)
        for (int j = 0; j + 1 < s.countV(); ++j) EXPECT_EQ(after.point(i, j), s.point(i, j));
}

TEST(ParameterLineErrors, BadInputIsRefusedWithAMessage)
{
    const Surface3d s = flatSheet();
    const ParameterLine line{Direction::U, 0.5};
    const Curve3d c = parameterLineCurve(s, line);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    // A marking off the surface, outside the domain, NaN, or a single point
    EXPECT_THROW(markingOnSurface(s, {{3, 3, 0}, {3, 4, 10}}, 0.5), GeometryError);
    EXPECT_THROW(pickParameterLine(s, {{0.5, 0.5}, {1.5, 0.5}}), GeometryError);
    EXPECT_THROW(pickParameterLine(s, {{0.5, nan}, {0.6, 0.5}}), GeometryError);
    EXPECT_THROW(pickParameterLine(s, {{0.5, 0.5}}), GeometryError);
    EXPECT_THROW(pickParameterLine(s, {{0.5, 0.5}, {0.5, 0.5}}), GeometryError);
    const std::vector<Eigen::Vector3d> up = {{3, 3, 10}, {3, 4, 10}};
    EXPECT_THROW(markingOnSurface(s, up, {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ()}, 0.5), GeometryError);  // away from it
    EXPECT_THROW(markingOnSurface(s, up, {Eigen::Vector3d(nan, 0, -1), -Eigen::Vector3d::UnitZ()}, 0.5), GeometryError);
    // A direction along the line (the strip would be a line), zero or NaN
    EXPECT_THROW(makeRuledStrip(s, line, RulingKind::Constant, Eigen::Vector3d::UnitY()), GeometryError);
    EXPECT_THROW(makeRuledStrip(s, line, RulingKind::Constant, Eigen::Vector3d::Zero()), GeometryError);
    EXPECT_THROW(makeRuledStrip(s, line, RulingKind::Constant, Eigen::Vector3d(nan, 0, 1)), GeometryError);
    EXPECT_THROW(makeRuledStrip(s, {Direction::U, nan}, RulingKind::Normal), GeometryError);
    // A degenerate stroke (one point repeated), a NaN stroke
    const std::vector<Eigen::Vector3d> dot(10, c.evaluate(0.5));
    EXPECT_THROW(resketchLine(c, dot), GeometryError);
    auto bad = raisedStroke(s, 0.5, 0.3, 0.7, 1.0);
    bad[5].y() = nan;
    EXPECT_THROW(resketchLine(c, bad), GeometryError);
    // A target with other knots, NaN points; rays with NaN
    EXPECT_THROW(followParameterLine(s, line, c.insertKnot(0.5)), GeometryError);
    EXPECT_THROW(followParameterLine(s, {Direction::U, 2.0}, c), GeometryError);
    const RuledStrip strip = makeRuledStrip(s, line, RulingKind::Normal);
    EXPECT_THROW(projectRaysOntoStrip(strip, {Eigen::Vector3d(nan, 0, 0)}, {Eigen::Vector3d::UnitX()}, 1.0), GeometryError);
    EXPECT_THROW(projectRaysOntoStrip(strip, {Eigen::Vector3d::Zero()}, {Eigen::Vector3d::UnitX()}, 0.0), GeometryError);
}
