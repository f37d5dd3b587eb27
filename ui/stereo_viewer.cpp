#include "ui/stereo_viewer.h"

#include "scene/eye_separation.h"
#include "ui/glx_stereo_probe.h"

#include <Inventor/SoSceneManager.h>
#include <Inventor/SbXfBox3f.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/nodes/SoCamera.h>

#include <QGLWidget>

#include <algorithm>
#include <cmath>

namespace sculptline::ui {
namespace {

/// Relative margin of the fitted clipping planes around the scene (SoQt uses the same).
constexpr float kClippingSlack = 0.001f;

}  // namespace

const char* stereoModeName(StereoMode mode)
{
    switch (mode) {
    case StereoMode::Off: return "off";
    case StereoMode::Anaglyph: return "anaglyph";
    case StereoMode::QuadBuffer: return "quad-buffer";
    case StereoMode::InterleavedRows: return "interleaved-rows";
    }
    return "off";
}

std::optional<StereoMode> stereoModeFromName(const std::string& name)
{
    for (StereoMode m : {StereoMode::Off, StereoMode::Anaglyph, StereoMode::QuadBuffer, StereoMode::InterleavedRows})
        if (name == stereoModeName(m)) return m;
    return std::nullopt;
}

StereoExaminerViewer::StereoExaminerViewer(QWidget* parent) : SoQtExaminerViewer(parent) {}

StereoMode StereoExaminerViewer::stereoMode() const
{
    if (interleavedRows_) return StereoMode::InterleavedRows;
    if (!isStereoViewing()) return StereoMode::Off;
    switch (getStereoType()) {
    case STEREO_ANAGLYPH: return StereoMode::Anaglyph;
    case STEREO_QUADBUFFER: return StereoMode::QuadBuffer;
    default: return StereoMode::Off;
    }
}

QString StereoExaminerViewer::setStereoMode(StereoMode mode)
{
    const auto mono = [this]() {
        // SoQt leaves its stereo type at the refused one (only stereo viewing off): reset it, so that
        // getStereoType() and a later request start from mono.
        setStereoType(STEREO_NONE);
        setStereoViewing(FALSE);
        setQuadBufferStereo(FALSE);
    };
    interleavedRows_ = false;
    switch (mode) {
    case StereoMode::Off:
        setStereoType(STEREO_NONE);
        break;
    case StereoMode::Anaglyph:
        setStereoType(STEREO_ANAGLYPH);
        break;
    case StereoMode::QuadBuffer: {
        // SoQt asks Qt for a GL format with stereo buffers and reports whether it got one; the
        // widget's format says the same from Qt's side (both are checked: a driver may hand out a
        // mono visual for a stereo request).
        auto* gl = dynamic_cast<QGLWidget*>(getGLWidget());
        if (gl) gl->makeCurrent();
        const std::optional<bool> possible = glxHasStereoConfig();
        if (possible.value_or(true)) {
            const bool accepted = setStereoType(STEREO_QUADBUFFER) != FALSE;
            gl = dynamic_cast<QGLWidget*>(getGLWidget());
            if (accepted && gl && gl->format().stereo()) break;
            mono();
        } else {
            setStereoType(STEREO_NONE);
        }
        return QStringLiteral("Quad-buffer stereo is not available: this OpenGL context has no stereo (left/right) "
                              "buffers; it needs a stereo-capable graphics card, driver and display. The view stays mono; "
                              "View > Stereo > Anaglyph works on any screen.");
    }
    case StereoMode::InterleavedRows: {
        setStereoType(STEREO_NONE);
        setStencilBuffer(TRUE);  // recreates the GL widget with a stencil buffer where the display has one
        if (getStencilBuffer() == FALSE) {
            mono();
            return QStringLiteral("Interleaved-rows stereo is not available: this OpenGL context has no stencil buffer. The view stays mono.");
        }
        interleavedRows_ = true;
        break;
    }
    }
    scheduleRedraw();
    return {};
}

void StereoExaminerViewer::updateEyeSeparation(SoCamera& camera)
{
    SoGetBoundingBoxAction bbox(getViewportRegion());
    if (SoNode* scene = getSceneGraph()) bbox.apply(scene);
    lastSeparation_ = scene::eyeSeparation(bbox.getBoundingBox(), camera);
    setStereoOffset(lastSeparation_);
}

void StereoExaminerViewer::fitClippingPlanes(SoCamera& camera)
{
    // SoQt fits them in its private redraw path, which the interleaved rendering bypasses; the same
    // rule (SoGuiViewerP::setClippingPlanes): the scene's box in camera space, a little slack, and
    // a near plane no closer than far / 2^(depth bits) so the depth buffer keeps its resolution.
    SoNode* scene = getSceneGraph();
    if (!isAutoClipping() || !scene) return;
    SoGetBoundingBoxAction bbox(getViewportRegion());
    bbox.apply(scene);
    SbXfBox3f box = bbox.getXfBoundingBox();
    if (box.isEmpty()) return;
    SbMatrix cameraToWorld;
    cameraToWorld.setTransform(camera.position.getValue(), camera.orientation.getValue(), SbVec3f(1, 1, 1));
    box.transform(cameraToWorld.inverse());
    const SbBox3f projected = box.project();
    const float farValue = -projected.getMin()[2];
    if (farValue <= 0.0f) return;
    GLint depthBits = 0;
    glGetIntegerv(GL_DEPTH_BITS, &depthBits);
    const float nearLimit = farValue / std::max(2.0f, std::ldexp(1.0f, std::min(depthBits, 24)));
    const float nearValue = std::max(-projected.getMax()[2], nearLimit);
    const SbBool notify = camera.isNotifyEnabled();
    camera.enableNotify(FALSE);  // no redraw for a change made while drawing
    camera.nearDistance = nearValue * (1.0f - kClippingSlack);
    camera.farDistance = farValue * (1.0f + kClippingSlack);
    camera.enableNotify(notify);
}

void StereoExaminerViewer::actualRedraw()
{
    SoCamera* camera = getCamera();
    if (camera && interleavedRows_) {
        updateEyeSeparation(*camera);
        fitClippingPlanes(*camera);
        renderInterleavedRows(*camera);
        return;
    }
    if (camera && getStereoType() != STEREO_NONE && isStereoViewing()) updateEyeSeparation(*camera);
    SoQtExaminerViewer::actualRedraw();
}

void StereoExaminerViewer::renderInterleavedRows(SoCamera& camera)
{
    const SbViewportRegion& region = getViewportRegion();
    const SbVec2s origin = region.getViewportOriginPixels();
    const SbVec2s size = region.getViewportSizePixels();
    // Coin tracks the GL state it set (lazy elements): what is changed here is put back as it was.
    const GLboolean depthTest = glIsEnabled(GL_DEPTH_TEST);

    // The mask, redrawn every frame (size/2 rectangles: cheap, and never stale after a resize):
    // stencil 1 on rows 1, 3, 5, ... from the bottom. A rectangle [y, y+1] covers exactly the pixel
    // centres of row y.
    glViewport(origin[0], origin[1], size[0], size[1]);
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 1);
    glStencilOp(GL_REPLACE, GL_REPLACE, GL_REPLACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    glOrtho(0, size[0], 0, size[1], -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadIdentity();
    for (int y = 1; y < size[1]; y += 2) glRecti(0, y, size[0], y + 1);
    glPopMatrix();
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    if (depthTest) glEnable(GL_DEPTH_TEST);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);

    // The two eyes, as SoQt renders them (SoCamera::setStereoMode changes no field: no redraw loop).
    const SbColor background = getBackgroundColor();
    glClearColor(background[0], background[1], background[2], 0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);  // glClear ignores the stencil test: once, for both
    SoSceneManager* manager = getSceneManager();
    camera.setStereoAdjustment(lastSeparation_);
    camera.setStereoMode(SoCamera::LEFT_VIEW);
    glStencilFunc(GL_EQUAL, 1, 1);
    manager->render(FALSE, FALSE);
    glClear(GL_DEPTH_BUFFER_BIT);
    camera.setStereoMode(SoCamera::RIGHT_VIEW);
    glStencilFunc(GL_NOTEQUAL, 1, 1);
    manager->render(FALSE, FALSE);
    camera.setStereoMode(SoCamera::MONOSCOPIC);
    glDisable(GL_STENCIL_TEST);
}

}  // namespace sculptline::ui
