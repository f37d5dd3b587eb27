#pragma once
// Building blocks for overlays: the scene's references rather than its objects (ground grid, stroke
// preview and feedback, pull handles).
#include <Inventor/SbColor.h>

class SoCoordinate3;
class SoSeparator;

namespace sculptline::scene {

/// A separator whose contents are unpickable, so that clicks reach what lies beneath, and unlit
/// (BASE_COLOR), so that they read the same from every side. The caller owns the reference count.
SoSeparator* makeOverlayRoot();

/// Adds a base colour, a draw style and an empty SoCoordinate3 to `group` and returns the
/// coordinates; the caller adds the shape (SoPointSet, SoLineSet) after it.
/// @param pointSize points in pixels (0: Coin's default)
/// @param lineWidth lines in pixels (0: Coin's default)
SoCoordinate3* addStyledCoordinates(SoSeparator* group, const SbColor& color, float pointSize, float lineWidth);

}  // namespace sculptline::scene
