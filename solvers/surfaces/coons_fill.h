#pragma once
// Fill (thesis mode 1, "geom-filling"): a bilinearly blended Coons patch bounded by two, three or
// four curves that meet end to end (The NURBS Book §10.5 eq. 10.29 with compatible boundaries;
// Farin, "Curves and Surfaces for CAGD", ch. 22). Exact on the boundaries.
#include "solvers/bspline/bspline_surface.h"
#include "solvers/surfaces/compatible_curves.h"
#include "solvers/surfaces/fill_tangents.h"

#include <array>
#include <memory>
#include <vector>

namespace sculptline::solvers::surfaces {

/// G1 along one boundary: the fill shares its tangent plane with `reference` along curves[curve],
/// e.g. the adjacent surface whose edge (or any curve on it) that boundary is. The curve must lie on
/// the reference (within the meet tolerance); where a neighbouring boundary meets it, that
/// neighbour must leave the corner within the reference's tangent plane (within the angle
/// tolerance), since the fill's tangent plane at a corner is spanned by its two boundaries.
struct FillTangent {
    int curve = 0;
    Surface3d reference;
};

/// G1 tolerance: 0.1 degree between the normals across a boundary, the usual CAD default for
/// tangent continuity (a crease below it does not show in shaded rendering).
constexpr double kDefaultFillAngleDegrees = 0.1;

struct FillOptions {
    /// Largest gap, in model units, between two ends that still counts as "meeting"; <= 0 means
    /// kDefaultMeetRelative times the diagonal of the curves' control-point bounding box.
    double meetTolerance = 0.0;
    /// Optional G1 conditions, at most one per curve.
    std::vector<FillTangent> tangents;
    /// Largest angle (degrees, in (0, 90)) between the fill's and a reference's normals along a G1
    /// boundary; the knots along G1 boundaries are refined until it is met or maxPoints is reached.
    double angleToleranceDegrees = kDefaultFillAngleDegrees;
    /// Bound on control points per direction that the G1 refinement may reach.
    int maxPoints = 257;
};

/// A gap below 1e-4 of the model's size is invisible at any zoom that shows the whole model
/// (about a tenth of a pixel when it spans 1000 pixels) but far above stroke-fitting round-off.
constexpr double kDefaultMeetRelative = 1e-4;

/// How the boundary curves chain into a loop: curve order[k] (reversed if reversed[k]) is side k,
/// running from corner k to corner k + 1.
struct FillLoop {
    std::vector<int> order;
    std::vector<bool> reversed;
    double tolerance = 0.0;  ///< the meet tolerance actually used (model units)
    double maxGap = 0.0;     ///< the largest gap found between meeting ends
};

/// Orders and orients 2-4 curves into a closed loop.
/// @throws GeometryError "curves: ..." naming the curve whose end meets no other within tolerance.
FillLoop chainBoundaries(const std::vector<Curve3d>& curves, const FillOptions& options = {});

/// The Coons patch of the loop: side 0 is v = 0 (u increasing), side 1 is u = 1, side 2 is v = 1
/// (run backwards), side 3 is u = 0 (backwards). Three curves: the side u = 0 degenerates to the
/// corner where side 0 starts; two curves: both u = 0 and u = 1 degenerate (a lens). Corners whose
/// ends differ by less than the tolerance are first moved to their midpoint (the end control
/// points only), so the surface meets those slightly moved boundaries to round-off.
/// @throws GeometryError for 1 or more than 4 curves, rational curves, or ends that do not meet.
/// With tangents the patch is at least bicubic and the control points next to each G1 boundary
/// are moved by the least change that puts the cross-boundary derivative into the reference's
/// tangent plane (fill_tangents.h); boundaries stay exact. FillBuilder::maxTangentAngleDegrees()
/// reports the angle reached. A 3-sided fill with tangents starts its loop so that the collapsed
/// corner lies off the G1 sides where it can (the normal at a collapsed corner is a limit the
/// conditions do not control).
/// @throws GeometryError "tangents[k]: ..." for a curve index out of range or used twice, a curve
///         not on its reference, or a neighbouring boundary that leaves a corner off the
///         reference's tangent plane (no G1 surface exists there).
Surface3d fill(const std::vector<Curve3d>& curves, const FillOptions& options = {});

/// Incremental fill for dragging: keeps the loop's order and orientation, the compatible layouts of
/// the two side pairs and their Greville abscissae; update() re-conforms the curves and sums the
/// three control nets (linear precision of B-splines makes the ruled and bilinear parts exact at
/// the Greville abscissae, so no surface elevation or refinement is needed per update).
class FillBuilder {
public:
    explicit FillBuilder(const std::vector<Curve3d>& curves, const FillOptions& options = {});
    /// Same number of curves; falls back to a full build if they no longer fit the kept loop or layouts.
    const Surface3d& update(const std::vector<Curve3d>& curves);
    const Surface3d& reset(const std::vector<Curve3d>& curves);
    const Surface3d& surface() const { return *surface_; }
    const FillLoop& loop() const { return loop_; }
    /// The largest angle (degrees) between the fill's and the references' normals along the G1
    /// boundaries, measured at kG1SamplesPerSpan points per knot span and the corners; 0 without tangents.
    double maxTangentAngleDegrees() const { return maxAngle_; }

private:
    bool build(const std::vector<Curve3d>& curves);
    void setupTangents(const std::vector<Curve3d>& loopSides);
    void refineUntilTangent(const std::vector<Curve3d>& curves);

    FillOptions options_;
    FillLoop loop_;
    std::array<CurveLayout, 2> layouts_;  // [0]: sides 0 and 2 (u); [1]: sides 3 and 1 (v)
    std::array<std::vector<double>, 2> greville_;
    std::unique_ptr<Surface3d> surface_;
    std::vector<G1Side> g1_;
    double maxAngle_ = 0.0;
};

}  // namespace sculptline::solvers::surfaces
