// The 3D mouse's motion reports as rigid steps (ui/space_mouse.h): speeds scale with deflection and
// the report's period, full deflection for one second moves kMaxSpeed and turns kMaxTurnRate. No
// device here: the spacenavd connection itself is tested only for its absence (gui_no_space_mouse).
#include "ui/space_mouse.h"

#include <gtest/gtest.h>

namespace sculptline::ui {
namespace {

constexpr double kRoundOff = 1e-12;

TEST(SpaceMouseStep, GivenCapAtRest_WhenConverted_ThenNoMotion)
{
    const int axes[6] = {0, 0, 0, 0, 0, 0};
    const SpaceMouseStep s = spaceMouseStep(axes, 0.016);
    EXPECT_EQ(s.translation, Eigen::Vector3d::Zero());
    EXPECT_EQ(s.rotation.coeffs(), Eigen::Quaterniond::Identity().coeffs());
}

TEST(SpaceMouseStep, GivenFullDeflectionForOneSecond_WhenConverted_ThenMaxSpeedAndTurnRate)
{
    const int push[6] = {static_cast<int>(kFullDeflection), 0, 0, 0, 0, 0};
    EXPECT_LT((spaceMouseStep(push, 1.0).translation - Eigen::Vector3d(kMaxSpeed, 0, 0)).norm(), kRoundOff);
    const int twist[6] = {0, 0, 0, 0, 0, -static_cast<int>(kFullDeflection)};
    const Eigen::AngleAxisd turn(spaceMouseStep(twist, 1.0).rotation);
    EXPECT_NEAR(turn.angle(), kMaxTurnRate, kRoundOff);
    EXPECT_LT((turn.axis() - Eigen::Vector3d(0, 0, -1)).norm(), kRoundOff);
}

TEST(SpaceMouseStep, GivenHalfDeflectionOrHalfThePeriod_WhenConverted_ThenHalfTheStep)
{
    const int full[6] = {0, 350, -350, 0, 0, 0};
    const int half[6] = {0, 175, -175, 0, 0, 0};
    const Eigen::Vector3d a = spaceMouseStep(full, 0.02).translation;
    EXPECT_LT((spaceMouseStep(half, 0.02).translation - 0.5 * a).norm(), kRoundOff);
    EXPECT_LT((spaceMouseStep(full, 0.01).translation - 0.5 * a).norm(), kRoundOff);
}

}  // namespace
}  // namespace sculptline::ui
