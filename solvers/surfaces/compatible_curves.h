#pragma once
// Making curves compatible: one degree, one clamped knot vector on [0, 1] (The NURBS Book §10.3,
// "compatible" curves; thesis eq. 5-3 builds every surface from such a network).
#include "solvers/bspline/bspline_curve.h"

#include <optional>
#include <vector>

namespace sculptline::solvers::surfaces {

/// A common degree and clamped knot vector on [0, 1].
struct CurveLayout {
    int degree = 1;
    KnotVector knots;
    int pointCount() const { return static_cast<int>(knots.size()) - degree - 1; }
};

/// The same geometry with clamped end knots and its domain mapped affinely onto [0, 1] (an affine
/// change of parameter leaves the control points and weights unchanged). Closed curves are opened
/// at their domain start.
Curve3d normalizedCurve(const Curve3d& curve);

/// The layout every one of the (normalized) curves can be brought to without changing its shape:
/// degree = max(minDegree, max degree); knots = the union of the elevated curves' knots, each value
/// with its largest multiplicity (The NURBS Book §10.3, "merging" the knot vectors).
/// @pre every curve is normalized (clamped on [0, 1]).
CurveLayout commonLayout(const std::vector<Curve3d>& normalized, int minDegree = 1);

/// `normalized` elevated to the layout's degree (A5.9) and refined to its knots (A5.4); the shape is
/// unchanged. std::nullopt when the curve has a knot the layout lacks (or a higher degree), so the
/// caller must compute a new layout.
std::optional<Curve3d> conformToLayout(const Curve3d& normalized, const CurveLayout& layout);

/// All curves normalized and made compatible: same degree (>= minDegree), same knots, same point
/// count; rational curves stay rational (the rest then get unit weights).
/// @throws GeometryError ("curves: ...") when the list is empty.
std::vector<Curve3d> makeCompatible(const std::vector<Curve3d>& curves, int minDegree = 1);

/// Homogeneous control rows (w·x, w·y, w·z, w) when `rational`, else (x, y, z). A non-rational curve
/// asked for rational rows gets unit weights.
ControlMatrix controlRows(const Curve3d& curve, bool rational);

/// True when any curve has weights.
bool anyRational(const std::vector<Curve3d>& curves);

/// The curve with its parameter reversed (u -> 1 - u on a normalized curve).
Curve3d reversedCurve(const Curve3d& normalized);

}  // namespace sculptline::solvers::surfaces
