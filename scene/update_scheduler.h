#pragma once
// Coalesces model edits into at most one model::Model::update() per displayed frame.
//
// A dragger writes its fields on every mouse event, and the model is told each time (cheap: the
// plane is only marked dirty). The first mark schedules a Coin one-shot sensor on the delay queue
// with a priority ahead of the viewer's redraw sensor (SoRenderManager's default is 10000): the
// queue runs once per frame, so the update runs once per frame and always before the frame is
// drawn — the picture is never a frame behind the hand. The thesis used a 0.02 s timer sensor for the
// same purpose (seed 002 §6.4); tying the update to the redraw keeps its bound without a fixed rate.
#include "model/model.h"

#include <Inventor/sensors/SoOneShotSensor.h>

#include <functional>

namespace sculptline::scene {

/// Delay-queue priority of the update: lower runs first; the redraw comes at 10000.
constexpr uint32_t kModelUpdatePriority = 50;

class UpdateScheduler {
public:
    /// Installs itself as `model`'s dirty callback; the model must outlive the scheduler.
    explicit UpdateScheduler(model::Model& model);
    ~UpdateScheduler();
    UpdateScheduler(const UpdateScheduler&) = delete;
    UpdateScheduler& operator=(const UpdateScheduler&) = delete;

    /// Runs a pending update now (before saving, before an undo step records a frame).
    void flush();
    /// model::Model updates run so far.
    int updates() const { return updates_; }
    /// Called after every update with its duration in milliseconds.
    void setUpdateListener(std::function<void(double ms)> listener) { listener_ = std::move(listener); }

private:
    static void trigger(void* self, SoSensor*);
    void run();

    model::Model& model_;
    SoOneShotSensor sensor_;
    int updates_ = 0;
    std::function<void(double)> listener_;
};

}  // namespace sculptline::scene
