#pragma once
// Least-squares primitives for shape recognition (thesis §3.1.1): lines, circles, ellipses and
// polygons fitted to stroke points in their plane, with residuals relative to the stroke's size.
#include <Eigen/Core>
#include <vector>

namespace sculptline::solvers::stroke {

using Point2 = Eigen::Vector2d;

/// Total-least-squares line (principal axis of the points).
struct LineFit {
    Point2 point, direction;  ///< a point on the line and its unit direction
    double maxResidual = 0;   ///< largest distance of a point to the line
};
LineFit fitLine(const std::vector<Point2>& pts);

/// Circle by the algebraic fit of Kasa (1976), then Gauss-Newton on the geometric distance
/// (Chernov, "Circular and Linear Regression", 2010, §4.2): the algebraic fit is biased for arcs.
struct CircleFit {
    Point2 center = Point2::Zero();
    double radius = 0;
    double maxResidual = 0;  ///< max | |p - c| - r |
    bool valid = false;
};
CircleFit fitCircle(const std::vector<Point2>& pts);

/// Ellipse by the direct least-squares fit of Fitzgibbon, Pilu & Fisher (1999) in the numerically
/// stable form of Halir & Flusser (1998), on coordinates centred and scaled for conditioning.
struct EllipseFit {
    Point2 center = Point2::Zero();
    double a = 0, b = 0;     ///< semi-axes, a >= b
    double angle = 0;        ///< direction of the a-axis, radians
    double maxResidual = 0;  ///< max distance of a point to the ellipse (sampled at 720 points)
    bool valid = false;
};
EllipseFit fitEllipse(const std::vector<Point2>& pts);

/// Max distance of the points, in order, to the polyline through `vertices` (closed: back to the
/// first), each point measured against the nearest edge.
double polylineResidual(const std::vector<Point2>& pts, const std::vector<Point2>& vertices, bool closed);

}  // namespace sculptline::solvers::stroke
