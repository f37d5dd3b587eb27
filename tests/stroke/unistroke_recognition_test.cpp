// Given real pen strokes (the $1 unistroke logs: 10 people, 16 gestures, 3 speeds; see
// tests/data/unistrokes/README.md), when fitted and recognized as the window does, then the classes a
// designer reads are recognized, on the subjects the recognizer was tuned on and on held-out ones,
// and learning from a person's first corrections raises that person's accuracy.
#include "unistroke_eval.h"

#include <gtest/gtest.h>

namespace sculptline::stroketest {
namespace {

// Floors a little under the accuracies measured when the recognizer was tuned (README, "Recognition
// on real pen strokes"): development s02-s06 95.9 % overall, every gesture >= 86.0 %; held-out
// s07-s11 89.8 % overall. They guard against regressions; the held-out goal (95 %) is not met yet.
constexpr double kDevOverall = 0.95;
constexpr double kDevPerGesture = 0.85;
constexpr double kHeldOutOverall = 0.89;
// Held-out, learning from each person's first three repetitions: 89.9 % -> 94.0 % measured.
constexpr double kMinAdaptationGain = 0.03;

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

TEST(UnistrokeRecognition, GivenHeldOutSubjects_WhenRecognized_ThenOverallAboveFloor)
{
    const auto recs = loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, heldOutSubjects());
    ASSERT_EQ(recs.size(), 2400u);
    const Confusion c = evaluate(recs);
    EXPECT_GE(c.accuracy(), kHeldOutOverall) << c.table();
    // Every stroke was fitted: none in the failure column.
    for (const auto& [gesture, row] : c.rows) EXPECT_EQ(row[kFailed], 0) << gesture;
}

TEST(UnistrokeRecognition, GivenHeldOutPeople_WhenTheModelLearnsTheirFirstCorrections_ThenTheirAccuracyRises)
{
    // Arrange
    const auto recs = loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, heldOutSubjects());
    // Act
    const auto results = adaptPerSubject(recs, 3);
    // Assert
    int tested = 0, before = 0, after = 0;
    for (const auto& r : results) {
        EXPECT_GE(r.correctAfter, r.correctBefore) << r.subject << ": adapting made this person's recognition worse";
        tested += r.tested;
        before += r.correctBefore;
        after += r.correctAfter;
    }
    ASSERT_GT(tested, 0);
    EXPECT_GE(double(after - before) / tested, kMinAdaptationGain);
}

}  // namespace
}  // namespace sculptline::stroketest
