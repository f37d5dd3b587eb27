#pragma once
// Plays a recorded session through the real Qt event path: pointer events become QMouseEvents sent
// to the viewer's GL widget (SoQt turns them into Coin events for draggers and the stroke input),
// keys trigger the action bound to them or go to the GL widget as QKeyEvents, actions are triggered
// by name. Each input event is timed from dispatch until the frame that shows it has been rendered
// (the pending model update flushed, the viewer redrawn): the latencies --stats reports.
#include "ui/latency_stats.h"
#include "ui/replay_session.h"

#include <QElapsedTimer>
#include <QObject>

#include <functional>
#include <optional>

namespace sculptline::ui {

class MainWindow;

class Replayer : public QObject {
    Q_OBJECT

public:
    Replayer(MainWindow& window, ReplaySession session, QObject* parent = nullptr);

    /// An empty string when every action the session names exists, else the message.
    QString check() const;
    /// Starts playing; `done` runs once the last event has been handled.
    void play(std::function<void()> done);
    const LatencyStats& stats() const { return stats_; }
    LatencyStats& stats() { return stats_; }

private:
    void next();
    void dispatch(const ReplayEvent& e);
    void sendMouse(const ReplayEvent& e);
    void sendKey(const ReplayEvent& e);
    /// Closes pop-up menus (the viewer's right-click menu) that would wait for a click forever.
    static void dismissPopups();

    MainWindow& window_;
    ReplaySession session_;
    size_t index_ = 0;
    Qt::MouseButtons held_;
    QElapsedTimer clock_;
    double eventTime_ = 0.0;  ///< seconds, the time stroke samples of the current event get
    std::optional<double> eventPressure_;  ///< the pen pressure they get (none: a mouse)
    LatencyStats stats_;
    std::function<void()> done_;
};

}  // namespace sculptline::ui
