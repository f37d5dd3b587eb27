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

TEST(UserModelHabits, GivenAConfirmedStroke_WhenLearned_ThenItIsRememberedWithItsClass)
{
    const auto recs = loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, {"s04"});
    const sk::StrokeRecognition star = sk::recognizeStroke(find(recs, "star", "slow", 1).stroke);
    sk::UserModel model = sk::UserModel::predefined();
    model.learnShape(star.recognition, ShapeKind::Diamond);  // not a candidate of a star: ignored
    EXPECT_TRUE(model.habits().empty());
    model.learnShape(star.recognition, star.recognition.kind);
    ASSERT_EQ(model.habits().size(), 1u);
    EXPECT_EQ(model.habits()[0].kind, star.recognition.kind);
}

// s03's square brackets lie near their curly braces. A corrected brace alone takes brackets the
// recognizer read right (unistroke-report --adapt dev lost 26 of them before confirmations were
// learned); the person's own first brackets, confirmed, keep the later ones theirs.
TEST(UserModelHabits, GivenACorrectedBraceAndConfirmedBrackets_WhenLaterBracketsAreRecognized_ThenTheyStayPolylines)
{
    // Arrange
    const auto recs = loadUnistrokes(SCULPTLINE_UNISTROKE_DATA, {"s03"});
    sk::UserModel correctedOnly = sk::UserModel::predefined("s03");
    for (const auto& r : recs) {
        if (r.gesture != "right_curly_brace" || r.number != 1) continue;
        const sk::StrokeRecognition brace = sk::recognizeStroke(r.stroke);
        if (brace.recognition.kind != ShapeKind::Freeform) correctedOnly.learnShape(brace.recognition, ShapeKind::Freeform);
    }
    ASSERT_FALSE(correctedOnly.habits().empty());
    sk::UserModel withConfirmations = correctedOnly;
    for (const auto& r : recs) {
        if (r.gesture != "right_sq_bracket" || r.number != 1) continue;
        const sk::StrokeRecognition bracket = sk::recognizeStroke(r.stroke);
        ASSERT_EQ(bracket.recognition.kind, ShapeKind::Polyline) << r.speed;
        withConfirmations.learnShape(bracket.recognition, ShapeKind::Polyline);
    }
    // Act
    int readRight = 0, takenByTheBrace = 0, takenWithConfirmations = 0;
    for (const auto& r : recs) {
        if (r.gesture != "right_sq_bracket" || r.number == 1) continue;
        const sk::StrokeRecognition bracket = sk::recognizeStroke(r.stroke);
        if (bracket.recognition.kind != ShapeKind::Polyline) continue;
        ++readRight;
        sk::Recognition a = bracket.recognition, b = bracket.recognition;
        correctedOnly.applyHabits(a, bracket.fit);
        withConfirmations.applyHabits(b, bracket.fit);
        takenByTheBrace += a.kind != ShapeKind::Polyline;
        takenWithConfirmations += b.kind != ShapeKind::Polyline;
    }
    // Assert
    EXPECT_GT(readRight, 20);
    EXPECT_GT(takenByTheBrace, 5);  // the harm the confirmations undo is there
    EXPECT_EQ(takenWithConfirmations, 0);
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
