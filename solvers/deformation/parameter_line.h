#pragma once
// Surface editing by re-sketching a parameter line (seed 001_08db50965017e161 §5.2, Figs. 9-10, the
// jug's mouth): a pen marking picks the nearest u- or v-curve of a B-spline surface, an auxiliary
// ruled surface through that curve along a direction the designer sets receives the re-sketch (the
// curve over-sketch of seed 001 §3-4, in 3D), and the surface follows by the least change of its
// control net (Fowler & Bartels, "Constraint-based curve manipulation", 1993: the [9] of seed 001).
// The surface's knot vectors are re-used (seed 001 §5.2: new knots would grow the net at every edit).
#include "solvers/bspline/bspline_surface.h"
#include "solvers/editing/oversketch.h"

#include <Eigen/Core>
#include <vector>

namespace sculptline::solvers::deformation {

/// An iso-parametric line of a surface. fixed = U: the curve at u = value, running along V (its
/// control points Q_j = Σ_i N_i(value) P_ij); fixed = V: the curve at v = value, running along U.
struct ParameterLine {
    Direction fixed = Direction::U;
    double value = 0.0;
};

struct PickOptions {
    /// A line within this fraction of the domain's width from a domain end is snapped onto that end
    /// (a marking drawn along a rim means the rim; a hand is never exactly on it). [0, 0.5).
    double snapToBoundary = 0.05;
};

/// Seed 001 §5.2: the marking's points, in the domain, decide the family by their dominant
/// direction (the domain steps weighted by |S_u| and |S_v|, so that the direction is the one seen on
/// the surface), and the line's parameter is the least-squares fit, the mean of the other coordinate.
/// @param uv the marking's points (u, v) on the surface's domain, at least two distinct ones.
/// @throws GeometryError naming "marking": fewer than two points, non-finite, outside the domain
///         (by more than 1e-9 of its width) or without extent on the surface.
ParameterLine pickParameterLine(const Surface3d& surface, const std::vector<Eigen::Vector2d>& uv,
                                const PickOptions& options = {});

/// The marking's points on the surface, from the pointer's rays: where each ray meets the surface
/// first (nearest the eye), else the surface point nearest to it (Gauss-Newton on the distance to
/// the ray from sample-grid seeds in depth order, The NURBS Book §6.1's method). Rays that pass
/// farther than `maxDistance` (model units) from the surface are dropped.
/// @throws GeometryError naming "marking" when fewer than two rays meet it, or a ray is not finite.
std::vector<Eigen::Vector2d> markingOnSurface(const Surface3d& surface, const std::vector<Eigen::Vector3d>& origins,
                                              const std::vector<Eigen::Vector3d>& directions, double maxDistance);

/// The same from 3D points (a marking already on or near the surface): their closest points.
/// @throws GeometryError naming "marking" for a point farther than `maxDistance` or non-finite.
std::vector<Eigen::Vector2d> markingOnSurface(const Surface3d& surface, const std::vector<Eigen::Vector3d>& points,
                                              double maxDistance);

/// The parameter line as a curve: exact (Q_j = Σ_i N_i(t) P_ij), with the surface's knots and degree
/// in the other direction. @throws GeometryError for a non-finite or out-of-domain parameter.
Curve3d parameterLineCurve(const Surface3d& surface, const ParameterLine& line);

/// How the rulings of the auxiliary surface point (seed 001 §5.2: "along a user defined direction").
enum class RulingKind {
    Normal,    ///< the surface normal along the line (Fig. 9's default, perpendicular to the line)
    Across,    ///< the surface's tangent across the line (a boundary line: the surface continued)
    Constant,  ///< one direction for all (the view direction)
};

/// The auxiliary ruled surface R(t, s) = C(t) + s·D(t), D(t) = Σ_j N_j(t) D_j with unit directors
/// D_j (one per control point of C, same knots): a B-spline surface of degree 1 in s. Constant
/// rulings make it a cylinder (developable); normal rulings of a surface line are Fig. 9's strip.
struct RuledStrip {
    Curve3d base;
    std::vector<Eigen::Vector3d> directors;
    Eigen::Vector3d at(double t, double s) const;
    Eigen::Vector3d ruling(double t) const;  ///< D(t), not normalized
};

/// A strip along `kind` for the surface's line (`direction` is used by Constant only).
/// Normal and Across sample the surface at the line's Greville abscissae; Across points out of the
/// domain at a boundary line (where the surface would continue).
/// @throws GeometryError naming "direction": zero or non-finite, or parallel to the line's tangent
///         everywhere (the strip would be a line; sin of the angle below 1e-6); naming "surface"
///         where the normal or cross tangent vanishes.
RuledStrip makeRuledStrip(const Surface3d& surface, const ParameterLine& line, RulingKind kind,
                          const Eigen::Vector3d& direction = Eigen::Vector3d::UnitZ());

/// Where the rays meet the strip within |s| <= halfWidth: the root nearest the eye of
/// f(t) = (C(t) - o)·(D(t) × r) (the ray and the ruling at t are coplanar), bracketed on a grid
/// and refined by bisection; then o + λr = C(t) + sD(t) by least squares. Rays that miss are dropped.
/// @throws GeometryError naming "stroke" for a non-finite ray or a non-positive half width.
std::vector<Eigen::Vector3d> projectRaysOntoStrip(const RuledStrip& strip, const std::vector<Eigen::Vector3d>& origins,
                                                  const std::vector<Eigen::Vector3d>& directions, double halfWidth);

struct ResketchResult {
    Curve3d curve;       ///< the new line: the old one's degree and knot vector
    double us = 0.0, ue = 0.0;  ///< the parameter span the over-sketch replaced (ends blended)
    double oversketchError = 0.0;  ///< the over-sketch's own fit error (model units)
    double knotFitError = 0.0;     ///< max |new line − over-sketched curve| over dense samples (model units)
    int movedPoints = 0;           ///< control points of the line that changed
};

/// The re-sketch (seed 001 §5.2): `stroke` (3D points, on the strip) over-sketches `line`
/// (solvers/editing's over-sketch, which replaces the part it covers and blends at the ends), then
/// the result is fitted by least squares in the line's own knot vector (step (5) of Alg. 1-1
/// modified: "a knot vector of the surface before the deformation is reused"), the control points
/// whose support lies outside the replaced span pinned exactly. A stroke running past an end of
/// the line is cut at that end (the surface's domain does not grow).
/// @throws GeometryError naming "stroke" (see editing::oversketch) or "line" (rational, closed).
/// @note A line whose ends meet (a revolved surface's rim with its seam, clamped) is an open curve
///       here: its ends stay where they are unless the over-sketch moves them, and a stroke across
///       the seam is not joined over it (the seam would open). Keep such edits away from the seam.
ResketchResult resketchLine(const Curve3d& line, const std::vector<Eigen::Vector3d>& stroke,
                            const editing::OversketchOptions& options = {});

/// The surface follows: the least change of the control net (Frobenius norm) for which the line
/// becomes `target` (same degree and knots as the line): ΔP_ij = N_i(t) ΔQ_j / Σ_k N_k(t)², which
/// meets Σ_i N_i(t) ΔP_ij = ΔQ_j exactly (Fowler & Bartels' pseudo-inverse of one basis row; it is
/// never singular, Σ_k N_k(t)² >= 1/(p+1) by partition of unity). Rows with N_i(t) = 0 do not move.
/// @throws GeometryError naming "target" (degree, knots or count differ from the line's; not
///         finite) or "surface" (rational).
Surface3d followParameterLine(const Surface3d& surface, const ParameterLine& line, const Curve3d& target);

}  // namespace sculptline::solvers::deformation
