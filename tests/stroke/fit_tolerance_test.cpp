// Given synthesized and real pen strokes, when fitted, then the tolerance bounds the distance of
// every raw sample the fit keeps (max_error reports exactly that), smoothing does not eat shape on
// sparse strokes, the curve does not depend on the sampling density, few samples are dropped, and
// the control-point count follows the tolerance.
#include "fit_checks.h"
#include "solvers/bspline/geometry_error.h"
#include "solvers/stroke/fit_check.h"
#include "solvers/stroke/stroke_fitter.h"
#include "unistroke_eval.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>

namespace sculptline::stroketest {
namespace {

// Largest distance from points of `a` (2,000 along its domain) to the curve `b`, and back.
double hausdorff(const solvers::Curve3d& a, const solvers::Curve3d& b)
{
    auto along = [](const solvers::Curve3d& c) {
        std::vector<Vec3> p;
        for (int i = 0; i <= 2000; ++i) p.push_back(c.evaluate(c.domainStart() + (c.domainEnd() - c.domainStart()) * i / 2000));
        return p;
    };
    return std::max(maxDeviation(b, along(a)), maxDeviation(a, along(b)));
}

TEST(FitTolerance, GivenNoisyShapesAtSeveralTolerances_WhenFitted_ThenEveryKeptRawSampleWithinToleranceAndMaxErrorExact)
{
    for (const auto& [name, shape] : toleranceShapes()) {
        for (double tol : {0.0, 0.3, 2.0}) {  // 0: the default, 0.5 % of the extent
            // Arrange
            DrawOptions d;
            d.noise = 0.1;
            const Stroke s = draw(shape, d);
            FitOptions o;
            o.tolerance = tol;
            // Act
            const FitResult r = fitStroke(s, o);
            // Assert
            const double independent = maxDeviation(r.curve, keptSamples(s, r));
            EXPECT_TRUE(r.converged) << name << " tol " << tol;
            EXPECT_LE(r.maxError, r.tolerance) << name << " tol " << tol;
            EXPECT_LE(independent, r.tolerance + kMeasureAgreement) << name << " tol " << tol;
            EXPECT_NEAR(r.maxError, independent, kMeasureAgreement) << name << " tol " << tol;
        }
    }
}

// Sparse real strokes (the fast drawings: 10 px between samples) keep their loops and tails: with
// smoothing bounded by the noise and the tolerance, even a tolerance of 0.05 px is met at every
// sample (two unbounded mean-filter passes cut a pigtail's loop by 3-4 px).
TEST(FitTolerance, GivenSparseRealCurvedStrokes_WhenFittedAtTinyTolerance_ThenEverySampleWithin)
{
    constexpr double kTinyTolerance = 0.05;  // px; the example
    constexpr int kSparse = 60;              // samples: the fast drawings of a ~200 px gesture
    const auto recs = loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, devSubjects());
    int tried = 0;
    for (const Recording& rec : recs) {
        if (rec.gesture != "pigtail" && rec.gesture != "left_curly_brace" && rec.gesture != "right_curly_brace") continue;
        if (static_cast<int>(rec.stroke.points.size()) > kSparse) continue;
        ++tried;
        FitOptions o;
        o.tolerance = kTinyTolerance;
        const FitResult r = fitStroke(rec.stroke, o);
        EXPECT_TRUE(r.converged) << rec.subject << " " << rec.gesture << " " << rec.number << ": " << r.maxError;
        EXPECT_LE(maxDeviation(r.curve, keptSamples(rec.stroke, r)), kTinyTolerance + kMeasureAgreement)
            << rec.subject << " " << rec.gesture << " " << rec.speed << " " << rec.number;
    }
    EXPECT_GE(tried, 20) << "the development subjects have sparse pigtails and braces";
}

// The same shape drawn with half, once and twice the samples (what the window gives at another
// size or pen rate) gives essentially the same curve: each is within the tolerance of samples of
// one shape, so two of them differ by at most twice the tolerance plus the noise between them.
TEST(FitTolerance, GivenSameStrokeAtThreeDensities_WhenFitted_ThenTheCurvesAgree)
{
    constexpr double kNoise = 0.05;
    for (const auto& [name, shape] : toleranceShapes()) {
        std::vector<FitResult> fits;
        for (int samples : {60, 120, 240}) {
            DrawOptions d;
            d.noise = kNoise;
            fits.push_back(fitStroke(drawWithSamples(shape, samples, d)));
        }
        const double tol = fits[1].tolerance;
        for (size_t k : {0u, 2u}) {
            EXPECT_LE(hausdorff(fits[k].curve, fits[1].curve), 2.0 * tol + 6.0 * kNoise) << name << " density " << k;
            EXPECT_EQ(fits[k].curve.isClosed(), fits[1].curve.isClosed()) << name;
        }
    }
}

// Dropped samples (hooks, loop overshoot farther than the tolerance from the curve) stay few on
// real strokes: the development subjects' 2,400 drawings, default fit. Every stroke converges.
TEST(FitTolerance, GivenRealDevelopmentStrokes_WhenFitted_ThenFewSamplesDropped)
{
    // Of one stroke's samples. The drops on these logs (no pressure, so no hooks) are overshoot
    // trimmed where conditioning closes a loop: up to 35 % of a fast x or star, whose ends meet
    // near its start (measured; README "Fitting"), a few per cent of a circle.
    constexpr double kMaxDroppedShare = 0.4;
    // Of all samples of all strokes (measured 3.2 %).
    constexpr double kMaxTotalDroppedShare = 0.05;
    const auto recs = loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, devSubjects());
    size_t dropped = 0, samples = 0, outliers = 0;
    std::map<int, int> histogram;
    std::map<std::string, size_t> byGesture;
    for (const Recording& rec : recs) {
        const FitResult r = fitStroke(rec.stroke);
        const double share = double(r.dropped.size()) / rec.stroke.points.size();
        EXPECT_LE(share, kMaxDroppedShare) << rec.subject << " " << rec.gesture << " " << rec.speed << " " << rec.number;
        dropped += r.dropped.size();
        outliers += r.outliers.size();
        samples += rec.stroke.points.size();
        ++histogram[static_cast<int>(r.dropped.size())];
        byGesture[rec.gesture] += r.dropped.size();
        EXPECT_TRUE(r.converged) << rec.subject << " " << rec.gesture << " " << rec.number << ": " << r.maxError << " > " << r.tolerance;
    }
    std::string h;
    for (const auto& [count, strokes] : histogram) h += " " + std::to_string(count) + ":" + std::to_string(strokes);
    std::printf("dropped samples per stroke (count:strokes):%s; %zu of %zu samples (%zu noise outliers)\nper gesture:",
                h.c_str(), dropped, samples, outliers);
    for (const auto& [g, n] : byGesture) std::printf(" %s %zu", g.c_str(), n);
    std::printf("\n");
    EXPECT_LE(static_cast<double>(dropped), kMaxTotalDroppedShare * static_cast<double>(samples)) << h;
    // The noise of these logs (whole pixels) is far below the tolerance: no sample is an outlier
    // (measured: none of 191,551).
    EXPECT_EQ(outliers, 0u);
}

// The tolerance bounds the distance from every kept sample to the curve; the curve must also stay
// near the stroke between two samples. Found in session 46 (scripts/stray_check.py): about a tenth
// of the development strokes had a curve that shot out between two samples by 3-70 tolerances (a
// v's first span 50 px out and back between samples 6 px apart, a caret's end hook 80 px) while
// every sample was within the tolerance. Every point of the curve must lie within the allowance of
// some segment of the polyline the fit was accepted on: the tolerance plus a sixth of the segment
// (the sagitta of a turn of 74 degrees between two samples), measured independently of the fitter
// (strayExcess) and as the fitter reports it (FitResult::stray). Before session 47, by this
// measure, 491 of the 2,400 strokes strayed, 116 by more than 3 times, 27 by more than 10. Measured
// in session 47: 6 strokes stray, by at most 1.58 (loops with 2-5 corners and a bracket whose pieces
// did not all fit, left to the error-driven fit; the two looked at stray across the gap where the
// loop closes), and each says so in a warning.
TEST(FitTolerance, GivenRealDevelopmentStrokes_WhenFitted_ThenTheCurveStaysNearTheStrokeBetweenSamples)
{
    constexpr double kChordShare = 1.0 / 6.0;
    constexpr double kMostExcess = 2.0;  // measured 1.58 (s03 x fast 9)
    constexpr int kMostStraying = 10;    // strokes beyond the allowance; measured 6
    // The fitter measures its curve at points up to about half a tolerance apart (kCheckSpacingShare):
    // a point between two of them lies at most a quarter tolerance farther, a quarter of the least
    // allowance. The two measures agree within that above 1; below it each is an upper bound (the
    // segments near the point only), so they need only agree that the curve is within.
    constexpr double kResolutionSlack = 0.25;
    int strokes = 0, straying = 0;
    double worst = 0.0;
    std::string worstName;
    for (const Recording& rec : loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, devSubjects())) {
        const FitResult r = fitStroke(rec.stroke);
        const std::string name = rec.subject + " " + rec.gesture + " " + rec.speed + " " + std::to_string(rec.number);
        ++strokes;
        // The polyline the fit was accepted on: the samples conditioning kept, less the noise's
        // outliers (a loop's overshoot the curve passes near is measured for its distance, but it
        // runs back over the loop's start and is no part of the polyline).
        std::vector<Vec3> polyline;
        for (int i = 0; i < static_cast<int>(rec.stroke.points.size()); ++i) {
            const auto has = [&](const std::vector<int>& v) { return std::binary_search(v.begin(), v.end(), i); };
            if (!has(r.conditioned.dropped) && !has(r.outliers))
                polyline.push_back(rec.stroke.points[static_cast<size_t>(i)]);
        }
        const double independent = strayExcess(r.curve, polyline, r.curve.isClosed(), r.tolerance, kChordShare);
        EXPECT_LE(independent, std::max(1.0, r.stray.excess) + kResolutionSlack) << name << ": " << r.stray.excess;
        EXPECT_LE(r.stray.excess, std::max(1.0, independent) + kResolutionSlack) << name << ": " << independent;
        EXPECT_LE(r.stray.excess, kMostExcess) << name;
        if (r.stray.excess > 1.0) {
            ++straying;
            const bool warned = std::any_of(r.warnings.begin(), r.warnings.end(),
                                            [](const std::string& w) { return w.find("strays") != std::string::npos; });
            EXPECT_TRUE(warned) << name;
        }
        if (independent > worst) worst = independent, worstName = name;
    }
    std::printf("%d strokes: %d stray beyond the allowance; the most %.3f (%s)\n", strokes, straying, worst,
                worstName.c_str());
    EXPECT_LE(straying, kMostStraying);
    EXPECT_EQ(strokes, 2400);
}

// The same on the second, independent source of real strokes (the Quick, Draw! test set: other
// people, a mouse or a finger, 338 drawings; tests/data/quickdraw). Measured when it was added
// (session 40): every stroke converges, 587 of 26,927 samples dropped (2.2 %, loops' overshoot;
// at most 20 % of one octagon's), 1 noise outlier.
TEST(FitTolerance, GivenQuickDrawStrokes_WhenFitted_ThenEveryOneConvergesAndFewSamplesDropped)
{
    constexpr double kMaxDroppedShare = 0.4;        // of one stroke's samples, as above
    constexpr double kMaxTotalDroppedShare = 0.05;  // of all samples, as above
    // Noise outliers: lone samples beyond the tolerance that the noise explains; "few" is here at
    // most one in a thousand samples.
    constexpr double kMaxOutlierShare = 0.001;
    const auto recs = loadQuickDraw();
    ASSERT_EQ(recs.size(), 338u);
    size_t dropped = 0, samples = 0, outliers = 0;
    for (const Recording& rec : recs) {
        const FitResult r = fitStroke(rec.stroke);
        EXPECT_TRUE(r.converged) << rec.gesture << " " << rec.number << ": " << r.maxError << " > " << r.tolerance;
        EXPECT_LE(r.maxError, r.tolerance) << rec.gesture << " " << rec.number;
        EXPECT_LE(double(r.dropped.size()) / rec.stroke.points.size(), kMaxDroppedShare)
            << rec.gesture << " " << rec.number;
        dropped += r.dropped.size();
        outliers += r.outliers.size();
        samples += rec.stroke.points.size();
    }
    EXPECT_LE(static_cast<double>(dropped), kMaxTotalDroppedShare * static_cast<double>(samples));
    EXPECT_LE(static_cast<double>(outliers), kMaxOutlierShare * static_cast<double>(samples));
}

// fitStroke's search for the fewest control points: where its climb's last step misses by more
// than the step before, the counts between the last two misses are tried before the error-driven
// fit. Two slow, jittery flourishes (seeds 3 and 15 of BM_StrokeFitSeeds/1) climbed 20, 22 and fell
// back to 30 and 32 control points; 21 fits both. Bound: the most of the other 14 seeds (23).
TEST(FitTolerance, GivenJitteryFlourishesWhoseClimbJumpsPastTheFit_WhenFitted_ThenTheCountBetweenTheMissesIsFound)
{
    constexpr int kMostOfTheOtherSeeds = 23;
    for (unsigned seed : {3u, 15u}) {
        DrawOptions d;
        d.noise = 0.5;
        d.seed = seed;
        const Stroke s = drawWithSamples(flourishShape(300), 1000, d);

        const FitResult r = fitStroke(s);

        ASSERT_TRUE(r.converged) << "seed " << seed;
        EXPECT_LE(r.curve.pointCount(), kMostOfTheOtherSeeds) << "seed " << seed;
        EXPECT_LE(maxDeviation(r.curve, keptSamples(s, r)), r.tolerance + kMeasureAgreement) << "seed " << seed;
    }
}

// A slow hand with sensor jitter (noise 0.5 on the 300-unit flourish, 1,000 samples; the default
// tolerance is 1.51, three sigma): a sample the noise puts beyond the tolerance is left out as an
// outlier (FitResult::outliers) only when it lies alone between neighbours within the tolerance and
// no farther from the curve than kOutlierSigmas noise sigmas; every other kept sample is within the
// tolerance, max_error is theirs, and the curve keeps to the pen's true path. Measured on seeds
// 1-8: 0-10 outliers per stroke (of 1,001 samples; 10 is the cap), the true path within 0.55-1.18
// of the curve.
TEST(FitTolerance, GivenSlowJitteryFlourishes_WhenFitted_ThenOnlyLoneNoiseOutliersAreLeftBeyondTheTolerance)
{
    size_t total = 0;
    for (unsigned seed = 1; seed <= 8; ++seed) {
        // Arrange
        DrawOptions d;
        d.noise = 0.5;
        d.seed = seed;
        const Stroke s = drawWithSamples(flourishShape(300), 1000, d);
        DrawOptions truthOptions = d;
        truthOptions.noise = 0.0;
        const Stroke truth = drawWithSamples(flourishShape(300), 1000, truthOptions);
        // Act
        const FitResult r = fitStroke(s);
        // Assert
        ASSERT_TRUE(r.converged) << "seed " << seed;
        const std::vector<Vec3> kept = keptSamples(s, r);
        const double keptMax = maxDeviation(r.curve, kept);
        EXPECT_LE(keptMax, r.tolerance + kMeasureAgreement) << "seed " << seed;
        EXPECT_NEAR(r.maxError, keptMax, kMeasureAgreement) << "seed " << seed;
        EXPECT_LE(static_cast<double>(r.outliers.size()), kMaxOutlierShare * static_cast<double>(s.points.size()))
            << "seed " << seed;
        for (int i : r.outliers) {
            ASSERT_TRUE(std::binary_search(r.dropped.begin(), r.dropped.end(), i))
                << "seed " << seed << " outlier " << i;
            ASSERT_GT(i, 0);
            ASSERT_LT(i + 1, static_cast<int>(s.points.size()));
            const double own = maxDeviation(r.curve, {s.points[static_cast<size_t>(i)]});
            EXPECT_GT(own, r.tolerance - kMeasureAgreement) << "seed " << seed << " outlier " << i;
            EXPECT_LE(own, kOutlierSigmas * r.conditioned.noise + kMeasureAgreement)
                << "seed " << seed << " outlier " << i;
            for (int j : {i - 1, i + 1})
                EXPECT_LE(maxDeviation(r.curve, {s.points[static_cast<size_t>(j)]}), r.tolerance + kMeasureAgreement)
                    << "seed " << seed << " neighbour " << j << " of outlier " << i;
        }
        // The outliers are noise, not shape: the curve keeps to the path the pen followed.
        EXPECT_LE(maxDeviation(r.curve, truth.points), r.tolerance) << "seed " << seed;
        total += r.outliers.size();
        std::printf("seed %u: %zu outliers, %d control points, true path within %.3f\n", seed, r.outliers.size(),
                    r.curve.pointCount(), maxDeviation(r.curve, truth.points));
    }
    EXPECT_GT(total, 0u) << "noise at a third of the tolerance should leave some sample beyond it";
}

// The dynamic threshold reads the hand's speed on the smoothed path (measureSpeed), so a slow
// hand's jitter does not add rows: on the drawn points every window's path was lengthened by the
// jitter, and the jittery flourishes took 1.27x the clean ones' rows.
TEST(FitTolerance, GivenSlowJitteryFlourishes_WhenFitted_ThenTheThresholdTakesAboutTheCleanStrokesRows)
{
    constexpr double kMaxRowRatio = 1.1;  // measured 1.07 over seeds 1-8 (1.27 with the speed on the drawn points)
    size_t clean = 0, jittery = 0;
    for (unsigned seed = 1; seed <= 8; ++seed) {
        DrawOptions d;
        d.seed = seed;
        d.noise = 0.25;
        clean += fitStroke(drawWithSamples(flourishShape(300), 1000, d)).samples.size();
        d.noise = 0.5;
        jittery += fitStroke(drawWithSamples(flourishShape(300), 1000, d)).samples.size();
    }
    std::printf("rows: clean %zu, jittery %zu (%.3f)\n", clean, jittery, double(jittery) / double(clean));
    EXPECT_LE(static_cast<double>(jittery), kMaxRowRatio * static_cast<double>(clean));
}

// A sample farther from the path than the noise explains is not an outlier: a one-sample spike of
// 3 units (5.6 sigma) on the jittery flourish is held within the tolerance like any other sample.
TEST(FitTolerance, GivenASpikeBeyondTheNoise_WhenFitted_ThenItIsHeldNotLeftOut)
{
    // Arrange
    DrawOptions d;
    d.noise = 0.5;
    Stroke s = drawWithSamples(flourishShape(300), 1000, d);
    constexpr size_t kSpike = 500;
    s.points[kSpike] += Vec3(0.0, 3.0, 0.0);
    // Act
    const FitResult r = fitStroke(s);
    // Assert
    ASSERT_TRUE(r.converged);
    EXPECT_FALSE(std::binary_search(r.dropped.begin(), r.dropped.end(), static_cast<int>(kSpike)));
    EXPECT_LE(maxDeviation(r.curve, {s.points[kSpike]}), r.tolerance + kMeasureAgreement);
    EXPECT_GT(kOutlierSigmas * r.conditioned.noise, r.tolerance)
        << "the rule must be in force for this test to mean anything";
}

// Smoothing follows the noise that is there: a jittery stroke is smoothed (by up to the share of
// the tolerance ConditioningOptions::smoothingShare allows), a clean one is left almost as drawn,
// and the noise estimate (fourth differences, robust median) finds the sigma the strokes were drawn
// with. 1,000 samples: the median of ~1,000 fourth differences has a relative standard error of
// ~3 %, so 25 % is a wide band that a biased estimator (second differences, which read the
// curvature of the 10-sample-per-unit flourish as noise) would still leave.
TEST(FitTolerance, GivenJitteryAndCleanStrokes_WhenFitted_ThenNoiseEstimatedAndOnlyTheJitterySmoothed)
{
    constexpr double kEstimateBand = 0.25;
    for (const auto& [name, shape] : toleranceShapes()) {
        for (double sigma : {0.0, 0.3, 1.0}) {
            // Arrange
            DrawOptions d;
            d.noise = sigma;
            const Stroke s = drawWithSamples(shape, 1000, d);
            // Act
            const FitResult r = fitStroke(s);
            // Assert
            const ConditionedStroke& cs = r.conditioned;
            const ConditioningOptions copt;
            if (sigma > 0.0) {
                EXPECT_NEAR(cs.noise, sigma, kEstimateBand * sigma) << name << " sigma " << sigma;
                // The filter moves points by about sigma; the budget caps it at share * tolerance.
                EXPECT_GT(cs.smoothingShift, 0.5 * std::min(sigma, copt.smoothingShare * r.tolerance)) << name << " sigma " << sigma;
            } else {
                // Only the synthesis' own rounding and the shape's fourth derivative remain.
                EXPECT_LT(cs.noise, 0.02) << name;
                EXPECT_LE(cs.smoothingShift, copt.noiseMultiple * cs.noise + 1e-12) << name;
            }
            EXPECT_LE(cs.smoothingShift, copt.smoothingShare * r.tolerance + 1e-12) << name << " sigma " << sigma;
        }
    }
}

TEST(FitTolerance, GivenCleanSCurve_WhenTheToleranceIsLoosened_ThenFewerControlPoints)
{
    DrawOptions d;
    d.noise = 0.02;
    const Stroke s = draw(sCurveShape(200), d);
    std::vector<int> counts;
    for (double tol : {0.25, 0.5, 1.0}) {
        FitOptions o;
        o.tolerance = tol;
        const FitResult r = fitStroke(s, o);
        ASSERT_TRUE(r.converged) << tol;
        counts.push_back(r.curve.pointCount());
    }
    EXPECT_LE(counts[1], counts[0]);
    EXPECT_LE(counts[2], counts[1]);
    EXPECT_LT(counts[2], counts[0]) << "1.0 against 0.25";
}

// Loops search for fewer control points too: a smooth loop with periodic averaged knots (its N
// control points have N spans, the breaks at every N_s / N-th sample's parameter), a loop with one
// corner as one clamped piece round from the corner. Before, both kept the error-driven fit. Every
// kept raw sample stays within the tolerance (measured independently), the curve stays closed.
TEST(FitTolerance, GivenLoops_WhenFitted_ThenFewerControlPointsThanTheErrorDrivenFitAndEverySampleWithin)
{
    const std::vector<std::tuple<std::string, Shape, size_t>> loops = {
        {"circle", circleShape({10, 20, 0}, 80), 0},
        {"ellipse", ellipseShape({0, 0, 0}, 120, 60, 0.4), 0},
        {"teardrop", teardropShape(80), 1},
    };
    for (const auto& [name, shape, corners] : loops) {
        // Arrange
        DrawOptions d;
        d.noise = 0.25;
        const Stroke s = draw(shape, d);
        FitOptions errorDriven;
        errorDriven.fewerControlPoints = false;
        // Act
        const FitResult r = fitStroke(s);
        const FitResult e = fitStroke(s, errorDriven);
        // Assert
        ASSERT_TRUE(r.curve.isClosed()) << name;
        ASSERT_EQ(r.corners.size(), corners) << name << ": the loop this test is about";
        EXPECT_TRUE(r.converged) << name;
        EXPECT_LE(maxDeviation(r.curve, keptSamples(s, r)), r.tolerance + kMeasureAgreement) << name;
        EXPECT_NEAR(r.maxError, maxDeviation(r.curve, keptSamples(s, r)), kMeasureAgreement) << name;
        EXPECT_LT(r.curve.pointCount(), e.curve.pointCount()) << name;
        std::printf("%s: %d control points, error-driven %d\n", name.c_str(), r.curve.pointCount() - 3, e.curve.pointCount() - 3);
    }
}

// Sparse loops (4-40 samples, noise 0, 0.5, 3), both knot-removal modes and both searches: the loops' search never
// turns a stroke the error-driven fit takes into an error, and converges wherever that fit does.
// (Teardrops of 16-24 samples failed: a trial's clamped piece kept too few distinct points for a
// closed cubic, and the curve's constructor threw out of fitStroke.)
TEST(FitTolerance, GivenSparseLoops_WhenFitted_ThenTheSearchFailsNoStrokeTheErrorDrivenFitTakes)
{
    const std::vector<std::pair<std::string, Shape>> loops = {
        {"circle", circleShape({0, 0, 0}, 80)}, {"ellipse", ellipseShape({0, 0, 0}, 120, 60, 0.4)}, {"teardrop", teardropShape(80)}};
    int fitted = 0;
    for (const auto& [name, shape] : loops) {
        for (int n = 4; n <= 40; ++n) {
            for (double noise : {0.0, 0.5, 3.0}) {
                // (Both removal modes with the predicted search, and the count-up search.)
                for (const auto& [removal, countUp] :
                     {std::pair{KnotRemoval::LastRound, false}, std::pair{KnotRemoval::AllKnots, false},
                      std::pair{KnotRemoval::AllKnots, true}}) {
                    DrawOptions d;
                    d.noise = noise;
                    const Stroke s = drawWithSamples(shape, n, d);
                    FitOptions o;
                    o.spline.removal = removal;
                    o.countUp = countUp;
                    FitOptions errorDriven = o;
                    errorDriven.fewerControlPoints = false;
                    FitResult e;
                    try {
                        e = fitStroke(s, errorDriven);
                    } catch (const solvers::GeometryError&) {
                        continue;  // a stroke too degenerate for either (not this test's subject)
                    }
                    ++fitted;
                    const std::string what = name + " of " + std::to_string(n) + " samples, noise " + std::to_string(noise);
                    FitResult r;
                    ASSERT_NO_THROW(r = fitStroke(s, o)) << what;
                    if (e.converged) {
                        EXPECT_TRUE(r.converged) << what;
                    }
                }
            }
        }
    }
    EXPECT_GT(fitted, 500) << "most of the 666 strokes should fit";
}

// An arc like the sail's target B (a 30-unit chord bulging 10 units), drawn with the pointer moving
// about a pixel per event, its samples rounded to a grid of pitch q (whole pixels).
Stroke quantizedArc(double q, bool quantize)
{
    Stroke s;
    s.dimension = 2;
    constexpr int kSamples = 150;
    for (int i = 0; i <= kSamples; ++i) {
        const double t = static_cast<double>(i) / kSamples;
        Vec3 p(10.0 * std::sin(M_PI * t), 30.0 * t, 0.0);
        if (quantize) p = Vec3(q * std::round(p.x() / q), q * std::round(p.y() / q), 0.0);
        s.points.push_back(p);
        s.times.push_back(0.01 * i);
    }
    return s;
}

// FitOptions::resolution: samples quantized to a grid of pitch q are only known to +-q/2 per axis.
// With resolution q the default tolerance is q (kResolutionTolerance), the fit ignores the
// staircase and needs about as few control points as the unquantized arc; every sample stays
// within the reported tolerance. Without it (0, unknown) the relative tolerance (0.5 % of the
// extent, ~0.16 here, below the half-pitch rounding) makes the curve follow the steps.
TEST(FitTolerance, GivenPixelQuantizedArc_WhenFittedWithItsResolution_ThenFewControlPointsAndEverySampleWithin)
{
    constexpr double kPitch = 0.45;  // the sail window's pixel on plane B, model units
    // Arrange
    const Stroke smooth = quantizedArc(kPitch, false);
    const Stroke stairs = quantizedArc(kPitch, true);
    FitOptions withResolution;
    withResolution.resolution = kPitch;
    // Act
    const FitResult reference = fitStroke(smooth);
    const FitResult unknown = fitStroke(stairs);
    const FitResult known = fitStroke(stairs, withResolution);
    // Assert
    std::printf("quantized arc (pitch %.2f): smooth %d control points (tolerance %.3f); quantized, resolution 0: %d "
                "(tolerance %.3f, max error %.3f); resolution %.2f: %d (tolerance %.3f, max error %.3f)\n",
                kPitch, reference.curve.pointCount(), reference.tolerance, unknown.curve.pointCount(), unknown.tolerance,
                unknown.maxError, kPitch, known.curve.pointCount(), known.tolerance, known.maxError);
    EXPECT_DOUBLE_EQ(unknown.tolerance, kDefaultRelativeTolerance * unknown.conditioned.extent);
    EXPECT_DOUBLE_EQ(known.tolerance, kResolutionTolerance * kPitch);
    EXPECT_TRUE(known.converged);
    EXPECT_LE(known.maxError, known.tolerance);
    EXPECT_LE(maxDeviation(known.curve, keptSamples(stairs, known)), known.tolerance + kMeasureAgreement);
    EXPECT_LE(known.curve.pointCount(), reference.curve.pointCount() + 2);
    EXPECT_LT(known.curve.pointCount(), unknown.curve.pointCount());
    // The curve is the arc, not the staircase: within half a pitch of the true arc throughout.
    EXPECT_LT(hausdorff(known.curve, reference.curve), 0.5 * kPitch);
}

// A resolution below what the relative tolerance already allows changes nothing: the same curve.
TEST(FitTolerance, GivenFineResolution_WhenFitted_ThenTheSameFitAsWithoutOne)
{
    DrawOptions d;
    d.noise = 0.1;
    const Stroke s = draw(sCurveShape(200), d);
    const FitResult plain = fitStroke(s);
    FitOptions o;
    o.resolution = 0.1 * plain.tolerance;
    const FitResult fine = fitStroke(s, o);
    EXPECT_EQ(fine.tolerance, plain.tolerance);
    EXPECT_EQ(fine.curve.points(), plain.curve.points());
    EXPECT_EQ(fine.curve.knots(), plain.curve.knots());
    FitOptions bad;
    bad.resolution = -1.0;
    EXPECT_THROW(fitStroke(s, bad), solvers::GeometryError);
    // An explicit tolerance wins over the resolution.
    FitOptions both;
    both.tolerance = 0.3;
    both.resolution = 5.0;
    EXPECT_EQ(fitStroke(s, both).tolerance, 0.3);
}

}  // namespace
}  // namespace sculptline::stroketest
