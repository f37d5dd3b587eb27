#pragma once
// The look of a projection plane: a translucent square with a grid, modelled in its local XY plane.
#include "model/document.h"

class SoSeparator;
class SoTransform;

namespace sculptline::scene {

/// Grid cells along each edge of a projection plane.
constexpr int kPlaneGridCells = 10;

/// The plane's geometry centred on the local origin in the XY plane (normal +Z), edge `size`: a
/// translucent two-sided quad, its border and grid lines; unpickable (clicks go to what is behind
/// it, or to the dragger carrying it). Reference count 0.
SoSeparator* makePlaneGeometry(double size);

/// The transform placing local XY-plane geometry at plane.origin with +Z along plane.normal.
/// Reference count 0.
SoTransform* makePlanePlacement(const model::PlaneSpec& plane);

/// SoSeparator { placement, geometry }: a static plane (no dragger), for scenes without
/// manipulators. Reference count 0.
SoSeparator* makePlaneNode(const model::PlaneSpec& plane);

}  // namespace sculptline::scene
