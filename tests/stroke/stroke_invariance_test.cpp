// Given a stroke, when it is translated, rotated, scaled or drawn in the opposite direction, then
// the fit is the same shape: same corners, same control-point count (similarity transforms), and
// a curve within tolerance of the transformed original.
#include "fit_checks.h"
#include "solvers/stroke/prime.h"
#include "solvers/stroke/shape_recognizer.h"
#include "solvers/stroke/stroke_fitter.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace sculptline::stroketest {
namespace {

using namespace solvers::stroke;

Stroke transformed(const Stroke& s, const Eigen::Affine3d& t)
{
    Stroke out = s;
    for (auto& p : out.points) p = t * p;
    return out;
}

double curveDistance(const solvers::Curve3d& a, const solvers::Curve3d& b)
{
    std::vector<Vec3> pts;
    for (int i = 0; i <= 300; ++i) pts.push_back(a.evaluate(a.domainStart() + (a.domainEnd() - a.domainStart()) * i / 300));
    return maxDeviation(b, pts);
}

std::vector<Shape> shapes()
{
    return {polygonShape({{0, 0, 0}, {60, 80, 0}, {120, 0, 0}, {180, 80, 0}}, false),
            polygonShape({{0, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}}, true), sCurveShape(200),
            ellipseShape({0, 0, 0}, 120, 60, 0.3)};
}

TEST(StrokeInvariance, GivenSimilarityTransforms_WhenFitted_ThenSameCornersCountsAndTransformedCurve)
{
    for (const Shape& shape : shapes()) {
        DrawOptions d;
        d.noise = 0.25;
        const Stroke s = draw(shape, d);
        const FitResult base = fitStroke(s);
        const std::vector<Eigen::Affine3d> transforms = {
            Eigen::Affine3d(Eigen::Translation3d(1000, -250, 0)),
            Eigen::Affine3d(Eigen::AngleAxisd(0.7, Vec3::UnitZ())),
            Eigen::Affine3d(Eigen::Scaling(0.01)),
            Eigen::Affine3d(Eigen::Translation3d(5, 7, 0) * Eigen::AngleAxisd(-2.1, Vec3::UnitZ()) * Eigen::Scaling(30.0)),
        };
        for (const auto& t : transforms) {
            const double scale = t.linear().col(0).norm();

            const FitResult r = fitStroke(transformed(s, t));

            EXPECT_EQ(r.corners, base.corners);
            EXPECT_NEAR(r.tolerance, base.tolerance * scale, 1e-9 * r.tolerance);
            EXPECT_EQ(r.curve.pointCount(), base.curve.pointCount());
            std::vector<Vec3> moved;
            for (const auto& p : base.curve.points()) moved.push_back(t * p);
            double shift = 0;
            for (size_t i = 0; i < moved.size() && i < r.curve.points().size(); ++i) {
                shift = std::max(shift, (moved[i] - r.curve.points()[i]).norm());
            }
            // Same computation up to round-off: control points agree to 1e-6 of the tolerance.
            EXPECT_LE(shift, 1e-6 * r.tolerance);
        }
    }
}

TEST(StrokeInvariance, GivenReversedDrawing_WhenFitted_ThenSameCornersAndCurveWithinTolerance)
{
    // The fit holds every drawn sample within the tolerance. At the default tolerance (0.5 % of
    // the extent: 0.71 on the square, 2.8 sigma) the count is then set by the few noise excursions
    // beyond ~2.5 sigma, which the error-driven insertion meets in a different order when the
    // drawing is reversed (measured: square 16 forward, 23 reversed). The symmetry of the fit itself
    // is compared at a tolerance above the excursions: 6 sigma, which 250 Gaussian draws exceed
    // with probability ~5e-7. (At 4 sigma, ~1.5 % per coordinate, the s-curve's raw samples still
    // decided the count: with clang's rounding 4 control points passed them reversed and 7 forward.)
    constexpr double kNoise = 0.25;
    constexpr double kAboveNoise = 6.0 * kNoise;
    const std::vector<Shape> all = shapes();
    for (size_t which = 0; which < all.size(); ++which) {
        const Shape& shape = all[which];
        SCOPED_TRACE("shape " + std::to_string(which));
        DrawOptions d;
        d.noise = kNoise;
        const Stroke s = draw(shape, d);
        Stroke rev = s;
        std::reverse(rev.points.begin(), rev.points.end());
        const double end = s.times.back();
        for (size_t i = 0; i < s.times.size(); ++i) rev.times[i] = end - s.times[s.times.size() - 1 - i];

        FitOptions o;
        o.tolerance = kAboveNoise;
        const FitResult a = fitStroke(s, o);
        const FitResult b = fitStroke(rev, o);

        ASSERT_EQ(a.corners.size(), b.corners.size());
        for (size_t k = 0; k < a.corners.size(); ++k) {
            const Vec3 pa = s.points[a.corners[k]];
            double best = 1e300;
            for (int j : b.corners) best = std::min(best, (rev.points[j] - pa).norm());
            EXPECT_LE(best, 4 * a.tolerance) << "corner " << k;
        }
        // Both fit the same samples within the tolerance, so they are within twice of each other.
        EXPECT_LE(curveDistance(a.curve, b.curve), 2 * a.tolerance);
        EXPECT_LE(curveDistance(b.curve, a.curve), 2 * a.tolerance);
        const double ca = a.curve.pointCount(), cb = b.curve.pointCount();
        EXPECT_LE(std::abs(ca - cb), 0.25 * std::max(ca, cb) + 1) << ca << " control points forward, " << cb << " reversed";
    }
}

// Given strokes fitted and recognized, when the pen-up path is primed (primeStrokeFit, as the
// window does at start) and they are fitted again, then every result is the same to the bit:
// priming leaves nothing behind but touched memory.
TEST(StrokeInvariance, GivenPrimedFitter_WhenStrokesRefitted_ThenResultsBitIdentical)
{
    std::vector<Stroke> strokes;
    for (const Shape& shape : shapes()) {
        DrawOptions d;
        d.noise = 0.3;
        strokes.push_back(drawWithSamples(shape, 400, d));
    }
    std::vector<StrokeRecognition> before;
    for (const Stroke& s : strokes) before.push_back(recognizeStroke(s));
    primeStrokeFit();
    for (size_t i = 0; i < strokes.size(); ++i) {
        const StrokeRecognition after = recognizeStroke(strokes[i]);
        EXPECT_EQ(after.recognition.kind, before[i].recognition.kind) << "stroke " << i;
        const auto& pa = after.fit.curve.points();
        const auto& pb = before[i].fit.curve.points();
        ASSERT_EQ(pa.size(), pb.size()) << "stroke " << i;
        for (size_t k = 0; k < pa.size(); ++k) EXPECT_EQ(pa[k], pb[k]) << "stroke " << i << ", control point " << k;
        EXPECT_EQ(after.fit.maxError, before[i].fit.maxError) << "stroke " << i;
        EXPECT_EQ(after.fit.corners, before[i].fit.corners) << "stroke " << i;
    }
}

}  // namespace
}  // namespace sculptline::stroketest
