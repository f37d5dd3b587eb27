// The VR module's pure part (ui/xr_session.h): the stage (OpenXR: metres, y up) to model (z up)
// mapping, controller states to pose events, and the adapter to the replay format's pose event
// (../shared/interfaces.md). No headset and no OpenXR runtime needed.
#include "ui/xr_session.h"

#include <gtest/gtest.h>

namespace {

using sculptline::ui::Hand;
using sculptline::ui::StageToModel;

constexpr double kTolerance = 1e-12;

TEST(StageToModel, StageUpIsModelUpAndTheAxesStayRightHanded)
{
    const Eigen::Matrix3d a = StageToModel::axes();
    EXPECT_TRUE((a * Eigen::Vector3d::UnitY()).isApprox(Eigen::Vector3d::UnitZ()));
    // OpenXR's forward (-z) is the model's +y (away from a viewer at the front)
    EXPECT_TRUE((a * -Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitY()));
    EXPECT_NEAR(a.determinant(), 1.0, kTolerance);
}

TEST(StageToModel, FramingPutsTheModelsCentreWhereTheUserStands)
{
    // Given a 300 mm model centred at (10, 20, 30), to be seen 0.6 m across at chest height ahead
    const Eigen::Vector3d centre(10, 20, 30);
    const Eigen::Vector3d stand(0.0, 1.1, -0.5);
    const StageToModel s = StageToModel::framing(centre, 300.0, 0.6, stand);
    // Then a metre is 500 model units and the stand point is the model's centre
    EXPECT_NEAR(s.unitsPerMetre, 500.0, kTolerance);
    EXPECT_TRUE(s.point(stand).isApprox(centre));
    // And 10 cm up on the stage is 50 units up (z) in the model
    EXPECT_TRUE(s.point(stand + Eigen::Vector3d(0, 0.1, 0)).isApprox(centre + Eigen::Vector3d(0, 0, 50)));
}

TEST(ControllerPose, RightTriggerDrawsLeftGripCarriesThePlane)
{
    const StageToModel stage = StageToModel::framing(Eigen::Vector3d::Zero(), 600.0, 0.6, Eigen::Vector3d(0, 1, 0));
    // Given the right controller half pressed past the threshold, pointing forward
    const auto right = sculptline::ui::controllerPoseEvent(Hand::Right, Eigen::Vector3d(0.1, 1.0, 0.0), Eigen::Quaterniond::Identity(),
                                                           0.9f, 0.1f, 12.5, stage);
    EXPECT_EQ(right.device, "pointer");
    EXPECT_EQ(right.buttons, std::vector<std::string>{"trigger"});
    EXPECT_TRUE(right.position.isApprox(Eigen::Vector3d(100, 0, 0)));
    // Its aim (local -z) points along the model's +y
    EXPECT_TRUE((right.orientation * -Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitY()));
    // Given the left one with its grip held and the trigger just below the threshold
    const auto left = sculptline::ui::controllerPoseEvent(Hand::Left, Eigen::Vector3d(-0.1, 1.0, 0.0), Eigen::Quaterniond::Identity(),
                                                          sculptline::ui::kButtonHeld, 1.0f, 12.5, stage);
    EXPECT_EQ(left.device, "plane");
    EXPECT_EQ(left.buttons, std::vector<std::string>{"grip"});
}

TEST(ControllerPose, ReplayEventHasTheSharedForm)
{
    sculptline::ui::XrPoseEvent e;
    e.device = "pointer";
    e.position = Eigen::Vector3d(1, 2, 3);
    e.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
    e.buttons = {"trigger"};
    e.t = 40.0;
    const nlohmann::json j = sculptline::ui::toReplayEvent(e);
    EXPECT_EQ(j.at("type"), "pose");
    EXPECT_EQ(j.at("device"), "pointer");
    EXPECT_EQ(j.at("position"), nlohmann::json::array({1.0, 2.0, 3.0}));
    // Orientation [x, y, z, w]: a quarter turn about z
    const double h = std::sqrt(0.5);
    EXPECT_NEAR(j.at("orientation")[2].get<double>(), h, kTolerance);
    EXPECT_NEAR(j.at("orientation")[3].get<double>(), h, kTolerance);
    EXPECT_NEAR(j.at("orientation")[0].get<double>(), 0.0, kTolerance);
    EXPECT_EQ(j.at("buttons"), nlohmann::json::array({"trigger"}));
    EXPECT_EQ(j.at("t"), 40.0);
}

}  // namespace
