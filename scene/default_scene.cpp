#include "scene/default_scene.h"

#include "scene/geometry_nodes.h"
#include "scene/ground_grid.h"
#include "model/model.h"
#include "model/model_document.h"
#include "scene/plane_node.h"

#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoSeparator.h>

#include <array>

namespace sculptline::scene {
namespace {

// Curves in warm colours, surfaces in cool ones, so the two never read as the same kind of thing.
const std::array<SbColor, 3> kCurveColors{SbColor(1.0f, 0.5f, 0.1f), SbColor(0.95f, 0.85f, 0.2f),
                                          SbColor(0.95f, 0.3f, 0.55f)};
const std::array<SbColor, 3> kSurfaceColors{SbColor(0.35f, 0.62f, 0.9f), SbColor(0.4f, 0.8f, 0.65f),
                                            SbColor(0.65f, 0.55f, 0.9f)};

SoGroup* namedGroup(const char* name)
{
    auto* group = new SoGroup;
    group->setName(name);
    return group;
}

std::string indexedName(const char* prefix, size_t i) { return prefix + std::to_string(i); }

/// Curve i in world coordinates (a curve on a plane is stored in the plane's frame).
solvers::Curve3d worldCurve(const model::SceneDocument& doc, size_t i)
{
    const int plane = i < doc.curvePlanes.size() ? doc.curvePlanes[i] : 0;
    for (const model::PlaneSpec& p : doc.planes) {
        if (plane != 0 && p.id == plane) return model::transformCurve(doc.curves[i], model::planeFrame(p));
    }
    return doc.curves[i];
}

}  // namespace

SoSeparator* buildSceneGraph(const model::SceneDocument& doc, const PlaneFactory& planes)
{
    // Built under a ref so that an exception from a factory cannot leak the partial graph.
    auto* root = new SoSeparator;
    root->ref();
    try {
        root->setName("SculptlineScene");
        root->addChild(makeGroundGrid(doc.grid));

        SoGroup* surfaces = namedGroup("Surfaces");
        root->addChild(surfaces);
        for (size_t i = 0; i < doc.surfaces.size(); ++i) {
            SurfaceStyle style;
            style.color = kSurfaceColors[i % kSurfaceColors.size()];
            SoSeparator* node = makeSurfaceNode(doc.surfaces[i], style);
            node->setName(indexedName("Surface", i).c_str());
            surfaces->addChild(node);
        }

        SoGroup* curves = namedGroup("Curves");
        root->addChild(curves);
        for (size_t i = 0; i < doc.curves.size(); ++i) {
            CurveStyle style;
            style.color = kCurveColors[i % kCurveColors.size()];
            SoSeparator* node = makeCurveNode(worldCurve(doc, i), style);
            node->setName(indexedName("Curve", i).c_str());
            curves->addChild(node);
        }

        SoGroup* planeGroup = namedGroup("Planes");
        root->addChild(planeGroup);
        for (size_t i = 0; i < doc.planes.size(); ++i) {
            SoNode* node = planes ? planes(doc.planes[i], i) : makePlaneNode(doc.planes[i]);
            node->setName(indexedName("Plane", i).c_str());
            planeGroup->addChild(node);
        }
    } catch (...) {
        root->unref();
        throw;
    }
    root->unrefNoDelete();
    return root;
}

SoSeparator* buildSceneGraph(const std::string& path, const PlaneFactory& planes)
{
    return buildSceneGraph(model::loadDocument(path), planes);
}

}  // namespace sculptline::scene
