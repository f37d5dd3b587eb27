// GLX on its own translation unit: X11's macros (None, Bool, Status, ...) stay away from Qt's headers.
#include "ui/glx_stereo_probe.h"

#include <GL/glx.h>

namespace sculptline::ui {

std::optional<bool> glxHasStereoConfig()
{
    Display* display = glXGetCurrentDisplay();
    GLXContext context = glXGetCurrentContext();
    if (!display || !context) return std::nullopt;
    int screen = 0;
    glXQueryContext(display, context, GLX_SCREEN, &screen);
    const int attributes[] = {GLX_STEREO, True, GLX_DOUBLEBUFFER, True, GLX_RENDER_TYPE, GLX_RGBA_BIT, None};
    int count = 0;
    GLXFBConfig* configs = glXChooseFBConfig(display, screen, attributes, &count);
    if (configs) XFree(configs);
    return count > 0;
}

}  // namespace sculptline::ui
