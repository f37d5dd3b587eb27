#include "scene/update_scheduler.h"

#include <chrono>

namespace sculptline::scene {

UpdateScheduler::UpdateScheduler(model::Model& model) : model_(model), sensor_(&UpdateScheduler::trigger, this)
{
    sensor_.setPriority(kModelUpdatePriority);
    model_.setDirtyCallback([this]() { sensor_.schedule(); });
    if (model_.updatePending()) sensor_.schedule();
}

UpdateScheduler::~UpdateScheduler()
{
    model_.setDirtyCallback({});
    sensor_.unschedule();
}

void UpdateScheduler::trigger(void* self, SoSensor*) { static_cast<UpdateScheduler*>(self)->run(); }

void UpdateScheduler::flush()
{
    sensor_.unschedule();
    run();
}

void UpdateScheduler::run()
{
    if (!model_.updatePending()) return;
    const auto start = std::chrono::steady_clock::now();
    model_.update();
    ++updates_;
    const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
    if (listener_) listener_(elapsed.count());
}

}  // namespace sculptline::scene
