// Stereo viewing in the real window under Xvfb (SoQt's stereo through View > Stereo): the anaglyph's
// red (left eye) and cyan (right eye) images of a sphere at a known depth lie apart by the parallax
// the camera predicts; interleaved rows carry the same two images on alternate rows; quad-buffer,
// which Xvfb's GLX cannot give, leaves a message and a mono view; View > VR session… without an
// OpenXR runtime says so and the window goes on drawing.
#include "scene/eye_separation.h"
#include "ui/main_window.h"
#include "ui/stereo_menu.h"
#include "ui/stereo_viewer.h"
#include "ui/sketch_document.h"
#include "ui/xr_session.h"
#include "model/model.h"
#include "window_shot.h"

#include <Inventor/nodes/SoBaseColor.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoSphere.h>
#include <Inventor/nodes/SoTranslation.h>

#include <QAction>
#include <QCoreApplication>
#include <QStatusBar>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <optional>

namespace sculptline {
namespace {

// The test scene: a camera at the origin looking down -z and a white unit sphere 20 units ahead.
// The zero-parallax (focal) plane is at 40, behind the sphere, so the sphere stands out of the
// screen: its right-eye (cyan) image lies left of the left-eye (red) one (crossed parallax).
// Coin converges the eyes at the focal distance or at the near plane, whichever is farther
// (SoCamera::GLRender); the viewer's auto-clipping puts the near plane just before the sphere, so a
// focal plane in front of the sphere needs auto-clipping off (the second anaglyph test).
constexpr float kHeightAngle = static_cast<float>(M_PI / 4.0);
constexpr float kFocalDistance = 40.0f;
constexpr float kNearFocalDistance = 10.0f;
constexpr float kSphereDepth = 20.0f;
constexpr float kSphereRadius = 1.0f;
constexpr int kViewportWidth = 800;
constexpr int kViewportHeight = 600;

/// Centroids of thresholded pixels are exact to well under a pixel for a disc 70 px wide; the
/// sphere's off-axis projection shifts its outline's centre from its centre's image by about
/// (r/z)² of the eye's angle, a hundredth of a pixel here. One pixel is a wide margin that a wrong
/// eye separation (Coin's default 0.1 gives 1.8 px instead of 11), a wrong sign or convergence at
/// the wrong depth cannot pass.
constexpr double kParallaxTolerancePx = 1.0;
/// A channel counts as "the sphere" above this (background 41..51, white sphere 255).
constexpr int kBright = 128;

/// The parallax predicted from the camera (pixels, right eye minus left eye). Coin skews each eye's
/// frustum so that the focal plane has none (SoCamera::GLRender, Bourke's off-axis method): a point at
/// depth z moves by s (1/f - 1/z) in normalized device units per tan(half horizontal angle), times
/// half the viewport's width.
double predictedParallax(double separation, double focal, double depth, double width, double height, double heightAngle)
{
    // ADJUST_CAMERA on a wide viewport keeps the height angle; the width follows the aspect.
    const double tanHalfWidth = std::tan(heightAngle / 2.0) * width / height;
    return separation * (1.0 / focal - 1.0 / depth) * width / (2.0 * tanHalfWidth);
}

/// The eye separation the 1/30 rule gives for the sphere, from its geometry (not from the code):
/// nearest point of its bounding sphere (half the box's diagonal, √3 r, before its centre) / 30.
double expectedSeparation() { return (kSphereDepth - std::sqrt(3.0) * kSphereRadius) / scene::kNearDistancePerEyeSeparation; }

SoSeparator* sphereScene()
{
    auto* root = new SoSeparator;
    // The camera renders twice per frame with different eye offsets (SoCamera::setStereoMode, not a
    // field change): a render cache around it would replay the left eye for the right one. SoQt's
    // own root above a scene without a camera has caching off for the same reason.
    root->renderCaching = SoSeparator::OFF;
    auto* camera = new SoPerspectiveCamera;
    camera->position.setValue(0, 0, 0);
    camera->heightAngle = kHeightAngle;
    camera->focalDistance = kFocalDistance;
    root->addChild(camera);
    auto* light = new SoLightModel;
    light->model = SoLightModel::BASE_COLOR;  // flat white: every sphere pixel passes the threshold
    root->addChild(light);
    auto* colour = new SoBaseColor;
    colour->rgb.setValue(1, 1, 1);
    root->addChild(colour);
    auto* at = new SoTranslation;
    at->translation.setValue(0, 0, -kSphereDepth);
    root->addChild(at);
    auto* sphere = new SoSphere;
    sphere->radius = kSphereRadius;
    root->addChild(sphere);
    return root;
}

/// Mean x of the pixels (rows chosen by `row`) whose `channel` value is bright; nullopt if none.
std::optional<double> centroidX(const QImage& image, const std::function<int(QRgb)>& channel, const std::function<bool(int)>& row)
{
    double sum = 0.0;
    long count = 0;
    for (int y = 0; y < image.height(); ++y) {
        if (!row(y)) continue;
        for (int x = 0; x < image.width(); ++x) {
            if (channel(image.pixel(x, y)) > kBright) {
                sum += x;
                ++count;
            }
        }
    }
    if (count == 0) return std::nullopt;
    return sum / count;
}

bool anyRow(int) { return true; }

class StereoWindow : public ::testing::Test {
protected:
    void SetUp() override
    {
        guitest::startApplication("stereo_window_test");
        window_ = std::make_unique<ui::MainWindow>();
        window_->setAutomated(true);
        window_->show();
        window_->setViewportSize(kViewportWidth, kViewportHeight);
        ASSERT_EQ(window_->viewport()->size(), QSize(kViewportWidth, kViewportHeight));
        ASSERT_EQ(window_->renderedViewportSize(), QSize(kViewportWidth, kViewportHeight))
            << "the picture would be drawn at another size than it is read";
        scene_ = sphereScene();
        scene_->ref();
        window_->viewer()->setSceneGraph(scene_);
    }
    void TearDown() override
    {
        window_->viewer()->setSceneGraph(nullptr);
        scene_->unref();
        window_.reset();
    }
    ui::StereoExaminerViewer* viewer() { return static_cast<ui::StereoExaminerViewer*>(window_->viewer()); }
    void select(ui::StereoMode mode) { window_->action(ui::StereoMenu::actionName(mode))->trigger(); }
    /// The viewport's picture, and the whole window saved beside it for a person to look at. The
    /// viewport must still have its size: every expected position below is measured from it.
    QImage shot(const char* name)
    {
        if (const char* dir = std::getenv("SCULPTLINE_STEREO_SHOTS"); dir && *dir)
            guitest::saveWindowShot(*window_, QString::fromLocal8Bit(dir) + "/" + name + ".png");
        EXPECT_EQ(window_->renderedViewportSize(), QSize(kViewportWidth, kViewportHeight));
        QImage image = window_->grabViewport();
        EXPECT_EQ(image.size(), QSize(kViewportWidth, kViewportHeight));
        return image;
    }

    std::unique_ptr<ui::MainWindow> window_;
    SoSeparator* scene_ = nullptr;
};

const auto red = [](QRgb p) { return qRed(p); };
const auto cyan = [](QRgb p) { return std::min(qGreen(p), qBlue(p)); };

TEST_F(StereoWindow, MonoViewHasNoParallax)
{
    // Given the sphere scene in the mono view, when it is shown
    const QImage image = shot("stereo_mono");
    // Then red and cyan images coincide (the check below is not true by construction)
    ASSERT_EQ(image.width(), kViewportWidth);
    const auto r = centroidX(image, red, anyRow);
    const auto c = centroidX(image, cyan, anyRow);
    ASSERT_TRUE(r && c) << "no sphere in the picture";
    EXPECT_NEAR(*c - *r, 0.0, kParallaxTolerancePx);
    EXPECT_NEAR(*r, kViewportWidth / 2.0, kParallaxTolerancePx);
}

TEST_F(StereoWindow, AnaglyphImagesDifferByThePredictedParallax)
{
    // Given the sphere 20 units ahead and the focal plane at 40, when View > Stereo > Anaglyph is chosen
    select(ui::StereoMode::Anaglyph);
    const QImage image = shot("stereo_anaglyph");
    ASSERT_TRUE(window_->action(QStringLiteral("view.stereo.anaglyph"))->isChecked());
    ASSERT_EQ(viewer()->getStereoType(), SoQtViewer::STEREO_ANAGLYPH);

    // Then the eye separation is the 1/30 rule's, from the sphere's size and distance
    EXPECT_NEAR(viewer()->lastEyeSeparation(), expectedSeparation(), 1e-4);
    // And the cyan (right eye) image lies left of the red (left eye) one by the predicted parallax
    const double predicted = predictedParallax(expectedSeparation(), kFocalDistance, kSphereDepth, kViewportWidth, kViewportHeight, kHeightAngle);
    const auto r = centroidX(image, red, anyRow);
    const auto c = centroidX(image, cyan, anyRow);
    ASSERT_TRUE(r && c) << "no sphere in one of the eyes' images";
    EXPECT_NEAR(*c - *r, predicted, kParallaxTolerancePx) << "red at " << *r << ", cyan at " << *c;
    std::cout << "anaglyph, focal plane behind the sphere: parallax " << *c - *r << " px, predicted " << predicted << " px\n";
    // And the two eyes are symmetric about the centre (the camera's own position is between them)
    EXPECT_NEAR((*r + *c) / 2.0, kViewportWidth / 2.0, kParallaxTolerancePx);
    // And the parallax is a fair stereo effect, not a rounding artefact
    EXPECT_LT(predicted, -10.0);
}

TEST_F(StereoWindow, AnaglyphBehindTheFocalPlaneHasUncrossedParallax)
{
    // Given the focal plane at 10, in front of the sphere, and the near plane before it (auto-clipping
    // off: it would put the near plane beyond 10)
    viewer()->setAutoClipping(FALSE);
    viewer()->getCamera()->nearDistance = 1.0f;
    viewer()->getCamera()->farDistance = 100.0f;
    viewer()->getCamera()->focalDistance = kNearFocalDistance;
    // When anaglyph stereo is on
    select(ui::StereoMode::Anaglyph);
    const QImage image = shot("stereo_anaglyph_behind");
    // Then the cyan image lies right of the red one, by the predicted parallax
    const double predicted = predictedParallax(expectedSeparation(), kNearFocalDistance, kSphereDepth, kViewportWidth, kViewportHeight, kHeightAngle);
    const auto r = centroidX(image, red, anyRow);
    const auto c = centroidX(image, cyan, anyRow);
    ASSERT_TRUE(r && c) << "no sphere in one of the eyes' images";
    EXPECT_NEAR(*c - *r, predicted, kParallaxTolerancePx) << "red at " << *r << ", cyan at " << *c;
    std::cout << "anaglyph, focal plane before the sphere: parallax " << *c - *r << " px, predicted " << predicted << " px\n";
    EXPECT_GT(predicted, 20.0);
}

TEST_F(StereoWindow, AnaglyphEyeSeparationFollowsTheCamera)
{
    // Given anaglyph stereo, when the camera moves halfway to the sphere
    select(ui::StereoMode::Anaglyph);
    shot("stereo_anaglyph_far");
    const float far = viewer()->lastEyeSeparation();
    viewer()->getCamera()->position.setValue(0, 0, -kSphereDepth / 2);
    shot("stereo_anaglyph_near");
    // Then the separation shrinks with the distance to the sphere's front
    EXPECT_NEAR(viewer()->lastEyeSeparation(), (kSphereDepth / 2 - std::sqrt(3.0) * kSphereRadius) / 30.0, 1e-4);
    EXPECT_LT(viewer()->lastEyeSeparation(), far);
}

TEST_F(StereoWindow, InterleavedRowsCarryTheTwoEyesOnAlternateRows)
{
    // Given the sphere scene, when View > Stereo > Interleaved rows is chosen
    select(ui::StereoMode::InterleavedRows);
    if (!window_->action(QStringLiteral("view.stereo.interleavedRows"))->isChecked()) {
        // Xvfb's Mesa (llvmpipe) offers 8 stencil bits; a display without any must say so.
        EXPECT_FALSE(window_->statusBar()->currentMessage().isEmpty());
        GTEST_SKIP() << "no stencil buffer on this display: " << window_->statusBar()->currentMessage().toStdString();
    }
    const QImage image = shot("stereo_interleaved_rows");
    // Then the rows the stencil mask gives the left eye (odd rows counted from the bottom, as in SoQt's
    // own mask: even rows from the top of an even-height viewport) and the others hold images apart
    // by the parallax
    ASSERT_EQ(image.height() % 2, 0);
    const auto left = centroidX(image, red, [](int y) { return y % 2 == 0; });
    const auto right = centroidX(image, red, [](int y) { return y % 2 == 1; });
    ASSERT_TRUE(left && right) << "no sphere on one set of rows";
    const double predicted = predictedParallax(expectedSeparation(), kFocalDistance, kSphereDepth, kViewportWidth, kViewportHeight, kHeightAngle);
    EXPECT_NEAR(*right - *left, predicted, kParallaxTolerancePx) << "even rows at " << *left << ", odd rows at " << *right;
    std::cout << "interleaved rows: parallax " << *right - *left << " px, predicted " << predicted << " px\n";
}

TEST_F(StereoWindow, QuadBufferWithoutStereoBuffersSaysSoAndStaysMono)
{
    // Given a display whose GLX has no stereo visuals (Xvfb), when quad-buffer stereo is chosen
    select(ui::StereoMode::QuadBuffer);
    // Then the view is mono, Off is checked, and the status bar says why
    EXPECT_EQ(viewer()->stereoMode(), ui::StereoMode::Off);
    EXPECT_EQ(viewer()->getStereoType(), SoQtViewer::STEREO_NONE);
    EXPECT_TRUE(window_->action(QStringLiteral("view.stereo.off"))->isChecked());
    EXPECT_FALSE(window_->action(QStringLiteral("view.stereo.quadBuffer"))->isChecked());
    EXPECT_TRUE(window_->statusBar()->currentMessage().startsWith(QStringLiteral("Quad-buffer stereo is not available")))
        << window_->statusBar()->currentMessage().toStdString();
    // And the picture is the mono one: red and cyan images coincide
    const QImage image = shot("stereo_quad_buffer_refused");
    const auto r = centroidX(image, red, anyRow);
    const auto c = centroidX(image, cyan, anyRow);
    ASSERT_TRUE(r && c);
    EXPECT_NEAR(*c - *r, 0.0, kParallaxTolerancePx);
    // And anaglyph still works afterwards
    select(ui::StereoMode::Anaglyph);
    EXPECT_EQ(viewer()->stereoMode(), ui::StereoMode::Anaglyph);
}

TEST_F(StereoWindow, VrWithoutRuntimeSaysSoAndTheDesktopGoesOn)
{
    // Given no OpenXR runtime (none is packaged in Debian 12; XR_RUNTIME_JSON points nowhere to be sure)
    setenv("XR_RUNTIME_JSON", "/nonexistent/sculptline-test-runtime.json", 1);
    // When View > VR session… is chosen
    window_->action(QStringLiteral("view.vr"))->trigger();
    // Then the status bar says there is no session, and why
    const QString message = window_->statusBar()->currentMessage();
    EXPECT_TRUE(message.startsWith(QStringLiteral("No VR"))) << message.toStdString();
#ifdef SCULPTLINE_HAVE_OPENXR
    EXPECT_TRUE(message.contains(QStringLiteral("XR_ERROR_"))) << "the loader's result is named: " << message.toStdString();
#endif
    // And the desktop view still draws the scene
    const QImage image = shot("stereo_vr_refused");
    EXPECT_TRUE(centroidX(image, red, anyRow).has_value());
}

TEST_F(StereoWindow, VrControllerPosesDrawThroughTheSixDofInputLayer)
{
    // Given a VR session object (its start fails here: no runtime), whose controller signal is the
    // only way a headset's poses reach the model
    setenv("XR_RUNTIME_JSON", "/nonexistent/sculptline-test-runtime.json", 1);
    window_->action(QStringLiteral("view.vr"))->trigger();
    auto* vr = window_->findChild<ui::VrSession*>();
    ASSERT_NE(vr, nullptr);
    const auto curves = [&] {
        int n = 0;
        for (const auto& [id, e] : window_->document().model().entities()) n += e.kind == model::EntityKind::Curve;
        return n;
    };
    const int before = curves();
    // When the right controller sweeps a quarter helix (60 mm radius, 40 mm rise) with its trigger held, then lets go
    constexpr int kSamples = 120;
    for (int i = 0; i <= kSamples + 1; ++i) {
        const double a = 0.5 * M_PI * std::min(i, kSamples) / kSamples;
        ui::XrPoseEvent e;
        e.device = "pointer";
        e.position = Eigen::Vector3d(60.0 * std::cos(a), 60.0 * std::sin(a), 40.0 * a / (0.5 * M_PI));
        if (i <= kSamples) e.buttons = {"trigger"};
        e.t = 11.0 * i;  // a 90 Hz headset's frames
        Q_EMIT vr->poseEvent(e);
        QCoreApplication::processEvents();
    }
    // Then the 6-DOF input layer made one space curve of it, as it does for a recorded pointer stroke
    EXPECT_EQ(curves(), before + 1);
}

}  // namespace
}  // namespace sculptline
