#pragma once
// Compatibility matrices (seed 000 §4.1; Michalik 2003): a sketched request curve H' of low degree
// is brought into the space of the exact surface curve H = F(G) by degree elevation and knot
// insertion, so that H' and A F have as many control points and can be equated row by row.
#include "solvers/incidence/composition.h"

namespace sculptline::solvers::incidence {

/// C with C P' = the control points, in `target`, of the curve of degree `degree` on `knots` with
/// control points P' (any number of columns): the kernel's degree elevation (The NURBS Book A5.9)
/// and knot refinement (A5.4) applied to the identity. target.pointCount() x (knots.size()-degree-1).
/// Unclamped ends are clamped first; interior knots within 1e-9 of the domain length of a
/// breakpoint of `target` are taken as that breakpoint.
/// @throws GeometryError when degree > target.degree, the domains differ (by more than 1e-12 of
///         their length) or an interior knot is not a breakpoint of `target` (compose with it as an
///         extra breakpoint).
SparseRows compatibilityMatrix(int degree, const KnotVector& knots, const CompositionSpace& target);

/// The request curve as a curve of `target`'s space (the same curve: C P').
/// @throws GeometryError for a rational request, and as compatibilityMatrix.
Curve3d bringIntoSpace(const Curve3d& request, const CompositionSpace& target);

}  // namespace sculptline::solvers::incidence
