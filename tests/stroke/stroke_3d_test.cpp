// Strokes drawn in space (a tracked pen): the same conditioning, corner detection, dynamic sampling
// and fitting as planar strokes (thesis ch. 4 §4.1), on 3D samples. A planar stroke is the special
// case z = 0 of the one pipeline, so a planar stroke turned out of the xy-plane must fit to the same
// curve turned the same way.
#include "solvers/stroke/stroke_fitter.h"
#include "fit_checks.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace sculptline::stroketest {
namespace {

using namespace solvers::stroke;

/// Positional jitter of a tracked pen at the scale of these shapes (~100 mm across): optical
/// trackers report 0.1-0.3 mm RMS; 0.15 mm sits in that range and is 30 % of the default tolerance.
constexpr double kTrackerNoise = 0.15;

/// Dense points of a curve (2,001 parameters, the curve's chords then 1e-4 of its length).
std::vector<Vec3> densePoints(const solvers::Curve3d& c)
{
    std::vector<Vec3> pts;
    for (int i = 0; i <= 2000; ++i) pts.push_back(c.evaluate(c.domainStart() + (c.domainEnd() - c.domainStart()) * i / 2000));
    return pts;
}

TEST(Stroke3d, GivenNoisyHelixDrawnInSpace_WhenFitted_ThenNonPlanarCurveWithinToleranceOfThePath)
{
    // Given two turns of a helix (radius 40, rising 30 per turn) drawn with tracker jitter in x, y and z
    const Shape helix = helixShape(40.0, 30.0, 2.0);
    DrawOptions d;
    d.noise = kTrackerNoise;
    d.seed = 7;
    const Stroke s = drawWithSamples(helix, 1000, d);
    ASSERT_EQ(s.dimension, 3);

    // When fitted with the default (relative) tolerance
    const FitResult r = fitStroke(s);

    // Then the fit converged, has no corners (a helix is smooth), is a cubic,
    EXPECT_TRUE(r.converged) << r.maxError << " > " << r.tolerance;
    EXPECT_TRUE(r.corners.empty()) << r.corners.size() << " corners";
    EXPECT_EQ(r.curve.degree(), 3);
    // lies within tolerance of the path the pen followed (both ways: every curve point near the
    // helix, every helix point near the curve; the noise the conditioning removed is not the path),
    EXPECT_LE(maxDeviation(r.curve, helix.reference), r.tolerance);
    double curveToPath = 0.0;
    for (const Vec3& p : densePoints(r.curve)) curveToPath = std::max(curveToPath, distanceToPolyline(p, helix.reference, false));
    EXPECT_LE(curveToPath, r.tolerance);
    // and is far from planar: its points leave their best plane by 20 tolerances and more (the helix
    // itself: about 30 mm, 60 tolerances).
    EXPECT_GT(distanceFromBestPlane(densePoints(r.curve)), 20.0 * r.tolerance);
    std::printf("helix: %zu samples, tolerance %.3f, max error %.3f, curve-to-path %.3f, %d control points, off-plane %.1f\n",
                s.points.size(), r.tolerance, r.maxError, curveToPath, r.curve.pointCount(), distanceFromBestPlane(densePoints(r.curve)));
}

TEST(Stroke3d, GivenPolylineAlongCubeEdgesDrawnInSpace_WhenFitted_ThenItsThreeCornersAreFoundAndKept)
{
    // Given a path along four edges of an 80 mm cube (no two consecutive edges in one plane with a
    // third), drawn with the slow-down at the vertices and tracker jitter
    const std::vector<Vec3> vertices = {{0, 0, 0}, {80, 0, 0}, {80, 80, 0}, {80, 80, 80}, {0, 80, 80}};
    const Shape path = polygonShape(vertices, false);
    DrawOptions d;
    d.noise = kTrackerNoise;
    const Stroke s = drawWithSamples(path, 1000, d);

    // When fitted
    const FitResult r = fitStroke(s);

    // Then exactly the three inner vertices are corners, each found at a sample within 2 % of the
    // stroke's extent of its vertex (the merge distance of corner detection is 5 %),
    ASSERT_EQ(r.corners.size(), 3u);
    const double near = 0.02 * strokeExtent(s.points);
    for (size_t k = 0; k < 3; ++k) {
        EXPECT_LT((s.points[static_cast<size_t>(r.corners[k])] - vertices[k + 1]).norm(), near) << "corner " << k;
    }
    // the curve interpolates the corner samples' smoothed positions and stays within tolerance,
    EXPECT_TRUE(r.converged);
    EXPECT_LE(maxDeviation(r.curve, path.reference), r.tolerance + 3.0 * kTrackerNoise);
    // and it is a space curve.
    EXPECT_GT(distanceFromBestPlane(densePoints(r.curve)), 20.0 * r.tolerance);
}

TEST(Stroke3d, GivenPlanarStrokesTurnedIntoSpace_WhenFitted_ThenTheTurnedPlanarFit)
{
    // Given planar strokes (the 2D special case: z = 0) and the same strokes turned by a rotation that
    // takes the xy-plane to a general plane of space, and moved
    const Eigen::Affine3d turn = Eigen::Translation3d(20, -30, 55) * Eigen::AngleAxisd(0.9, Vec3(1, 2, 0.5).normalized());
    const std::vector<Shape> shapes = {polygonShape({{0, 0, 0}, {60, 80, 0}, {120, 0, 0}, {180, 80, 0}}, false), flourishShape(300),
                                       circleShape({0, 0, 0}, 60)};
    for (const Shape& shape : shapes) {
        DrawOptions d;
        d.noise = 0.25;
        const Stroke flat = draw(shape, d);
        Stroke turned = flat;
        turned.dimension = 3;
        for (Vec3& p : turned.points) p = turn * p;

        // When both are fitted
        const FitResult a = fitStroke(flat);
        const FitResult b = fitStroke(turned);

        // Then the space fit is the planar fit turned: the same corners, samples and control
        // points, the points moved by the rotation up to round-off (1e-6 of the tolerance: the
        // space path adds z terms that are not exact zeros, nothing else).
        EXPECT_EQ(b.corners, a.corners);
        EXPECT_EQ(b.samples, a.samples);
        ASSERT_EQ(b.curve.pointCount(), a.curve.pointCount());
        EXPECT_EQ(b.curve.isClosed(), a.curve.isClosed());
        double shift = 0.0;
        for (int i = 0; i < a.curve.pointCount(); ++i) shift = std::max(shift, (turn * a.curve.points()[i] - b.curve.points()[i]).norm());
        EXPECT_LE(shift, 1e-6 * a.tolerance);
    }
}

}  // namespace
}  // namespace sculptline::stroketest
