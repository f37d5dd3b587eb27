#include "scene/ground_grid.h"

#include "scene/overlay_nodes.h"

#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoSeparator.h>

#include <cmath>
#include <vector>

namespace sculptline::scene {
namespace {

/// A separator holding a colour and a set of two-point lines.
SoSeparator* lineGroup(const std::vector<SbVec3f>& endpoints, const SbColor& color, float width)
{
    auto* group = new SoSeparator;
    SoCoordinate3* coords = addStyledCoordinates(group, color, 0.0f, width);
    coords->point.setValues(0, static_cast<int>(endpoints.size()), endpoints.data());
    group->addChild(coords);
    auto* lines = new SoLineSet;
    const std::vector<int32_t> counts(endpoints.size() / 2, 2);
    lines->numVertices.setValues(0, static_cast<int>(counts.size()), counts.data());
    group->addChild(lines);
    return group;
}

}  // namespace

SoSeparator* makeGroundGrid(const model::GridSpec& grid)
{
    const float half = static_cast<float>(grid.size / 2.0);
    // Lines at multiples of the spacing that fit inside the grid, so the axes are always grid lines.
    const int n = static_cast<int>(std::floor(grid.size / 2.0 / grid.spacing + 1e-9));
    std::vector<SbVec3f> minor, major;
    for (int k = -n; k <= n; ++k) {
        if (k == 0) continue;  // drawn as an axis below
        const float t = static_cast<float>(k * grid.spacing);
        auto& bucket = (k % kGridMajorEvery == 0) ? major : minor;
        bucket.insert(bucket.end(), {SbVec3f(t, -half, 0), SbVec3f(t, half, 0), SbVec3f(-half, t, 0), SbVec3f(half, t, 0)});
    }

    // The grid is a reference, not an object: clicks should reach what lies on it.
    auto* root = makeOverlayRoot();
    root->setName("GroundGrid");
    if (!minor.empty()) root->addChild(lineGroup(minor, SbColor(0.36f, 0.38f, 0.42f), 1.0f));
    if (!major.empty()) root->addChild(lineGroup(major, SbColor(0.52f, 0.55f, 0.6f), 1.0f));
    root->addChild(lineGroup({SbVec3f(-half, 0, 0), SbVec3f(half, 0, 0)}, SbColor(0.85f, 0.3f, 0.3f), 2.0f));
    root->addChild(lineGroup({SbVec3f(0, -half, 0), SbVec3f(0, half, 0)}, SbColor(0.35f, 0.8f, 0.35f), 2.0f));
    return root;
}

}  // namespace sculptline::scene
