// Given fitted curves and strokes, when the samples' distances and the curve's straying between
// samples are measured (measureSamples, measureStray: solvers/stroke/fit_check.h), then the bounds
// agree with the independent dense-polyline measures of fit_checks.h, and bad input is refused.
// (Split from fit_tolerance_test.cpp; the suite keeps its name, FitTolerance.)
#include "fit_checks.h"
#include "solvers/bspline/geometry_error.h"
#include "solvers/stroke/fit_check.h"
#include "solvers/stroke/stroke_fitter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sculptline::stroketest {
namespace {

// The measure tests' strokes: noise 0.5, fitted at a loose tolerance of 3.0, so that many samples
// lie away from the curve.
Stroke noisyStroke(const Shape& shape)
{
    DrawOptions d;
    d.noise = 0.5;
    return draw(shape, d);
}

FitResult looselyFitted(const Stroke& s)
{
    FitOptions o;
    o.tolerance = 3.0;
    return fitStroke(s, o);
}

// measureSamples against the independent dense-polyline measure of fit_checks.h: no sample's
// bound below its distance, and the same maximum, on open curves, loops and loops with corners.
// (The kernel's CurveProjector is no reference here: on the square it misses foot points beside
// the triple knots at a closed curve's seam, reporting 2.83 where the curve passes at 0.57.)
TEST(FitTolerance, GivenFittedCurves_WhenSamplesMeasured_ThenMaxEqualsDensePolylineMeasure)
{
    for (const auto& [name, shape] : toleranceShapes()) {
        const Stroke s = noisyStroke(shape);
        const FitResult r = looselyFitted(s);
        const SampleDeviation dev = measureSamples(r.curve, s.points, {}, 1.0);
        double worst = 0;
        for (size_t i = 0; i < s.points.size(); ++i) {
            const double dense = maxDeviation(r.curve, {s.points[i]});
            worst = std::max(worst, dense);
            EXPECT_GE(dev.bound[i], dense - kMeasureAgreement)
                << name << " sample " << i << ": a bound below the distance";
        }
        EXPECT_NEAR(dev.maxError, worst, kMeasureAgreement) << name;
    }
}

// Every bound is the sample's own distance, not only the maximum's, wherever the samples run along
// the curve: they are tracked by Newton from the foot the previous ones predict, within
// measureSamples' kTrackSlack (2e-2 of the resolution, 1.0 here) of the local minimum. The fitter
// chooses the rows it adds to a count by these bounds (kRowShare), which then no longer depend on
// the exact projection's polyline spacing. (With one polyline of the whole curve the bounds were its
// points' distances, up to half its spacing more: 0.5 here.) Not the square: at its seam, where the
// stroke starts and ends in a jumble at a corner, a sample can settle on the other leg's local
// minimum (1.51 against 0.54), a valid bound that the exact projection settles wherever it could be
// the maximum (GivenFittedCurves_WhenSamplesMeasured_ThenMaxEqualsDensePolylineMeasure).
TEST(FitTolerance, GivenFittedCurves_WhenSamplesMeasured_ThenEveryBoundAwayFromASeamCornerIsTheSamplesDistance)
{
    constexpr double kTrackAgreement = 2e-2 + kMeasureAgreement;
    for (const auto& [name, shape] : toleranceShapes()) {
        if (name == "square") continue;
        const Stroke s = noisyStroke(shape);
        const FitResult r = looselyFitted(s);
        const SampleDeviation dev = measureSamples(r.curve, s.points, {}, 1.0);
        double furthest = 0.0;  // the largest bound above the dense measure
        for (size_t i = 0; i < s.points.size(); ++i) {
            const double dense = maxDeviation(r.curve, {s.points[i]});
            EXPECT_NEAR(dev.bound[i], dense, kTrackAgreement) << name << " sample " << i;
            furthest = std::max(furthest, dev.bound[i] - dense);
        }
        std::printf("%s: bounds at most %.2g above the dense measure\n", name.c_str(), furthest);
    }
}

// exactAbove: every sample whose bound is beyond it has its exact distance (the dense measure), and
// every other lies within it. The fitter decides with it which of a loop's overshoot samples stay
// dropped. Noise 0.5 against a threshold of 0.75: dozens of samples beyond it on each shape (at 1.0
// the sanitizer build's fits left 6 on the s-curve: its floating point differs).
TEST(FitTolerance, GivenExactAbove_WhenSamplesMeasured_ThenEveryBoundBeyondItIsTheDistance)
{
    constexpr double kExactAbove = 0.75;
    for (const auto& [name, shape] : toleranceShapes()) {
        const Stroke s = noisyStroke(shape);
        const FitResult r = looselyFitted(s);
        const SampleDeviation dev = measureSamples(r.curve, s.points, {}, 1.0, kExactAbove);
        int beyond = 0;
        for (size_t i = 0; i < s.points.size(); ++i) {
            const double dense = maxDeviation(r.curve, {s.points[i]});
            if (dev.bound[i] > kExactAbove) {
                ++beyond;
                EXPECT_NEAR(dev.bound[i], dense, kMeasureAgreement) << name << " sample " << i;
            } else {
                EXPECT_LE(dense, kExactAbove + kMeasureAgreement) << name << " sample " << i;
            }
        }
        EXPECT_GT(beyond, 10) << name << ": the threshold should leave samples beyond it";
        // maxWithin: the largest distance of the samples within the threshold, exact.
        std::vector<Vec3> within;
        for (size_t i = 0; i < s.points.size(); ++i)
            if (!(dev.bound[i] > kExactAbove)) within.push_back(s.points[i]);
        EXPECT_NEAR(dev.maxWithin, maxDeviation(r.curve, within), kMeasureAgreement) << name;
        EXPECT_LE(dev.maxWithin, kExactAbove) << name;
        std::printf("%s: %d samples beyond %.2f\n", name.c_str(), beyond, kExactAbove);
    }
}

// A sample just before a C0 corner whose nearest polyline point is the corner itself: the curve's
// derivative at the corner is the next leg's, so one Newton bracket around the corner searched only
// that leg and reported the distance to the corner (a closed square's seam: 0.47 against 0.004).
TEST(FitTolerance, GivenSampleBesideACorner_WhenMeasured_ThenTheNearerLegFound)
{
    // An L: three units along x, a corner (triple knot) at (3, 0), three units up.
    const solvers::Curve3d c(
        3, {0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 2},
        {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(3, 1, 0), Vec3(3, 2, 0), Vec3(3, 3, 0)});
    for (const Vec3& x : {Vec3(2.7, 0.001, 0), Vec3(2.7, -0.001, 0), Vec3(2.999, 0.3, 0), Vec3(3.001, 0.3, 0)}) {
        const SampleDeviation d = measureSamples(c, {x}, {}, 1.0);  // polyline points 1 apart: the corner is nearest
        EXPECT_NEAR(d.maxError, 0.001, 1e-12) << x.transpose();
    }
}

// A polyline curve (degree 1) along three samples on the x axis, 10 apart, with a spike of height h
// at x = 5 (a knot, so a point of the measure's polyline): the spike's excess is h over the
// allowance of the segment below it, tolerance + a quarter of 10.
TEST(FitTolerance, GivenACurveWithASpikeBetweenSamples_WhenStrayMeasured_ThenItsExcessIsTheSpikeOverTheAllowance)
{
    constexpr double kTolerance = 0.5, kShare = 0.25, kResolution = 0.25;
    const std::vector<Vec3> samples = {Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(20, 0, 0)};
    for (const double h : {1.0, 6.0, 30.0}) {
        const solvers::Curve3d c(1, {0, 0, 1, 2, 3, 3}, {Vec3(0, 0, 0), Vec3(5, h, 0), Vec3(10, 0, 0), Vec3(20, 0, 0)});
        const StrayMeasure m = measureStray(c, samples, {}, kTolerance, kShare, kResolution);
        EXPECT_NEAR(m.excess, h / (kTolerance + kShare * 10.0), 1e-12) << h;
        EXPECT_NEAR(m.distance, h, 1e-12) << h;
        EXPECT_NEAR(m.parameter, 1.0, 1e-12) << h;
        EXPECT_EQ(m.after, 0) << h;
        // Stopping once beyond 1 (the fitter's question): a spike beyond it is still reported beyond it.
        EXPECT_EQ(measureStray(c, samples, {}, kTolerance, kShare, kResolution, nullptr, 1.0).excess > 1.0, h > 3.0)
            << h;
    }
    // The curve along the polyline itself strays nowhere; a dropped sample leaves its segment out.
    const solvers::Curve3d along(1, {0, 0, 1, 2, 2}, samples);
    EXPECT_NEAR(measureStray(along, samples, {}, kTolerance, kShare, kResolution).excess, 0.0, 1e-12);
    const std::vector<Vec3> bent = {Vec3(0, 0, 0), Vec3(10, 8, 0), Vec3(20, 0, 0)};
    EXPECT_GT(measureStray(along, bent, {}, kTolerance, kShare, kResolution).excess, 1.0);
    EXPECT_NEAR(measureStray(along, bent, {1, 0, 1}, kTolerance, kShare, kResolution).excess, 0.0, 1e-12);
}

// The samples in the order of their feet along the curve (measureStray's order: an insertion sort
// where they are nearly so, stable_sort past 8 moves a sample) do not depend on the order drawn:
// the same samples drawn against the curve (the feet descending, every pair inverted: stable_sort)
// give the same polyline and so the same excess as drawn along it (a noisy sample's foot before
// its neighbour's now and then: the insertion sort). At the fit's tolerance and at a tenth of it,
// where the curve strays (beyond 1: the least over every segment).
TEST(FitTolerance, GivenSamplesDrawnAgainstTheCurve_WhenStrayMeasured_ThenTheSameAsAlongIt)
{
    // The fitter's share of a segment and resolution (half the tolerance).
    constexpr double kShare = 0.25, kResolutionShare = 0.5;
    // (The same segments, a and b swapped: the projection's round-off alone.)
    constexpr double kSameMeasure = 1e-9;
    int strayed = 0;
    for (const auto& [name, shape] : toleranceShapes()) {
        const Stroke s = noisyStroke(shape);
        const FitResult r = looselyFitted(s);
        const std::vector<Vec3> against(s.points.rbegin(), s.points.rend());
        for (const double tol : {r.tolerance, 0.1 * r.tolerance}) {
            const StrayMeasure along = measureStray(r.curve, s.points, {}, tol, kShare, kResolutionShare * tol);
            const StrayMeasure back = measureStray(r.curve, against, {}, tol, kShare, kResolutionShare * tol);
            EXPECT_NEAR(back.excess, along.excess, kSameMeasure * along.excess) << name << " at " << tol;
            EXPECT_NEAR(back.distance, along.distance, kSameMeasure * std::max(1.0, along.distance))
                << name << " at " << tol;
            EXPECT_NEAR(back.parameter, along.parameter, kSameMeasure) << name << " at " << tol;
            strayed += along.excess > 1.0;
        }
    }
    EXPECT_GE(strayed, 5);  // (every curve at a tenth of the tolerance)
}

TEST(FitTolerance, GivenBadCheckInput_WhenMeasured_ThenClearError)
{
    const solvers::Curve3d c(3, {0, 0, 0, 0, 1, 1, 1, 1}, {Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(2, 1, 0), Vec3(3, 0, 0)});
    EXPECT_THROW(measureSamples(c, {Vec3(0, 0, 0)}, {}, 0.0), solvers::GeometryError);
    EXPECT_THROW(measureSamples(c, {Vec3(0, 0, 0)}, {1, 0}, 0.1), solvers::GeometryError);
    const std::vector<Vec3> two = {Vec3(0, 0, 0), Vec3(3, 0, 0)};
    EXPECT_THROW(measureStray(c, two, {}, 0.0, 0.25, 0.1), solvers::GeometryError);
    EXPECT_THROW(measureStray(c, two, {}, 0.1, 0.25, 0.0), solvers::GeometryError);
    EXPECT_THROW(measureStray(c, two, {1}, 0.1, 0.25, 0.1), solvers::GeometryError);
    const std::vector<double> oneFoot = {0.0};
    EXPECT_THROW(measureStray(c, two, {}, 0.1, 0.25, 0.1, &oneFoot), solvers::GeometryError);
}

}  // namespace
}  // namespace sculptline::stroketest
