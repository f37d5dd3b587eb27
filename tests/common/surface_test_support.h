#pragma once
// Shared by the surface entity tests (headless), the surface model replay checks and the model tests.
#include "solvers/bspline/bspline_surface.h"
#include "solvers/bspline/projection.h"

#include <algorithm>

namespace sculptline::guitest {

/// Largest distance from 41 evenly spaced samples of `curve` to `surface` (a defining curve is met
/// when this is round-off).
inline double curveToSurface(const solvers::Curve3d& curve, const solvers::Surface3d& surface)
{
    const solvers::SurfaceProjector projector(surface);
    double worst = 0.0;
    for (int k = 0; k <= 40; ++k) {
        const double u = curve.domainStart() + (curve.domainEnd() - curve.domainStart()) * k / 40.0;
        worst = std::max(worst, projector.project(curve.evaluate(u)).distance);
    }
    return worst;
}

}  // namespace sculptline::guitest
