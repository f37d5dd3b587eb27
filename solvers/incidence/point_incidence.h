#pragma once
// Curve-surface incidence by discretization (seed 000 §2.1, the third approach, after Dietz 1998):
// the curve constraint becomes point constraints S(G(t_k)) = H'(t_k) at m parameters, each row the
// basis products N_i(u_k) N_j(v_k) over F's control points. Kept for comparison with the exact
// composition, and for the point incidences where two domain curves cross.
#include "solvers/incidence/composition.h"

namespace sculptline::solvers::incidence {

/// The row of S(u, v): N_i(u) N_j(v) at column i * countV + j ((p+1)(q+1) non-zeros).
/// @note (u, v) is clamped to F's domain, as the kernel's evaluation does.
Eigen::SparseVector<double> surfacePointRow(const SurfaceStructure& surface, double u, double v);

/// m rows, one per parameter: S(G(t_k)). Parameters are clamped to G's domain.
SparseRows discretizedIncidence(const SurfaceStructure& surface, const Curve2d& domainCurve,
                                const std::vector<double>& parameters);

/// m parameters spread evenly over G's domain, both ends included (m >= 2).
std::vector<double> uniformParameters(const Curve2d& domainCurve, int m);

/// The evaluation matrix of a B-spline space at the parameters: row k = N_i(t_k) (the matrix E with
/// discretizedIncidence = E * compose(...).matrix, when both use the same G).
SparseRows evaluationMatrix(int degree, const KnotVector& knots, const std::vector<double>& parameters);

}  // namespace sculptline::solvers::incidence
