#include "ui/stereo_menu.h"

#include "ui/pose_event.h"
#include "ui/pose_input.h"
#include "ui/xr_session.h"

#include "solvers/io/geometry_json.h"

#include <nlohmann/json.hpp>

#include <QAction>
#include <QActionGroup>
#include <QMainWindow>
#include <QMenu>
#include <QStatusBar>

namespace sculptline::ui {
namespace {

/// How long a stereo or VR message stays in the status bar (ms): long enough to read two sentences.
constexpr int kMessageMs = 15000;

}  // namespace

QString StereoMenu::actionName(StereoMode mode)
{
    switch (mode) {
    case StereoMode::Off: return QStringLiteral("view.stereo.off");
    case StereoMode::Anaglyph: return QStringLiteral("view.stereo.anaglyph");
    case StereoMode::QuadBuffer: return QStringLiteral("view.stereo.quadBuffer");
    case StereoMode::InterleavedRows: return QStringLiteral("view.stereo.interleavedRows");
    }
    return {};
}

StereoMenu::StereoMenu(QMainWindow* window, QMenu* viewMenu, StereoExaminerViewer* viewer)
    : QObject(window), window_(window), viewer_(viewer)
{
    QMenu* menu = viewMenu->addMenu(tr("S&tereo"));
    group_ = new QActionGroup(this);
    struct Entry {
        StereoMode mode;
        QString text;
    };
    const Entry entries[] = {
        {StereoMode::Off, tr("&Off (mono)")},
        {StereoMode::Anaglyph, tr("&Anaglyph (red/cyan glasses)")},
        {StereoMode::QuadBuffer, tr("&Quad-buffer (shutter glasses, stereo GL)")},
        {StereoMode::InterleavedRows, tr("&Interleaved rows (passive 3D display)")},
    };
    for (const Entry& e : entries) {
        auto* a = new QAction(e.text, window);
        a->setObjectName(actionName(e.mode));
        a->setCheckable(true);
        a->setChecked(e.mode == StereoMode::Off);
        connect(a, &QAction::triggered, this, [this, m = e.mode]() { select(m); });
        group_->addAction(a);
        menu->addAction(a);
    }
    auto* vr = new QAction(tr("&VR session…"), window);
    vr->setObjectName(QStringLiteral("view.vr"));
    connect(vr, &QAction::triggered, this, [this]() { startVr(); });
    viewMenu->addAction(vr);
}

StereoMenu::~StereoMenu() = default;

QString StereoMenu::select(StereoMode mode)
{
    QString message;
    if (!viewer_) {
        message = tr("No 3D view (started without a display): stereo is off.");
    } else {
        message = viewer_->setStereoMode(mode);
        if (message.isEmpty()) viewer_->render();
    }
    const StereoMode shown = viewer_ ? viewer_->stereoMode() : StereoMode::Off;
    if (QAction* a = window_->findChild<QAction*>(actionName(shown))) a->setChecked(true);
    if (!message.isEmpty()) window_->statusBar()->showMessage(message, kMessageMs);
    else if (mode != StereoMode::Off)
        window_->statusBar()->showMessage(tr("Stereo: %1, eye separation 1/30 of the distance to the model's front.")
                                              .arg(QString::fromLatin1(stereoModeName(mode))),
                                          kMessageMs);
    return message;
}

QString StereoMenu::startVr()
{
    if (!viewer_) {
        const QString message = tr("No 3D view (started without a display): no VR session.");
        window_->statusBar()->showMessage(message, kMessageMs);
        return message;
    }
    if (!xr_) {
        xr_ = new VrSession(viewer_, this);
        connect(xr_, &VrSession::message, this, [this](const QString& m) { window_->statusBar()->showMessage(m, kMessageMs); });
        // The controllers feed the same 6-DOF input layer as recorded pose events (ui/pose_input.h),
        // through the replay format's pose event, the one documented form of a pose.
        connect(xr_, &VrSession::poseEvent, this, [this](const XrPoseEvent& e) {
            PoseInput* poses = window_->findChild<PoseInput*>();
            if (!poses) return;
            try {
                poses->handle(poseEventFromJson(toReplayEvent(e), "vr"), e.t / 1000.0);
            } catch (const solvers::io::InputError& error) {
                window_->statusBar()->showMessage(tr("VR pose ignored: %1").arg(QString::fromStdString(error.what())), kMessageMs);
            }
        });
    }
    const QString message = xr_->start();
    window_->statusBar()->showMessage(message, kMessageMs);
    return message;
}

}  // namespace sculptline::ui
