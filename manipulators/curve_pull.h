#pragma once
// Pulling a point of a curve (thesis §6.1, direct constrained manipulation): press on a curve that
// lies on a plane, drag, release. The pointer's ray meets the curve's plane at pointer rate and the
// point under the handle follows it; CurvePullBinding (below) drives the model with it: the
// model's least-change solver is factored once at the press and re-solved per event. A marker shows
// the handle.
#include "manipulators/stroke_input.h"
#include "model/model.h"

#include <Eigen/Core>

#include <functional>
#include <optional>
#include <string>

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

namespace sculptline::scene {
class UpdateScheduler;
}

namespace sculptline::manipulators {

/// The binding of a curve pull to the model (thesis §6.1): at the grab the model factors the
/// curve's least-change solver once (Model::beginPull, its pins held and fixed points blocked), each
/// pointer event is one Model::pullTo, and the release ends the drag so the surfaces it drove come
/// to rest as fresh builds. The caller decides what a finished pull means (the ui pushes one undo
/// step with the shape before and after).
class CurvePullBinding {
public:
    /// A finished pull: the curve, its plane-local shape at the grab, and the solver's last remark
    /// (a compromise, too few free points; empty when it met everything).
    using Finished = std::function<void(model::EntityId curve, const solvers::Curve3d& before, const std::string& message)>;

    /// Both must outlive this object.
    CurvePullBinding(model::Model& model, scene::UpdateScheduler& scheduler);

    /// Grabs `hit.curve` where the hit is: the frame of its plane to pull in, or empty when it
    /// cannot be pulled (not on a plane; `error` then says why when the model refused it).
    std::optional<model::PlaneFrame> grab(const StrokeHit& hit, std::string* error = nullptr);
    /// Per pointer event: the pulled point goes to `local` (the plane's frame).
    void moveTo(const Eigen::Vector3d& local);
    /// The release: ends the drag and reports it.
    void release();
    void setFinishedCallback(Finished finished) { finished_ = std::move(finished); }
    /// The curve being pulled, or 0.
    model::EntityId pulled() const { return pulled_; }

private:
    model::Model& model_;
    scene::UpdateScheduler& scheduler_;
    model::EntityId pulled_ = 0;
    std::optional<solvers::Curve3d> before_;
    std::string message_;
    Finished finished_;
};

}  // namespace sculptline::manipulators
