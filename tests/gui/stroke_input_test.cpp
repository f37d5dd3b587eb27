// The stroke input (manipulators/stroke_input.h) without a window: simulated Coin mouse events go
// through an SoHandleEventAction, as the viewer would send them, and the pointer rays meet the
// active plane where the camera's geometry says.
#include "manipulators/stroke_input.h"

#include "model/auxiliary_plane.h"

#include <Inventor/SoInteraction.h>
#include <Inventor/actions/SoHandleEventAction.h>
#include <Inventor/events/SoLocation2Event.h>
#include <Inventor/events/SoMouseButtonEvent.h>
#include <Inventor/nodes/SoCube.h>
#include <Inventor/nodes/SoOrthographicCamera.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace sculptline::manipulators {
namespace {

/// Coin's view volume is single precision.
constexpr double kTolerance = 1e-3;
/// The camera sees 100 units vertically (an orthographic camera of height 100 at z = 100 looking
/// down -Z onto the plane z = 0).
constexpr float kViewHeight = 100.0f;

class StrokeInputTest : public testing::Test {
protected:
    void SetUp() override
    {
        SoInteraction::init();  // before any node: Coin's type system
        input_ = std::make_unique<StrokeInput>();
        root_ = new SoSeparator;
        root_->ref();
        camera_ = new SoOrthographicCamera;
        camera_->position.setValue(0, 0, 100);
        camera_->height = kViewHeight;
        root_->addChild(camera_);
        root_->addChild(input_->root());
        input_->setCamera([this]() { return camera_; });
        input_->setActivePlane([](const StrokeHit&) { return model::PlaneFrame{}; });
        input_->setFinishedCallback([this](const FinishedStroke& s) { strokes_.push_back(s); });
        input_->setEnabled(true);
    }
    void TearDown() override
    {
        root_->unref();
        input_.reset();
    }

    /// Sends one event at pixel (x, y), Coin's convention (origin bottom-left).
    void send(SoEvent& event, short x, short y, const SbViewportRegion& viewport)
    {
        event.setPosition(SbVec2s(x, y));
        SoHandleEventAction action(viewport);
        action.setEvent(&event);
        action.apply(root_);
    }
    void drawLine(const SbViewportRegion& viewport, SbVec2s from, SbVec2s to, int steps)
    {
        SoMouseButtonEvent press;
        press.setButton(SoMouseButtonEvent::BUTTON1);
        press.setState(SoButtonEvent::DOWN);
        send(press, from[0], from[1], viewport);
        for (int i = 1; i <= steps; ++i) {
            SoLocation2Event move;
            send(move, static_cast<short>(from[0] + (to[0] - from[0]) * i / steps),
                 static_cast<short>(from[1] + (to[1] - from[1]) * i / steps), viewport);
        }
        SoMouseButtonEvent release;
        release.setButton(SoMouseButtonEvent::BUTTON1);
        release.setState(SoButtonEvent::UP);
        send(release, to[0], to[1], viewport);
    }

    SoSeparator* root_ = nullptr;
    SoOrthographicCamera* camera_ = nullptr;
    std::unique_ptr<StrokeInput> input_;
    std::vector<FinishedStroke> strokes_;
};

TEST_F(StrokeInputTest, PointerRaysMeetThePlaneWhereTheCameraLooks)
{
    // Given a wide 800 x 600 viewport (6 pixels per unit) / When a line is drawn from the centre
    // 200 pixels right and 60 up
    drawLine(SbViewportRegion(800, 600), SbVec2s(400, 300), SbVec2s(600, 360), 10);
    // Then one stroke of 12 samples arrives, from (0, 0) to (33.3, 10) in the plane's frame
    ASSERT_EQ(strokes_.size(), 1u);
    const FinishedStroke& s = strokes_[0];
    ASSERT_EQ(s.points.size(), 12u);
    EXPECT_LT((s.points.front() - Eigen::Vector3d(0, 0, 0)).norm(), kTolerance);
    EXPECT_LT((s.points.back() - Eigen::Vector3d(200.0 / 6, 10, 0)).norm(), kTolerance);
    EXPECT_EQ(s.times.size(), s.points.size());
    EXPECT_EQ(s.start.curve, 0u);  // started in the air
}

TEST_F(StrokeInputTest, TallViewportsAreNotSqueezed)
{
    // A 600 x 800 viewport shows 100 units across and 133 up (Coin widens a tall view's volume):
    // still 6 pixels per unit in both directions
    drawLine(SbViewportRegion(600, 800), SbVec2s(300, 400), SbVec2s(400, 340), 4);
    ASSERT_EQ(strokes_.size(), 1u);
    EXPECT_LT((strokes_[0].points.back() - Eigen::Vector3d(100.0 / 6, -10, 0)).norm(), kTolerance);
}

TEST_F(StrokeInputTest, AClickThatTremblesAPixelOrTwoDrawsNothing)
{
    // Given a press and release two pixels apart, with a move in between (a hand clicking)
    drawLine(SbViewportRegion(800, 600), SbVec2s(400, 300), SbVec2s(402, 301), 2);
    // Then no stroke arrives: it would be a curve the size of a dot
    EXPECT_TRUE(strokes_.empty());
    // But three pixels are a (short) stroke
    drawLine(SbViewportRegion(800, 600), SbVec2s(400, 300), SbVec2s(403, 300), 3);
    EXPECT_EQ(strokes_.size(), 1u);
}

TEST_F(StrokeInputTest, AClickReportsTheSurfaceUnderThePointerEvenWhereNoPlaneTakesAStroke)
{
    // Given a surface entity's node (a 20-unit block named "Surface9", its top at z = 1) under the pointer
    auto* surface = new SoSeparator;
    surface->setName("Surface9");
    auto* block = new SoCube;
    block->width = 20;
    block->height = 20;
    block->depth = 2;
    surface->addChild(block);
    root_->addChild(surface);
    camera_->farDistance = 200.0f;  // the block at z = 0 within the view volume (the pick clips to it)
    std::vector<PointerClick> clicks;
    bool clickOnly = false;
    input_->setClickCallback([&](const PointerClick& c) { clicks.push_back(c); }, [&]() { return clickOnly; });
    const SbViewportRegion viewport(800, 600);  // 6 pixels per unit, (0, 0) at the centre
    // When it is clicked (a pixel of tremble): the click names the surface and the point on its top
    drawLine(viewport, SbVec2s(400, 300), SbVec2s(401, 300), 1);
    ASSERT_EQ(clicks.size(), 1u);
    EXPECT_EQ(clicks[0].surface, 9u);
    EXPECT_NEAR(clicks[0].point.z(), 1.0, kTolerance);
    EXPECT_TRUE(strokes_.empty());
    // A click beside it names no surface
    drawLine(viewport, SbVec2s(700, 300), SbVec2s(700, 300), 1);
    ASSERT_EQ(clicks.size(), 2u);
    EXPECT_EQ(clicks[1].surface, 0u);
    // A stroke is no click
    drawLine(viewport, SbVec2s(400, 300), SbVec2s(430, 300), 5);
    EXPECT_EQ(clicks.size(), 2u);
    EXPECT_EQ(strokes_.size(), 1u);
    // When no plane takes strokes (a click tool): a click still arrives when the tool wants clicks only
    input_->setActivePlane([](const StrokeHit&) { return std::optional<model::PlaneFrame>(); });
    drawLine(viewport, SbVec2s(400, 300), SbVec2s(400, 301), 1);
    EXPECT_EQ(clicks.size(), 2u);  // not wanted: the press goes on to the rest of the scene
    clickOnly = true;
    drawLine(viewport, SbVec2s(400, 300), SbVec2s(400, 301), 1);
    ASSERT_EQ(clicks.size(), 3u);
    EXPECT_EQ(clicks[2].surface, 9u);
    // And a drag there is neither a click nor a stroke
    drawLine(viewport, SbVec2s(400, 300), SbVec2s(440, 300), 5);
    EXPECT_EQ(clicks.size(), 3u);
    EXPECT_EQ(strokes_.size(), 1u);
}

TEST_F(StrokeInputTest, AStrokeThatLeavesThePlaneKeepsOneTimePerPoint)
{
    // Given a perspective camera at x = -10 looking down -Z, and the active plane x = 0 (seen
    // edge-on from nearby): rays through the left of the view never meet it, those to the right do
    auto* perspective = new SoPerspectiveCamera;
    perspective->position.setValue(-10, 0, 100);
    root_->replaceChild(camera_, perspective);
    input_->setCamera([perspective]() { return perspective; });
    input_->setActivePlane([](const StrokeHit&) {
        return model::PlaneFrame::fromNormal(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 100.0, Eigen::Vector3d::UnitY());
    });

    // When a stroke runs from the left of the view to the right
    drawLine(SbViewportRegion(800, 600), SbVec2s(100, 300), SbVec2s(700, 320), 30);

    // Then it arrives with the points that met the plane, each with its time, and every ray with its
    // time (the fitter refused such strokes: "stroke.times: <rays> values for <points> points")
    ASSERT_EQ(strokes_.size(), 1u);
    const FinishedStroke& s = strokes_[0];
    EXPECT_FALSE(s.points.empty());
    EXPECT_LT(s.points.size(), s.rayOrigins.size());
    EXPECT_EQ(s.times.size(), s.points.size());
    EXPECT_EQ(s.rayTimes.size(), s.rayOrigins.size());
}

TEST_F(StrokeInputTest, APixelsFootprintOnThePlaneIsTheStrokesResolution)
{
    // Given the orthographic view of 100 units over 600 pixels (1/6 unit per pixel, square pixels)
    const SbViewportRegion viewport(800, 600);
    // When a stroke is drawn on the plane facing the camera
    drawLine(viewport, SbVec2s(200, 300), SbVec2s(600, 400), 40);
    // Then one pixel is 1/6 unit on it
    ASSERT_EQ(strokes_.size(), 1u);
    FinishedStroke s = strokes_[0];
    EXPECT_EQ(s.pixelRays.size(), s.rayOrigins.size());
    EXPECT_NEAR(pixelFootprint(s), kViewHeight / 600.0, kTolerance);
    // And on a plane tilted by 60 degrees about x the pixel's y step is stretched by 1/cos 60 = 2
    const double c = std::cos(M_PI / 3.0), sn = std::sin(M_PI / 3.0);
    reproject(s, model::PlaneFrame::fromNormal(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, -sn, c), 100.0,
                                               Eigen::Vector3d::UnitX()));
    EXPECT_NEAR(pixelFootprint(s), 2.0 * kViewHeight / 600.0, kTolerance);
    // A stroke without pixel rays (not from the pointer) has no known resolution
    s.pixelRays.clear();
    EXPECT_EQ(pixelFootprint(s), 0.0);
}

TEST_F(StrokeInputTest, DisabledInputDrawsNothing)
{
    input_->setEnabled(false);
    drawLine(SbViewportRegion(800, 600), SbVec2s(400, 300), SbVec2s(500, 300), 3);
    EXPECT_TRUE(strokes_.empty());
}

TEST(AuxiliaryPlane, AlongATangentItContainsTheTangentAndFacesTheEye)
{
    const Eigen::Vector3d point(1, 2, 3), tangent(1, 0, 0), view(0.3, 0.2, -1);
    const auto plane = model::planeAlongTangent(point, tangent, view, 50);
    ASSERT_TRUE(plane);
    EXPECT_LT((plane->origin - point).norm(), 1e-12);
    EXPECT_LT(std::abs(plane->normal().dot(tangent)), 1e-12);
    EXPECT_GT(plane->normal().dot(-view.normalized()), 0.9);  // as much facing as a plane holding X can
    EXPECT_FALSE(model::planeAlongTangent(point, Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, -1), 50));  // edge-on
}

TEST(AuxiliaryPlane, ThroughTwoPointsItContainsTheBinormal)
{
    const Eigen::Vector3d a(0, 0, 0), b(10, 0, 5), binormal(0, 1, 0), view(0, 0, -1);
    const auto plane = model::planeThroughPoints(a, b, binormal, view, 50);
    ASSERT_TRUE(plane);
    EXPECT_LT(std::abs((a - plane->origin).dot(plane->normal())), 1e-12);
    EXPECT_LT(std::abs((b - plane->origin).dot(plane->normal())), 1e-12);
    EXPECT_LT(std::abs(plane->normal().dot(binormal)), 1e-12);
    EXPECT_GT(plane->normal().dot(-view), 0.0);  // turned towards the eye
    EXPECT_FALSE(model::planeThroughPoints(a, Eigen::Vector3d(0, 3, 0), binormal, view, 50));  // chord along the binormal
}

}  // namespace
}  // namespace sculptline::manipulators
