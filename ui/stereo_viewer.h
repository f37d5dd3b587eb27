#pragma once
// The examiner viewer with stereo: SoQt 1.6's own stereo rendering for anaglyph (colour masks) and
// quad-buffer (GL_BACK_LEFT/RIGHT) through SoQtViewer::setStereoType; Coin's SoCamera skews each
// eye's frustum so that the focal plane has no parallax (Bourke's "off-axis" method). The eye
// separation is set before every frame from the model's size and the camera's distance to it
// (scene/eye_separation.h).
//
// Interleaved rows are drawn here, not by SoQt: SoQt writes its row mask into the stencil buffer with
// glDrawPixels(GL_STENCIL_INDEX, GL_BITMAP), which Mesa rejects ("Unsupported format/type"), leaving
// no mask (seen under Xvfb with llvmpipe). The same mask is drawn as one-pixel rectangles instead,
// and the two eyes are rendered through it.
#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>

#include <QString>

#include <optional>
#include <string>

namespace sculptline::ui {

enum class StereoMode { Off, Anaglyph, QuadBuffer, InterleavedRows };

/// The `--stereo` names: "off", "anaglyph", "quad-buffer", "interleaved-rows".
const char* stereoModeName(StereoMode mode);
std::optional<StereoMode> stereoModeFromName(const std::string& name);

class StereoExaminerViewer : public SoQtExaminerViewer {
public:
    explicit StereoExaminerViewer(QWidget* parent);

    /// Switches the stereo rendering. Returns an empty string when `mode` is on, else the reason it
    /// is not (quad-buffer without a stereo GL format, interleaved rows without a stencil buffer),
    /// in which case the viewer is mono (StereoMode::Off).
    QString setStereoMode(StereoMode mode);
    StereoMode stereoMode() const;
    /// The eye separation (model units) of the last stereo frame; 0 before the first.
    float lastEyeSeparation() const { return lastSeparation_; }

protected:
    void actualRedraw() override;

private:
    /// Sets the eye separation for the coming frame (the 1/30 rule on the scene's bounding box).
    void updateEyeSeparation(SoCamera& camera);
    /// Near and far planes around the scene, as SoQt's auto-clipping sets them.
    void fitClippingPlanes(SoCamera& camera);
    /// Left eye on the odd rows counted from the bottom (as SoQt's own mask), right eye on the even ones.
    void renderInterleavedRows(SoCamera& camera);

    float lastSeparation_ = 0.0f;
    bool interleavedRows_ = false;
};

}  // namespace sculptline::ui
