#pragma once
// The stereo eye separation from the model's size and the camera's distance to it.
//
// Rule: the stereographers' "1/30 rule" (interaxial distance = 1/30 of the distance from the
// lenses to the nearest subject; e.g. B. Mendiburu, "3D Movie Making", 2009, ch. 4). It keeps the
// nearest point's on-screen parallax small enough to fuse comfortably whatever the model's units:
// a 20 mm part seen from 60 mm and a 5 m hull seen from 15 m look equally deep. The nearest
// subject is the front of the model's bounding sphere (half the bounding-box diagonal in front of
// its centre's depth), so the separation follows the camera as it zooms in and out.
#include <Inventor/SbBox3f.h>

class SoCamera;

namespace sculptline::scene {

/// The 1/30 rule's divisor: nearest-subject distance / eye separation.
constexpr float kNearDistancePerEyeSeparation = 30.0f;
/// Lower bound of the nearest distance, as a fraction of the bounding-box diagonal: with the camera
/// inside the model's bounding sphere the front of the sphere is behind the eye, and the
/// separation would vanish (or turn negative).
constexpr float kMinNearDistancePerDiagonal = 0.05f;

/// Eye separation (model units) for `camera` looking at a model bounded by `box`.
/// @param box world-space bounding box of the model; empty: the focal distance stands for the
///        nearest distance (nothing to be nearer).
/// @return > 0 for a camera with a positive focal distance; 0 for a degenerate one.
float eyeSeparation(const SbBox3f& box, const SoCamera& camera);

}  // namespace sculptline::scene
