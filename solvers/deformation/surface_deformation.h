#pragma once
// Constraint-based deformation of B-spline surfaces (thesis 002_d9515b9d07f9cfd1 §6.2): the control
// net is the unknown; user constraints located by surface parameters (Table 6-1) become linear rows
// F d = b in the control point changes d, and d minimizes either the plain adjustment ‖d‖ (eqs.
// 6-4..6-9, the surface form of solvers/editing/curve_manipulation.h) or the change of the bar
// network's external forces ‖K d‖ (the force-density view of §6.2.3, K the net's graph Laplacian
// with unit force densities), which spreads the change smoothly instead of locally.
#include "solvers/bspline/bspline_surface.h"
#include "solvers/bspline/projection.h"
#include "solvers/editing/curve_manipulation.h"

#include <Eigen/Core>
#include <array>
#include <optional>
#include <vector>

namespace sculptline::solvers::deformation {

using editing::ManipulationReport;

enum class SurfaceConstraintType {
    Position,      ///< S(u, v) = value                                   (3 rows)
    Normal,        ///< S_u·n = S_v·n = 0 with n = value: normal ∥ value   (2 rows, linear given n)
    Curve,         ///< S(G(t_k)) = H(t_k) at m key points (eq. 6-24)      (3 rows per key point)
    CurveTangent,  ///< along G the cross tangent S_u a + S_v b ∥ value     (2 rows per key point)
    Distance,      ///< |S(uv2) − S(uv)| = distance: linearized, a few chord-Newton steps (1 row)
    Angle,         ///< ∠(normal at uv, value) = angle: the nearest such normal n*, then Normal's rows (2 rows)
    Tangents,      ///< S_u(uv) = value, S_v(uv) = value2: tangent values (Table 6-1), linear (6 rows);
                   ///< a point handle turned by R holds R S_u°, R S_v°: its normal tilts with it, and
                   ///< a new turn changes only the right-hand side (no new factorization mid-drag)
};

/// Where a target curve lies against a bound curve (thesis §6.3): over-constrained when all of it
/// lies outside (the surface is not affected), under-constrained when partly inside (only the
/// inside span acts), well-constrained when inside. Unbounded deformations and other constraint
/// types are Unbounded.
enum class BoundCase { Unbounded, Over, Under, Well };
const char* boundCaseName(BoundCase c);

enum class Objective {
    Displacement,  ///< least adjustment of the free control points, min ‖d‖ (eqs. 6-4..6-9)
    Force,         ///< least change of the net's external forces, min ‖K d‖ (force density, unit q)
};

/// One user constraint (thesis Table 6-1). Units: model units; uv in the surface's domain.
struct SurfaceConstraint {
    SurfaceConstraintType type = SurfaceConstraintType::Position;
    Eigen::Vector2d uv = Eigen::Vector2d::Zero();
    Eigen::Vector2d uv2 = Eigen::Vector2d::Zero();  ///< Distance only
    Eigen::Vector3d value = Eigen::Vector3d::Zero();  ///< point (Position), direction (Normal, CurveTangent), S_u (Tangents)
    Eigen::Vector3d value2 = Eigen::Vector3d::Zero();  ///< S_v (Tangents only); set by factor() for Angle: n*
    double distance = 0.0;                         ///< Distance only, ≥ 0
    double angle = 0.0;                            ///< Angle only: radians in [0, π]
    std::optional<BSplineCurve<2>> domain;         ///< G: Curve (optional), CurveTangent (required)
    std::optional<BSplineCurve<3>> target;         ///< H: Curve only
    int keyPoints = 0;  ///< Curve/CurveTangent: 0 = decided by eq. 6-24; at most kMaxKeyPoints
};

struct DeformationOptions {
    Objective objective = Objective::Force;
    /// λ in (0, 1] (eq. 6-20): every target is moved to current + λ (target − current).
    double stiffness = 1.0;
    /// Control points (i, j) that never move.
    std::vector<std::array<int, 2>> blocked;
    /// Closed polygon in the domain (u, v) (first point repeated or not); empty = no bound. Control
    /// points whose Greville abscissae lie outside do not move (eq. 6-22), and the change fades to
    /// zero with its slope at the bound (§6.2.4): Force through the fixed nodes' force rows,
    /// Displacement through weights (R/r)² on the points r < 3 rings in from the bound.
    std::vector<Eigen::Vector2d> bound;
};

/// What the deformation achieved, beside the curve solver's report fields.
struct DeformationReport : ManipulationReport {
    std::vector<Eigen::Vector3d> keyPoints;  ///< the 3D targets of Curve constraints' key points
    int moved = 0;                           ///< control points whose position changed
    int gaussNewtonSteps = 0;                ///< chord-Newton steps taken for Distance constraints
    /// Per constraint: where it lies against the bound (§6.3); Over ones add no rows and leave the
    /// surface alone (residual 0), Under ones act with their key points inside the bound only.
    std::vector<BoundCase> boundCases;
};

/// Stateful solver for a drag, like CurveManipulationSolver: factor() sets up F and the objective's
/// factorization for the constraint locations (and Normal/CurveTangent directions), solve() takes
/// the new target values and is a back-substitution: d = C b with C precomputed.
///
/// With the objective ½ dᵀ H d (H = I or KᵀK + εI, block-diagonal over x, y, z) and H = RᵀR
/// (sparse Cholesky), e = R d turns min dᵀHd s.t. F d = b into the minimum-norm problem
/// min ‖e‖ s.t. (F R⁻¹) e = b, solved as in the curve solver by a column-pivoted QR of (F R⁻¹)ᵀ —
/// exact when the rows are independent, the least-squares compromise otherwise. FFᵀ is never
/// formed or inverted.
class SurfaceDeformationSolver {
public:
    /// @throws GeometryError naming the field: a parameter outside the domain, a non-finite value,
    ///         a blocked index outside the net, a Curve without target, a CurveTangent without domain.
    void factor(const Surface3d& surface, const std::vector<SurfaceConstraint>& constraints,
                const DeformationOptions& options = {});

    /// Per event: `constraints` has the factored types and locations; their values (Position value,
    /// Curve target, Distance distance) are read. Normal and CurveTangent directions are those given
    /// to factor() (a new direction needs factor() again).
    Surface3d solve(const std::vector<SurfaceConstraint>& constraints, DeformationReport* report = nullptr) const;

    int rows() const { return static_cast<int>(F_.rows()); }
    int freePoints() const { return static_cast<int>(free_.size()); }
    int rank() const { return rank_; }
    /// The constraint matrix over the free points' changes, ordered [x of free points; y; z].
    const Eigen::MatrixXd& constraintMatrix() const { return F_; }
    const std::vector<int>& freeIndices() const { return free_; }
    /// Key point locations (u, v) of each Curve/CurveTangent constraint (empty for others).
    const std::vector<std::vector<Eigen::Vector2d>>& keyPointLocations() const { return keyUv_; }

private:
    struct Row;
    Eigen::VectorXd rightHandSide(const std::vector<SurfaceConstraint>& constraints,
                                  std::vector<Eigen::Vector3d>* keyPoints) const;

    Surface3d surface_{1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2, std::vector<Eigen::Vector3d>(4, Eigen::Vector3d::Zero())};
    std::vector<SurfaceConstraint> factored_;
    DeformationOptions options_;
    std::vector<int> free_;
    std::vector<int> rowOwner_;                         // constraint index of each row
    std::vector<std::vector<Eigen::Vector2d>> keyUv_;   // per constraint
    std::vector<std::vector<double>> keyT_;             // per constraint: parameters on H
    std::vector<Eigen::Vector3d> distanceDirection_;    // per constraint (Distance): linearization
    std::vector<BoundCase> boundCases_;                 // per constraint
    Eigen::MatrixXd F_;                                 // rows × 3·free
    Eigen::VectorXd current_;                           // F·(current net) restricted row values
    Eigen::MatrixXd C_;                                 // 3·free × rows: d = C b
    Eigen::MatrixXd F1_, C1_;                           // separable: one coordinate's F and C
    bool separable_ = false;                            // only Position/Curve rows: per coordinate
    int rank_ = 0;
    bool nonLinear_ = false;  // Distance rows: chord-Newton steps after the linear solve
};

/// One-shot: the deformed surface meeting `constraints` (values from the constraints).
Surface3d deformSurface(const Surface3d& surface, const std::vector<SurfaceConstraint>& constraints,
                        const DeformationOptions& options = {}, DeformationReport* report = nullptr);

/// Key points of a Curve constraint: their (u, v) on the surface and parameters t on the target H
/// (count by eq. 6-24 unless keyPoints > 0; uniform in G's parameter, or, when no domain G is given,
/// evenly spaced along H's length with the feet on the surface by global projection).
struct KeyPoints {
    std::vector<Eigen::Vector2d> uv;
    std::vector<double> t;
};
KeyPoints curveKeyPoints(const Surface3d& surface, const SurfaceConstraint& curve,
                         const SurfaceProjector* projector = nullptr);

/// Residual of each constraint on `after` against its stiffness-scaled target from `before`:
/// model units for Position, Curve (largest over the key points `keyUv`/`keyT`) and Distance;
/// radians for Normal and CurveTangent at stiffness 1 (directions taken from `factored`).
std::vector<double> constraintResiduals(const Surface3d& before, const Surface3d& after,
                                        const std::vector<SurfaceConstraint>& factored,
                                        const std::vector<SurfaceConstraint>& constraints,
                                        const std::vector<std::vector<Eigen::Vector2d>>& keyUv,
                                        const std::vector<std::vector<double>>& keyT, double lambda);

/// Sets report.compromise and its message when a residual shows a constraint not met although its
/// linearized rows are (a collapsed tangent under a Normal constraint, distance steps not converged).
void flagUnmet(const Surface3d& surface, const std::vector<SurfaceConstraint>& constraints, DeformationReport& report);

/// ‖K d‖ of the change from `before` to `after` (same net): the change of the bar network's external
/// forces with unit force densities, K the net's graph Laplacian (4-neighbours) — what the Force
/// objective minimizes, and the smoothness measure of the benchmarks and tests (lower is smoother).
double forceChange(const Surface3d& before, const Surface3d& after);

/// Most key points one Curve or CurveTangent constraint uses (eq. 6-24's count is capped here: a
/// wildly turning target would otherwise ask for thousands of rows, each 3 dense rows of F).
constexpr int kMaxKeyPoints = 256;

/// Number of key points on a target curve H by eq. 6-24: the knot spans crossed between the feet
/// of H's ends in the dominant direction, plus one per π/8 of H's turning (more where it bends),
/// at most the spans crossed + the degree in that direction − 2 (what the net can meet well).
int keyPointCount(const Surface3d& surface, const BSplineCurve<3>& target, const Eigen::Vector2d& footStart,
                  const Eigen::Vector2d& footEnd);

}  // namespace sculptline::solvers::deformation
