#pragma once
// Quadrilaterals for the shape recognizer (shape_recognizer.cpp): what a drawn quad is (right
// angles, equal sides, convex), and the regular rectangle, square and diamond it stands for.
#include "solvers/stroke/shape_recognizer.h"

#include <cmath>
#include <vector>

namespace sculptline::solvers::stroke::detail {

/// Direction of a plane vector, radians in (-pi, pi].
inline double angleOf(const Point2& v)
{
    return std::atan2(v.y(), v.x());
}

/// Orientation of a quadrilateral's edges modulo 90 degrees.
double quadOrientation(const std::vector<Point2>& v);

struct QuadShape {
    bool right = false;            ///< every angle within RecognizeOptions::rightAngle of 90 degrees
    bool equal = false;            ///< sides equal within RecognizeOptions::equalSides
    bool axisAligned = false;      ///< sides within 22.5 degrees of the plane's axes (square, not diamond)
    bool convex = false;           ///< every vertex turns the same way
    double smallestAngle = 1e300;  ///< the smallest interior angle, radians
};
/// What the four vertices `v` (in drawing order) make.
QuadShape classifyQuad(const std::vector<Point2>& v, const RecognizeOptions& o);

/// How many of a quad's vertices (sample indices `at`) lie within `sameCorner` samples of a corner
/// the detector found (`detected`) on a loop of `n` samples.
int detectedVertices(const std::vector<int>& at, const std::vector<int>& detected, int n, int sameCorner);

/// The rectangle (square) a quad stands for, one corner per vertex in the vertices' order.
std::vector<Point2> regularRectangle(const std::vector<Point2>& v, bool square);
/// The largest distance of `pts` from that rectangle with its corners rounded by the radius, among
/// f * its shorter half-side for f = 0, 0.05, .. maxShare, that fits closest.
double roundedRectangleResidual(const std::vector<Point2>& pts, const std::vector<Point2>& v, bool square,
                                double maxShare);
/// The same for the convex polygon `v` itself, not the rectangle it stands for (any number of
/// vertices, either orientation): its corners rounded by f * half its smallest width (the least
/// distance between a side's line and the vertex farthest from it; a rectangle's shorter
/// half-side), f = 0, 0.05, .. maxShare. A radius at which the polygon's inward offset loses a side
/// is not tried. Infinity for a polygon that is not convex or has fewer than 3 vertices.
double roundedPolygonResidual(const std::vector<Point2>& pts, const std::vector<Point2>& v, double maxShare);
/// Rhombus: diagonals through the centroid, perpendicular, with the measured half-lengths.
std::vector<Point2> regularDiamond(const std::vector<Point2>& v);

}  // namespace sculptline::solvers::stroke::detail
