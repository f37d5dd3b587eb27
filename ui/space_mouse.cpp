#include "ui/space_mouse.h"

#include "scene/eigen_coin.h"
#include "ui/main_window.h"
#include "ui/sketch_document.h"

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>
#include <Inventor/nodes/SoCamera.h>

#include <QLabel>
#include <QSocketNotifier>
#include <QStatusBar>
#include <QTimer>

#include <spnav.h>

#include <algorithm>
#include <iostream>

namespace sculptline::ui {

SpaceMouseStep spaceMouseStep(const int axes[6], double seconds)
{
    SpaceMouseStep s;
    const double scale = seconds / kFullDeflection;
    s.translation = Eigen::Vector3d(axes[0], axes[1], axes[2]) * (kMaxSpeed * scale);
    const Eigen::Vector3d turn = Eigen::Vector3d(axes[3], axes[4], axes[5]) * (kMaxTurnRate * scale);
    if (turn.norm() > 0.0) s.rotation = Eigen::AngleAxisd(turn.norm(), turn.normalized());
    return s;
}

SpaceMouse::SpaceMouse(MainWindow& window, QObject* parent) : QObject(parent), window_(window)
{
    idle_ = new QTimer(this);
    idle_->setSingleShot(true);
    idle_->setInterval(kIdleMs);
    connect(idle_, &QTimer::timeout, this, [this]() {
        if (window_.document().carriedPlane() != 0) window_.document().endCarry();
    });
    if (spnav_open() == -1 || spnav_fd() < 0) {
        message_ = tr("No 3D mouse: spacenavd is not running (or no device is attached); the mouse and keyboard work as before.");
        // A label of its own beside the status bar's message, gone after kNoticeMs: the message line
        // stays the mode's and the last stroke's (a start-up notice must not replace what they say).
        // Short, with the whole sentence as its tool tip: a long permanent label would cut off the
        // status line beside it.
        auto* notice = new QLabel(tr("No 3D mouse"), window_.statusBar());
        notice->setToolTip(message_);
        notice->setObjectName(QStringLiteral("spaceMouseNotice"));
        window_.statusBar()->addPermanentWidget(notice);
        QTimer::singleShot(kNoticeMs, notice, [notice]() { notice->deleteLater(); });
        if (window_.automated()) std::cerr << "sculptline: " << message_.toStdString() << "\n";
        return;
    }
    notifier_ = new QSocketNotifier(spnav_fd(), QSocketNotifier::Read, this);
    connect(notifier_, &QSocketNotifier::activated, this, [this]() { readEvents(); });
}

SpaceMouse::~SpaceMouse()
{
    if (notifier_) spnav_close();
}

void SpaceMouse::readEvents()
{
    spnav_event e;
    while (spnav_poll_event(&e) != 0) {
        if (e.type != SPNAV_EVENT_MOTION) continue;
        const int axes[6] = {e.motion.x, e.motion.y, e.motion.z, e.motion.rx, e.motion.ry, e.motion.rz};
        // period: ms since the previous report (0 on the first): then one 60 Hz frame.
        const double seconds = e.motion.period > 0 ? std::min(0.1, e.motion.period / 1000.0) : 1.0 / 60.0;
        apply(spaceMouseStep(axes, seconds));
    }
}

void SpaceMouse::apply(const SpaceMouseStep& step)
{
    SoCamera* camera = window_.viewer() ? window_.viewer()->getCamera() : nullptr;
    if (!camera) return;
    const Eigen::Quaterniond view = scene::toEigen(camera->orientation.getValue());
    // The step is in the camera's frame: the world sees it turned by the camera's orientation.
    const Eigen::Vector3d move = view * step.translation;
    const Eigen::Quaterniond turn = view * step.rotation * view.conjugate();
    SketchDocument& doc = window_.document();
    const model::Entity* selected = doc.model().find(doc.selection());
    if (selected && selected->kind == model::EntityKind::Plane) {
        if (doc.carriedPlane() != selected->id) doc.beginCarry(selected->id);
        const model::PlaneFrame& f = selected->frame;
        doc.carryTo(f.origin + move, turn * f.rotation);
        idle_->start();
        doc.scheduler().flush();
    } else {
        camera->position.setValue(scene::toSb(Eigen::Vector3d(scene::toEigen(camera->position.getValue()) + move)));
        camera->orientation.setValue(scene::toSb(Eigen::Quaterniond(turn * view).normalized()));
    }
    window_.renderViewport();
}

}  // namespace sculptline::ui
