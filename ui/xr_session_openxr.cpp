// VrSession through the OpenXR loader (OpenXR 1.0 specification, "hello_xr" structure): instance
// with XR_KHR_opengl_enable, the headset system, a session bound to the viewer's own GLX context,
// one swapchain per eye, the Coin scene rendered per eye through an SoFrustumCamera set from
// xrLocateViews, and the controllers' aim poses, trigger and grip read as actions.
//
// Only the failure paths up to xrCreateInstance have run on the development machines (Debian 12 has
// no OpenXR runtime); everything from xrGetSystem on is written to the specification, untested.
#include "ui/xr_session.h"

#include <Inventor/Qt/viewers/SoQtViewer.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoSceneManager.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/nodes/SoFrustumCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <QElapsedTimer>
#include <QGLWidget>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QTimer>

#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

// X11 and GLX last: their macros (None, Bool, Success, ...) must not reach Qt's or Eigen's headers.
#include <GL/glx.h>
#include <X11/Xlib.h>
#define XR_USE_PLATFORM_XLIB
#define XR_USE_GRAPHICS_API_OPENGL
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>
#include <openxr/openxr_reflection.h>

namespace sculptline::ui {
namespace {

/// The model is shown this wide (metres: its bounding-box diagonal) ...
constexpr double kModelSizeMetres = 0.6;
/// ... its centre at chest height half a metre ahead on a stage (origin on the floor) ...
const Eigen::Vector3d kStageStand(0.0, 1.1, -0.5);
/// ... or, in a LOCAL space (origin at the head at start), 0.3 m below and half a metre ahead.
const Eigen::Vector3d kLocalStand(0.0, -0.3, -0.5);
/// Near and far clipping planes of the eye cameras (metres).
constexpr double kNearMetres = 0.05;
constexpr double kFarMetres = 100.0;
/// Swapchain formats: sRGB where offered (Coin's colours are already gamma-encoded, as the
/// compositor then reads them), else plain RGBA8, else the runtime's first.
constexpr int64_t kGlSrgb8Alpha8 = 0x8C43;
constexpr int64_t kGlRgba8 = 0x8058;

/// The result's name as the specification spells it (xrResultToString needs an instance, which is
/// what may be missing).
std::string resultName(XrResult r)
{
#define SL_XR_RESULT_CASE(name, value) \
    case name: return #name;
    switch (r) {
        XR_LIST_ENUM_XrResult(SL_XR_RESULT_CASE)
    default: return "XrResult " + std::to_string(static_cast<int>(r));
    }
#undef SL_XR_RESULT_CASE
}

QString failed(const char* call, XrResult r)
{
    return QStringLiteral("%1: %2").arg(QString::fromLatin1(call), QString::fromStdString(resultName(r)));
}

Eigen::Vector3d toEigen(const XrVector3f& v) { return {v.x, v.y, v.z}; }
Eigen::Quaterniond toEigen(const XrQuaternionf& q) { return Eigen::Quaterniond(q.w, q.x, q.y, q.z); }

}  // namespace

struct VrSession::Impl {
    XrInstance instance = XR_NULL_HANDLE;
    XrSystemId system = XR_NULL_SYSTEM_ID;
    ::XrSession session = XR_NULL_HANDLE;
    XrSessionState state = XR_SESSION_STATE_UNKNOWN;
    bool sessionRunning = false;
    XrSpace space = XR_NULL_HANDLE;
    bool stageSpace = false;
    struct Eye {
        XrSwapchain swapchain = XR_NULL_HANDLE;
        int32_t width = 0;
        int32_t height = 0;
        std::vector<XrSwapchainImageOpenGLKHR> images;
        GLuint depth = 0;
    };
    std::array<Eye, 2> eyes;
    GLuint framebuffer = 0;
    XrActionSet actionSet = XR_NULL_HANDLE;
    XrAction aim = XR_NULL_HANDLE;
    XrAction trigger = XR_NULL_HANDLE;
    XrAction grip = XR_NULL_HANDLE;
    std::array<XrPath, 2> hands{XR_NULL_PATH, XR_NULL_PATH};  // left, right
    std::array<XrSpace, 2> aimSpaces{XR_NULL_HANDLE, XR_NULL_HANDLE};
    StageToModel stage;
    SoSeparator* root = nullptr;  // eye camera + the viewer's scene graph
    SoFrustumCamera* camera = nullptr;
    QTimer timer;
    QElapsedTimer clock;

    QString create(SoQtViewer* viewer);
    QString createActions();
    void destroy();
    /// One frame: events, wait/begin, poses, the two eyes, end. Returns a message when the session ended.
    QString frame(SoQtViewer* viewer, VrSession& owner);
    void renderEye(SoQtViewer* viewer, const XrView& view, Eye& eye, QOpenGLFunctions& gl);
};

VrSession::VrSession(SoQtViewer* viewer, QObject* parent)
    : QObject(parent), impl_(std::make_unique<Impl>()), viewer_(viewer), viewerAlive_(viewer->getBaseWidget())
{
    // Paced by xrWaitFrame, which blocks until the runtime wants the next frame.
    impl_->timer.setInterval(0);
    connect(&impl_->timer, &QTimer::timeout, this, [this]() {
        const QString ended = impl_->frame(viewer_, *this);
        if (!ended.isEmpty()) {
            stop();
            Q_EMIT message(ended);
        }
    });
}

VrSession::~VrSession() { stop(); }

bool VrSession::compiledWithOpenXr() { return true; }

bool VrSession::running() const { return impl_->session != XR_NULL_HANDLE; }

void VrSession::stop()
{
    impl_->timer.stop();
    const bool held = impl_->instance != XR_NULL_HANDLE || impl_->session != XR_NULL_HANDLE || impl_->root;
    if (!held) return;
    // The main window deletes its viewer before its child objects (this one among them): then the GL
    // context is gone with it, and only the OpenXR handles are left to free.
    if (viewerAlive_) {
        if (auto* gl = dynamic_cast<QGLWidget*>(viewer_->getGLWidget())) gl->makeCurrent();
    }
    impl_->destroy();
}

QString VrSession::start()
{
    if (running()) return tr("The VR session is already running.");
    const QString why = impl_->create(viewer_);
    if (!why.isEmpty()) {
        stop();
        return tr("No VR session (%1). The desktop view goes on.").arg(why);
    }
    impl_->clock.start();
    impl_->timer.start();
    return tr("VR session started: the scene is on the headset; the right controller's trigger draws, the left "
              "controller's grip carries the plane.");
}

QString VrSession::Impl::create(SoQtViewer* viewer)
{
    // 1. The instance, with OpenGL. Without a runtime the loader fails here (or already when asked
    //    for the runtime's extensions), typically with XR_ERROR_RUNTIME_UNAVAILABLE.
    uint32_t count = 0;
    XrResult r = xrEnumerateInstanceExtensionProperties(nullptr, 0, &count, nullptr);
    if (XR_FAILED(r))
        return QStringLiteral("the OpenXR loader found no runtime; install one (Debian 12 packages none) and make it "
                              "active (XR_RUNTIME_JSON, or /etc/xdg/openxr/1/active_runtime.json) — ") +
               failed("xrEnumerateInstanceExtensionProperties", r);
    std::vector<XrExtensionProperties> extensions(count, {XR_TYPE_EXTENSION_PROPERTIES});
    xrEnumerateInstanceExtensionProperties(nullptr, count, &count, extensions.data());
    bool haveOpenGl = false;
    for (const XrExtensionProperties& e : extensions) haveOpenGl |= std::strcmp(e.extensionName, XR_KHR_OPENGL_ENABLE_EXTENSION_NAME) == 0;
    if (!haveOpenGl) return QStringLiteral("the OpenXR runtime does not offer %1").arg(QLatin1String(XR_KHR_OPENGL_ENABLE_EXTENSION_NAME));

    XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
    std::strncpy(info.applicationInfo.applicationName, "Sculptline", XR_MAX_APPLICATION_NAME_SIZE - 1);
    info.applicationInfo.applicationVersion = 1;
    std::strncpy(info.applicationInfo.engineName, "Coin", XR_MAX_ENGINE_NAME_SIZE - 1);
    info.applicationInfo.apiVersion = XR_CURRENT_API_VERSION;
    const char* enabled[] = {XR_KHR_OPENGL_ENABLE_EXTENSION_NAME};
    info.enabledExtensionCount = 1;
    info.enabledExtensionNames = enabled;
    if (XR_FAILED(r = xrCreateInstance(&info, &instance))) return failed("xrCreateInstance", r);

    // 2. The headset.
    XrSystemGetInfo systemInfo{XR_TYPE_SYSTEM_GET_INFO};
    systemInfo.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
    if (XR_FAILED(r = xrGetSystem(instance, &systemInfo, &system)))
        return QStringLiteral("no headset: ") + failed("xrGetSystem", r);
    PFN_xrGetOpenGLGraphicsRequirementsKHR requirements = nullptr;
    if (XR_FAILED(r = xrGetInstanceProcAddr(instance, "xrGetOpenGLGraphicsRequirementsKHR",
                                            reinterpret_cast<PFN_xrVoidFunction*>(&requirements))))
        return failed("xrGetInstanceProcAddr(xrGetOpenGLGraphicsRequirementsKHR)", r);
    XrGraphicsRequirementsOpenGLKHR needs{XR_TYPE_GRAPHICS_REQUIREMENTS_OPENGL_KHR};
    if (XR_FAILED(r = requirements(instance, system, &needs))) return failed("xrGetOpenGLGraphicsRequirementsKHR", r);

    // 3. The session, on the viewer's GLX context (the headset and the desktop share its display lists).
    auto* widget = dynamic_cast<QGLWidget*>(viewer->getGLWidget());
    if (!widget) return QStringLiteral("the 3D view has no OpenGL widget");
    widget->makeCurrent();
    Display* display = glXGetCurrentDisplay();
    GLXContext context = glXGetCurrentContext();
    if (!display || !context) return QStringLiteral("the 3D view has no GLX context (OpenXR's OpenGL binding needs X11/GLX)");
    int configId = 0;
    int screen = 0;
    glXQueryContext(display, context, GLX_FBCONFIG_ID, &configId);
    glXQueryContext(display, context, GLX_SCREEN, &screen);
    const int attributes[] = {GLX_FBCONFIG_ID, configId, 0};
    int configs = 0;
    GLXFBConfig* config = glXChooseFBConfig(display, screen, attributes, &configs);
    if (!config || configs < 1) return QStringLiteral("the GLX context's framebuffer configuration is not found");
    XrGraphicsBindingOpenGLXlibKHR binding{XR_TYPE_GRAPHICS_BINDING_OPENGL_XLIB_KHR};
    binding.xDisplay = display;
    binding.glxFBConfig = config[0];
    if (XVisualInfo* visual = glXGetVisualFromFBConfig(display, config[0])) {
        binding.visualid = static_cast<uint32_t>(visual->visualid);
        XFree(visual);
    }
    XFree(config);
    binding.glxDrawable = glXGetCurrentDrawable();
    binding.glxContext = context;
    XrSessionCreateInfo sessionInfo{XR_TYPE_SESSION_CREATE_INFO};
    sessionInfo.next = &binding;
    sessionInfo.systemId = system;
    if (XR_FAILED(r = xrCreateSession(instance, &sessionInfo, &session))) return failed("xrCreateSession", r);

    // 4. Where the model stands: a stage (floor origin) where there is one, else the head's start.
    uint32_t spaceCount = 0;
    xrEnumerateReferenceSpaces(session, 0, &spaceCount, nullptr);
    std::vector<XrReferenceSpaceType> spaces(spaceCount);
    xrEnumerateReferenceSpaces(session, spaceCount, &spaceCount, spaces.data());
    for (XrReferenceSpaceType t : spaces) stageSpace |= t == XR_REFERENCE_SPACE_TYPE_STAGE;
    XrReferenceSpaceCreateInfo spaceInfo{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
    spaceInfo.referenceSpaceType = stageSpace ? XR_REFERENCE_SPACE_TYPE_STAGE : XR_REFERENCE_SPACE_TYPE_LOCAL;
    spaceInfo.poseInReferenceSpace.orientation.w = 1.0f;
    if (XR_FAILED(r = xrCreateReferenceSpace(session, &spaceInfo, &space))) return failed("xrCreateReferenceSpace", r);
    SoGetBoundingBoxAction bbox(viewer->getViewportRegion());
    bbox.apply(viewer->getSceneGraph());
    const SbBox3f box = bbox.getBoundingBox();
    if (!box.isEmpty()) {
        const SbVec3f c = box.getCenter();
        stage = StageToModel::framing(Eigen::Vector3d(c[0], c[1], c[2]), (box.getMax() - box.getMin()).length(), kModelSizeMetres,
                                      stageSpace ? kStageStand : kLocalStand);
    }

    // 5. One swapchain per eye at the runtime's recommended size.
    uint32_t viewCount = 0;
    if (XR_FAILED(r = xrEnumerateViewConfigurationViews(instance, system, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, 0, &viewCount, nullptr)) ||
        viewCount != 2)
        return QStringLiteral("the headset has no two-eye view configuration");
    std::vector<XrViewConfigurationView> views(viewCount, {XR_TYPE_VIEW_CONFIGURATION_VIEW});
    xrEnumerateViewConfigurationViews(instance, system, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, viewCount, &viewCount, views.data());
    uint32_t formatCount = 0;
    xrEnumerateSwapchainFormats(session, 0, &formatCount, nullptr);
    std::vector<int64_t> formats(formatCount);
    xrEnumerateSwapchainFormats(session, formatCount, &formatCount, formats.data());
    if (formats.empty()) return QStringLiteral("the runtime offers no swapchain format");
    int64_t format = formats.front();
    for (int64_t wanted : {kGlRgba8, kGlSrgb8Alpha8})  // the later match wins: sRGB over RGBA8
        for (int64_t f : formats)
            if (f == wanted) format = f;
    QOpenGLFunctions* gl = QOpenGLContext::currentContext() ? QOpenGLContext::currentContext()->functions() : nullptr;
    if (!gl) return QStringLiteral("the 3D view's OpenGL functions are not available");
    gl->glGenFramebuffers(1, &framebuffer);
    for (std::size_t i = 0; i < eyes.size(); ++i) {
        Eye& eye = eyes[i];
        XrSwapchainCreateInfo sc{XR_TYPE_SWAPCHAIN_CREATE_INFO};
        sc.usageFlags = XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT | XR_SWAPCHAIN_USAGE_SAMPLED_BIT;
        sc.format = format;
        sc.sampleCount = 1;
        sc.width = views[i].recommendedImageRectWidth;
        sc.height = views[i].recommendedImageRectHeight;
        sc.faceCount = 1;
        sc.arraySize = 1;
        sc.mipCount = 1;
        if (XR_FAILED(r = xrCreateSwapchain(session, &sc, &eye.swapchain))) return failed("xrCreateSwapchain", r);
        eye.width = static_cast<int32_t>(sc.width);
        eye.height = static_cast<int32_t>(sc.height);
        uint32_t images = 0;
        xrEnumerateSwapchainImages(eye.swapchain, 0, &images, nullptr);
        eye.images.assign(images, {XR_TYPE_SWAPCHAIN_IMAGE_OPENGL_KHR});
        xrEnumerateSwapchainImages(eye.swapchain, images, &images, reinterpret_cast<XrSwapchainImageBaseHeader*>(eye.images.data()));
        gl->glGenRenderbuffers(1, &eye.depth);
        gl->glBindRenderbuffer(GL_RENDERBUFFER, eye.depth);
        gl->glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, eye.width, eye.height);
    }

    // 6. The scene seen through one eye camera, set per eye from xrLocateViews.
    root = new SoSeparator;
    root->ref();
    camera = new SoFrustumCamera;
    camera->viewportMapping = SoCamera::LEAVE_ALONE;
    root->addChild(camera);
    if (SoNode* scene = viewer->getSceneGraph()) root->addChild(scene);
    return createActions();
}

QString VrSession::Impl::createActions()
{
    XrResult r;
    XrActionSetCreateInfo setInfo{XR_TYPE_ACTION_SET_CREATE_INFO};
    std::strcpy(setInfo.actionSetName, "sculptline");
    std::strcpy(setInfo.localizedActionSetName, "Sculptline");
    if (XR_FAILED(r = xrCreateActionSet(instance, &setInfo, &actionSet))) return failed("xrCreateActionSet", r);
    xrStringToPath(instance, "/user/hand/left", &hands[0]);
    xrStringToPath(instance, "/user/hand/right", &hands[1]);
    const auto makeAction = [&](const char* name, const char* text, XrActionType type, XrAction& action) {
        XrActionCreateInfo a{XR_TYPE_ACTION_CREATE_INFO};
        std::strcpy(a.actionName, name);
        std::strcpy(a.localizedActionName, text);
        a.actionType = type;
        a.countSubactionPaths = 2;
        a.subactionPaths = hands.data();
        return xrCreateAction(actionSet, &a, &action);
    };
    if (XR_FAILED(r = makeAction("aim", "Aim", XR_ACTION_TYPE_POSE_INPUT, aim))) return failed("xrCreateAction(aim)", r);
    if (XR_FAILED(r = makeAction("trigger", "Draw", XR_ACTION_TYPE_FLOAT_INPUT, trigger))) return failed("xrCreateAction(trigger)", r);
    if (XR_FAILED(r = makeAction("grip", "Carry the plane", XR_ACTION_TYPE_FLOAT_INPUT, grip))) return failed("xrCreateAction(grip)", r);

    // Suggested bindings: Khronos' simple controller (select = trigger, no grip) and the Oculus Touch
    // profile, which most runtimes emulate for other controllers.
    const auto suggest = [&](const char* profile, std::vector<std::pair<XrAction, const char*>> pairs) {
        std::vector<XrActionSuggestedBinding> bindings;
        for (const auto& [action, path] : pairs) {
            XrPath p = XR_NULL_PATH;
            xrStringToPath(instance, path, &p);
            bindings.push_back({action, p});
        }
        XrPath profilePath = XR_NULL_PATH;
        xrStringToPath(instance, profile, &profilePath);
        XrInteractionProfileSuggestedBinding s{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
        s.interactionProfile = profilePath;
        s.countSuggestedBindings = static_cast<uint32_t>(bindings.size());
        s.suggestedBindings = bindings.data();
        return xrSuggestInteractionProfileBindings(instance, &s);
    };
    suggest("/interaction_profiles/khr/simple_controller",
            {{aim, "/user/hand/left/input/aim/pose"}, {aim, "/user/hand/right/input/aim/pose"},
             {trigger, "/user/hand/left/input/select/click"}, {trigger, "/user/hand/right/input/select/click"}});
    suggest("/interaction_profiles/oculus/touch_controller",
            {{aim, "/user/hand/left/input/aim/pose"}, {aim, "/user/hand/right/input/aim/pose"},
             {trigger, "/user/hand/left/input/trigger/value"}, {trigger, "/user/hand/right/input/trigger/value"},
             {grip, "/user/hand/left/input/squeeze/value"}, {grip, "/user/hand/right/input/squeeze/value"}});
    XrSessionActionSetsAttachInfo attach{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
    attach.countActionSets = 1;
    attach.actionSets = &actionSet;
    if (XR_FAILED(r = xrAttachSessionActionSets(session, &attach))) return failed("xrAttachSessionActionSets", r);
    for (std::size_t h = 0; h < 2; ++h) {
        XrActionSpaceCreateInfo s{XR_TYPE_ACTION_SPACE_CREATE_INFO};
        s.action = aim;
        s.subactionPath = hands[h];
        s.poseInActionSpace.orientation.w = 1.0f;
        if (XR_FAILED(r = xrCreateActionSpace(session, &s, &aimSpaces[h]))) return failed("xrCreateActionSpace", r);
    }
    return {};
}

void VrSession::Impl::destroy()
{
    // Null when the viewer (and its context) is gone: the GL names went with it.
    QOpenGLFunctions* gl = QOpenGLContext::currentContext() ? QOpenGLContext::currentContext()->functions() : nullptr;
    for (Eye& eye : eyes) {
        if (eye.swapchain != XR_NULL_HANDLE) xrDestroySwapchain(eye.swapchain);
        if (gl && eye.depth) gl->glDeleteRenderbuffers(1, &eye.depth);
        eye = Eye{};
    }
    if (gl && framebuffer) gl->glDeleteFramebuffers(1, &framebuffer);
    framebuffer = 0;
    for (XrSpace& s : aimSpaces) {
        if (s != XR_NULL_HANDLE) xrDestroySpace(s);
        s = XR_NULL_HANDLE;
    }
    if (space != XR_NULL_HANDLE) xrDestroySpace(space);
    space = XR_NULL_HANDLE;
    if (actionSet != XR_NULL_HANDLE) xrDestroyActionSet(actionSet);  // destroys its actions too
    actionSet = XR_NULL_HANDLE;
    aim = trigger = grip = XR_NULL_HANDLE;
    if (session != XR_NULL_HANDLE) xrDestroySession(session);
    session = XR_NULL_HANDLE;
    sessionRunning = false;
    state = XR_SESSION_STATE_UNKNOWN;
    if (instance != XR_NULL_HANDLE) xrDestroyInstance(instance);
    instance = XR_NULL_HANDLE;
    system = XR_NULL_SYSTEM_ID;
    if (root) root->unref();
    root = nullptr;
    camera = nullptr;
}

QString VrSession::Impl::frame(SoQtViewer* viewer, VrSession& owner)
{
    // Events: the session's life cycle (specification §9.3).
    XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER};
    while (xrPollEvent(instance, &event) == XR_SUCCESS) {
        if (event.type == XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING) return QStringLiteral("The OpenXR runtime is going away: VR session ended.");
        if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
            state = reinterpret_cast<const XrEventDataSessionStateChanged&>(event).state;
            if (state == XR_SESSION_STATE_READY) {
                XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO};
                begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
                if (const XrResult r = xrBeginSession(session, &begin); XR_FAILED(r))
                    return QStringLiteral("VR session ended (") + failed("xrBeginSession", r) + QStringLiteral(").");
                sessionRunning = true;
            } else if (state == XR_SESSION_STATE_STOPPING) {
                xrEndSession(session);
                sessionRunning = false;
            } else if (state == XR_SESSION_STATE_EXITING || state == XR_SESSION_STATE_LOSS_PENDING) {
                return QStringLiteral("VR session ended by the runtime.");
            }
        }
        event = {XR_TYPE_EVENT_DATA_BUFFER};
    }
    if (!sessionRunning) return {};

    XrFrameState frameState{XR_TYPE_FRAME_STATE};
    if (const XrResult r = xrWaitFrame(session, nullptr, &frameState); XR_FAILED(r))
        return QStringLiteral("VR session ended (") + failed("xrWaitFrame", r) + QStringLiteral(").");
    xrBeginFrame(session, nullptr);

    // The controllers: one pose event per hand whose aim pose is tracked.
    const XrActiveActionSet active{actionSet, XR_NULL_PATH};
    XrActionsSyncInfo sync{XR_TYPE_ACTIONS_SYNC_INFO};
    sync.countActiveActionSets = 1;
    sync.activeActionSets = &active;
    xrSyncActions(session, &sync);
    for (std::size_t h = 0; h < 2; ++h) {
        XrSpaceLocation location{XR_TYPE_SPACE_LOCATION};
        if (XR_FAILED(xrLocateSpace(aimSpaces[h], space, frameState.predictedDisplayTime, &location))) continue;
        const XrSpaceLocationFlags valid = XR_SPACE_LOCATION_POSITION_VALID_BIT | XR_SPACE_LOCATION_ORIENTATION_VALID_BIT;
        if ((location.locationFlags & valid) != valid) continue;
        const auto value = [&](XrAction action) {
            XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
            get.action = action;
            get.subactionPath = hands[h];
            XrActionStateFloat s{XR_TYPE_ACTION_STATE_FLOAT};
            return XR_SUCCEEDED(xrGetActionStateFloat(session, &get, &s)) && s.isActive ? s.currentState : 0.0f;
        };
        Q_EMIT owner.poseEvent(controllerPoseEvent(h == 1 ? Hand::Right : Hand::Left, toEigen(location.pose.position),
                                                   toEigen(location.pose.orientation), value(trigger), value(grip),
                                                   static_cast<double>(clock.elapsed()), stage));
    }

    std::array<XrCompositionLayerProjectionView, 2> projection{};
    XrCompositionLayerProjection layer{XR_TYPE_COMPOSITION_LAYER_PROJECTION};
    std::vector<XrCompositionLayerBaseHeader*> layers;
    if (frameState.shouldRender) {
        XrViewLocateInfo locate{XR_TYPE_VIEW_LOCATE_INFO};
        locate.viewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
        locate.displayTime = frameState.predictedDisplayTime;
        locate.space = space;
        XrViewState viewState{XR_TYPE_VIEW_STATE};
        std::array<XrView, 2> views{XrView{XR_TYPE_VIEW}, XrView{XR_TYPE_VIEW}};
        uint32_t located = 0;
        if (XR_SUCCEEDED(xrLocateViews(session, &locate, &viewState, 2, &located, views.data())) && located == 2) {
            auto* widget = dynamic_cast<QGLWidget*>(viewer->getGLWidget());
            widget->makeCurrent();
            QOpenGLFunctions* gl = QOpenGLContext::currentContext()->functions();
            for (std::size_t i = 0; i < 2; ++i) {
                renderEye(viewer, views[i], eyes[i], *gl);
                projection[i] = {XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW};
                projection[i].pose = views[i].pose;
                projection[i].fov = views[i].fov;
                projection[i].subImage.swapchain = eyes[i].swapchain;
                projection[i].subImage.imageRect = {{0, 0}, {eyes[i].width, eyes[i].height}};
            }
            gl->glBindFramebuffer(GL_FRAMEBUFFER, 0);
            layer.space = space;
            layer.viewCount = 2;
            layer.views = projection.data();
            layers.push_back(reinterpret_cast<XrCompositionLayerBaseHeader*>(&layer));
        }
    }
    XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
    end.displayTime = frameState.predictedDisplayTime;
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    end.layerCount = static_cast<uint32_t>(layers.size());
    end.layers = layers.data();
    xrEndFrame(session, &end);
    return {};
}

void VrSession::Impl::renderEye(SoQtViewer* viewer, const XrView& view, Eye& eye, QOpenGLFunctions& gl)
{
    uint32_t index = 0;
    XrSwapchainImageAcquireInfo acquire{XR_TYPE_SWAPCHAIN_IMAGE_ACQUIRE_INFO};
    if (XR_FAILED(xrAcquireSwapchainImage(eye.swapchain, &acquire, &index))) return;
    XrSwapchainImageWaitInfo wait{XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO};
    wait.timeout = XR_INFINITE_DURATION;
    xrWaitSwapchainImage(eye.swapchain, &wait);

    gl.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl.glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, eye.images[index].image, 0);
    gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, eye.depth);
    gl.glViewport(0, 0, eye.width, eye.height);
    const SbColor bg = viewer->getBackgroundColor();
    gl.glClearColor(bg[0], bg[1], bg[2], 1.0f);
    gl.glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    // The eye's pose on the stage, in model units; its asymmetric field of view as a frustum at the
    // near plane (XrFovf angles are signed: left and down negative).
    const Eigen::Vector3d p = stage.point(toEigen(view.pose.position));
    const Eigen::Quaterniond q = stage.rotation(toEigen(view.pose.orientation));
    const double nearDistance = kNearMetres * stage.unitsPerMetre;
    camera->position.setValue(float(p.x()), float(p.y()), float(p.z()));
    camera->orientation.setValue(float(q.x()), float(q.y()), float(q.z()), float(q.w()));
    camera->nearDistance = float(nearDistance);
    camera->farDistance = float(kFarMetres * stage.unitsPerMetre);
    camera->left = float(nearDistance * std::tan(view.fov.angleLeft));
    camera->right = float(nearDistance * std::tan(view.fov.angleRight));
    camera->top = float(nearDistance * std::tan(view.fov.angleUp));
    camera->bottom = float(nearDistance * std::tan(view.fov.angleDown));
    // The desktop's document may have been replaced (File > Open): the headset follows it.
    SoNode* scene = viewer->getSceneGraph();
    if (root->getNumChildren() > 1 && root->getChild(1) != scene) root->removeChild(1);
    if (scene && root->getNumChildren() == 1) root->addChild(scene);
    SoGLRenderAction* desktop = viewer->getSceneManager()->getGLRenderAction();
    SoGLRenderAction action(SbViewportRegion(short(eye.width), short(eye.height)));
    action.setCacheContext(desktop->getCacheContext());
    action.setTransparencyType(desktop->getTransparencyType());
    action.apply(root);

    XrSwapchainImageReleaseInfo release{XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO};
    xrReleaseSwapchainImage(eye.swapchain, &release);
}

}  // namespace sculptline::ui
