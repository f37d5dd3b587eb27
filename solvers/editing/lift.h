#pragma once
// Lifting a 2D stroke into a space curve of minimum curvature within a depth range (seed
// 004_5c4069c4b3f67ca2 §3: Theorem 1, Algorithms 1 and 2, the Laplacian depth filter).
#include "solvers/bspline/bspline_curve.h"

#include <Eigen/Core>
#include <vector>

namespace sculptline::solvers::editing {

/// Orthographic view: a stroke point (x, y) at depth z is origin + x·right + y·up + z·depth.
struct ViewFrame {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    Eigen::Vector3d right = Eigen::Vector3d::UnitX();
    Eigen::Vector3d up = Eigen::Vector3d::UnitY();
    Eigen::Vector3d depth = Eigen::Vector3d::UnitZ();
};

/// How depths are spread along the stroke (seed 004 §3.1, Theorem 1: the minimum-curvature lift of
/// a 2D Bézier curve has equally spaced control depths, i.e. a depth linear in the Bézier parameter).
enum class DepthModel {
    /// Depth linear in the parameter of a least-squares cubic B-spline fitted to the stroke with
    /// parameter correction: for a Bézier stroke that parameter is the Bézier's own, and for a
    /// longer stroke it is the B-spline form of Theorem 1 (equally spaced depths at the Greville
    /// abscissae). The default, see lift.cpp for the measurement.
    FittedParameter,
    /// Alg. 2 as written: depths equally spaced over the critical points of Alg. 1, arc-length
    /// interpolation between them.
    CriticalPoints,
};

struct LiftOptions {
    DepthModel depths = DepthModel::FittedParameter;
    /// Alg. 1's "user-defined threshold": a critical point closer than this to the chord of its
    /// segment is dropped and recursion stops. Fraction of the stroke's length, (0, 1).
    double linearityThreshold = 0.01;
    /// Laplacian filter z' = z + λ((z₋ + z₊)/2 - z) on interior samples (seed 004 §3.1); λ in (0, 1).
    double lambda = 0.5;
    /// "A few iterations" (seed 004): passes of the filter over the arc-length resampled stroke.
    int filterIterations = 10;
    /// The stroke is resampled to this many points equally spaced by arc length (>= 3), so that
    /// the index-space Laplacian is a length-space one.
    int samples = 200;
    /// CriticalPoints only. Depths of the critical points: true spaces them equally within each
    /// recursion level's segment (Theorem 1 per de Casteljau sub-curve); false spaces them equally
    /// over the whole flat list (the literal reading of Alg. 2). See lift.cpp for the measurement.
    bool hierarchicalDepths = true;
    /// Fit tolerance of the output cubic, fraction of the stroke's 3D length.
    double fitTolerance = 1e-3;
};

struct LiftResult {
    std::vector<Eigen::Vector3d> points;  ///< resampled stroke with depths, in view coordinates (x, y, z)
    std::vector<int> critical;            ///< indices into points: first, critical points (Alg. 1), last
    Curve3d curve;                        ///< cubic fit of the points mapped through the view frame
    double fitError = 0.0;                ///< max distance of a lifted point from the curve, model units
};

/// Alg. 1 on a polyline: the critical points of the signed distance from the chord, recursively,
/// in stroke order (indices strictly between first and last). A local extremum counts only once the
/// distance has turned back by `threshold` (hysteresis, so that pen jitter is not a critical point)
/// and when it lies farther than `threshold` from the chord.
std::vector<int> criticalPoints(const std::vector<Eigen::Vector2d>& pts, double threshold);

/// Seed 004 §3: critical points (Alg. 1, reported), depths by `options.depths` (Theorem 1), then
/// the Laplacian filter with the end depths held (Alg. 2).
/// @throws GeometryError naming "stroke" (fewer than two distinct points, non-finite) or "depth".
LiftResult liftStroke(const std::vector<Eigen::Vector2d>& stroke, double z0, double z1, const LiftOptions& options = {},
                      const ViewFrame& view = {});

}  // namespace sculptline::solvers::editing
