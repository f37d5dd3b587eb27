#include "scene/plane_node.h"

#include "scene/eigen_coin.h"

#include <Inventor/nodes/SoBaseColor.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoFaceSet.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoPickStyle.h>
#include <Inventor/nodes/SoPolygonOffset.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShapeHints.h>
#include <Inventor/nodes/SoTransform.h>

#include <vector>

namespace sculptline::scene {
namespace {

const SbColor kPlaneColor(0.55f, 0.72f, 0.95f);
/// Mostly see-through: the plane is a drawing aid and must not hide the geometry behind it.
constexpr float kPlaneTransparency = 0.7f;

/// The quad is drawn unlit: a drawing aid reads as a flat tint, and its colour then does not
/// depend on where the light is (a shaded plane seen edge-on turns dark and hides its grid).
SoSeparator* makeQuad(float half)
{
    auto* quad = new SoSeparator;
    auto* lightModel = new SoLightModel;
    lightModel->model = SoLightModel::BASE_COLOR;
    quad->addChild(lightModel);
    auto* material = new SoMaterial;
    material->diffuseColor = kPlaneColor;
    material->transparency = kPlaneTransparency;
    quad->addChild(material);
    auto* hints = new SoShapeHints;
    hints->vertexOrdering = SoShapeHints::COUNTERCLOCKWISE;
    hints->shapeType = SoShapeHints::UNKNOWN_SHAPE_TYPE;
    quad->addChild(hints);
    // The grid lines lie in the quad's plane: push the quad back so they are not half hidden.
    quad->addChild(new SoPolygonOffset);
    auto* coords = new SoCoordinate3;
    const SbVec3f corners[4] = {{-half, -half, 0}, {half, -half, 0}, {half, half, 0}, {-half, half, 0}};
    coords->point.setValues(0, 4, corners);
    quad->addChild(coords);
    auto* face = new SoFaceSet;
    face->numVertices.setValue(4);
    quad->addChild(face);
    return quad;
}

SoSeparator* makeGridLines(float half)
{
    std::vector<SbVec3f> endpoints;
    for (int k = 0; k <= kPlaneGridCells; ++k) {
        const float t = -half + 2.0f * half * static_cast<float>(k) / kPlaneGridCells;
        endpoints.insert(endpoints.end(), {SbVec3f(t, -half, 0), SbVec3f(t, half, 0), SbVec3f(-half, t, 0), SbVec3f(half, t, 0)});
    }
    auto* lines = new SoSeparator;
    auto* lightModel = new SoLightModel;
    lightModel->model = SoLightModel::BASE_COLOR;
    lines->addChild(lightModel);
    auto* color = new SoBaseColor;
    color->rgb = kPlaneColor * 0.8f;
    lines->addChild(color);
    auto* coords = new SoCoordinate3;
    coords->point.setValues(0, static_cast<int>(endpoints.size()), endpoints.data());
    lines->addChild(coords);
    auto* set = new SoLineSet;
    const std::vector<int32_t> counts(endpoints.size() / 2, 2);
    set->numVertices.setValues(0, static_cast<int>(counts.size()), counts.data());
    lines->addChild(set);
    return lines;
}

}  // namespace

SoSeparator* makePlaneGeometry(double size)
{
    const float half = static_cast<float>(size / 2.0);
    auto* root = new SoSeparator;
    root->setName("PlaneGeometry");
    // Unpickable: the plane is moved through its dragger, which sits in the plane; a pickable quad
    // would take the clicks meant for the dragger. Drawing on the plane intersects the mouse ray
    // with the plane's equation, not with this geometry.
    auto* pick = new SoPickStyle;
    pick->style = SoPickStyle::UNPICKABLE;
    root->addChild(pick);
    root->addChild(makeGridLines(half));
    root->addChild(makeQuad(half));
    return root;
}

SoTransform* makePlanePlacement(const model::PlaneSpec& plane)
{
    auto* placement = new SoTransform;
    placement->translation = toSb(plane.origin);
    placement->rotation = rotationFromZ(plane.normal);
    return placement;
}

SoSeparator* makePlaneNode(const model::PlaneSpec& plane)
{
    auto* root = new SoSeparator;
    root->addChild(makePlanePlacement(plane));
    root->addChild(makePlaneGeometry(plane.size));
    return root;
}

}  // namespace sculptline::scene
