// Given strokes synthesized from known curves with human-like timing and noise, when fitted, then
// the curve stays within tolerance of the samples and of the true curve, interpolates the ends,
// keeps corners as G0 joints, is C2 elsewhere, and closes when the stroke does.
#include "solvers/stroke/stroke_fitter.h"
#include "fit_checks.h"

#include <gtest/gtest.h>

namespace sculptline::stroketest {
namespace {

using namespace solvers::stroke;

// Noise of a good tablet at the drawing's scale (shapes are ~100-200 units across): 0.1-0.3 units.
constexpr double kNoiseSigma = 0.25;
// The fitted curve may deviate from the noise-free curve by the tolerance plus what the mean
// filter leaves of the noise: 4 sigma bounds the Gaussian tail over a few hundred samples.
constexpr double kNoiseAllowance = 4.0 * kNoiseSigma;

std::vector<std::pair<std::string, Shape>> testShapes()
{
    return {
        {"line", lineShape({0, 0, 0}, {200, 50, 0})},
        {"arc", arcShape({0, 0, 0}, 100, 0.2, 2.5)},
        {"circle", circleShape({10, 20, 0}, 80)},
        {"ellipse", ellipseShape({0, 0, 0}, 120, 60, 0.3)},
        {"square", polygonShape({{0, 0, 0}, {100, 0, 0}, {100, 100, 0}, {0, 100, 0}}, true)},
        {"triangle", polygonShape({{0, 0, 0}, {160, 10, 0}, {70, 120, 0}}, true)},
        {"zigzag", polygonShape({{0, 0, 0}, {60, 80, 0}, {120, 0, 0}, {180, 80, 0}}, false)},
        {"s-curve", sCurveShape(200)},
        {"spiral", spiralShape(100, 2.5)},
    };
}

TEST(StrokeFit, GivenNoisyShapes_WhenFitted_ThenWithinToleranceOfSamplesAndOfTrueCurve)
{
    for (const auto& [name, shape] : testShapes()) {
        for (unsigned seed = 1; seed <= 3; ++seed) {
            DrawOptions d;
            d.noise = kNoiseSigma;
            d.seed = seed;
            const Stroke s = draw(shape, d);

            const FitResult r = fitStroke(s);

            EXPECT_TRUE(r.converged) << name << " seed " << seed;
            // The tolerance bounds the drawn samples the fit kept (measured independently of the
            // fitter), not the smoothed points recognition reads (r.conditioned): since the minimax
            // trials fit the drawn points (session 51) a curve may come nearer to a drawn sample
            // than to its smoothed point (session 53: the spiral of seed 1, 0.978 from a smoothed
            // point at the tolerance 0.975).
            EXPECT_LE(maxDeviation(r.curve, keptSamples(s, r)), r.tolerance + kMeasureAgreement)
                << name << " seed " << seed;
            EXPECT_LE(r.maxError, r.tolerance) << name;
            double toTruth = 0;  // curve -> true shape
            for (int i = 0; i <= 400; ++i) {
                const double u = r.curve.domainStart() + (r.curve.domainEnd() - r.curve.domainStart()) * i / 400;
                toTruth = std::max(toTruth, distanceToPolyline(r.curve.evaluate(u), shape.reference, shape.closed));
            }
            EXPECT_LE(toTruth, r.tolerance + kNoiseAllowance) << name << " seed " << seed;
            EXPECT_EQ(r.curve.isClosed(), shape.closed) << name;
            EXPECT_EQ(r.curve.degree(), 3);
        }
    }
}

TEST(StrokeFit, GivenOpenStroke_WhenFitted_ThenEndsAreInterpolated)
{
    DrawOptions d;
    d.noise = kNoiseSigma;
    const Stroke s = draw(sCurveShape(150), d);

    const FitResult r = fitStroke(s);

    EXPECT_LE((r.curve.evaluate(r.curve.domainStart()) - s.points.front()).norm(), 1e-9);
    EXPECT_LE((r.curve.evaluate(r.curve.domainEnd()) - s.points.back()).norm(), 1e-9);
}

TEST(StrokeFit, GivenPolyline_WhenFitted_ThenC2ExceptTripleKnotsAtCornersWhichAreInterpolated)
{
    DrawOptions d;
    d.noise = kNoiseSigma;
    const Stroke s = draw(polygonShape({{0, 0, 0}, {60, 80, 0}, {120, 0, 0}, {180, 80, 0}}, false), d);

    const FitResult r = fitStroke(s);

    ASSERT_EQ(r.corners.size(), 2u);
    const auto& k = r.curve.knots();
    std::vector<double> triple;
    for (double b : solvers::interiorBreakpoints(3, k)) {
        const int mult = solvers::knotMultiplicity(k, b);
        EXPECT_TRUE(mult == 1 || mult == 3) << "knot " << b << " multiplicity " << mult;
        if (mult == 3) triple.push_back(b);
    }
    ASSERT_EQ(triple.size(), 2u);
    for (size_t c = 0; c < 2; ++c) {
        // The corner is a control point hit by the curve: the nearest conditioned sample to the raw
        // corner sample is interpolated, which the dense deviation confirms within round-off.
        const Vec3 at = r.curve.evaluate(triple[c]);
        const Vec3 raw = s.points[r.corners[c]];
        EXPECT_LE((at - raw).norm(), 2 * kNoiseAllowance);
        const auto left = r.curve.derivatives(triple[c] - 1e-9, 1)[1].normalized();
        const auto right = r.curve.derivatives(triple[c] + 1e-9, 1)[1].normalized();
        EXPECT_LT(left.dot(right), std::cos(0.5)) << "the corner keeps its sharp turn";
    }
}

TEST(StrokeFit, GivenLoopsWithGapOrOvershoot_WhenFitted_ThenCurveIsClosed)
{
    for (double offset : {-0.03, 0.0, 0.05}) {
        for (const Shape& shape : {circleShape({0, 0, 0}, 90), polygonShape({{0, 0, 0}, {120, 0, 0}, {60, 100, 0}}, true)}) {
            DrawOptions d;
            d.noise = kNoiseSigma;
            d.closureOffset = offset;
            const Stroke s = draw(shape, d);
            const FitResult r = fitStroke(s);
            EXPECT_TRUE(r.curve.isClosed()) << "offset " << offset;
            EXPECT_TRUE(r.converged);
            // The tolerance bounds the drawn samples kept (FitResult::tolerance; before session 43
            // this read the conditioned points, which the least squares fitted; a minimax curve
            // holds the drawn samples, and a loop's smoothed seam points can lie farther).
            EXPECT_LE(maxDeviation(r.curve, keptSamples(s, r)), r.tolerance + kMeasureAgreement) << "offset " << offset;
        }
    }
}

TEST(StrokeFit, GivenExplicitTolerance_WhenFitted_ThenItIsUsedAndTighterMeansMoreControlPoints)
{
    DrawOptions d;
    d.noise = 0.05;
    const Stroke s = draw(spiralShape(100, 2.0), d);
    FitOptions loose, tight;
    loose.tolerance = 2.0;
    tight.tolerance = 0.2;

    const FitResult a = fitStroke(s, loose);
    const FitResult b = fitStroke(s, tight);

    EXPECT_EQ(a.tolerance, 2.0);
    EXPECT_EQ(b.tolerance, 0.2);
    // The tolerance bounds the drawn samples (no sample of this spiral is dropped), not the smoothed
    // points: those lie up to the smoothing shift from the drawn ones, on either side of the curve.
    // fit_checks.h's dense polyline over-reports a distance by up to ~4e-3 here (its sagitta);
    // maxError is the exact projection.
    constexpr double kDensePolylineSlack = 1e-2;
    EXPECT_TRUE(b.dropped.empty());
    EXPECT_LE(b.maxError, 0.2);
    EXPECT_LE(maxDeviation(b.curve, s.points), 0.2 + kDensePolylineSlack);
    EXPECT_GT(b.curve.pointCount(), a.curve.pointCount());
}

TEST(StrokeFit, GivenAllKnotsRemovalPass_WhenFitted_ThenNoMoreControlPointsAndStillWithinTolerance)
{
    for (const auto& [name, shape] : testShapes()) {
        DrawOptions d;
        d.noise = kNoiseSigma;
        const Stroke s = draw(shape, d);
        // Every knot tried (the default since session 40) against the last round's only; and the
        // count-up search (FitOptions::countUp) within tolerance too.
        FitOptions lastRound;
        lastRound.spline.removal = KnotRemoval::LastRound;
        FitOptions countUp;
        countUp.countUp = true;

        const FitResult a = fitStroke(s, lastRound);
        const FitResult b = fitStroke(s);
        const FitResult c = fitStroke(s, countUp);

        EXPECT_LE(b.curve.pointCount(), a.curve.pointCount()) << name;
        for (const FitResult* r : {&b, &c}) {
            EXPECT_TRUE(r->converged) << name;
            EXPECT_LE(maxDeviation(r->curve, r->conditioned.points), r->tolerance * (1 + 1e-9)) << name;
        }
    }
}

// Thesis §4.1.1, Fig. 4-3: "in (a) the first sketch is approximated into a B-spline by more than 46
// control points ... in (b) the similar first B-spline is reconstructed by only 18 control points
// with the use of our dynamical threshold method". The stroke: bowed sweeps joined by tight turns
// where the pen nearly stops (5 % of its peak speed, as at the cusps of handwriting), 600 samples
// at a fixed rate, so that speed-only sampling crowds the turns.
TEST(StrokeFit, GivenFig43Stroke_WhenDynamicThresholdSampling_ThenAtMost18ControlPointsAndNoMoreThanSpeedOnly)
{
    constexpr int kThesisDynamicCount = 18;  // thesis Fig. 4-3 (b)
    // The thesis's 46 vs 18 comes from a fit whose knots follow the samples (more samples in the
    // slow turns, more control points). Ours go where the error is (insertion cut by the error's
    // fourth root, then removal), so the count hardly depends on the sampling: 17 vs 17-19 on
    // seeds 1-3 (bench BM_StrokeFig43; README "Strokes"). What the dynamic threshold still buys
    // is a least-squares system 4-5x smaller (and a fit ~1.7x faster) for no more control points.
    for (unsigned seed = 1; seed <= 3; ++seed) {
        DrawOptions d;
        d.noise = kNoiseSigma;
        d.seed = seed;
        d.cornerSlowdown = 0.05;
        const Stroke s = drawWithSamples(hairpinShape(200, 3, 25), 600, d);
        FitOptions speedOnly;
        speedOnly.dynamicSampling = false;
        const FitResult a = fitStroke(s, speedOnly);
        const FitResult b = fitStroke(s);  // dynamic threshold is the default
        ASSERT_TRUE(a.converged && b.converged) << seed;
        EXPECT_TRUE(a.corners.empty() && b.corners.empty()) << "the turns are smooth bends, seed " << seed;
        EXPECT_LE(b.curve.pointCount(), kThesisDynamicCount) << seed;
        EXPECT_LE(b.curve.pointCount(), a.curve.pointCount()) << seed << ": " << b.curve.pointCount() << " vs " << a.curve.pointCount();
        // The threshold thins the rows of the search's least squares. (The minimax trials, which
        // may take fewer control points than the search, fit every conditioned point: where they
        // take a count, as on these hairpins since session 54: 13 control points, the search's 14,
        // FitResult::samples are all of them.)
        FitOptions searchOnly;
        searchOnly.minimaxTrials = false;
        FitOptions speedSearchOnly = searchOnly;
        speedSearchOnly.dynamicSampling = false;
        const FitResult c = fitStroke(s, searchOnly), e = fitStroke(s, speedSearchOnly);
        EXPECT_LT(c.samples.size() * 3, e.samples.size()) << "the threshold thins the least-squares rows, seed " << seed;
        EXPECT_LE(maxDeviation(b.curve, s.points), b.tolerance + kNoiseAllowance) << seed;
    }
}

// A pen-down hook: the first samples, drawn while the pressure builds up, curl ~9 units away from
// the stroke (about 4 % of its length) before the line starts at pressure 0.8.
Stroke hookedLine()
{
    DrawOptions d;
    d.noise = kNoiseSigma;
    Stroke line = draw(lineShape({0, 0, 0}, {200, 0, 0}), d);
    const std::vector<Vec3> hook = {{-2, 9, 0}, {-5, 7.5, 0}, {-6.5, 5, 0}, {-6, 2.5, 0}, {-4, 0.8, 0}, {-1.5, 0.1, 0}};
    const std::vector<double> hookPressure = {0.05, 0.1, 0.15, 0.2, 0.25, 0.3};
    Stroke s;
    const double dt = line.times[1] - line.times[0];
    for (size_t i = 0; i < hook.size(); ++i) {
        s.points.push_back(hook[i]);
        s.times.push_back(dt * static_cast<double>(i));
        s.pressure.push_back(hookPressure[i]);
    }
    for (size_t i = 0; i < line.points.size(); ++i) {
        s.points.push_back(line.points[i]);
        s.times.push_back(dt * static_cast<double>(hook.size()) + line.times[i]);
        s.pressure.push_back(0.8);
    }
    return s;
}

double worstDistanceToXAxisSegment(const solvers::Curve3d& c)
{
    double worst = 0;
    for (int i = 0; i <= 2000; ++i) {
        const Vec3 p = c.evaluate(c.domainStart() + (c.domainEnd() - c.domainStart()) * i / 2000);
        worst = std::max(worst, distanceToPolyline(p, {{0, 0, 0}, {200, 0, 0}}, false));
    }
    return worst;
}

TEST(StrokeFit, GivenLightPressureHookAtPenDown_WhenFitted_ThenHookTrimmedAndCurveFollowsTheLine)
{
    const Stroke withPressure = hookedLine();
    Stroke withoutPressure = withPressure;
    withoutPressure.pressure.clear();

    const FitResult a = fitStroke(withPressure);
    const FitResult b = fitStroke(withoutPressure);

    // The hook is gone: the curve stays within the tolerance (and the smoothed noise) of the line.
    EXPECT_LE(worstDistanceToXAxisSegment(a.curve), a.tolerance + kNoiseAllowance);
    EXPECT_TRUE(std::any_of(a.warnings.begin(), a.warnings.end(), [](const std::string& w) { return w.find("hook") != std::string::npos; }));
    EXPECT_GE(a.samples.front(), 6);  // sample indices still refer to the input
    // Without pressure there is nothing to tell the hook from the stroke: it is fitted.
    EXPECT_GE(worstDistanceToXAxisSegment(b.curve), 5.0);
}

TEST(StrokeFit, GivenLongLightStart_WhenFitted_ThenKeptAsDrawnOnPurpose)
{
    // The hook and the first 30 % of the line drawn lightly: far longer than a hook
    // (ConditioningOptions::maxHookLength, 8 % of the path), so nothing is trimmed.
    Stroke s = hookedLine();
    for (size_t i = 0; i < s.pressure.size() * 3 / 10; ++i) s.pressure[i] = 0.1;
    const FitResult r = fitStroke(s);
    EXPECT_EQ(r.samples.front(), 0);
    EXPECT_GE(worstDistanceToXAxisSegment(r.curve), 5.0);
}

}  // namespace
}  // namespace sculptline::stroketest
