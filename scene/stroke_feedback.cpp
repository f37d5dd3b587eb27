#include "scene/stroke_feedback.h"

#include "scene/eigen_coin.h"

#include <Inventor/nodes/SoBaseColor.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoPickStyle.h>
#include <Inventor/nodes/SoPointSet.h>
#include <Inventor/nodes/SoSeparator.h>

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
    auto* base = new SoBaseColor;
    base->rgb = color;
    group->addChild(base);
    auto* style = new SoDrawStyle;
    style->pointSize = size;
    group->addChild(style);
    auto* coords = new SoCoordinate3;
    coords->point.setNum(0);
    group->addChild(coords);
    group->addChild(new SoPointSet);
    parent->addChild(group);
    return coords;
}

}  // namespace

StrokeFeedback::StrokeFeedback()
{
    root_ = new SoSeparator;
    root_->ref();
    root_->setName("StrokeFeedback");
    auto* pick = new SoPickStyle;
    pick->style = SoPickStyle::UNPICKABLE;
    root_->addChild(pick);
    auto* light = new SoLightModel;
    light->model = SoLightModel::BASE_COLOR;
    root_->addChild(light);
    samples_ = addDots(root_, kSampleColor, kSampleSize);
    corners_ = addDots(root_, kCornerColor, kCornerSize);
}

StrokeFeedback::~StrokeFeedback() { root_->unref(); }

void StrokeFeedback::show(const std::vector<Eigen::Vector3d>& samples, const std::vector<Eigen::Vector3d>& corners)
{
    setPoints(samples_->point, samples);
    setPoints(corners_->point, corners);
}

int StrokeFeedback::sampleCount() const { return samples_->point.getNum(); }
int StrokeFeedback::cornerCount() const { return corners_->point.getNum(); }

}  // namespace sculptline::scene
