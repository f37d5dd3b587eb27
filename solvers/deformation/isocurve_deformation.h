#pragma once
// The thesis's iso-curve propagation (002_d9515b9d07f9cfd1 §6.2.3, eqs. 6-17 and 6-18): a point
// constraint first moves the control polygon of the iso-curve along U through it by the curve
// least-change solver, and the moved polygon's points then become position constraints of the
// curves along V (the columns of the net), solved the same way.
#include "solvers/deformation/surface_deformation.h"

namespace sculptline::solvers::deformation {

/// The iso-curve method for Position and Curve constraints (Curve: at its key points).
///
/// Constraint points sharing one v are solved together on their U iso-curve (its control points
/// c_i = Σ_j N_j(v) P_ij); each column i then gets one position constraint C_i(v) = c_i + Δc_i per
/// such v whose points its basis function reaches. For a single point this equals the global
/// least-displacement solution (the tensor-product row's pseudo-inverse factors into the two).
/// Blocked points and the bound are honoured in both stages; the objective option is not used.
/// @throws GeometryError for other constraint types or a rational surface (naming the field).
Surface3d deformByIsocurves(const Surface3d& surface, const std::vector<SurfaceConstraint>& constraints,
                            const DeformationOptions& options = {}, DeformationReport* report = nullptr);

}  // namespace sculptline::solvers::deformation
