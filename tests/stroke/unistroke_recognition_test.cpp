// Given real pen strokes (the $1 unistroke logs: 10 people, 16 gestures, 3 speeds; see
// tests/data/unistrokes/README.md), when fitted and recognized as the window does, then the classes a
// designer reads are recognized, on the subjects the recognizer was tuned on and on held-out ones,
// and learning from a person's first corrections raises that person's accuracy.
#include "unistroke_eval.h"

#include "solvers/stroke/stroke_fitter.h"

#include <gtest/gtest.h>

#include <cmath>

#include <ostream>
#include <string>

namespace sculptline::stroketest {
namespace {

// Floors a little under the accuracies measured when the recognizer was tuned (README, "Recognition
// on real pen strokes"): development s02-s06 98.2 % overall, every gesture >= 90.7 %; held-out
// s07-s11 95.6 % overall (2,295 of 2,400 since session 41's relocated vertices; 2,290 since session
// 38). They guard against regressions. The held-out floors are the goal itself: 95 % overall (2,280
// strokes) and every gesture at least 90 %, met since session 41 (the lowest: checks 90.7 %,
// delete marks 91.3 %, rectangles 91.3 %).
constexpr double kDevOverall = 0.97;
constexpr double kDevPerGesture = 0.90;
constexpr double kHeldOutOverall = 0.95;
constexpr double kHeldOutPerGesture = 0.90;
// Held-out, learning from each person's first three repetitions (unistroke-report --adapt held-out,
// the strokes after them): 89.9 % -> 94.0 % measured at first, 94.5 % -> 98.5 % now that
// confirmations are learned too (96.5 % before). What the person sees is the accuracy after
// learning, and that learning helps at all; development, after one and three: +1.2 and +1.7 points.
constexpr double kMinAdaptedAccuracy = 0.95;
constexpr double kMinAdaptationGain = 0.01;
// A learned stroke takes the strokes nearest to it, so a person can lose a stroke or two that the
// recognizer alone read right: on the development subjects, learning their first one to three
// repetitions (confirmed or corrected), at most 0.5 % of a person's remaining strokes
// (unistroke-report --adapt dev: s03 after one, 2 of 432). A person losing more than 1 % would be
// habits doing harm.
constexpr double kMaxPersonalLoss = 0.01;

void expectAdaptationHelps(const std::vector<AdaptationResult>& results)
{
    int tested = 0, before = 0, after = 0;
    for (const auto& r : results) {
        ASSERT_GT(r.tested, 0) << r.subject;
        EXPECT_GE(double(r.correctAfter - r.correctBefore) / r.tested, -kMaxPersonalLoss)
            << r.subject << ": adapting lost " << r.correctBefore - r.correctAfter << " of " << r.tested << " strokes";
        tested += r.tested;
        before += r.correctBefore;
        after += r.correctAfter;
    }
    ASSERT_GT(tested, 0);
    EXPECT_GE(double(after - before) / tested, kMinAdaptationGain);
    EXPECT_GE(double(after) / tested, kMinAdaptedAccuracy);
}

TEST(UnistrokeRecognition, GivenDevelopmentSubjects_WhenRecognized_ThenOverallAndEveryGestureAboveFloor)
{
    // Arrange
    const auto recs = loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, devSubjects());
    ASSERT_EQ(recs.size(), 2400u);
    // Act
    const Confusion c = evaluate(recs);
    // Assert
    EXPECT_GE(c.accuracy(), kDevOverall) << c.table();
    for (const auto& [gesture, row] : c.rows) EXPECT_GE(c.accuracy(gesture), kDevPerGesture) << gesture;
}

TEST(UnistrokeRecognition, GivenHeldOutSubjects_WhenRecognized_ThenOverallAndEveryGestureAboveFloor)
{
    const auto recs = loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, heldOutSubjects());
    ASSERT_EQ(recs.size(), 2400u);
    const Confusion c = evaluate(recs);
    EXPECT_GE(c.accuracy(), kHeldOutOverall) << c.table();
    for (const auto& [gesture, row] : c.rows) EXPECT_GE(c.accuracy(gesture), kHeldOutPerGesture) << gesture;
    // Every stroke was fitted: none in the failure column.
    for (const auto& [gesture, row] : c.rows) EXPECT_EQ(row[kFailed], 0) << gesture;
}

// A second source of real strokes, never tuned on: 338 Quick, Draw! drawings made in one stroke by
// players with a mouse or a finger (tests/data/quickdraw/README.md). Measured once when the set was
// added (unistroke-report --quickdraw, session 40): 81.1 % overall; circles 100 %, lines 96.1 %,
// stars 95.7 %, triangles 92.5 %, squares 85.3 %, zigzags 76.2 %, and hexagons 37.5 % and octagons
// 16.1 %, most read as ellipses or circles (the recognizer has no class for more than four sides).
// The floors are a little under those figures: they guard against regressions.
constexpr double kQuickDrawOverall = 0.78;
constexpr double kQuickDrawBasicShapes = 0.90;  // circle, line, star, triangle

TEST(UnistrokeRecognition, GivenQuickDrawDrawings_WhenRecognized_ThenAboveFloor)
{
    // Arrange
    const auto recs = loadQuickDraw();
    ASSERT_EQ(recs.size(), 338u);
    // Act
    const Confusion c = evaluate(recs);
    // Assert
    EXPECT_GE(c.accuracy(), kQuickDrawOverall) << c.table();
    for (const char* g : {"circle", "line", "star", "triangle"})
        EXPECT_GE(c.accuracy(g), kQuickDrawBasicShapes) << g << '\n' << c.table();
    for (const auto& [gesture, row] : c.rows) EXPECT_EQ(row[kFailed], 0) << gesture;
}

// classFitOptions (the recognitions of these tests) leaves the minimax trials out, which is exact
// only while the class never depends on them: the 750 development circles, triangles, rectangles,
// stars and x's (loops and corners) recognized with the default fit and with classFitOptions.
TEST(UnistrokeRecognition, GivenDevelopmentStrokes_WhenFittedWithOrWithoutMinimaxTrials_ThenTheSameClass)
{
    const auto recs = loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, devSubjects());
    int compared = 0, fewer = 0;
    for (const Recording& r : recs) {
        if (r.gesture != "circle" && r.gesture != "triangle" && r.gesture != "rectangle" && r.gesture != "star" &&
            r.gesture != "x")
            continue;
        const auto product = solvers::stroke::recognizeStroke(r.stroke);
        const auto measured = solvers::stroke::recognizeStroke(r.stroke, classFitOptions());
        EXPECT_EQ(product.recognition.kind, measured.recognition.kind)
            << r.subject << " " << r.gesture << " " << r.speed << " " << r.number;
        ++compared;
        fewer += product.fit.curve.pointCount() < measured.fit.curve.pointCount();
    }
    EXPECT_EQ(compared, 750);
    EXPECT_GT(fewer, 0) << "the minimax trials changed no curve: the comparison shows nothing";
}

// A window of another size passes the same stroke in other plane units per pixel: scaled, and with
// its samples (pointer events a pixel or more apart) denser or sparser in plane units. Measured on
// the development strokes (unistroke-report --invariance dev): scaled alone, 100.0 % keep their class
// (every threshold is relative to the stroke's extent); resampled at 0.5x / 2x the spacing, 98.6 % /
// 97.5-97.6 %, about the 98.9 % that merely resampling at the same spacing keeps: the strokes that
// change sit on a decision boundary (polyline or freeform, circle or ellipse) that moving the samples
// along the stroke crosses, with no trend in the accuracy (97.5 % before, 97.2-97.7 % after).
constexpr double kScaledSameClass = 0.999;
constexpr double kResampledSameClass = 0.965;

// One test per window-size variant: each recognizes the 2,400 development strokes twice, which
// under the sanitizer build takes over a minute, so four in one test would pass ctest's time limit.
struct WindowSizeVariant {
    const char* name;
    double scale, spacing, floor;
};
// The variant's name in test names and messages (instead of gtest's bytes of the struct).
void PrintTo(const WindowSizeVariant& v, std::ostream* os) { *os << v.name; }

class UnistrokeWindowSize : public ::testing::TestWithParam<WindowSizeVariant> {};

TEST_P(UnistrokeWindowSize, GivenDevelopmentStrokes_WhenScaledOrResampledAsByAnotherWindowSize_ThenTheSameClass)
{
    // Arrange
    const WindowSizeVariant v = GetParam();
    const auto recs = loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, devSubjects());
    // Act
    const InvarianceResult r = measureInvariance(recs, v.scale, v.spacing);
    // Assert
    ASSERT_EQ(r.total, 2400);
    EXPECT_GE(double(r.same) / r.total, v.floor) << "scale " << v.scale << ", sample spacing x" << v.spacing;
}

INSTANTIATE_TEST_SUITE_P(UnistrokeRecognition, UnistrokeWindowSize,
                         ::testing::Values(WindowSizeVariant{"TenthSize", 0.1, 1.0, kScaledSameClass},
                                           WindowSizeVariant{"TenTimesSize", 10.0, 1.0, kScaledSameClass},
                                           WindowSizeVariant{"TenTimesSizeTwiceTheSamples", 10.0, 0.5, kResampledSameClass},
                                           WindowSizeVariant{"TenthSizeHalfTheSamples", 0.1, 2.0, kResampledSameClass}),
                         [](const ::testing::TestParamInfo<WindowSizeVariant>& info) { return std::string(info.param.name); });

TEST(UnistrokeRecognition, GivenAStroke_WhenTransformed_ThenScaledAndResampledAlongItWithTimes)
{
    // Arrange: an L of two 10-unit legs sampled every 2 units, one sample per 10 ms.
    solvers::stroke::Stroke s;
    for (int i = 0; i <= 5; ++i) s.points.emplace_back(2.0 * i, 0.0, 0.0);
    for (int i = 1; i <= 5; ++i) s.points.emplace_back(10.0, 2.0 * i, 0.0);
    for (size_t i = 0; i < s.points.size(); ++i) s.times.push_back(0.01 * double(i));
    // Act
    const auto denser = transformStroke(s, 3.0, 0.5);
    // Assert: every 1 unit (3 after scaling) along the path, times interpolated, ends kept.
    constexpr double kTol = 1e-12;
    ASSERT_EQ(denser.points.size(), 21u);
    EXPECT_NEAR((denser.points[5] - Eigen::Vector3d(15.0, 0.0, 0.0)).norm(), 0.0, kTol);
    EXPECT_NEAR((denser.points[15] - Eigen::Vector3d(30.0, 15.0, 0.0)).norm(), 0.0, kTol);
    EXPECT_NEAR(denser.times[15], 0.075, kTol);
    EXPECT_NEAR((denser.points.back() - Eigen::Vector3d(30.0, 30.0, 0.0)).norm(), 0.0, kTol);
    EXPECT_EQ(denser.times.back(), s.times.back());
}

// Rectangles a hand drew askew: four development rectangles sheared by 0.3 or tapered by 0.4
// (Perturbation) whose obtuse corner turns 55-60 degrees seen from the corners beside it, under
// minCornerTurn, so that only three vertices were read: a triangle that fits nothing, then an
// ellipse or freeform (unistroke-report --dump-dev rectangle, DUMP_PERTURB). The corner is taken
// because its edge is two straight sides (RecognizeOptions::straightLegs).
TEST(UnistrokeRecognition, GivenSkewedRectanglesWithAnObtuseCorner_WhenRecognized_ThenFourVerticesAndARectangle)
{
    // Arrange
    const auto recs = loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, devSubjects());
    Perturbation sheared, tapered;
    sheared.shear = 0.3;
    tapered.taper = 0.4;
    struct Case {
        const char* subject;
        const char* speed;
        int number;
        const Perturbation* way;
    };
    const Case cases[] = {{"s03", "slow", 1, &sheared},
                          {"s05", "fast", 6, &sheared},
                          {"s06", "fast", 1, &sheared},
                          {"s06", "fast", 1, &tapered}};
    solvers::stroke::RecognizeOptions off;
    off.straightLegs = 0.0;
    int found = 0;
    for (const auto& r : recs) {
        for (const Case& c : cases) {
            if (r.gesture != "rectangle" || r.subject != c.subject || r.speed != c.speed || r.number != c.number)
                continue;
            ++found;
            const auto stroke = perturbStroke(r.stroke, *c.way);
            // Act
            const auto with = solvers::stroke::recognizeStroke(stroke, {}, {});
            const auto without = solvers::stroke::recognizeStroke(stroke, {}, off);
            // Assert
            const std::string name = std::string(c.subject) + " " + c.speed + " " + std::to_string(c.number);
            EXPECT_EQ(with.recognition.geometry.vertices.size(), 4u) << name;
            EXPECT_TRUE(isCorrect("rectangle", with.recognition.kind))
                << name << ": " << solvers::stroke::shapeName(with.recognition.kind);
            EXPECT_EQ(without.recognition.geometry.vertices.size(), 3u) << name << " (the rule off)";
            EXPECT_FALSE(isCorrect("rectangle", without.recognition.kind)) << name << " (the rule off)";
        }
    }
    ASSERT_EQ(found, 4);
}

// Rectangles with corners a hand rounded off, drawn on past the start: the development rectangles
// with corners rounded over 12 % of the length and drawn on 10 % past the start (Perturbation). The
// vertices refineVertices places on a rounded corner lie toward the longer side (the farthest
// samples from a diagonal), the sides fitted between them tilt, and without relocateVertices 54 of
// the 150 were read as ellipses (unistroke-report --dump-dev rectangle with
// DUMP_PERTURB=0,1,0,0.1,1,0,0.12); with it 9 (one round with the polygon's edgeTrim: 19). The
// bounds sit between the two. On one of them, s02 slow 3, the vertices are checked after five
// rounds, against none.
TEST(UnistrokeRecognition, GivenRoundedRectanglesDrawnPastTheStart_WhenRecognized_ThenVerticesWhereTheSidesMeet)
{
    // Arrange
    const auto recs = loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, devSubjects());
    Perturbation way;
    way.roundShare = 0.12;
    way.overshootShare = 0.10;
    solvers::stroke::RecognizeOptions off, converged;
    off.relocateRounds = 0;
    converged.relocateRounds = 5;
    int total = 0, withRight = 0, withoutRight = 0;
    double worstWith = 0.0, worstWithout = 0.0;  // s02 slow 3: farthest vertex from a box corner / extent
    for (const auto& r : recs) {
        if (r.gesture != "rectangle") continue;
        ++total;
        const auto stroke = perturbStroke(r.stroke, way);
        // Act
        const auto with = solvers::stroke::recognizeStroke(stroke, {}, {});
        const auto without = solvers::stroke::recognizeStroke(stroke, {}, off);
        withRight += isCorrect("rectangle", with.recognition.kind);
        withoutRight += isCorrect("rectangle", without.recognition.kind);
        if (r.subject == "s02" && r.speed == "slow" && r.number == 3) {
            // The recognized polygon's vertices against the corners of the samples' bounding box
            // (the rectangle is drawn square to the axes): each near one, with the vertices moved.
            const auto farthest = [](const solvers::stroke::Recognition& rec) {
                const auto& p = rec.geometry.points;
                Eigen::Vector2d lo = p.front(), hi = p.front();
                for (const auto& q : p) {
                    lo = lo.cwiseMin(q);
                    hi = hi.cwiseMax(q);
                }
                double worst = 0.0;
                for (const auto& v : rec.geometry.vertices) {
                    double nearest = 1e300;
                    for (const Eigen::Vector2d& c :
                         {lo, hi, Eigen::Vector2d(lo.x(), hi.y()), Eigen::Vector2d(hi.x(), lo.y())})
                        nearest = std::min(nearest, (v - c).norm());
                    worst = std::max(worst, nearest);
                }
                return worst / rec.geometry.extent;
            };
            const auto moved = solvers::stroke::recognizeStroke(stroke, {}, converged);
            ASSERT_EQ(moved.recognition.geometry.vertices.size(), 4u);
            EXPECT_TRUE(isCorrect("rectangle", moved.recognition.kind))
                << solvers::stroke::shapeName(moved.recognition.kind);
            worstWith = farthest(moved.recognition);
            worstWithout = farthest(without.recognition);
        }
    }
    // Assert
    ASSERT_EQ(total, 150);
    EXPECT_GE(withRight, 125) << "rectangles read as rectangles with the vertices moved";
    EXPECT_LE(withoutRight, 105) << "and without";
    EXPECT_LT(worstWith, 0.1);
    EXPECT_GT(worstWithout, 0.15);
}

TEST(UnistrokeRecognition, GivenAStraightStroke_WhenWavering_ThenMovedAcrossItBySinesOfTheGivenAmplitude)
{
    // Arrange: 101 samples along x over 100 units (extent 100).
    solvers::stroke::Stroke s;
    for (int i = 0; i <= 100; ++i) {
        s.points.emplace_back(double(i), 0.0, 0.0);
        s.times.push_back(0.01 * i);
    }
    Perturbation p;
    p.wobble = 0.02;
    p.wobbleWaves = 5;
    // Act
    const auto w = perturbStroke(s, p);
    // Assert: x unchanged, y = 2 sin(2 pi 5 x / 100) (the normal of a stroke along +x is +y).
    ASSERT_EQ(w.points.size(), s.points.size());
    constexpr double kTol = 1e-9;
    for (size_t i = 0; i < w.points.size(); ++i) {
        EXPECT_NEAR(w.points[i].x(), s.points[i].x(), kTol) << i;
        EXPECT_NEAR(w.points[i].y(), 2.0 * std::sin(2.0 * M_PI * 5.0 * double(i) / 100.0), kTol) << i;
    }
    EXPECT_EQ(w.times, s.times);
}

TEST(UnistrokeRecognition, GivenDevelopmentPeople_WhenTheModelLearnsTheirFirstStrokes_ThenTheirAccuracyRises)
{
    // Three repetitions, as on the held-out people (one more recognition pass of 2,400 strokes
    // costs over half a minute under the sanitizers; after one, unistroke-report --adapt dev).
    const auto recs = loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, devSubjects());
    expectAdaptationHelps(adaptPerSubject(recs, 3));
}

TEST(UnistrokeRecognition, GivenHeldOutPeople_WhenTheModelLearnsTheirFirstCorrections_ThenTheirAccuracyRises)
{
    const auto recs = loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, heldOutSubjects());
    expectAdaptationHelps(adaptPerSubject(recs, 3));
}

}  // namespace
}  // namespace sculptline::stroketest
