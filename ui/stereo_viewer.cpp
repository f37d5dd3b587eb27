#include "ui/stereo_viewer.h"

#include "scene/eye_separation.h"

#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/nodes/SoCamera.h>

#include <QGLWidget>

namespace sculptline::ui {

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
    if (!isStereoViewing()) return StereoMode::Off;
    switch (getStereoType()) {
    case STEREO_ANAGLYPH: return StereoMode::Anaglyph;
    case STEREO_QUADBUFFER: return StereoMode::QuadBuffer;
    case STEREO_INTERLEAVED_ROWS: return StereoMode::InterleavedRows;
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
    switch (mode) {
    case StereoMode::Off:
        setStereoType(STEREO_NONE);
        return {};
    case StereoMode::Anaglyph:
        setStereoType(STEREO_ANAGLYPH);
        return {};
    case StereoMode::QuadBuffer: {
        // SoQt asks Qt for a GL format with stereo buffers and reports whether it got one; the
        // widget's format says the same from Qt's side (both are checked: a driver may hand out a
        // mono visual for a stereo request).
        const bool accepted = setStereoType(STEREO_QUADBUFFER) != FALSE;
        const auto* gl = dynamic_cast<QGLWidget*>(getGLWidget());
        if (accepted && gl && gl->format().stereo()) return {};
        mono();
        return QStringLiteral("Quad-buffer stereo is not available: this OpenGL context has no stereo (left/right) "
                              "buffers; it needs a stereo-capable graphics card, driver and display. The view stays mono; "
                              "View > Stereo > Anaglyph works on any screen.");
    }
    case StereoMode::InterleavedRows: {
        if (setStereoType(STEREO_INTERLEAVED_ROWS) != FALSE) return {};
        mono();
        return QStringLiteral("Interleaved-rows stereo is not available: this OpenGL context has no stencil buffer. The view stays mono.");
    }
    }
    return {};
}

void StereoExaminerViewer::actualRedraw()
{
    SoCamera* camera = getCamera();
    if (getStereoType() != STEREO_NONE && isStereoViewing() && camera && getSceneGraph()) {
        SoGetBoundingBoxAction bbox(getViewportRegion());
        bbox.apply(getSceneGraph());
        lastSeparation_ = scene::eyeSeparation(bbox.getBoundingBox(), *camera);
        setStereoOffset(lastSeparation_);
    }
    SoQtExaminerViewer::actualRedraw();
}

}  // namespace sculptline::ui
