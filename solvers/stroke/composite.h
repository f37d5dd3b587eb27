#pragma once
// Composite reasoning between successive strokes (thesis §3.1.1, Table 3-1 STEP 4, Fig. 3-4):
// topological relations and the composite objects they form.
#include "solvers/stroke/shape_recognizer.h"

namespace sculptline::solvers::stroke {

/// Relations of the current stroke to the previous one (thesis §3.1.3 constraints C7-C11 and
/// Fig. 3-3: parallel, intersect, vertical, disjoint).
enum class Relation { Parallel, Perpendicular, Touching, Overlapping, Inside, Disjoint };
const char* relationName(Relation r);

struct RelationOptions {
    double angle = 0.14;  ///< parallel / perpendicular within 8 degrees
    /// Strokes closer than this share of the smaller extent touch (a pen lands within ~2 mm of
    /// where it aims on a 100 mm sketch).
    double touch = 0.05;
};

/// Relations of `current` to `previous`: any of Parallel / Perpendicular (both line-like) together
/// with exactly one of Overlapping (the strokes cross), Inside (current lies inside the closed
/// previous), Touching (within `touch`, or crossing only within `touch` of an open stroke's end),
/// Disjoint.
std::vector<Relation> relate(const Recognition& previous, const Recognition& current, const RelationOptions& o = {});

/// Composite objects of Fig. 3-4: from a pair of strokes (a, b, c, e), or from three (d).
enum class CompositeKind { None, Prism, Cylinder, Cone, Extrusion, Skinning, PolygonVolume };
const char* compositeName(CompositeKind k);

/// Fig. 3-4: (a) prism = triangle crossed by a line; (b) cylinder = line starting on and outside a
/// circle or ellipse; (c) cone = line starting inside a circle or ellipse; extrusion = any other
/// closed profile with a line touching it; (e) skinning = two open curves side by side (disjoint,
/// roughly parallel).
CompositeKind composeShapes(const Recognition& previous, const Recognition& current, const std::vector<Relation>& rel);

struct VolumeOptions {
    /// The top face's extent may differ from the profile's by this share (a hand redraws a shape
    /// within ~15 % of its size).
    double sizeMatch = 0.25;
    /// The top face's centroid must lie within this share of the profile's extent of the profile's
    /// centroid moved by the edge (the translation the edge stroke shows).
    double placement = 0.2;
};

/// Fig. 3-4 (d): "once the sequent three strokes satisfy the predefined spatial topological and
/// sequence constraints, a polygon volume is shown". Our predefined constraints, in drawing order:
/// `first` is a closed polygon (triangle, square, rectangle, diamond, closed polyline), `second` a
/// line that starts on it and leaves it (one lateral edge: the pair's Extrusion, or Prism when the
/// profile is a triangle the edge's start crosses), and `third` closes the volume as
///   - the top face: a polygon of the profile's kind and size whose centroid is the profile's
///     centroid moved along the edge (from its end on the profile to its far end), or
///   - a second lateral edge: a line parallel to the first that touches the profile elsewhere.
/// Returns PolygonVolume, or None when the three strokes do not satisfy these constraints.
CompositeKind composeThree(const Recognition& first, const Recognition& second, const Recognition& third,
                           const VolumeOptions& o = {});

}  // namespace sculptline::solvers::stroke
