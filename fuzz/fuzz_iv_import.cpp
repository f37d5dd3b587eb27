// The .iv importer (scene/iv_import.h): bytes -> size limit, text check, Coin's reader, index checks
// and census, what File > Import Reference and --import-reference do with a file.
//
// A refusal (InputError) is fine. An accepted file must come out within the limits, with only
// allow-listed node types in Coin's graph (anything else means the text check let a construct
// through that Coin reads as another node), and Coin must be able to bound and write it.
#include "fuzz/fuzz_target.h"
#include "scene/iv_import.h"
#include "solvers/io/geometry_json.h"

#include <Inventor/SoOutput.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoWriteAction.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoSeparator.h>

#include <cmath>
#include <cstdlib>
#include <set>
#include <string>

namespace {

using namespace sculptline;

void checkTypes(const SoNode* node, int depth)
{
    static const std::set<std::string> allowed{
        "Separator", "Group", "TransformSeparator", "Transform", "Translation", "Rotation", "RotationXYZ", "Scale",
        "MatrixTransform", "Coordinate3", "Material", "BaseColor", "DrawStyle", "ShapeHints", "Complexity", "LightModel",
        "IndexedFaceSet", "IndexedLineSet", "FaceSet", "LineSet", "PointSet", "Cube", "Sphere", "Cone", "Cylinder"};
    const std::string type = node->getTypeId().getName().getString();
    if (!allowed.count(type)) fuzz::fuzzFailure("iv-import", "an accepted file holds a " + type + " node");
    if (depth > scene::IvLimits{}.maxDepth + 1) fuzz::fuzzFailure("iv-import", "an accepted file nests deeper than the limit");
    if (node->isOfType(SoGroup::getClassTypeId())) {
        const auto* group = static_cast<const SoGroup*>(node);
        for (int i = 0; i < group->getNumChildren(); ++i) checkTypes(group->getChild(i), depth + 1);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    scene::ImportedIv imported;
    try {
        imported = scene::importIvText(std::string(reinterpret_cast<const char*>(data), size));
    } catch (const solvers::io::InputError& e) {
        fuzz::noteRejected(e.what());
        return 0;
    }
    const scene::IvLimits limits;
    const scene::IvGeometryCensus& g = imported.geometry;
    if (g.triangles + g.segments + g.points == 0) fuzz::fuzzFailure("iv-import", "accepted with nothing to draw");
    if (g.triangles + g.segments + g.points > limits.maxPrimitives) fuzz::fuzzFailure("iv-import", "accepted over the primitive budget");
    for (int k = 0; k < 3; ++k) {
        if (!(std::abs(g.min[k]) <= limits.maxCoordinate && std::abs(g.max[k]) <= limits.maxCoordinate && g.min[k] <= g.max[k]))
            fuzz::fuzzFailure("iv-import", "accepted with a bounding box outside the limits");
    }
    checkTypes(imported.root.get(), 0);
    // What the viewer and File > Frame do with it, and a write (the graph must be consistent).
    SoGetBoundingBoxAction box(SbViewportRegion(640, 480));
    box.apply(imported.root.get());
    SoOutput out;
    out.setBuffer(nullptr, 0, [](void* p, size_t n) { return std::realloc(p, n); });
    SoWriteAction write(&out);
    write.apply(imported.root.get());
    void* buffer = nullptr;
    size_t written = 0;
    out.getBuffer(buffer, written);
    std::free(buffer);
    return 0;
}
