#pragma once
// Sweep (thesis mode 4; seed 000 "sweeping mode"): a profile carried along a path by
// rotation-minimizing frames, sampled and approximated by a B-spline surface (The NURBS Book §10.4
// sweeps by skinning sampled instances of the profile).
#include "solvers/bspline/bspline_surface.h"

namespace sculptline::solvers::surfaces {

struct SweepOptions {
    /// Largest allowed distance from the exact sweep (model units); <= 0 means
    /// kDefaultSweepRelative times the size (control-polygon diagonal) of profile and path.
    double tolerance = 0.0;
    /// Upper bound on the number of sections; the deviation reached is reported either way.
    int maxSections = 513;
};

/// 1e-4 of the model's size: a tenth of a pixel when the model spans the viewport.
constexpr double kDefaultSweepRelative = 1e-4;

struct SweepResult {
    Surface3d surface;
    double maxDeviation = 0.0;  ///< measured between sections against the exact sweep (model units)
    int sections = 0;
    double tolerance = 0.0;     ///< the tolerance used
};

/// S(u, v): u along the profile (its degree and knots, clamped), v along the path on [0, 1]
/// (proportional to the path's parameter). The profile is taken as it lies at the path's start
/// and moved rigidly with the path's rotation-minimizing frame: section v is
/// x(v) + F(v) F(0)^T (profile - x(0)), F = (t, r, s). Sections at path parameters are exact
/// (control points transformed rigidly); between them the surface interpolates cubically across;
/// the number of sections doubles until the deviation, measured at the quarter points between
/// sections (profile samples 1/(2n) apart), is within tolerance.
/// @throws GeometryError "path: ..." for a path with a cusp or no length.
SweepResult sweep(const Curve3d& profile, const Curve3d& path, const SweepOptions& options = {});

}  // namespace sculptline::solvers::surfaces
