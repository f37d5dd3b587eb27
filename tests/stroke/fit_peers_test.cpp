// Given real pen strokes (the $1 unistroke logs' development subjects), when fitted, then they need
// no more control points than the peers (FITPACK's splprep, OCCT's GeomAPI_PointsToBSpline) at the
// same measured deviation where scripts/compare_splprep.py found them short, and each of the fit's
// readings (a loop's two, an end hook's corner left out, the minimax trials) never takes more
// control points while every kept sample stays within the tolerance.
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

// A sparse real pigtail (s02, fast, number 1: 47 samples) leaves the dynamic threshold 10 rows; a
// count near that interpolates them and swings between them (9 control points: rows within 0.11,
// a raw sample 16.7 off), so the search on those rows finds nothing. Searched again on rows spread
// two per control point it needs no more control points than FITPACK's splprep at the same measured
// deviation: 24 (scripts/compare_splprep.py, default mode; 26 before, from the error-driven fit).
TEST(FitTolerance, GivenSparseRealPigtail_WhenFitted_ThenNoMoreControlPointsThanSplprep)
{
    constexpr int kSplprepCount = 24;
    const auto recs = loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, {"s02"});
    int tried = 0;
    for (const Recording& rec : recs) {
        if (rec.gesture != "pigtail" || rec.speed != "fast" || rec.number != 1) continue;
        ++tried;
        const FitResult r = fitStroke(rec.stroke);
        ASSERT_TRUE(r.converged) << r.maxError;
        EXPECT_LE(r.curve.pointCount(), kSplprepCount);
        EXPECT_LE(maxDeviation(r.curve, keptSamples(rec.stroke, r)), r.tolerance + kMeasureAgreement);
    }
    EXPECT_EQ(tried, 1) << "s02's first fast pigtail";
}

// A loop with at most one corner has two readings, periodic and one clamped piece (from the corner,
// or from the seam where the hand closed it), and takes the one with fewer control points. On the
// development circles no loop needs more than with the detected corners alone, every kept sample
// stays within the tolerance, and the loops need fewer in all (measured: 3,051 -> 2,838 control
// points over the 96 loops; 2,828 since session 44 searches the other reading too). s03's eighth
// slow circle, whose periodic fit needs 80 control points, takes 35 clamped at its seam.
//
// Each of the 150 development circles fitted with `first` (a) and `second` (b): b holds the
// tolerance on every kept raw sample, needs no more control points than a and reports the same
// corners; `each(rec, name, a, b)` checks and counts the rest.
template <class Each>
void compareOnDevelopmentCircles(const FitOptions& first, const FitOptions& second, Each&& each)
{
    for (const Recording& rec : loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, devSubjects())) {
        if (rec.gesture != "circle") continue;
        const FitResult a = fitStroke(rec.stroke, first), b = fitStroke(rec.stroke, second);
        const std::string name = rec.subject + " " + rec.speed + " " + std::to_string(rec.number);
        ASSERT_TRUE(b.converged) << name;
        EXPECT_LE(maxDeviation(b.curve, keptSamples(rec.stroke, b)), b.tolerance + kMeasureAgreement) << name;
        EXPECT_LE(b.curve.pointCount(), a.curve.pointCount()) << name;
        EXPECT_EQ(a.corners, b.corners) << name << ": the detected corners are reported either way";
        each(rec, name, a, b);
    }
}

TEST(FitTolerance, GivenRealLoops_WhenFittedInBothReadings_ThenNeverMoreControlPointsAndTheToleranceHeld)
{
    // Of the loops' control points, the least saving taken as a gain (measured 7.0 %; 7.3 % in
    // session 44). The minimax trials (session 43) are off in both fits: they make either reading's
    // count fewer, and this measures the readings.
    constexpr double kMinSavedShare = 0.05;
    int loops = 0, one = 0, both = 0, fewer = 0;
    FitOptions alone, readings;
    alone.bothLoopReadings = false;
    alone.minimaxTrials = readings.minimaxTrials = false;
    compareOnDevelopmentCircles(
        alone, readings, [&](const Recording& rec, const std::string& name, const FitResult& a, const FitResult& b) {
            if (!b.conditioned.closed) {
                EXPECT_EQ(a.curve.pointCount(), b.curve.pointCount()) << name << ": open strokes have one reading";
                return;
            }
            ++loops;
            one += a.curve.pointCount() - 3;
            both += b.curve.pointCount() - 3;
            fewer += b.curve.pointCount() < a.curve.pointCount();
            if (rec.subject == "s03" && rec.speed == "slow" && rec.number == 8) {
                EXPECT_GE(a.curve.pointCount() - 3, 70) << "periodic alone";
                EXPECT_LE(b.curve.pointCount() - 3, 35) << "clamped at the seam";
            }
        });
    std::printf("%d loops: %d control points with one reading, %d with both (%d fewer)\n", loops, one, both, fewer);
    EXPECT_GE(loops, 90) << "the development circles that close";
    EXPECT_LE(static_cast<double>(both), (1.0 - kMinSavedShare) * static_cast<double>(one));
}

// FitOptions::minimaxTrials: below the count the least squares' search takes, minimax trials
// (Lawson's reweighting) find fewer control points where the development circles' noise is near
// the tolerance, every kept raw sample still within it, and never more.
// A loop with one corner away from its seam is also fitted as one clamped piece from the seam
// (stroke_fitter.cpp). s02's fourth fast circle closes across a zigzag (x 99, 103, 101, 99 over
// the seam's four samples) and its corner is detected a sample before the seam: at the window's
// resolution of one pixel, the clamped piece from that corner and the periodic curve need 14
// control points; the piece from the seam 8 (OCCT's GeomAPI_PointsToBSpline 10 and FITPACK's
// splprep 17 at the same deviation, scripts/compare_splprep.py at one pixel). The corner stays
// reported.
TEST(FitTolerance, GivenRealLoopClosedAcrossAZigzag_WhenItsCornerIsOffTheSeam_ThenThePieceFromTheSeamIsTaken)
{
    constexpr int kMostControlPoints = 10;  // OCCT's count at the same deviation
    int tried = 0;
    for (const Recording& rec : loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, {"s02"})) {
        if (rec.gesture != "circle" || rec.speed != "fast" || rec.number != 4) continue;
        ++tried;
        FitOptions options;
        options.resolution = 1.0;
        const FitResult r = fitStroke(rec.stroke, options);
        ASSERT_TRUE(r.converged) << r.maxError;
        ASSERT_TRUE(r.curve.isClosed());
        EXPECT_EQ(r.corners.size(), 1u) << "the corner near the seam is reported";
        EXPECT_NE(r.corners.front(), r.conditioned.source.front()) << "the corner is not at the seam";
        EXPECT_LE(r.curve.pointCount() - 3, kMostControlPoints);
        EXPECT_LE(maxDeviation(r.curve, keptSamples(rec.stroke, r)), r.tolerance + kMeasureAgreement);
    }
    EXPECT_EQ(tried, 1) << "s02's fourth fast circle";
}

// Given question marks of the development subjects that OCCT's GeomAPI_PointsToBSpline fitted
// with fewer control points at one pixel (scripts/compare_splprep.py BUILD --mode default --no-real
// --resolution 1 --dev question_mark, session 50), when the minimax trials fit the drawn points
// (fit_minimax.cpp, minimaxTrials), then none takes more than OCCT's count and every kept sample
// is within the tolerance. On the smoothed points alone they took 18, 13 and 13: a curve within
// 0.85 of the smoothed points missed a drawn sample by 1.10.
TEST(FitTolerance,
     GivenRealQuestionMarksAtOnePixel_WhenTheMinimaxTrialsFitTheDrawnPoints_ThenNoMoreControlPointsThanOCCT)
{
    struct Peer {
        const char* subject;
        const char* speed;
        int number;
        int occt;  // OCCT's control points at the same deviation
    };
    const Peer peers[] = {{"s04", "medium", 7, 17}, {"s05", "slow", 6, 12}, {"s06", "slow", 9, 11}};
    int tried = 0;
    for (const Recording& rec : loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, {"s04", "s05", "s06"})) {
        if (rec.gesture != "question_mark") continue;
        for (const Peer& peer : peers) {
            if (rec.subject != peer.subject || rec.speed != peer.speed || rec.number != peer.number) continue;
            ++tried;
            FitOptions options;
            options.resolution = 1.0;
            const FitResult r = fitStroke(rec.stroke, options);
            const std::string name = rec.subject + " " + rec.speed + " " + std::to_string(rec.number);
            ASSERT_TRUE(r.converged) << name << ": " << r.maxError;
            EXPECT_LE(r.curve.pointCount(), peer.occt) << name;
            EXPECT_LE(maxDeviation(r.curve, keptSamples(rec.stroke, r)), r.tolerance + kMeasureAgreement) << name;
        }
    }
    EXPECT_EQ(tried, 3);
}

// Given the development pigtails whose last or first few samples hook into a corner (s02 fast 2 at
// one pixel: OCCT 11 control points, ours 12 with the hook's corner kept; s02 slow 8 and s06 fast 2
// at the default tolerance: 15 and 17), when the reading without the end corner is fitted too
// (FitOptions::endHookReading), then the counts drop (10, 13, 15 measured), every kept sample is within the
// tolerance, the corner is still reported, and without that reading the counts are as before.
// (Session 52 measured 13, 19, 19 with the corner kept and 10, 15, 15 without it, before the removal
// trials of session 53, kRemovalTrials.)
TEST(FitTolerance,
     GivenRealPigtailsEndingInAHook_WhenTheEndCornerIsLeftOutToo_ThenFewerControlPointsAndTheCornerReported)
{
    struct Case {
        const char* subject;
        const char* speed;
        int number;
        double resolution;  // 0: the default tolerance
        int before;         // control points with the end corner kept
        int most;           // at most this many with the reading without it (OCCT's 11 at one pixel)
    };
    const Case cases[] = {
        {"s02", "fast", 2, 1.0, 12, 11}, {"s02", "slow", 8, 0.0, 15, 14}, {"s06", "fast", 2, 0.0, 17, 16}};
    int tried = 0;
    for (const Recording& rec : loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, {"s02", "s06"})) {
        if (rec.gesture != "pigtail") continue;
        for (const Case& c : cases) {
            if (rec.subject != c.subject || rec.speed != c.speed || rec.number != c.number) continue;
            ++tried;
            FitOptions options;
            options.resolution = c.resolution;
            FitOptions kept = options;
            kept.endHookReading = false;
            const FitResult r = fitStroke(rec.stroke, options);
            const FitResult k = fitStroke(rec.stroke, kept);
            const std::string name = rec.subject + " " + rec.speed + " " + std::to_string(rec.number);
            ASSERT_TRUE(r.converged) << name << ": " << r.maxError;
            EXPECT_EQ(k.curve.pointCount(), c.before) << name;
            EXPECT_LE(r.curve.pointCount(), c.most) << name;
            EXPECT_LE(maxDeviation(r.curve, keptSamples(rec.stroke, r)), r.tolerance + kMeasureAgreement) << name;
            EXPECT_EQ(r.corners, k.corners) << name;
            EXPECT_FALSE(r.corners.empty()) << name;
        }
    }
    EXPECT_EQ(tried, 3);
}

TEST(FitTolerance, GivenRealCircles_WhenMinimaxTrialsFollowTheSearch_ThenNeverMoreControlPointsAndTheToleranceHeld)
{
    // Of the circles' control points, the least saving taken as a gain (measured 3.8 %: 5,176 ->
    // 4,979 over the 150, a closed curve's 3 repeated points counted; 5.2 % in session 44, 5,166 ->
    // 4,898, with a loop's other reading searched and the equidistributed breaks chained; 9.0 % in
    // session 45, 5,157 -> 4,693, with FITPACK's knots tried where the averaged ones miss and the
    // other reading of a loop whose two corners meet across the seam; 12.0 % in session 46,
    // 5,157 -> 4,540, the last descent looking below a near miss; 13.8 %, 5,157 -> 4,443, with the
    // equidistributed trials started from the parameters of the trial before; 12.4 % in session
    // 47, 5,135 -> 4,496, curves that stray between samples refused).
    constexpr double kMinSavedShare = 0.02;
    int strokes = 0, without = 0, with = 0, fewer = 0;
    FitOptions plain;
    plain.minimaxTrials = false;
    compareOnDevelopmentCircles(
        plain, FitOptions{},
        [&](const Recording& rec, const std::string& name, const FitResult& a, const FitResult& b) {
            ++strokes;
            without += a.curve.pointCount();
            with += b.curve.pointCount();
            fewer += b.curve.pointCount() < a.curve.pointCount();
            const auto loop = [&](const char* subject, const char* speed, int number) {
                return rec.subject == subject && rec.speed == speed && rec.number == number;
            };
            const int count = b.curve.pointCount() - (b.curve.isClosed() ? 3 : 0);
            // The most control points each of these circles may take, and what took it there.
            struct Anchor {
                const char* subject;
                const char* speed;
                int number;
                int most;
            };
            static constexpr Anchor kAnchors[] = {
                // A loop's other reading searched with its minimax trials too (session 44; session
                // 43: 18 and 16, the fewer peer 13 and 14); s02 fast 5 9 since session 46's look
                // below (11 before).
                {"s02", "fast", 5, 9},
                {"s02", "medium", 10, 12},
                // FITPACK's knots tried where a count's averaged knots miss (session 45; before:
                // 24, 53 and 42; the fewer peer at our new deviation: 20, 53 and 49).
                {"s02", "medium", 9, 16},
                {"s04", "medium", 7, 40},
                // 30 in sessions 45-46, a curve that strayed 5.2 allowances from the stroke between
                // two samples (FitResult::stray, session 47).
                {"s04", "slow", 2, 35},
                // Two corners meeting across the seam, where the hand closed the loop: its other
                // reading, one clamped piece, is fitted too (session 45; 31 before, the fewer peer
                // 24). Its corners stay reported, below.
                {"s02", "slow", 1, 17},
                // Session 46: the last descent looks below a count that missed by little (before:
                // 36, 35 and 23; with it 31, 32 and 20), and the equidistributed trials start from
                // the parameters of the trial before (29 and 18; s06 medium 5 36 -> 35 -> 34). The
                // fewer peer at our new deviation: 32, 30, 21 and 35.
                {"s03", "medium", 7, 31},
                {"s03", "medium", 10, 29},
                {"s05", "fast", 8, 18},
                // 36 since session 47: its 34 came by way of counts whose curves strayed between
                // samples (FitResult::stray), now refused.
                {"s06", "medium", 5, 36},
                // Session 50: a loop with one corner off its seam is fitted from the seam too
                // (48 before; FITPACK's splprep 46 at the new deviation).
                {"s06", "medium", 9, 41},
            };
            for (const Anchor& anchor : kAnchors) {
                if (loop(anchor.subject, anchor.speed, anchor.number)) {
                    EXPECT_LE(count, anchor.most) << name;
                }
            }
            if (loop("s02", "slow", 1)) {
                EXPECT_EQ(b.corners.size(), 2u) << name << ": the corners are reported";
            }
            if (loop("s06", "fast", 9)) {
                // 49 samples at a tolerance of 0.73 pixel: 24 control points by least squares,
                // 14 with the minimax trials (FITPACK's splprep 21, OCCT 28 at the least
                // squares' deviation). 22 by least squares since session 50, the loop's one
                // clamped piece from its seam tried too (stroke_fitter.cpp).
                EXPECT_GE(a.curve.pointCount() - 3, 22) << "least squares";
                EXPECT_LE(count, 15) << "minimax trials";
            }
        });
    std::printf("%d circles: %d control points by least squares, %d with minimax trials (%d fewer)\n", strokes, without,
                with, fewer);
    EXPECT_EQ(strokes, 150);
    EXPECT_LE(static_cast<double>(with), (1.0 - kMinSavedShare) * static_cast<double>(without));
}

// The two development drawings that still needed more control points than FITPACK's splprep at the
// same measured deviation after session 53 (scripts/compare_splprep.py BUILD --mode default --no-real
// --dev G): s04's fifth slow circle (121 samples at a tolerance of 0.55: ours 56, splprep 55), whose
// trials below 56 all held every sample but strayed between two, and s06's first fast question mark
// (ours 24, splprep 23), whose removal trials from the averaged trial of the search's count missed.
// With the second seed from the search's own breaks (ReadingFit::seedAbove) and the last descent's
// straying trials made again with a firmer fairing term (ReadingFit::firmDescent), each takes fewer
// than splprep did (49 and 19 measured, session 54), with every kept sample within the tolerance
// and the curve near the stroke between them.
TEST(FitTolerance, GivenRealStrokesShortOfSplprep_WhenTheSearchSeedsAndFirmerFairingAreTried_ThenNoMoreThanSplprep)
{
    struct Peer {
        const char* gesture;
        const char* subject;
        const char* speed;
        int number;
        int splprep;  // splprep's control points at our deviation, session 53
    };
    const Peer peers[] = {{"circle", "s04", "slow", 5, 55}, {"question_mark", "s06", "fast", 1, 23}};
    int tried = 0;
    for (const Recording& rec : loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, {"s04", "s06"})) {
        for (const Peer& peer : peers) {
            if (rec.gesture != peer.gesture || rec.subject != peer.subject || rec.speed != peer.speed ||
                rec.number != peer.number)
                continue;
            ++tried;
            const FitResult r = fitStroke(rec.stroke);
            const std::string name =
                rec.gesture + " " + rec.subject + " " + rec.speed + " " + std::to_string(rec.number);
            ASSERT_TRUE(r.converged) << name << ": " << r.maxError;
            const int count = r.curve.pointCount() - (r.curve.isClosed() ? 3 : 0);
            EXPECT_LE(count, peer.splprep) << name;
            EXPECT_LE(maxDeviation(r.curve, keptSamples(rec.stroke, r)), r.tolerance + kMeasureAgreement) << name;
            EXPECT_LE(r.stray.excess, 1.0) << name << ": the curve stays near the stroke between samples";
        }
    }
    EXPECT_EQ(tried, 2);
}
}  // namespace
}  // namespace sculptline::stroketest
