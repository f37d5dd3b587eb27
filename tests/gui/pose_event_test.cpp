// Pose events in a recorded session (../shared/interfaces.md, "6-DOF input"): read into the
// device, position, orientation and buttons; a wrong field is refused with its name, never guessed.
#include "ui/replay_session.h"

#include "solvers/io/geometry_json.h"

#include <gtest/gtest.h>

#include <string>

namespace sculptline::ui {
namespace {

std::string session(const std::string& event) { return R"({"events": [)" + event + "]}"; }

std::string errorOf(const std::string& event)
{
    try {
        parseReplaySession(session(event));
    } catch (const solvers::io::InputError& e) {
        return e.what();
    }
    return "";
}

TEST(PoseEvent, GivenPointerPoseWithTrigger_WhenParsed_ThenDevicePositionOrientationAndButtons)
{
    const ReplaySession s = parseReplaySession(session(
        R"({"type": "pose", "device": "pointer", "position": [1.5, -2, 30], "orientation": [0, 0, 0.7071067811865476, 0.7071067811865476], "buttons": ["trigger"], "t": 12})"));
    ASSERT_EQ(s.events.size(), 1u);
    const ReplayEvent& e = s.events[0];
    EXPECT_EQ(e.type, ReplayEvent::Type::Pose);
    EXPECT_EQ(e.t, 12.0);
    EXPECT_EQ(e.pose.device, PoseEvent::Device::Pointer);
    EXPECT_EQ(e.pose.position, Eigen::Vector3d(1.5, -2, 30));
    EXPECT_TRUE(e.pose.trigger);
    EXPECT_FALSE(e.pose.grip);
    // [x, y, z, w]: a quarter turn about z takes x to y.
    EXPECT_LT((e.pose.orientation * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).norm(), 1e-15);
}

TEST(PoseEvent, GivenPlaneAndViewPosesWithoutOrientationOrButtons_WhenParsed_ThenIdentityAndNothingHeld)
{
    const ReplaySession s = parseReplaySession(session(R"({"type": "pose", "device": "plane", "position": [0, 0, 0], "buttons": ["grip"]},
                                                          {"type": "pose", "device": "view", "position": [1, 2, 3]})"));
    ASSERT_EQ(s.events.size(), 2u);
    EXPECT_EQ(s.events[0].pose.device, PoseEvent::Device::Plane);
    EXPECT_TRUE(s.events[0].pose.grip);
    EXPECT_EQ(s.events[1].pose.device, PoseEvent::Device::View);
    EXPECT_FALSE(s.events[1].pose.grip || s.events[1].pose.trigger);
    EXPECT_EQ(s.events[1].pose.orientation.coeffs(), Eigen::Quaterniond::Identity().coeffs());
}

TEST(PoseEvent, GivenWrongFields_WhenParsed_ThenTheFieldIsNamed)
{
    EXPECT_NE(errorOf(R"({"type": "pose", "device": "glove", "position": [0, 0, 0]})").find("events[0].device"), std::string::npos);
    EXPECT_NE(errorOf(R"({"type": "pose", "device": "pointer"})").find("position"), std::string::npos);
    EXPECT_NE(errorOf(R"({"type": "pose", "device": "pointer", "position": [0, 0, 0], "orientation": [0, 0, 0, 2]})").find("events[0].orientation"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"type": "pose", "device": "pointer", "position": [0, 0, 0], "orientation": [0, 0, 1]})").find("events[0].orientation"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"type": "pose", "device": "pointer", "position": [0, 0, 0], "buttons": ["menu"]})").find("events[0].buttons"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"type": "pose", "device": "pointer", "position": [0, "x", 0]})").find("events[0].position"), std::string::npos);
}

// A pen's pressure on a press, move or release ("pressure", 0..1): kept as recorded; none for a
// mouse; outside 0..1 or not a number, refused with the field's name.
TEST(ReplayPressure, GivenPenEventsWithPressure_WhenParsed_ThenKeptAndBadValuesNamed)
{
    const ReplaySession s = parseReplaySession(session(R"({"type": "press", "x": 10, "y": 20, "pressure": 0.25},
                                                          {"type": "move", "x": 11, "y": 20, "pressure": 1},
                                                          {"type": "release", "x": 11, "y": 20})"));
    ASSERT_EQ(s.events.size(), 3u);
    ASSERT_TRUE(s.events[0].pressure.has_value());
    EXPECT_EQ(*s.events[0].pressure, 0.25);
    ASSERT_TRUE(s.events[1].pressure.has_value());
    EXPECT_EQ(*s.events[1].pressure, 1.0);
    EXPECT_FALSE(s.events[2].pressure.has_value());
    EXPECT_NE(errorOf(R"({"type": "move", "x": 1, "y": 2, "pressure": 1.5})").find("events[0].pressure"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"type": "move", "x": 1, "y": 2, "pressure": -0.1})").find("events[0].pressure"),
              std::string::npos);
    EXPECT_NE(errorOf(R"({"type": "move", "x": 1, "y": 2, "pressure": "hard"})").find("events[0].pressure"),
              std::string::npos);
}

TEST(PoseEvent, GivenNearlyUnitQuaternion_WhenParsed_ThenNormalized)
{
    // Within kQuaternionNormSlack of unit length: a recording's rounding, normalized.
    const ReplaySession s = parseReplaySession(session(R"({"type": "pose", "device": "view", "position": [0, 0, 0], "orientation": [0, 0, 0, 1.0005]})"));
    EXPECT_NEAR(s.events[0].pose.orientation.norm(), 1.0, 1e-15);
}

}  // namespace
}  // namespace sculptline::ui
