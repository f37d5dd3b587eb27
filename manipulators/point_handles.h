#pragma once
// Sculpt handles (thesis Fig. 6-5 c–d): one small Coin SoJackDragger (without its scaler) per Point
// entity of the model, kept in step with the model as its observer, like manipulators/plane_binding.h
// does for planes. The jack's centre translates the point in 3D, its outer sphere turns it. A drag
// calls model.beginDrag(point) at the press (the sculpts it drives factor once), writes the pose
// into the model on every dragger event (the scheduler solves once per frame) and endDrag() at the
// release; any other change of a point (undo, redo, a document) puts its jack where the model says.
//   SoSeparator "PointHandles" { SoSeparator "Point<id>" { SoTransform placement, SoScale s,
//                                                          SoJackDragger } .. }
#include "model/model.h"

#include <Eigen/Geometry>

#include <functional>
#include <map>
#include <memory>

class SoDragger;
class SoJackDragger;
class SoNodeSensor;
class SoSensor;
class SoSeparator;
class SoTransform;
class SoTranslation;

namespace sculptline::scene {
class UpdateScheduler;
}

namespace sculptline::manipulators {

/// A point's pose: where it is and how it is turned (model::Entity's position and rotation).
struct PointPose {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
    bool operator==(const PointPose& o) const { return position == o.position && rotation.coeffs() == o.rotation.coeffs(); }
    bool operator!=(const PointPose& o) const { return !(*this == o); }
};

class PointHandle;

class PointHandles : public model::ModelObserver {
public:
    using StartedCallback = std::function<void(model::EntityId point)>;
    /// A drag ended: the pose at the press and the model's pose at the release.
    using FinishedCallback = std::function<void(model::EntityId point, const PointPose& before, const PointPose& after)>;

    PointHandles(model::Model& model, scene::UpdateScheduler& scheduler);
    ~PointHandles() override;
    PointHandles(const PointHandles&) = delete;
    PointHandles& operator=(const PointHandles&) = delete;

    SoSeparator* root() const { return root_; }
    size_t size() const { return handles_.size(); }
    PointHandle* handle(model::EntityId id) const;
    /// The point being dragged (between press and release), 0 = none.
    model::EntityId dragging() const { return dragging_; }
    void setDragCallbacks(StartedCallback started, FinishedCallback finished);

    /// The jack's size (model units) of a point driving a surface whose net spans `extent`.
    static double sizeFor(double extent);

    void entityAdded(const model::Entity& entity) override;
    void entityRemoved(const model::Entity& entity) override;
    void entityUpdated(const model::Entity& entity) override;

private:
    double sizeOf(const model::Entity& point) const;
    void dragStarted(model::EntityId point);
    void dragFinished(model::EntityId point);

    model::Model& model_;
    scene::UpdateScheduler& scheduler_;
    SoSeparator* root_ = nullptr;
    std::map<model::EntityId, std::unique_ptr<PointHandle>> handles_;
    model::EntityId dragging_ = 0;
    PointPose dragStart_;
    StartedCallback started_;
    FinishedCallback finished_;
};

/// One point's jack (an orange ball marks the point). Its pose = placement ∘ (s · dragger translation, dragger rotation).
class PointHandle {
public:
    PointHandle(const PointPose& pose, double size);
    ~PointHandle();
    PointHandle(const PointHandle&) = delete;
    PointHandle& operator=(const PointHandle&) = delete;

    SoSeparator* root() const { return root_; }
    SoJackDragger* dragger() const { return dragger_; }
    PointPose pose() const;
    /// Puts the jack at `pose` without calling the moved callback.
    void setPose(const PointPose& pose);
    double size() const { return size_; }
    /// True while the jack is where setPose() put it (not moved nor turned since).
    bool atRest() const;
    void setMovedCallback(std::function<void()> f) { moved_ = std::move(f); }
    void setDragCallbacks(std::function<void()> started, std::function<void()> finished);

private:
    static void changed(void* self, SoSensor*);
    static void started(void* self, SoDragger*);
    static void finished(void* self, SoDragger*);

    double size_;
    SoSeparator* root_ = nullptr;
    SoTransform* placement_ = nullptr;
    SoJackDragger* dragger_ = nullptr;
    SoTranslation* markerAt_ = nullptr;
    SoNodeSensor* sensor_ = nullptr;
    std::function<void()> moved_, started_, finished_;
};

}  // namespace sculptline::manipulators
