#pragma once
// The aesthetic operators in the viewport (thesis §7.4, issue 16 §3): a one-axis handle on the
// operated characteristic point of the selected curve, and its binding to the model. Dragging the
// handle sets the operator's amount: the operator's constraints are factored once at the press
// (solvers/aesthetics OperatorDrag), each dragger event is one product and one Model::setCurveShape
// (the scheduler updates the dependents once per frame), the release ends the drag and hands the
// shape before to the caller for one undo step.
//   SoSeparator "AestheticHandle" { SoSwitch { SoTransform placement, SoTranslate1Dragger } }
#include "model/model.h"
#include "solvers/aesthetics/curve_operators.h"

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <optional>
#include <string>

class SoDragger;
class SoSeparator;
class SoSwitch;
class SoTransform;
class SoTranslate1Dragger;
class SoNodeSensor;
class SoSensor;

namespace sculptline::scene {
class UpdateScheduler;
}

namespace sculptline::manipulators {

/// Where the handle of an operator sits and which way its amount grows, in world coordinates.
struct AestheticHandlePlacement {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  ///< unit
    double size = 1.0;                                      ///< the handle's length scale, model units
};

/// The operator's set-up on a model curve (its plane-local shape read in its plane), and the handle.
/// @throws solvers::GeometryError when the operator does not apply (the message says why).
struct AestheticOperation {
    solvers::aesthetics::OperatorSetup setup;
    solvers::aesthetics::PlaneFrame planar;  ///< the curve's local shape's plane (z = 0 on a plane)
    AestheticHandlePlacement handle;
};
AestheticOperation prepareAesthetic(const model::Model& model, model::EntityId curve, solvers::aesthetics::Operator op,
                                    const solvers::aesthetics::OperatorOptions& options = {});

class AestheticHandle {
public:
    AestheticHandle();
    ~AestheticHandle();
    AestheticHandle(const AestheticHandle&) = delete;
    AestheticHandle& operator=(const AestheticHandle&) = delete;

    SoSeparator* root() const { return root_; }
    /// Shows the handle there (the amount starts at 0), or hides it.
    void show(const AestheticHandlePlacement& placement);
    void hide();
    bool visible() const;
    /// The amount the handle has been dragged along its direction, model units (may be negative).
    double amount() const;
    /// Called at the press, per move, and at the release.
    void setCallbacks(std::function<void()> started, std::function<void(double amount)> moved, std::function<void()> finished);
    SoTranslate1Dragger* dragger() const { return dragger_; }

private:
    static void startedCb(void* self, SoDragger*);
    static void finishedCb(void* self, SoDragger*);
    static void changedCb(void* self, SoSensor*);

    SoSeparator* root_ = nullptr;
    SoSwitch* switch_ = nullptr;
    SoTransform* placement_ = nullptr;
    SoTranslate1Dragger* dragger_ = nullptr;
    SoNodeSensor* sensor_ = nullptr;
    double size_ = 1.0;
    bool dragging_ = false;
    std::function<void()> started_;
    std::function<void(double)> moved_;
    std::function<void()> finished_;
};

/// Drives the model from the handle: grab at the press, moveTo per event, release at the end.
class AestheticDragBinding {
public:
    /// A finished drag: the curve, its local shape at the press, the amount, the solver's remark.
    using Finished = std::function<void(model::EntityId curve, const solvers::Curve3d& before, double amount, const std::string& message)>;

    AestheticDragBinding(model::Model& model, scene::UpdateScheduler& scheduler);
    /// Factors the operator on `curve`; false (and `error`) when it does not apply.
    bool grab(model::EntityId curve, solvers::aesthetics::Operator op, const solvers::aesthetics::OperatorOptions& options,
              std::string* error = nullptr);
    /// The curve for amount `amount` (negative amounts count as 0: operators take amounts >= 0).
    void moveTo(double amount);
    void release();
    bool active() const { return curve_ != 0; }
    void setFinished(Finished finished) { finished_ = std::move(finished); }

private:
    model::Model& model_;
    scene::UpdateScheduler& scheduler_;
    model::EntityId curve_ = 0;
    std::optional<AestheticOperation> operation_;
    std::unique_ptr<solvers::aesthetics::OperatorDrag> drag_;
    std::optional<solvers::Curve3d> before_;
    double amount_ = 0.0;
    std::string message_;
    Finished finished_;
};

}  // namespace sculptline::manipulators
