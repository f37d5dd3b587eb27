// The tuned constants of one reading of a stroke (ReadingFit, reading_fit.h) that fitStroke does
// not share (those are in fit_reading.h), each with what it was measured against. Included by
// reading_fit.h only.
#pragma once

namespace sculptline::solvers::stroke::detail {

// The constants of one reading (fitReading) that fitStroke does not share (fit_reading.h).
// The inner tolerance is cut a little more than the excess (the error does not fall exactly in
// proportion), and never below a tenth of the tolerance (a sample out of reach would otherwise
// drive it to interpolation).
constexpr double kRefineMargin = 0.95;
constexpr double kMinInnerShare = 0.1;
// Where the error-driven fit holds every sample but strays between two (measureStray), it is
// repeated with the fairing term's weight (SplineFitOptions::fairing, 1e-6) raised kStrayFairingStep
// times, at most kStrayFairingSteps times. The minimax trials' last descent does the same with the
// trials of a count refused for straying (ReadingFit::firmDescent, session 54: on the development
// strokes 41,553 -> 41,394 control points, circle-s04s5 56 -> 49; in every descent instead of the
// last, 41,076, but 22 strokes took more, by up to 8: a count taken so changes what follows).
constexpr double kStrayFairingStep = 100.0;
constexpr int kStrayFairingSteps = 3;
// Hoschek corrections per trial of the fewer-control-points search. Measured on the benchmark
// strokes (s-curve, flourish): 3 corrections left the error-driven count (the averaged knots'
// chord parameters are off by too much); 8 brought the s-curve from 11 to 7 and the 1,000-sample
// flourish from 28 to 18.
constexpr int kAveragedCorrections = 8;
// Rows added to a count whose raw samples miss the tolerance: the conditioned points of the raw
// samples beyond 0.75 of it (those near the limit too, or the re-solved curve pushes them past
// it), in at most 4 rounds. At 0.9 flourish-200 needed 2 rounds (a round added 3-4 rows) to reach
// 21 control points; at 0.75 one round of 5 rows reached them (BM_StrokeFit/200 194 -> 147 us).
// (That was with measureSamples' polyline bounds, up to a quarter tolerance above the distance.
// With each sample's own distance, 0.6-0.68 give flourish-200 one round again, BM_StrokeFit/200
// 3.14 against 4.07 M instructions, but more rows at once can make the count fail on its own
// rows: under clang the noisy ellipse of FitTolerance.GivenLoops_... went 5 -> 13 control points,
// and scripts/compare_splprep.py's results moved either way from one share to the next.)
constexpr double kRowShare = 0.75;
constexpr int kRowRounds = 4;
// Rows per control point of a search on evenly spread rows (see `search` below): with fewer, a
// count near the dynamic threshold's row count interpolates its rows and swings between them
// (a sparse real pigtail: 10 rows for 47 samples, 9 control points fit the rows within 0.11
// and miss a raw sample by 16.7). Two, the least that leaves each control point over-determined;
// three gave no more on scripts/compare_splprep.py (minimize mode 25 of 28 strokes against 27).
constexpr int kDenseRowsPerPoint = 2;
// Lawson rounds (SplineFitOptions::minimaxRounds) of the minimax trials below. On the 2,400
// development strokes (unistroke-report --fit-dev; the least squares alone 57,342 control points),
// measured with 8 corrections before the rounds and the second search of the bisection's note: 6 rounds 57,172, 10
// rounds 57,148, 20 rounds 57,124 (for a tenth more time than 10).
constexpr int kMinimaxRounds = 10;
// Hoschek corrections before a minimax trial's rounds (each round corrects the parameters too).
// Development strokes, measured with the second search of the bisection's note: 57,154 control
// points with the search's 8, 57,107 with 3, 57,149 with 2 and 57,147 with 1; 411 against 438 M
// instructions with 8 (BM_StrokeRecorded/0, callgrind).
constexpr int kMinimaxCorrections = 3;
// Rounds run to the end on the count a minimax trial took (see the descent below). On the 150
// development circles against the peers (compare_splprep.py --dev circle): 145 -> 146 of 163
// strokes (with the 13 synthesized) meet the fewer peer, for 3 % more instructions.
constexpr int kPolishRounds = 20;
// Trials with the breaks equidistributed (SplineFitOptions::equidistributions) per count of the
// last descent, where the count leaves fewer than kNoiseRowsPerPoint points per control point (4 until session 50). On
// the development strokes: 57,037 control points without, 56,852 with 3 and 56,784 with 5, for 398 / 410 / 418 M
// instructions (BM_StrokeRecorded/0, callgrind); on every stroke, 3 trials: 56,834 for 501 M. The
// 150 development circles against the peers (compare_splprep.py --dev circle): 136 -> 142 meet
// the fewer peer with 3.
constexpr int kEquidistributions = 3;
// The last descent (equidistributed breaks) does not stop at the first count that misses where it
// missed by little (its samples' or its raw samples' largest distance within kLookMissShare of the
// tolerance): up to kLookBelow counts below it are tried, and from one taken the descent goes on.
// The counts do not fall monotonically (each count's knots, averaged, inserted or equidistributed,
// are its own), and a count or two below one that just missed often fits. On the development
// strokes (unistroke-report --fit-dev): 56,459 control points without, 56,203 looking 2 below
// and 56,156 looking 3 (circles 4,405 -> 4,252), for 16 / 23 % more fit time; 56,081 looking 3
// below every miss (+34 %), 56,254 with a share of 1.05 (+13 %). compare_splprep.py --dev circle:
// 145 -> 147 of the 150 development circles meet the fewer peer (ours 4,541 -> 4,388 in all).
constexpr int kLookBelow = 3;
constexpr double kLookMissShare = 1.1;
// Removal trials (SplineFitOptions::removalTrials) per count of the minimax trials: the breaks of
// the count above, taken (or, at the count the trials start from, its trial on their rows, and
// where that seed's trials are refused, its trial on the breaks of the search's curve: session 54,
// ReadingFit::seedAbove, 42,480 -> 41,553 control points on the development strokes, 472 strokes
// fewer by 999, 38 more by 72; in the last descent only, 42,256 and none more), less one,
// cheapest first (session 53). Knot removal was the third suggestion: each taken
// curve hands its breaks down, where before every count started afresh from averaged knots. On the
// 2,400 development strokes (unistroke-report --fit-dev; instructions of fitStroke by callgrind
// --toggle-collect='*fitStroke*', 36.17 G without): 45,934 control points without, 43,139 with 4
// (41.57 G), 42,480 with 8 (44.53 G), 1,484 strokes fewer by 3,456, one more by 2 (question-s06s10:
// a count taken earlier on the drawn points leaves the smoothed points' descent a count that
// misses by more than kLookMissShare). Without the removal trials first where the count above has
// a seed: 42,563 for 47.50 G. Ranked by a least squares without each break: 42,943 with 2 trials
// (44.06 G), 42,599 with 4 (46.97 G). (Those figures with a loop's seam break among the ranked.)
// Removal trials before every minimax trial, the minimax trial skipped where they come within
// (the first version): 42,520 but 37 strokes more, by up to 10.
constexpr int kRemovalTrials = 8;
// The bisection's note (minimaxTrials). Until session 50 the minimax trials bisected below the
// count taken, tried FITPACK's knots and made the equidistributed descent only where the count
// left fewer than 4 conditioned points per control point (kNoiseRowsPerPoint; there the fit follows
// the digitizer's noise: a circle of 39 samples drawn at a medium speed, 20 control points for a
// tolerance of 0.62 pixel) and on a piece read by descent. Measured then on the development strokes:
// 57,070 control points with 3, 57,037 with 4, 57,029 with 6 or every stroke, for 391 / 399 / 425 /
// 447 M instructions (BM_StrokeRecorded/0, callgrind; 358 M without the minimax trials). (Searching
// again with the climbs and rows of the least squares' search instead of the bisection on every
// point: 57,107 control points for 421 M.) Session 50 measured it again at the window's resolution
// of one pixel, where the default tolerance leaves 5-8 samples per control point and the rule
// skipped them: on every stroke, BM_StrokeRecorded/0 (240 development strokes at one pixel) 14.38
// -> 14.20 control points a stroke, for a mean fit of 363-385 -> 432-454 us (p50 280-295 -> 287-306
// us, p99 1.43-1.48 -> 2.13-2.36 ms); the bisection alone 14.33 (+6 %), the equidistributed
// descent alone 14.25 (+9 %). compare_splprep.py --resolution 1 --dev G, strokes meeting the fewer
// peer (of 163) and our total: circle 161 -> 163 (2,059 -> 1,897), question mark 154 -> 160
// (1,865 -> 1,727), pigtail 161 -> 161 (2,317 -> 2,176), right curly brace 162 -> 162 (2,414 ->
// 2,405). At the default tolerance (unistroke-report --fit-dev): 50,306 -> 50,233 control points
// for 2.2 % more instructions in fitStroke (28.08 -> 28.72 G). But on a long, densely sampled
// stroke every count it bisects is a minimax trial on all its points: the 1,000-sample flourish of
// BM_StrokeFitWarm (18 control points) 348 -> 1,260 us warm. So the rule stays, at 8 points per
// control point instead of 4: the same control points on the development strokes at the default
// tolerance (50,233) and at one pixel (BM_StrokeRecorded/0 14.20), the flourish not bisected.
constexpr int kNoiseRowsPerPoint = 8;
// The minimax trials fit the drawn points first where the count leaves fewer than this many
// conditioned points per control point (minimaxTrials' note).
constexpr int kDrawnRowsPerPoint = 16;

}  // namespace sculptline::solvers::stroke::detail
