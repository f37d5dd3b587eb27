#pragma once
// The ground grid: the user's sense of scale and of "down" in the modelling space.
#include "model/document.h"

class SoSeparator;

namespace sculptline::scene {

/// Every this many lines one is drawn brighter: with a 10 mm spacing, a major line every 50 mm.
constexpr int kGridMajorEvery = 5;

/// Unlit lines in the plane z = 0, centred on the origin: minor lines, brighter major lines, and
/// the X (red) and Y (green) axes. Reference count 0: the caller owns it.
SoSeparator* makeGroundGrid(const model::GridSpec& grid);

}  // namespace sculptline::scene
