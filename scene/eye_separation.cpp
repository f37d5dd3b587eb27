#include "scene/eye_separation.h"

#include <Inventor/nodes/SoCamera.h>

#include <algorithm>

namespace sculptline::scene {

float eyeSeparation(const SbBox3f& box, const SoCamera& camera)
{
    const float focal = camera.focalDistance.getValue();
    if (box.isEmpty()) return std::max(0.0f, focal) / kNearDistancePerEyeSeparation;
    SbVec3f forward;
    camera.orientation.getValue().multVec(SbVec3f(0, 0, -1), forward);
    const float diagonal = (box.getMax() - box.getMin()).length();
    const float centreDepth = (box.getCenter() - camera.position.getValue()).dot(forward);
    const float nearest = std::max(centreDepth - 0.5f * diagonal, kMinNearDistancePerDiagonal * diagonal);
    return nearest / kNearDistancePerEyeSeparation;
}

}  // namespace sculptline::scene
