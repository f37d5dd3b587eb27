#pragma once
// Independent measurements of a fitted curve for the stroke tests.
#include "solvers/bspline/bspline_curve.h"
#include "solvers/geometry/plane_fit.h"
#include "solvers/stroke/stroke_synthesis.h"

#include <algorithm>
#include <cmath>

namespace sculptline::stroketest {

using Vec3 = Eigen::Vector3d;
using namespace solvers::stroke;

/// Max distance from `pts` to the curve, measured against a 20,000-segment polyline of it (the
/// chord sagitta at that resolution is below 1e-7 of the curve's size): a measurement independent
/// of the fitter's own foot-point search and of the kernel's CurveProjector (which missed foot
/// points beside G0 triple knots until commit 39980b6).
inline double maxDeviation(const solvers::Curve3d& c, const std::vector<Vec3>& pts)
{
    std::vector<Vec3> dense;
    constexpr int kSegments = 20000;
    for (int i = 0; i <= kSegments; ++i) {
        dense.push_back(c.evaluate(c.domainStart() + (c.domainEnd() - c.domainStart()) * i / kSegments));
    }
    double m = 0;
    for (const auto& p : pts) m = std::max(m, distanceToPolyline(p, dense, false));
    return m;
}

/// Largest distance of the points from their best-fit plane: how far from planar a space curve is.
inline double distanceFromBestPlane(const std::vector<Vec3>& pts)
{
    const solvers::PlaneFit plane = solvers::bestFitPlane(pts);
    double d = 0.0;
    for (const Vec3& p : pts) d = std::max(d, std::abs((p - plane.centroid).dot(plane.normal)));
    return d;
}

}  // namespace sculptline::stroketest
