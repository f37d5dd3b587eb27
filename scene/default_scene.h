#pragma once
// Builds the scene graph of a document (data/default_scene.json by default): ground grid, surfaces,
// curves and projection planes, each under a named node so tools and tests can find them.
#include "model/document.h"

#include <functional>
#include <string>

class SoNode;
class SoSeparator;

namespace sculptline::scene {

/// Makes the node shown for plane `index`. The scene layer draws static planes; the ui passes a
/// factory that wraps them in draggers (manipulators/ sits above scene/ and cannot be called here).
/// The returned node must have reference count 0 (the graph takes it over).
using PlaneFactory = std::function<SoNode*(const model::PlaneSpec& plane, size_t index)>;

/// The graph of `doc`:
///   SoSeparator "SculptlineScene"
///     SoSeparator "GroundGrid"
///     SoGroup "Surfaces" { SoSeparator "Surface0", ... }
///     SoGroup "Curves"   { SoSeparator "Curve0", ... }
///     SoGroup "Planes"   { plane 0, ... }    (last: translucent, drawn over what is behind it)
/// Returned with reference count 0; the caller ref()s it (and unref()s when done).
/// @param planes node factory for the planes; empty = static planes (makePlaneNode).
SoSeparator* buildSceneGraph(const model::SceneDocument& doc, const PlaneFactory& planes = {});

/// model::loadDocument(path) then buildSceneGraph; throws solvers::io::InputError like model::loadDocument.
SoSeparator* buildSceneGraph(const std::string& path, const PlaneFactory& planes = {});

}  // namespace sculptline::scene
