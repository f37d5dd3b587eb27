#pragma once
// How a drawn polygon's vertices are found, for the shape recognizer (shape_recognizer.cpp).
#include "solvers/stroke/shape_recognizer.h"

#include <vector>

namespace sculptline::solvers::stroke::detail {

/// Douglas-Peucker-like refinement of g's vertices (g.vertexIndex, g.vertices; a loop with fewer
/// than two is seeded seam-free): a vertex is inserted at the sample farthest from its edge while
/// that lies beyond `insertAbove` and the stroke turns there by at least `minCornerTurn` (seen from
/// the edge's ends or one `cornerLeg` either side), or, on a loop read as three vertices, where the
/// edge is two straight sides (`straightLegs`, RecognizeOptions); then vertices nearly collinear
/// (`collinear`) or ending an edge shorter than `shortEdgeLength` are dropped. Returns how many of
/// the final vertices the corner detector did not find (none within `sameCorner` samples).
int refineVertices(StrokeGeometry& g, double insertAbove, double minCornerTurn, double cornerLeg, double collinear,
                   double shortEdgeLength, int sameCorner, double straightLegs);

/// The polygon's vertices as the intersections of lines fitted to the middle of each edge (`trim`
/// of its samples left out at either end); a vertex stays where its lines are within `minAngle` of
/// parallel or meet farther than `maxShift` from it, and an open stroke's ends are projected onto
/// their edges' lines. One vertex per g.vertices entry, in order.
std::vector<Point2> edgeLineVertices(const StrokeGeometry& g, double trim, double minAngle, double maxShift);

/// A triangle's or quadrilateral's loop vertices moved to the samples nearest where its sides meet
/// (edgeLineVertices), for up to `rounds` rounds; vertices within `sameCorner` samples of a
/// `detected` corner stay (RecognizeOptions::relocateRounds).
void relocateVertices(StrokeGeometry& g, int rounds, double trim, double minAngle, double maxShift,
                      const std::vector<int>& detected, int sameCorner);

}  // namespace sculptline::solvers::stroke::detail
