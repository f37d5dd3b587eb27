#pragma once
// One entry point for every surface mode (issue 6): the CLI's `surface` subcommand and the GUI's
// surface entities (scene/model) build through it, so a mode behaves the same in both.
#include "solvers/bspline/bspline_surface.h"
#include "solvers/surfaces/coons_fill.h"
#include "solvers/surfaces/gordon.h"

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sculptline::solvers::surfaces {

class LoftBuilder;
class SweepBuilder;

enum class SurfaceMode { Fill, Revolve, Extrude, Sweep, Loft, BoundaryRotation, RailRotation };

/// "fill", "revolve", "extrude", "sweep", "loft", "boundary-rotation", "rail-rotation".
/// @throws std::invalid_argument for any other name (the message lists the valid ones).
SurfaceMode parseSurfaceMode(const std::string& name);
const char* surfaceModeName(SurfaceMode mode);

struct SurfaceOptions {
    /// revolve: the axis (a point on it and a non-zero direction, model units) and the angle in
    /// degrees, counter-clockwise about the direction.
    Eigen::Vector3d axisPoint = Eigen::Vector3d::Zero();
    Eigen::Vector3d axisDirection = Eigen::Vector3d::UnitZ();
    double angleDegrees = 360.0;
    /// extrude: direction and distance (model units).
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();
    /// extrude: when set, the profile is carried along this curve without turning (translational
    /// sweep) instead of along `direction`.
    std::optional<Curve3d> extrudePath;
    /// fill: the largest gap between ends that still meet; sweep, boundary- and rail-rotation: the
    /// largest deviation from the exact construction. Model units; <= 0 = the mode's default,
    /// relative to the curves' size.
    double tolerance = 0.0;
    /// loft: the degree across the sections (lowered to sections - 1 when there are fewer).
    int loftDegree = 3;
    /// fill: optional G1 conditions (curve index -> adjacent reference surface, coons_fill.h) and
    /// the largest angle in degrees between the normals across those boundaries.
    std::vector<FillTangent> fillTangents;
    double fillAngleToleranceDegrees = kDefaultFillAngleDegrees;
};

struct SurfaceBuild {
    Surface3d surface;
    /// Approximating modes: the deviation reached and the tolerance used (model units); exact
    /// modes: -1 and 0.
    double maxDeviation = -1.0;
    double tolerance = 0.0;
    /// fill with tangents: the largest angle (degrees) reached between the normals across the G1
    /// boundaries; -1 otherwise.
    double maxTangentAngleDegrees = -1.0;
};

/// @throws std::invalid_argument "curves: mode needs <what>, got <n> curves" when `count` curves
/// cannot make a surface of `mode` (loft: any count passes here; buildSurface then reports fewer
/// than two sections in the loft's own words).
void checkCurveCount(SurfaceMode mode, size_t count);

/// Builds the surface of `mode` from `curves` (world coordinates, in the mode's order: fill 2-4
/// boundaries; revolve [profile]; extrude [profile]; sweep [profile, path]; loft [sections..];
/// boundary-rotation [left, right]; rail-rotation [rail 1, rail 2, profile]).
/// Before any mode runs, every mode refuses: a non-finite option (axis, angle, direction,
/// tolerance, angle tolerance, extrusion path); a collapsed curve (BSplineCurve::isCollapsed:
/// "curves[k]: degenerate, all control points coincide"); fill boundaries that repeat one another.
/// After it ran, a surface with a non-finite control point or weight is refused ("surface: ...")
/// rather than returned. Approximating modes clamp a tolerance below what double precision can
/// meet (approximation_tolerance.h) and report the one used.
/// @throws std::invalid_argument for a wrong number of curves, GeometryError for input the mode
///         cannot build (the message says why: curves that do not meet, a path with a cusp, ...).
///         Messages start with the input they blame: "curves: ", "curves[1] (path): " (sweep),
///         "axis: ", "angle: ", "direction: ", "path: " (extrudePath), "tolerance: ".
SurfaceBuild buildSurface(SurfaceMode mode, const std::vector<Curve3d>& curves, const SurfaceOptions& options = {});

/// A Gordon surface (gordon.h) with the same input and result checks as buildSurface: it takes two
/// curve families, so it is not a SurfaceMode. Collapsed curves are named "curves[k]" (u family)
/// and "v_curves[k]" (v family); a non-finite tolerance is "tolerance: ...".
GordonResult buildGordon(const std::vector<Curve3d>& uCurves, const std::vector<Curve3d>& vCurves,
                         const GordonOptions& options = {});

/// Incremental builds for dragging (issue 6 §2): keeps the mode's builder (fill: FillBuilder, loft:
/// LoftBuilder, sweep: SweepBuilder), so that update() re-solves with what was set up at the first
/// build; the other modes rebuild in full (each under a millisecond at 20 control points per
/// direction, bench/surfaces_bench.cpp). While a drag lasts the loft keeps its cross parameters and
/// the fill and sweep their refinement (a surface that moves smoothly with the pointer); reset()
/// when the drag ends gives exactly buildSurface's result.
class SurfaceBuilder {
public:
    /// @throws like buildSurface.
    SurfaceBuilder(SurfaceMode mode, const std::vector<Curve3d>& curves, const SurfaceOptions& options = {});
    ~SurfaceBuilder();
    SurfaceBuilder(SurfaceBuilder&&) noexcept;
    SurfaceBuilder& operator=(SurfaceBuilder&&) noexcept;

    /// The same mode and options with moved curves. @throws like buildSurface; build() then still
    /// returns the last good surface.
    const SurfaceBuild& update(const std::vector<Curve3d>& curves);
    /// Full rebuild (new parameterization and refinement), as buildSurface.
    const SurfaceBuild& reset(const std::vector<Curve3d>& curves);
    const SurfaceBuild& build() const { return *build_; }
    SurfaceMode mode() const { return mode_; }

private:
    SurfaceMode mode_;
    SurfaceOptions options_;
    std::unique_ptr<FillBuilder> fill_;
    std::unique_ptr<LoftBuilder> loft_;
    std::unique_ptr<SweepBuilder> sweep_;
    std::unique_ptr<SurfaceBuild> build_;
};

}  // namespace sculptline::solvers::surfaces
