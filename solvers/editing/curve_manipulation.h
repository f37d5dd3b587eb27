#pragma once
// Direct manipulation of B-spline curves under linear constraints (thesis
// 002_d9515b9d07f9cfd1 §6.1, after Fowler & Bartels, "Constraint-based curve manipulation",
// IEEE CG&A 1993): the control points move by the least change d that makes the constraints hold.
#include "solvers/bspline/bspline_curve.h"

#include <Eigen/Core>
#include <string>
#include <vector>

namespace sculptline::solvers::editing {

enum class ConstraintType {
    Position,   ///< C(u) = value
    Tangent,    ///< C'(u) = value (the first derivative vector, as Fowler & Bartels constrain it)
    Curvature,  ///< C''(u) = value (second derivative: the linear "higher derivative" constraint of §6.1)
    Distance,   ///< C(u2) - C(u) = value (a vector: length and direction, thesis Fig. 6-3)
};

/// One linear constraint on the curve. Every type is a vector equation whose coefficients are the
/// same for each coordinate, so it contributes one row to F and one row (Dim columns) to b.
template <int Dim>
struct CurveConstraint {
    using Point = Eigen::Matrix<double, Dim, 1>;
    ConstraintType type = ConstraintType::Position;
    double u = 0.0;               ///< curve parameter (open curves: clamped to the domain; closed: wrapped)
    double u2 = 0.0;              ///< second parameter, Distance only
    Point value = Point::Zero();  ///< target, in model units (per unit parameter for derivatives)
};

/// What the solve achieved.
struct ManipulationReport {
    int constraintRows = 0;         ///< number of constraints (rows of F)
    int freePoints = 0;             ///< control points allowed to move (columns of F)
    int rank = 0;                   ///< numerical rank of F
    bool tooFewFreePoints = false;  ///< rows > free points: thesis §7.5; try insertKnotsNearConstraints
    bool compromise = false;        ///< rank < rows: over-determined or contradictory, least-squares answer
    double maxResidual = 0.0;       ///< max over constraints of |f_j(new curve) - value_j| (model units)
    std::vector<double> residuals;  ///< per constraint, same units
    std::string message;            ///< human-readable summary of the two flags above (empty when fine)
};

/// Stateful solver for a drag: the preprocessing stage (constructor) builds F for the constraint
/// parameters and factors it once; the per-event stage (solve) is one matrix product d = C·b.
///
/// The minimum-norm change d = Fᵀ(FFᵀ)⁻¹b is computed from a column-pivoted Householder QR of Fᵀ,
/// never from an inverse or the adjugate of FFᵀ (the thesis's eq. 6-9 is unstable as FFᵀ squares
/// the condition number). With FᵀΠ = Q[R₁ R₂; 0 0], rank r, and d = Q[y; 0] (minimum norm), F d = b
/// becomes Π[R₁ᵀ; R₂ᵀ] y = b, solved in least squares: exact when F has full row rank (then
/// y = R₁⁻ᵀΠᵀb, the formula above) and the best compromise otherwise. C = Q₁·[R₁ᵀ; R₂ᵀ]⁺·Πᵀ.
///
/// @note Rational curves keep their weights: the constraints are then exactly linear in the
///       Cartesian control points (rational basis R_i = w_i N_i / Σ w_j N_j), and d is the least
///       change of those points (curve_manipulation.cpp).
/// @note Closed curves: unknowns are the unique control points; blocked indices refer to them.
template <int Dim>
class CurveManipulationSolver {
public:
    using Curve = BSplineCurve<Dim>;
    using Point = Eigen::Matrix<double, Dim, 1>;
    /// Displacement rows: one per free control point, Dim columns.
    using Displacements = Eigen::Matrix<double, Eigen::Dynamic, Dim>;

    /// @param constraints types and parameters; their values are ignored here (targets come per event).
    /// @param blocked control point indices that must not move (unique indices for closed curves).
    /// @throws GeometryError for a non-finite parameter or a bad blocked index.
    CurveManipulationSolver(Curve curve, std::vector<CurveConstraint<Dim>> constraints, std::vector<int> blocked = {});

    /// Per-event stage: the curve that meets `targets` (one per constraint, same order and meaning
    /// as CurveConstraint::value) with the least control point change. Cost: O(free points × rows).
    Curve solve(const std::vector<Point>& targets, ManipulationReport* report = nullptr) const;
    /// The bare per-event product: displacement of each free point (rows follow freeIndices()).
    void displacements(const std::vector<Point>& targets, Displacements& d) const;

    /// Current constraint values f_j(curve) of the undeformed curve.
    const std::vector<Point>& currentValues() const { return current_; }
    const std::vector<int>& freeIndices() const { return free_; }
    const Eigen::MatrixXd& constraintMatrix() const { return F_; }
    int rank() const { return rank_; }
    const Curve& curve() const { return curve_; }

private:
    Curve curve_;
    std::vector<CurveConstraint<Dim>> constraints_;
    std::vector<int> free_;  // unique indices of the free control points
    Eigen::MatrixXd F_;      // rows × free
    Eigen::MatrixXd C_;      // free × rows: d = C b
    std::vector<Point> current_;
    int rank_ = 0;
};

/// One-off: the curve meeting all constraints (values taken from the constraints) with the least
/// change of the free control points.
template <int Dim>
BSplineCurve<Dim> constrainCurve(const BSplineCurve<Dim>& curve, const std::vector<CurveConstraint<Dim>>& constraints,
                                 const std::vector<int>& blocked = {}, ManipulationReport* report = nullptr);

/// Row j of F for a constraint: the coefficients of the unique control points (size: unique count).
template <int Dim>
Eigen::VectorXd constraintRow(const BSplineCurve<Dim>& curve, const CurveConstraint<Dim>& c);

/// Offers more freedom when the free points are too few (thesis §7.5): inserts one knot at the
/// middle of the knot span holding each constraint parameter, repeated `rounds` times. The shape is
/// unchanged (knot insertion is exact); only the local freedom grows.
template <int Dim>
BSplineCurve<Dim> insertKnotsNearConstraints(const BSplineCurve<Dim>& curve,
                                             const std::vector<CurveConstraint<Dim>>& constraints, int rounds = 1);

}  // namespace sculptline::solvers::editing
