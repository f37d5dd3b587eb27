#include "ui/replayer.h"

#include "ui/main_window.h"
#include "ui/pose_input.h"
#include "ui/sketch_document.h"
#include "manipulators/stroke_input.h"

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>

#include <QAction>
#include <QApplication>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QTimer>

#include <chrono>
#include <iostream>

namespace sculptline::ui {
namespace {

const char* seriesName(ReplayEvent::Type type)
{
    switch (type) {
    case ReplayEvent::Type::Press: return "press";
    case ReplayEvent::Type::Move: return "move";
    case ReplayEvent::Type::Release: return "release";
    case ReplayEvent::Type::Key: return "key";
    case ReplayEvent::Type::Action: return "action";
    case ReplayEvent::Type::Wait: return "wait";
    case ReplayEvent::Type::Pose: return "pose";
    }
    return "?";
}

}  // namespace

Replayer::Replayer(MainWindow& window, ReplaySession session, QObject* parent)
    : QObject(parent), window_(window), session_(std::move(session))
{
    window_.document().scheduler().setUpdateListener([this](double ms) { stats_.add("model_update", ms); });
    window_.document().strokeInput().setClock([this]() { return eventTime_; });
    window_.document().strokeInput().setPressure([this]() { return eventPressure_; });
}

QString Replayer::check() const
{
    for (size_t i = 0; i < session_.events.size(); ++i) {
        const ReplayEvent& e = session_.events[i];
        if (e.type == ReplayEvent::Type::Action && !window_.action(e.name)) {
            return QStringLiteral("events[%1].name: no action \"%2\" (see sculptline --list-actions)").arg(i).arg(e.name);
        }
    }
    return {};
}

void Replayer::play(std::function<void()> done)
{
    done_ = std::move(done);
    index_ = 0;
    clock_.start();
    QTimer::singleShot(0, this, [this]() { next(); });
}

void Replayer::next()
{
    if (index_ >= session_.events.size()) {
        if (done_) done_();
        return;
    }
    const ReplayEvent& e = session_.events[index_];
    // Honour the recorded time: the event loop runs meanwhile, as it would between a person's
    // movements (sensors, timers, redraws).
    if (e.t >= 0.0 && clock_.elapsed() < static_cast<qint64>(e.t)) {
        QTimer::singleShot(static_cast<int>(e.t - static_cast<double>(clock_.elapsed())), this, [this]() { next(); });
        return;
    }
    ++index_;
    if (e.type == ReplayEvent::Type::Wait) {
        QTimer::singleShot(e.waitMs, this, [this]() { next(); });
        return;
    }
    dispatch(e);
    QTimer::singleShot(0, this, [this]() { next(); });
}

void Replayer::dispatch(const ReplayEvent& e)
{
    SketchDocument& doc = window_.document();
    const bool dragging = doc.dragging();
    const bool drawing = doc.strokeInput().drawing();  // a release then ends a stroke
    // The recorded time when there is one, so that a replayed stroke carries its recorded timing.
    eventTime_ = (e.t >= 0.0 ? e.t : static_cast<double>(clock_.elapsed())) / 1000.0;
    eventPressure_ = e.pressure;
    const auto start = std::chrono::steady_clock::now();
    switch (e.type) {
    case ReplayEvent::Type::Press:
    case ReplayEvent::Type::Move:
    case ReplayEvent::Type::Release: sendMouse(e); break;
    case ReplayEvent::Type::Key: sendKey(e); break;
    case ReplayEvent::Type::Action: window_.action(e.name)->trigger(); break;
    case ReplayEvent::Type::Wait: break;
    case ReplayEvent::Type::Pose:
        if (PoseInput* poses = window_.findChild<PoseInput*>()) poses->handle(e.pose, eventTime_);
        break;
    }
    // What the person would see next: the model solved (once) and the frame drawn.
    doc.scheduler().flush();
    const auto updated = std::chrono::steady_clock::now();
    window_.renderViewport();
    const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
    const std::chrono::duration<double, std::milli> update = updated - start;
    stats_.add("event_update", update.count());
    stats_.add("event_render", elapsed.count() - update.count());
    stats_.add("event", elapsed.count());
    stats_.add(seriesName(e.type), elapsed.count());
    if (e.type == ReplayEvent::Type::Move && (dragging || doc.dragging())) stats_.add("drag_move", elapsed.count());
    if (e.type == ReplayEvent::Type::Move && doc.strokeInput().drawing()) stats_.add("stroke_move", elapsed.count());
    // Pen-up to the fitted, recognized curve on screen (issue 15 §3).
    if (e.type == ReplayEvent::Type::Release && drawing) {
        stats_.add("stroke_release", elapsed.count());
        // Of which the fit and recognition (the first of a session is the cold call).
        if (doc.lastStroke().fitMs > 0.0) stats_.add("stroke_fit", doc.lastStroke().fitMs);
    }
}

void Replayer::sendMouse(const ReplayEvent& e)
{
    QWidget* target = window_.viewport();
    const QPoint pixel = e.at ? window_.pixelOf(*e.at) : QPoint(e.x, e.y);
    const QPointF local(pixel);
    const QPointF global = target->mapToGlobal(pixel);
    QEvent::Type type = QEvent::MouseMove;
    Qt::MouseButton button = Qt::NoButton;
    if (e.type == ReplayEvent::Type::Press) {
        type = QEvent::MouseButtonPress;
        button = e.button;
        held_ |= e.button;
    } else if (e.type == ReplayEvent::Type::Release) {
        type = QEvent::MouseButtonRelease;
        button = e.button;
        held_ &= ~Qt::MouseButtons(e.button);
    }
    QMouseEvent event(type, local, local, global, button, held_, e.modifiers);
    // A right click opens the context menu (on its release), which would wait for a click the
    // session does not have: dismiss it as a person would (Esc) once it is up.
    if (e.type != ReplayEvent::Type::Move) QTimer::singleShot(0, this, []() { dismissPopups(); });
    QApplication::sendEvent(target, &event);
}

void Replayer::dismissPopups()
{
    while (QWidget* popup = QApplication::activePopupWidget()) {
        std::cerr << "sculptline: replay: closed the pop-up menu a click opened\n";
        popup->close();
    }
}

void Replayer::sendKey(const ReplayEvent& e)
{
    // A shortcut is resolved by Qt's shortcut map from window-system key events only; a replayed
    // key goes to the action it is bound to, as the map would send it, else to the viewer.
    for (QAction* action : window_.namedActions()) {
        if (action->isEnabled() && action->shortcuts().contains(e.key)) {
            action->trigger();
            return;
        }
    }
    const int combined = e.key[0];
    const auto key = static_cast<Qt::Key>(combined & ~Qt::KeyboardModifierMask);
    const auto modifiers = static_cast<Qt::KeyboardModifiers>(combined & Qt::KeyboardModifierMask);
    QKeyEvent press(QEvent::KeyPress, key, modifiers);
    QApplication::sendEvent(window_.viewport(), &press);
    QKeyEvent release(QEvent::KeyRelease, key, modifiers);
    QApplication::sendEvent(window_.viewport(), &release);
}

}  // namespace sculptline::ui
