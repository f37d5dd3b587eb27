#pragma once
// What the fitter made of the last stroke, shown in the viewport (issue 5 §3, recognition
// feedback): the sampling points the least squares used as small dots, the detected corners as
// larger red ones. In the frame of the plane the stroke's curve lies on, so the dots follow that
// plane when it is dragged; replaced by the next stroke.
#include "model/plane_frame.h"

#include <Eigen/Core>

#include <vector>

class SoCoordinate3;
class SoTransform;
class SoSeparator;

namespace sculptline::scene {

class StrokeFeedback {
public:
    StrokeFeedback();
    ~StrokeFeedback();
    StrokeFeedback(const StrokeFeedback&) = delete;
    StrokeFeedback& operator=(const StrokeFeedback&) = delete;

    /// SoSeparator "StrokeFeedback" (unpickable); ref()ed by this object.
    SoSeparator* root() const { return root_; }
    /// Dots at `samples` and `corners`, given in `frame`'s local coordinates.
    void show(const model::PlaneFrame& frame, const std::vector<Eigen::Vector3d>& samples, const std::vector<Eigen::Vector3d>& corners);
    /// Moves the dots with their plane (one transform write).
    void setFrame(const model::PlaneFrame& frame);
    void clear() { show(model::PlaneFrame{}, {}, {}); }
    int sampleCount() const;
    int cornerCount() const;

private:
    SoSeparator* root_ = nullptr;
    SoCoordinate3* samples_ = nullptr;
    SoCoordinate3* corners_ = nullptr;
    SoTransform* frame_ = nullptr;
};

}  // namespace sculptline::scene
