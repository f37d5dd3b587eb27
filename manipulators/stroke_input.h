#pragma once
// Sketching on the active projection plane (thesis §5.1.1–5.1.2): an SoEventCallback turns the
// pointer into a ray through the camera's view volume and intersects it with the plane's equation
// (not its geometry, which is unpickable), at pointer rate, while a preview line follows the pen.
// On release the stroke's points go to the finished callback in the plane's local frame.
//
// Presses that land on a dragger are left to the dragger, so planes stay movable while sketching.
#include "model/plane_frame.h"

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

class SoCamera;
class SoCoordinate3;
class SoEventCallback;
class SoLineSet;
class SoSeparator;

namespace sculptline::manipulators {

/// Where a stroke's end met an existing curve (a pick through its node, scene/entity_path.h).
struct StrokeHit {
    std::uint32_t curve = 0;  ///< entity id; 0 = the stroke end is in the air
    Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< picked point, world
    Eigen::Vector3d view = -Eigen::Vector3d::UnitZ();  ///< eye -> point direction, unit
    bool shift = false;  ///< Shift was held at the press (pull mode: pin instead of pull)
};

/// A click (press and release within a few pixels, nothing drawn): the nearest surface under the
/// pointer, if any (sculpt handles, blocked points and distances are placed by clicks).
struct PointerClick {
    std::uint32_t surface = 0;  ///< entity id; 0 = no surface under the pointer
    Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< picked point on it, world
    Eigen::Vector3d view = -Eigen::Vector3d::UnitZ();  ///< eye -> point direction, unit
};

/// The nearest surface (scene::entityAt on the pick path) under the pointer, not through a dragger.
PointerClick pickSurface(SoEventCallback* node, const Eigen::Vector3d& view);

/// The plane a stroke is previewed on, chosen when the pen goes down (knowing whether it went
/// down on a curve); empty = no stroke.
using ActivePlane = std::function<std::optional<model::PlaneFrame>(const StrokeHit& start)>;

struct FinishedStroke {
    model::PlaneFrame frame;  ///< the plane the points are in
    std::vector<Eigen::Vector3d> points;  ///< in `frame`, z = 0, model units
    std::vector<double> times;  ///< seconds since the pen went down, one per point
    /// The pen's pressure, 0..1, one per point where every sample carried one (a tablet pen); empty
    /// for a mouse (solvers::stroke::Stroke::pressure: the fitter trims light-pressure hooks).
    std::vector<double> pressure;
    /// The pointer's ray per point (world): a stroke that ends on a curve goes onto another plane
    /// (seed 000 §3.1), so its points are intersected again.
    std::vector<Eigen::Vector3d> rayOrigins, rayDirections;
    /// Seconds since the pen went down, one per ray (a ray that misses the plane has no point, and
    /// so no entry in `times`).
    std::vector<double> rayTimes;
    /// The pressure per ray, as `pressure` per point (empty when a sample had none).
    std::vector<double> rayPressure;
    /// Per ray, the rays through the pixel one to the right (x) and one up (y) of it, world: the
    /// pointer's pixel on whatever plane the stroke ends up on (pixelFootprint).
    struct PixelRays {
        Eigen::Vector3d originX, directionX, originY, directionY;
    };
    std::vector<PixelRays> pixelRays;
    StrokeHit start, end;
};

/// The footprint of one pointer pixel on the stroke's plane (`frame`), model units: per ray that
/// meets the plane, the larger distance from its point to the points of its x and y neighbour rays;
/// the median over the stroke (robust to a few rays nearly parallel to the plane). The stroke's
/// samples are whole pixels, so this is the pitch they are quantized to (the fitter's
/// FitOptions::resolution). 0 when unknown (no pixel rays, or none meets the plane).
double pixelFootprint(const FinishedStroke& stroke);

/// The pointer's world ray for the event `node` handles, seen through `camera` (the viewer's
/// aspect-adjusted volume); false without a camera.
bool pointerRay(SoEventCallback* node, SoCamera* camera, Eigen::Vector3d& from, Eigen::Vector3d& direction);
/// pointerRay for the pointer moved by (dx, dy) pixels.
bool pointerRay(SoEventCallback* node, SoCamera* camera, Eigen::Vector3d& from, Eigen::Vector3d& direction, int dx,
                int dy);
/// The nearest curve (scene::entityAt on the pick path) under the pointer, within a few pixels, looking
/// through other shapes.
StrokeHit pickCurve(SoEventCallback* node, const Eigen::Vector3d& view);
/// Where the ray meets the frame's plane, local (z = 0); empty when parallel or behind the eye.
std::optional<Eigen::Vector3d> intersectPlane(const model::PlaneFrame& frame, const Eigen::Vector3d& from,
                                              const Eigen::Vector3d& direction);

/// The points where the rays meet `frame`'s plane, in its local frame (z = 0); rays that miss
/// it (parallel, or the plane behind the eye) are skipped, with their times.
void reproject(FinishedStroke& stroke, const model::PlaneFrame& frame);

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
    /// Where each sample's pen pressure comes from, 0..1, or none (a mouse): the window's last
    /// tablet reading, or a replay's recorded value. A stroke keeps pressure only if every sample
    /// had one.
    void setPressure(std::function<std::optional<double>()> pressure) { pressure_ = std::move(pressure); }
    /// Called on a click (a press and release within a few pixels): also when no plane takes a
    /// stroke (the active-plane callback returned none), so a tool that only clicks can refuse strokes.
    /// `clickOnly` says whether a press that no plane takes is kept for a click (default: no, the
    /// press goes on to the rest of the scene).
    void setClickCallback(std::function<void(const PointerClick&)> f, std::function<bool()> clickOnly = {})
    {
        clicked_ = std::move(f);
        clickOnly_ = std::move(clickOnly);
    }
    /// Called after each accepted pointer sample (stroke latency statistics).
    void setSampleCallback(std::function<void()> f) { sampled_ = std::move(f); }

private:
    static void handleEvent(void* self, SoEventCallback* node);
    void onEvent(SoEventCallback* node);
    /// The pointer's ray in world coordinates.
    bool ray(SoEventCallback* node, Eigen::Vector3d& from, Eigen::Vector3d& direction) const;
    StrokeHit hit(SoEventCallback* node, const Eigen::Vector3d& view) const;
    void addSample(SoEventCallback* node, double time);
    /// Ends the stroke; true when it was a click (nothing drawn).
    bool endStroke(bool keep);
    void click(SoEventCallback* node);

    SoSeparator* root_ = nullptr;
    SoEventCallback* callback_ = nullptr;
    SoCoordinate3* previewPoints_ = nullptr;
    SoLineSet* previewLine_ = nullptr;
    bool enabled_ = false;
    bool drawing_ = false;
    bool clicking_ = false;  ///< a press that no plane took: it can only become a click
    double startTime_ = 0.0;
    /// The pointer's pixel bounding box over the stroke (x0, y0, x1, y1): a click that jittered.
    int pixelBox_[4] = {0, 0, 0, 0};
    FinishedStroke stroke_;
    std::function<SoCamera*()> camera_;
    ActivePlane plane_;
    std::function<void(const FinishedStroke&)> finished_;
    std::function<void()> sampled_;
    std::function<void(const PointerClick&)> clicked_;
    std::function<bool()> clickOnly_;
    std::function<double()> clock_;
    std::function<std::optional<double>()> pressure_;
};

}  // namespace sculptline::manipulators
