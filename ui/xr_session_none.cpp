// XrSession in a build without the OpenXR loader (CMake found no `openxr` pkg-config module).
#include "ui/xr_session.h"

namespace sculptline::ui {

struct VrSession::Impl {};

VrSession::VrSession(SoQtViewer* viewer, QObject* parent) : QObject(parent), viewer_(viewer) {}
// viewerAlive_ stays null: nothing here touches the viewer.
VrSession::~VrSession() = default;
bool VrSession::compiledWithOpenXr() { return false; }
bool VrSession::running() const { return false; }
void VrSession::stop() {}

QString VrSession::start()
{
    return tr("No VR: this build of Sculptline has no OpenXR support (the OpenXR loader, Debian's libopenxr-dev, "
              "was not found when it was built). The desktop view goes on.");
}

}  // namespace sculptline::ui
