#pragma once
// The examiner viewer with stereo: SoQt 1.6's own stereo rendering (SoQtViewer::setStereoType:
// anaglyph through colour masks, quad-buffer through GL_BACK_LEFT/RIGHT, interleaved rows through a
// stencil mask; Coin's SoCamera skews the frustum of each eye toward the focal point, Bourke's
// "off-axis" method), with the eye separation set before every frame from the model's size and the
// camera's distance to it (scene/eye_separation.h).
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
    float lastSeparation_ = 0.0f;
};

}  // namespace sculptline::ui
