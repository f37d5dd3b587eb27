#pragma once
// Sketching on the active projection plane (thesis §5.1.1–5.1.2): an SoEventCallback turns the
// pointer into a ray through the camera's view volume and intersects it with the plane's equation
// (not its geometry, which is unpickable), at pointer rate, while a preview line follows the pen.
// On release the stroke's points go to the finished callback in the plane's local frame.
//
// Presses that land on a dragger are left to the dragger, so planes stay movable while sketching.
#include "scene/model/plane_frame.h"

#include <Eigen/Core>

#include <functional>
#include <optional>
#include <vector>

class SoCamera;
class SoCoordinate3;
class SoEventCallback;
class SoLineSet;
class SoSeparator;

namespace sculptline::manipulators {

/// The plane a stroke goes onto, read when the pen goes down.
using ActivePlane = std::function<std::optional<scene::PlaneFrame>()>;

struct FinishedStroke {
    std::vector<Eigen::Vector3d> points;  ///< plane-local, z = 0, model units
    std::vector<double> times;  ///< seconds since the pen went down, one per point
};

class StrokeInput {
public:
    StrokeInput();
    ~StrokeInput();
    StrokeInput(const StrokeInput&) = delete;
    StrokeInput& operator=(const StrokeInput&) = delete;

    /// SoSeparator "StrokeInput" { SoEventCallback, preview }; ref()ed by this object. Put it first
    /// in the scene so it sees events before the draggers do.
    SoSeparator* root() const { return root_; }

    void setEnabled(bool enabled);
    bool enabled() const { return enabled_; }
    bool drawing() const { return drawing_; }

    /// The camera whose view volume maps the pointer to a ray (the viewer's; it may change).
    void setCamera(std::function<SoCamera*()> camera) { camera_ = std::move(camera); }
    void setActivePlane(ActivePlane plane) { plane_ = std::move(plane); }
    void setFinishedCallback(std::function<void(const FinishedStroke&)> f) { finished_ = std::move(f); }
    /// Where sample times come from, seconds; default: the Coin event's time stamp. A replay sets
    /// the recorded times, so a replayed stroke is sampled, and fitted, exactly as recorded.
    void setClock(std::function<double()> clock) { clock_ = std::move(clock); }
    /// Called after each accepted pointer sample (stroke latency statistics).
    void setSampleCallback(std::function<void()> f) { sampled_ = std::move(f); }

private:
    static void handleEvent(void* self, SoEventCallback* node);
    void onEvent(SoEventCallback* node);
    std::optional<Eigen::Vector3d> planePoint(SoEventCallback* node) const;
    void addSample(const Eigen::Vector3d& local, double time);
    void endStroke(bool keep);

    SoSeparator* root_ = nullptr;
    SoEventCallback* callback_ = nullptr;
    SoCoordinate3* previewPoints_ = nullptr;
    SoLineSet* previewLine_ = nullptr;
    bool enabled_ = false;
    bool drawing_ = false;
    scene::PlaneFrame frame_;
    double startTime_ = 0.0;
    FinishedStroke stroke_;
    std::function<SoCamera*()> camera_;
    ActivePlane plane_;
    std::function<void(const FinishedStroke&)> finished_;
    std::function<void()> sampled_;
    std::function<double()> clock_;
};

}  // namespace sculptline::manipulators
