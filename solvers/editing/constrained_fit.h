#pragma once
// Least-squares B-spline approximation on a fixed knot vector with some control points fixed: the
// building block of lifting (seed 004 §3.1, the final curve), blend over-sketching (thesis §4.2,
// the replacement control points) and local-c2 over-sketching (seed 001 Alg. 1-1, step 2).
#include "solvers/bspline/basis.h"

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace sculptline::solvers::editing {

template <int Dim>
struct FixedKnotFit {
    using Point = Eigen::Matrix<double, Dim, 1>;
    int degree = 3;
    KnotVector knots;                         ///< clamped or not; n + degree + 1 values
    std::vector<double> params;               ///< one parameter per sample, inside the domain
    std::vector<Point> samples;               ///< the data
    std::vector<std::optional<Point>> fixed;  ///< size n (or empty): a value pins that control point
    /// Size n (or empty: non-rational): fixed positive weights; the fit is then over the Cartesian
    /// points of the rational curve Σ w_i N_i P_i / Σ w_i N_i, still linear in them.
    std::vector<double> weights;
};

/// Minimises Σ|C(params_k) - samples_k|² + w·Σ|P_{i-1} - 2P_i + P_{i+1}|² over the free control
/// points (The NURBS Book §9.4.1 with the fixed points moved to the right-hand side). The fairing
/// weight w = kFitFairing × (samples per control point) only keeps the problem definite when a knot
/// span holds no sample (the Schoenberg-Whitney condition fails); it is solved by Householder QR on
/// the stacked system, not the normal equations, so the squared condition number never appears.
/// @return all n control points (the fixed ones copied exactly).
template <int Dim>
std::vector<Eigen::Matrix<double, Dim, 1>> fitFixedKnots(const FixedKnotFit<Dim>& problem);

/// Clamped knot vector of `degree` on [a, b] with `spans` equal spans.
KnotVector clampedUniformKnots(int degree, int spans, double a = 0.0, double b = 1.0);

/// Cumulative chord lengths of a polyline (first 0); the last value is its length.
template <int Dim>
std::vector<double> chordLengths(const std::vector<Eigen::Matrix<double, Dim, 1>>& pts);

/// `count` points equally spaced by arc length along the polyline (ends kept).
template <int Dim>
std::vector<Eigen::Matrix<double, Dim, 1>> resampleByArcLength(const std::vector<Eigen::Matrix<double, Dim, 1>>& pts,
                                                               int count);

/// The polyline without consecutive points closer than `minDistance`.
template <int Dim>
std::vector<Eigen::Matrix<double, Dim, 1>> dropDuplicates(const std::vector<Eigen::Matrix<double, Dim, 1>>& pts,
                                                          double minDistance);

}  // namespace sculptline::solvers::editing
