#pragma once
// The tolerance an approximating surface mode (sweep, boundary- and rail-based rotation) works to.
#include "solvers/bspline/bspline_curve.h"

#include <algorithm>
#include <initializer_list>

namespace sculptline::solvers::surfaces {

/// The tightest tolerance an approximating mode accepts, relative to the scale of the model's
/// coordinates (the larger of their spread and their magnitude). The deviation is measured as the
/// distance between two points each computed from coordinates of that magnitude through a few
/// dozen operations (frames, rotations, the interpolation solve, evaluation), each adding about
/// 1.1e-16 relative round-off that the solve's condition number can amplify tenfold or more: below
/// about 1e-13 relative the measured deviation is noise, and refinement chasing it grows the
/// control net to its maximum (seconds of work) without meeting it. 1e-10 leaves three orders of
/// magnitude of margin over that noise and is still 1e6 times finer than the default (1e-4).
/// A requested tolerance below it is clamped to it, not refused: a script asking for "as tight as
/// possible" (1e-300) gets the tightest meaningful surface, and the tolerance actually used is
/// reported beside the result ("tolerance" in the CLI's output).
constexpr double kMinApproximationRelative = 1e-10;

/// The scale of the curves' coordinates: max over their control points of the spread and of the
/// largest coordinate magnitude.
inline double coordinateScale(std::initializer_list<const Curve3d*> curves)
{
    double scale = 0.0;
    for (const Curve3d* c : curves) {
        scale = std::max(scale, c->controlSize());
        for (const auto& q : c->points()) scale = std::max(scale, q.cwiseAbs().maxCoeff());
    }
    return scale;
}

/// `requested` (model units) if positive, else `defaultTolerance`; never below
/// kMinApproximationRelative times `scale` (coordinateScale of the defining curves).
inline double approximationTolerance(double requested, double defaultTolerance, double scale)
{
    const double asked = requested > 0.0 ? requested : defaultTolerance;
    return std::max(asked, kMinApproximationRelative * scale);
}

}  // namespace sculptline::solvers::surfaces
