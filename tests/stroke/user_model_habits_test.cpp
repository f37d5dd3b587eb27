// Given a person's corrected strokes (real pen data, tests/data/unistrokes), when the user model has
// learned them, then the same person's similar strokes take the corrected class, dissimilar ones keep
// theirs, and the learned shapes survive the model's JSON round trip.
#include "solvers/stroke/stroke_json.h"
#include "solvers/stroke/user_model.h"
#include "unistroke_eval.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace sculptline::stroketest {
namespace {

namespace sk = solvers::stroke;

const Recording& find(const std::vector<Recording>& recs, const std::string& gesture, const std::string& speed, int number)
{
    for (const auto& r : recs)
        if (r.gesture == gesture && r.speed == speed && r.number == number) return r;
    throw std::runtime_error("no recording " + gesture);
}

// s04 draws checks with a curved long stroke: the recognizer reads most of them as freeform
// (unistroke_report --dump-dev check).
TEST(UserModelHabits, GivenACorrectedCheck_WhenTheNextSimilarCheckIsRecognized_ThenItIsAPolyline)
{
    // Arrange
    const auto recs = loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, {"s04"});
    const sk::StrokeRecognition first = sk::recognizeStroke(find(recs, "check", "medium", 8).stroke);
    ASSERT_EQ(first.recognition.kind, ShapeKind::Freeform);
    sk::UserModel model = sk::UserModel::predefined("s04");
    // Act
    model.learnShape(first.recognition, ShapeKind::Polyline);
    sk::StrokeRecognition next = sk::recognizeStroke(find(recs, "check", "medium", 9).stroke);
    ASSERT_EQ(next.recognition.kind, ShapeKind::Freeform);
    model.applyHabits(next.recognition, next.fit);
    sk::StrokeRecognition brace = sk::recognizeStroke(find(recs, "left_curly_brace", "medium", 9).stroke);
    model.applyHabits(brace.recognition, brace.fit);
    // Assert
    ASSERT_EQ(model.habits().size(), 1u);
    EXPECT_EQ(next.recognition.kind, ShapeKind::Polyline);
    EXPECT_EQ(next.recognition.candidates.front().kind, ShapeKind::Polyline);
    EXPECT_EQ(brace.recognition.kind, ShapeKind::Freeform);
}

TEST(UserModelHabits, GivenAConfirmedStroke_WhenLearned_ThenNothingIsRemembered)
{
    const auto recs = loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, {"s04"});
    const sk::StrokeRecognition star = sk::recognizeStroke(find(recs, "star", "slow", 1).stroke);
    sk::UserModel model = sk::UserModel::predefined();
    model.learnShape(star.recognition, star.recognition.kind);
    model.learnShape(star.recognition, ShapeKind::Diamond);  // not a candidate of a star
    EXPECT_TRUE(model.habits().empty());
}

TEST(UserModelHabits, GivenLearnedHabits_WhenWrittenAndReadAsJson_ThenTheSameShapesAndClasses)
{
    // Arrange
    const auto recs = loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, {"s04"});
    const sk::StrokeRecognition check = sk::recognizeStroke(find(recs, "check", "medium", 8).stroke);
    sk::UserModel model = sk::UserModel::predefined("s04");
    model.learnShape(check.recognition, ShapeKind::Polyline);
    // Act
    const sk::UserModel back = sk::userModelFromJson(sk::toJson(model), "user_model");
    // Assert
    ASSERT_EQ(back.habits().size(), 1u);
    EXPECT_EQ(back.habits()[0].kind, ShapeKind::Polyline);
    ASSERT_EQ(back.habits()[0].shape.size(), model.habits()[0].shape.size());
    for (size_t i = 0; i < back.habits()[0].shape.size(); ++i) EXPECT_EQ(back.habits()[0].shape[i], model.habits()[0].shape[i]);
    EXPECT_EQ(back.nodes().size(), model.nodes().size());
}

}  // namespace
}  // namespace sculptline::stroketest
