#pragma once
// The quadratic surface functionals of the MTSVD side constraint (seed 000 §4.4; Greiner 1994,
// Greiner & Seidel 1997): E(F) = sum over x, y, z of f^T G f with f a coordinate of F's control
// points (point (i, j) at index i * countV + j), integrated over the parameter domain:
//   area (membrane)         ∫∫ S_u² + S_v²
//   thin plate              ∫∫ S_uu² + 2 S_uv² + S_vv²
//   curvature variation     ∫∫ S_uuu² + 3 S_uuv² + 3 S_uvv² + S_vvv²
// (the third one weighs each mixed derivative by its multiplicity, the binomial coefficients, so
// that like the thin plate energy it is the squared Frobenius norm of the full derivative tensor:
// invariant under rotations of the (u, v) plane). Each is a sum of tensor products of univariate
// Gram matrices ∫ N_i^(d) N_k^(d), computed by Gauss-Legendre quadrature on every knot span with
// degree + 1 points, exact for the polynomial integrand of degree <= 2 degree.
#include "solvers/incidence/composition.h"

#include <Eigen/Dense>

namespace sculptline::solvers::incidence {

enum class Functional { Area, ThinPlate, CurvatureVariation };

/// Gauss-Legendre nodes and weights on [-1, 1] (n >= 1 points; exact for degree 2n - 1).
void gaussLegendre(int n, Eigen::VectorXd& nodes, Eigen::VectorXd& weights);

/// ∫ N_i^(d)(t) N_k^(d)(t) dt over the domain, count x count (count = knots.size() - degree - 1).
Eigen::MatrixXd univariateGram(int degree, const KnotVector& knots, int derivative);

/// The Gram matrix of one functional: n x n, n = countU * countV, symmetric positive semidefinite.
Eigen::SparseMatrix<double> gramMatrix(const SurfaceStructure& surface, Functional functional);

/// L = a1 L_area + a2 L_thin-plate + a3 L_curvature-variation (seed 000 §4.4 takes a1+a2+a3 = 1).
Eigen::SparseMatrix<double> smoothingGram(const SurfaceStructure& surface, double areaWeight, double thinPlateWeight,
                                          double curvatureVariationWeight);

/// How gramFactor makes L with L^T L = G.
enum class FactorMethod {
    /// L = sqrt(Λ) Q^T from G = Q Λ Q^T, rows only for eigenvalues above 1e-13 of the largest:
    /// L^T L = G to round-off, and L's null space is exactly G's (constants, affine maps), which
    /// MTSVD's correction L V_{k+1} f = L (F0 - F_k) relies on. rank x n.
    SquareRoot,
    /// L = R from the Cholesky factorization R^T R = G + ε I, ε = ridge * max diag(G): n x n upper
    /// triangular, cheaper, but G's null space gets the tiny weight ε instead of none.
    CholeskyRidge,
};

/// A factor L with L^T L = G (SquareRoot) or G + ε I (CholeskyRidge).
/// @param ridge relative to the largest diagonal entry; used by CholeskyRidge only
/// @throws GeometryError when G is not symmetric positive semidefinite to round-off.
Eigen::MatrixXd gramFactor(const Eigen::MatrixXd& gram, FactorMethod method = FactorMethod::SquareRoot,
                           double ridge = 1e-12);

}  // namespace sculptline::solvers::incidence
