#pragma once
// Import of an Open Inventor file as reference geometry to sketch over. The file passes, in order:
// its size (before it is read), the text check of scene/iv_validate.h, Coin's reader (from memory),
// a traversal that checks every shape's indices against the coordinates in effect before Coin draws
// it, and a census of what is drawn (primitive budget, finite coordinates within the document's
// limit after the transforms, a non-empty bounding box). Only then is the graph handed out.
#include "scene/iv_validate.h"

#include <array>
#include <memory>
#include <string>
#include <string_view>

class SoSeparator;

namespace sculptline::scene {

/// What a reference draws, counted by Coin's own primitive generation (every USE drawn again).
struct IvGeometryCensus {
    std::size_t triangles = 0;
    std::size_t segments = 0;
    std::size_t points = 0;
    std::array<double, 3> min{0.0, 0.0, 0.0};  ///< bounding box of the drawn vertices, model units
    std::array<double, 3> max{0.0, 0.0, 0.0};
};

/// A validated graph: Coin's reading of the text, with its Normal, NormalBinding and
/// MaterialBinding nodes and its shapes' normal and material indices removed (a reference is drawn
/// in one colour with normals Coin generates, so no index other than the checked coordinate
/// indices is ever followed).
struct ImportedIv {
    std::shared_ptr<SoSeparator> root;  ///< ref()ed; the last owner unref()s it
    IvTextCensus text;
    IvGeometryCensus geometry;
};

/// Validates and reads `text` (a whole .iv file).
/// @throws solvers::io::InputError naming the problem ("line 4: node type File is not accepted ..",
///         "coordIndex 12 of IndexedFaceSet is past its 8 coordinates", "nothing to draw", ..).
ImportedIv importIvText(std::string_view text, const IvLimits& limits = {});

/// Checks the size of the file at `path` against limits.maxBytes, then reads it and imports it.
/// @throws solvers::io::InputError whose message starts with the path ("x.iv: line 3: ..").
ImportedIv importIvFile(const std::string& path, const IvLimits& limits = {});

/// One line for a status bar: "8 coordinates, 12 triangles; box 20 x 20 x 20".
std::string describe(const ImportedIv& imported);

}  // namespace sculptline::scene
