#include "scene/stroke_feedback.h"

#include "scene/eigen_coin.h"
#include "scene/overlay_nodes.h"

#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoPointSet.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoTransform.h>

namespace sculptline::scene {
namespace {

/// Sampling points: small and pale, they show density, not objects.
const SbColor kSampleColor(0.85f, 0.9f, 1.0f);
constexpr float kSampleSize = 3.0f;
/// Corners: the pen's red, large enough to count at a glance.
const SbColor kCornerColor(0.95f, 0.2f, 0.2f);
constexpr float kCornerSize = 8.0f;

SoCoordinate3* addDots(SoSeparator* parent, const SbColor& color, float size)
{
    auto* group = new SoSeparator;
    SoCoordinate3* coords = addStyledCoordinates(group, color, size, 0.0f);
    group->addChild(new SoPointSet);
    parent->addChild(group);
    return coords;
}

}  // namespace

StrokeFeedback::StrokeFeedback()
{
    root_ = makeOverlayRoot();
    root_->ref();
    root_->setName("StrokeFeedback");
    frame_ = new SoTransform;
    root_->addChild(frame_);
    samples_ = addDots(root_, kSampleColor, kSampleSize);
    corners_ = addDots(root_, kCornerColor, kCornerSize);
}

StrokeFeedback::~StrokeFeedback() { root_->unref(); }

void StrokeFeedback::show(const model::PlaneFrame& frame, const std::vector<Eigen::Vector3d>& samples,
                          const std::vector<Eigen::Vector3d>& corners)
{
    setFrame(frame);
    setPoints(samples_->point, samples);
    setPoints(corners_->point, corners);
}

void StrokeFeedback::setFrame(const model::PlaneFrame& frame)
{
    frame_->translation = toSb(frame.origin);
    frame_->rotation = toSb(frame.rotation);
}

int StrokeFeedback::sampleCount() const { return samples_->point.getNum(); }
int StrokeFeedback::cornerCount() const { return corners_->point.getNum(); }

}  // namespace sculptline::scene
