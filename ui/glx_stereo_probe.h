#pragma once
// Whether the display can give quad-buffer stereo at all, asked of GLX before the viewer's GL widget
// is recreated for it: SoQt's setQuadBufferStereo(TRUE) then FALSE replaces the widget twice, and the
// replacement does not always draw like the original (seen under Xvfb: depth order of curves over
// surfaces changed), so a request that cannot succeed should leave the widget alone.
#include <optional>

namespace sculptline::ui {

/// With a GLX context current: whether its screen has a double-buffered RGBA stereo framebuffer
/// configuration. nullopt when the current context is not GLX (Wayland, offscreen): only trying tells.
std::optional<bool> glxHasStereoConfig();

}  // namespace sculptline::ui
