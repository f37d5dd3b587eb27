#include "scene/solid_node.h"
#include "scene/iv_export.h"

#include "scene/eigen_coin.h"
#include "scene/geometry_nodes.h"
#include "scene/ground_grid.h"
#include "scene/plane_node.h"
#include "solvers/io/geometry_json.h"

#include <Inventor/SoOutput.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/actions/SoWriteAction.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoPolygonOffset.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoTransform.h>

#include <cstdio>
#include <string>

namespace sculptline::scene {
namespace {

SoSeparator* named(const char* name)
{
    auto* node = new SoSeparator;
    node->setName(name);
    return node;
}

/// SoPolygonOffset is a Coin (and Inventor 2.1.x TGS) extension that SGI's 2.1 reader does not
/// know; it only nudges depth for drawing, so the export leaves it out.
void removePolygonOffsets(SoSeparator* root)
{
    SoSearchAction search;
    search.setType(SoPolygonOffset::getClassTypeId());
    search.setInterest(SoSearchAction::ALL);
    search.apply(root);
    const SoPathList& paths = search.getPaths();
    for (int i = 0; i < paths.getLength(); ++i) {
        const SoPath* path = paths[i];
        auto* parent = static_cast<SoGroup*>(path->getNodeFromTail(1));
        parent->removeChild(path->getTail());
    }
}

}  // namespace

SoSeparator* makeExportGraph(const model::Model& model, const model::GridSpec& grid)
{
    auto* root = named("SculptlineExport");
    root->ref();
    root->addChild(makeGroundGrid(grid));
    SoSeparator* surfaces = named("Surfaces");
    SoSeparator* curves = named("Curves");
    SoSeparator* planes = named("Planes");
    root->addChild(surfaces);
    root->addChild(curves);
    root->addChild(planes);
    for (const auto& [id, e] : model.entities()) {
        if (!model::hasFiniteGeometry(e)) continue;  // as the view: a NaN never reaches Coin
        const std::string name = std::string(model::kindName(e.kind)) + std::to_string(id);
        SoSeparator* node = nullptr;
        switch (e.kind) {
        case model::EntityKind::Surface:
            if (!e.surface) continue;  // a construction that failed to build: nothing to draw
            node = makeSurfaceNode(*e.surface);
            surfaces->addChild(node);
            break;
        case model::EntityKind::Curve:
            // World coordinates: the exported file carries no plane hierarchy to interpret.
            node = makeCurveNode(e.world ? *e.world : *e.local);
            curves->addChild(node);
            break;
        case model::EntityKind::Point: continue;  // a construction aid, not geometry
        case model::EntityKind::Solid:
            if (!e.solid) continue;  // not converted yet
            node = makeSolidNode(e.solid->mesh);
            surfaces->addChild(node);
            break;
        case model::EntityKind::Mesh:
            node = makeMeshNode(e.mesh->vertices, e.mesh->normals, e.mesh->triangles);
            surfaces->addChild(node);
            break;
        case model::EntityKind::Plane: {
            node = new SoSeparator;
            auto* placement = new SoTransform;
            placement->translation = toSb(e.frame.origin);
            placement->rotation = toSb(e.frame.rotation);
            node->addChild(placement);
            node->addChild(makePlaneGeometry(e.frame.size));
            planes->addChild(node);
            break;
        }
        }
        node->setName(name.c_str());
    }
    removePolygonOffsets(root);
    root->unrefNoDelete();
    return root;
}

void exportIv(const model::Model& model, const model::GridSpec& grid, const std::string& path)
{
    SoSeparator* root = makeExportGraph(model, grid);
    root->ref();
    SoOutput out;
    const bool opened = out.openFile(path.c_str());
    if (opened) {
        SoWriteAction write(&out);
        write.apply(root);
        out.closeFile();
    }
    root->unref();
    if (!opened) throw solvers::io::InputError(path + ": cannot write file");
}

}  // namespace sculptline::scene
