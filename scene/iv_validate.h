#pragma once
// The text check an .iv file passes before Coin's reader sees it. Coin 4.0.0's SoInput predates
// later parser fixes (buffer overreads, recursive PROTOs, malformed paths: Coin 4.0.9/4.0.10), and
// loads a shared library for a node type it does not know (SoType::fromName). So the text must be
// Open Inventor 2.x ASCII made only of plain geometry and property nodes whose fields are written
// as plain values: no strings, no file names, no engines or connections, no PROTO, no nesting or
// instancing beyond the limits below. Plain C++: no Coin here, so every refusal is testable alone.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace sculptline::scene {

/// What an imported reference may cost. Each limit is reached by geometry far beyond what one
/// sketches over, long before the memory or time of this machine runs out.
struct IvLimits {
    /// File size, checked before reading: 64 MiB holds a mesh of about one million triangles as
    /// text (Coordinate3 ~30 bytes a point, coordIndex ~30 bytes a triangle).
    std::size_t maxBytes = std::size_t{64} << 20;
    /// Nodes inside nodes. Coin's reader and every traversal recurse per level; exporters write
    /// fewer than 20.
    int maxDepth = 64;
    /// Nodes written in the file (DEF and USE included).
    std::size_t maxNodes = 200000;
    /// Numbers written in all fields (the text's tokens are at most this plus the punctuation).
    std::size_t maxNumbers = 32000000;
    /// Points of all Coordinate3 nodes: 2e6 points are 24 MB in Coin's floats.
    std::size_t maxCoordinates = 2000000;
    /// Values traversed once every USE is expanded (each USE draws its node again): stops a file
    /// of a few kilobytes whose nested USEs multiply into billions of triangles. A mesh of
    /// maxPrimitives triangles holds about 22 million values (2e6 points, 4 indices a triangle).
    double maxInstancedValues = 24e6;
    /// Triangles, line segments and points drawn (counted by Coin after the text check).
    std::size_t maxPrimitives = 4000000;
    /// Largest coordinate after the transforms, model units: the document's own limit (Coin draws in
    /// float, whose resolution at 1e6 is 0.06 units).
    double maxCoordinate = 1e6;
};

/// What the text holds.
struct IvTextCensus {
    std::size_t nodes = 0;  ///< nodes written (a USE counts once)
    std::size_t numbers = 0;
    std::size_t coordinates = 0;  ///< Coordinate3 points written
    int depth = 0;  ///< deepest nesting of nodes
    double instancedValues = 0.0;  ///< values traversed with every USE expanded
};

/// Checks `text` (the whole file) against the header, the node allow-list, each node's fields and
/// `limits` (all but maxBytes, maxPrimitives and maxCoordinate, which need the file or Coin).
/// Accepted nodes: Separator, Group, TransformSeparator, Transform, Translation, Rotation,
/// RotationXYZ, Scale, MatrixTransform, Coordinate3, Normal, NormalBinding, Material,
/// MaterialBinding, BaseColor, DrawStyle, ShapeHints, Complexity, LightModel, IndexedFaceSet,
/// IndexedLineSet, FaceSet, LineSet, PointSet, Cube, Sphere, Cone, Cylinder ("So" prefix allowed).
/// @throws solvers::io::InputError "line N: <problem>" (or, for the header, "<problem>").
IvTextCensus validateIvText(std::string_view text, const IvLimits& limits = {});

}  // namespace sculptline::scene
