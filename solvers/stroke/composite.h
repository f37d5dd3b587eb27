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
/// previous), Touching (within `touch`), Disjoint.
std::vector<Relation> relate(const Recognition& previous, const Recognition& current, const RelationOptions& o = {});

/// Composite objects of Fig. 3-4 built from a pair of strokes.
enum class CompositeKind { None, Prism, Cylinder, Cone, Extrusion, Skinning };
const char* compositeName(CompositeKind k);

/// Fig. 3-4: (a) prism = triangle crossed by a line; (b) cylinder = line starting on and outside a
/// circle or ellipse; (c) cone = line starting inside a circle or ellipse; extrusion = any other
/// closed profile with a line touching it; (e) skinning = two open curves side by side (disjoint,
/// roughly parallel).
CompositeKind composeShapes(const Recognition& previous, const Recognition& current, const std::vector<Relation>& rel);

}  // namespace sculptline::solvers::stroke
