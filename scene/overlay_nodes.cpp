#include "scene/overlay_nodes.h"

#include <Inventor/nodes/SoBaseColor.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoPickStyle.h>
#include <Inventor/nodes/SoSeparator.h>

namespace sculptline::scene {

SoSeparator* makeOverlayRoot()
{
    auto* root = new SoSeparator;
    auto* pick = new SoPickStyle;
    pick->style = SoPickStyle::UNPICKABLE;
    root->addChild(pick);
    auto* light = new SoLightModel;
    light->model = SoLightModel::BASE_COLOR;
    root->addChild(light);
    return root;
}

SoCoordinate3* addStyledCoordinates(SoSeparator* group, const SbColor& color, float pointSize, float lineWidth)
{
    auto* base = new SoBaseColor;
    base->rgb = color;
    group->addChild(base);
    auto* style = new SoDrawStyle;
    style->pointSize = pointSize;
    style->lineWidth = lineWidth;
    group->addChild(style);
    auto* coords = new SoCoordinate3;
    coords->point.setNum(0);
    group->addChild(coords);
    return coords;
}

}  // namespace sculptline::scene
