#pragma once
// Global B-spline interpolation (The NURBS Book §9.2.1, A9.1) with a kept factorization, so that a
// surface built by interpolating across sections can be re-solved cheaply when only the data move
// (the geometry-central "factor once, solve per event" pattern of ../shared/STYLE.md).
#include "solvers/bspline/basis.h"

#include <Eigen/LU>
#include <Eigen/SparseLU>
#include <memory>
#include <vector>

namespace sculptline::solvers::surfaces {

/// Chord-length parameters in [0, 1] of consecutive rows of `data` (one data "point" per row; rows
/// may hold several points side by side, groupSize columns each, and the chord is then the mean over
/// the groups: The NURBS Book eq. 10.8 for skinning). Coincident neighbours fall back to uniform.
std::vector<double> chordParameters(const ControlMatrix& data, int groupSize);

/// Knots by averaging (The NURBS Book eq. 9.8) for interpolation at `params` with `degree`.
KnotVector averagedKnots(const std::vector<double>& params, int degree);

/// Greville abscissae (knot averages) of a knot vector: the parameters at which interpolation is
/// always well posed (Schoenberg-Whitney) and linear functions are reproduced exactly.
std::vector<double> grevilleAbscissae(int degree, const KnotVector& knots);

/// Interpolation at fixed parameters: the collocation matrix N(k, i) = N_i(t_k) (A9.1) is factored
/// once: dense partial-pivot LU up to kDenseInterpolationLimit unknowns (fastest for the sizes a
/// drag re-solves), sparse LU above (the matrix is banded, degree + 1 entries per row, so memory
/// and time stay linear for long inputs).
constexpr int kDenseInterpolationLimit = 128;

class CurveInterpolator {
public:
    /// @param params strictly increasing, params.front() = 0, params.back() = 1.
    /// @param degree 1 <= degree < params.size().
    /// @throws GeometryError ("params: ...") when the system would be singular.
    CurveInterpolator(std::vector<double> params, int degree);
    /// Interpolation with a given knot vector (params must satisfy Schoenberg-Whitney for it).
    CurveInterpolator(std::vector<double> params, int degree, KnotVector knots);

    /// Control rows whose curve passes through row k of `data` at params[k] (any number of columns).
    ControlMatrix solve(const ControlMatrix& data) const;

    int degree() const { return degree_; }
    const KnotVector& knots() const { return knots_; }
    const std::vector<double>& params() const { return params_; }

private:
    void factor();

    std::vector<double> params_;
    int degree_;
    KnotVector knots_;
    Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
    std::shared_ptr<Eigen::SparseLU<Eigen::SparseMatrix<double>>> sparse_;
};

}  // namespace sculptline::solvers::surfaces
