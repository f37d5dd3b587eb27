#pragma once
// Sweep (thesis mode 4; seed 000 "sweeping mode"): a profile carried along a path by
// rotation-minimizing frames, sampled and approximated by a B-spline surface (The NURBS Book §10.4
// sweeps by skinning sampled instances of the profile).
#include "solvers/bspline/bspline_surface.h"

#include <memory>

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
/// (control points transformed rigidly); between them the surface is a C1 cubic Hermite in v with
/// the sections' exact v-derivatives. The deviation is measured at the quarter points between
/// sections (profile samples 1/(2n) apart) for each path knot span; a span over tolerance gets
/// (r·1.25)^(1/4) times its sections (r = deviation / tolerance; the Hermite error falls as h^4)
/// until every span is within tolerance or maxSections is reached. A closed path (periodic, or ends
/// and end tangents that coincide) gets its frames' holonomy spread evenly along it, so the last
/// section is the first and the surface closes at the path's seam; a closed profile closes the
/// surface along u (its seam stays where the profile's domain starts). A polyline path (degree 1)
/// gives the exact mitred sweep instead: straight tubes joined in the bisector planes of its
/// vertices (degree 1 in v, maxDeviation 0; a closed planar polyline is mitred at its seam too).
/// @throws GeometryError "path: ..." for a path with a cusp or no length, or with a corner (a knot
///         where the tangent turns) at which the swept profile would tear by more than the
///         tolerance; "curves: ..." for a profile that is a single point.
SweepResult sweep(const Curve3d& profile, const Curve3d& path, const SweepOptions& options = {});

struct SweepPathSamples;  // sweep.cpp: frames and derivatives of the path at the sections and probes

/// Incremental sweep for dragging (a curve's plane moves, so profile or path moves rigidly): the
/// path's frames, section parameters and derivatives are kept; update() maps them by the path's
/// rigid motion (rotation-minimizing frames are equivariant: F' = R F) and re-transforms the
/// profile's control points, then re-measures the deviation. A path that changed shape, or a
/// deviation over tolerance, falls back to a full build (reset).
class SweepBuilder {
public:
    SweepBuilder(const Curve3d& profile, const Curve3d& path, const SweepOptions& options = {});
    const SweepResult& update(const Curve3d& profile, const Curve3d& path);
    const SweepResult& reset(const Curve3d& profile, const Curve3d& path);
    const SweepResult& result() const { return *result_; }

private:
    SweepOptions options_;
    std::unique_ptr<Curve3d> path_;  // clamped, as the samples were taken (or moved to)
    std::shared_ptr<SweepPathSamples> samples_;
    std::unique_ptr<SweepResult> result_;
};

}  // namespace sculptline::solvers::surfaces
