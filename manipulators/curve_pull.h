#pragma once
// Pulling a point of a curve (thesis §6.1, direct constrained manipulation): press on a curve that
// lies on a plane, drag, release. The pointer's ray meets the curve's plane at pointer rate and the
// point under the handle follows it; the solver (solvers/editing, factored once at the press) is
// run by the caller per event. A marker shows the handle.
#include "manipulators/stroke_input.h"

#include <Eigen/Core>

#include <functional>
#include <optional>

class SoCamera;
class SoCoordinate3;
class SoEventCallback;
class SoSeparator;

namespace sculptline::manipulators {

class CurvePull {
public:
    /// At the press on curve `hit.curve`: the frame of the curve's plane to pull in, or empty to
    /// decline (no curve, a curve in space).
    using Grab = std::function<std::optional<model::PlaneFrame>(const StrokeHit& hit)>;
    /// Per pointer event while pulling: where the handle is, in the plane's local frame (z = 0).
    using Move = std::function<void(const Eigen::Vector3d& local)>;

    CurvePull();
    ~CurvePull();
    CurvePull(const CurvePull&) = delete;
    CurvePull& operator=(const CurvePull&) = delete;

    /// SoSeparator "CurvePull" { SoEventCallback, handle marker }; ref()ed by this object.
    SoSeparator* root() const { return root_; }
    void setEnabled(bool enabled);
    bool pulling() const { return pulling_; }
    void setCamera(std::function<SoCamera*()> camera) { camera_ = std::move(camera); }
    void setCallbacks(Grab grab, Move move, std::function<void()> release);

private:
    static void handleEvent(void* self, SoEventCallback* node);
    void onEvent(SoEventCallback* node);
    void showHandle(const Eigen::Vector3d& world);

    SoSeparator* root_ = nullptr;
    SoEventCallback* callback_ = nullptr;
    SoCoordinate3* handle_ = nullptr;
    bool enabled_ = false;
    bool pulling_ = false;
    model::PlaneFrame frame_;
    std::function<SoCamera*()> camera_;
    Grab grab_;
    Move move_;
    std::function<void()> release_;
};

}  // namespace sculptline::manipulators
