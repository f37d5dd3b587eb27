// The stereo eye separation (scene/eye_separation.h): 1/30 of the distance to the front of the
// model's bounding sphere, headless.
#include "scene/eye_separation.h"

#include <Inventor/SoDB.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>

#include <gtest/gtest.h>

#include <cmath>

namespace {

constexpr float kTolerance = 1e-5f;

class EyeSeparation : public ::testing::Test {
protected:
    static void SetUpTestSuite() { SoDB::init(); }
    void SetUp() override
    {
        camera_ = new SoPerspectiveCamera;
        camera_->ref();
        camera_->position.setValue(0, 0, 0);
        camera_->focalDistance = 10.0f;
    }
    void TearDown() override { camera_->unref(); }
    SoPerspectiveCamera* camera_ = nullptr;
};

TEST_F(EyeSeparation, IsAThirtiethOfTheDistanceToTheModelsFront)
{
    // Given a 2-unit cube centred 20 units ahead (diagonal 2√3)
    const SbBox3f box(-1, -1, -21, 1, 1, -19);
    // When the separation is derived
    const float s = sculptline::scene::eyeSeparation(box, *camera_);
    // Then it is (20 - √3) / 30
    EXPECT_NEAR(s, (20.0f - std::sqrt(3.0f)) / 30.0f, kTolerance);
}

TEST_F(EyeSeparation, ScalesWithTheModel)
{
    // Given the same view of a model a thousand times larger (metres drawn in millimetres)
    const SbBox3f small(-1, -1, -21, 1, 1, -19);
    const SbBox3f large(-1000, -1000, -21000, 1000, 1000, -19000);
    camera_->focalDistance = 10.0f;
    const float s = sculptline::scene::eyeSeparation(small, *camera_);
    camera_->focalDistance = 10000.0f;
    // Then the separation is a thousand times larger too
    EXPECT_NEAR(sculptline::scene::eyeSeparation(large, *camera_), 1000.0f * s, 1000.0f * kTolerance);
}

TEST_F(EyeSeparation, UsesTheViewingDirection)
{
    // Given a camera looking along +x (its -z turned -90° about y) at a cube 20 units along +x
    camera_->orientation.setValue(SbRotation(SbVec3f(0, 1, 0), static_cast<float>(-M_PI / 2)));
    const SbBox3f box(19, -1, -1, 21, 1, 1);
    // Then the depth is measured along that direction
    EXPECT_NEAR(sculptline::scene::eyeSeparation(box, *camera_), (20.0f - std::sqrt(3.0f)) / 30.0f, kTolerance);
}

TEST_F(EyeSeparation, InsideTheModelKeepsAPositiveFloor)
{
    // Given the camera inside the model's bounding sphere
    const SbBox3f box(-10, -10, -10, 10, 10, 10);
    // Then the separation does not vanish: 5% of the diagonal over 30
    const float diagonal = 20.0f * std::sqrt(3.0f);
    EXPECT_NEAR(sculptline::scene::eyeSeparation(box, *camera_), 0.05f * diagonal / 30.0f, kTolerance);
}

TEST_F(EyeSeparation, EmptySceneFallsBackOnTheFocalDistance)
{
    EXPECT_NEAR(sculptline::scene::eyeSeparation(SbBox3f(), *camera_), 10.0f / 30.0f, kTolerance);
}

}  // namespace
