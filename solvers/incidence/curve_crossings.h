#pragma once
// Where two domain curves cross: the point incidences that tie two curve constraints on one surface
// (seed 000 §3.2, Fig. 3: the crossings P1, P2).
#include "solvers/bspline/bspline_curve.h"

#include <vector>

namespace sculptline::solvers::incidence {

struct Crossing {
    double t1 = 0.0;  ///< parameter on the first curve
    double t2 = 0.0;  ///< parameter on the second curve
    Eigen::Vector2d point = Eigen::Vector2d::Zero();
};

/// The crossings of two non-rational 2D B-spline curves, sorted by t1: Bezier pieces of both,
/// recursive subdivision of pairs whose bounding boxes overlap, then Newton on
/// G1(t1) - G2(t2) = 0 from each candidate; candidates within 1e-7 of each domain length merge.
/// Touching curves report the touch point (to about 1e-8 of their size); curves that overlap along
/// a stretch report points along it (at most 1000 candidates are followed).
/// @throws GeometryError for rational curves.
std::vector<Crossing> curveCrossings(const Curve2d& first, const Curve2d& second);

}  // namespace sculptline::solvers::incidence
