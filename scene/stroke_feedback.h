#pragma once
// What the fitter made of the last stroke, shown in the viewport (issue 5 §3, recognition
// feedback): the sampling points the least squares used as small dots, the detected corners as
// larger red ones. World coordinates; replaced by the next stroke.
#include <Eigen/Core>

#include <vector>

class SoCoordinate3;
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
    void show(const std::vector<Eigen::Vector3d>& samples, const std::vector<Eigen::Vector3d>& corners);
    void clear() { show({}, {}); }
    int sampleCount() const;
    int cornerCount() const;

private:
    SoSeparator* root_ = nullptr;
    SoCoordinate3* samples_ = nullptr;
    SoCoordinate3* corners_ = nullptr;
};

}  // namespace sculptline::scene
