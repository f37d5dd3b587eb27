#pragma once
// The surface through curves drawn on it (seed 000 §3–4): the stacked incidence system A F = H of
// incidence_system.h solved by regularization (solvers/regularization): fixed curves exactly (their
// rows' null space carries the rest), the others by TSVD with the present surface as the prior, the
// truncation at the L-curve's corner, and MTSVD's correction by the smoothing functionals.
#include "solvers/incidence/incidence_system.h"
#include "solvers/regularization/tsvd.h"

#include <memory>
#include <optional>
#include <vector>

namespace sculptline::solvers::incidence {

/// One curve for solveIncidence: the domain curve G (or none: the target's pre-image by global
/// projection onto the surface), the target H (or none: the surface keeps its present image S(G)),
/// and whether it is met exactly.
struct IncidenceCurve {
    std::optional<Curve2d> domain;
    std::optional<Curve3d> target;
    bool fixed = false;
};

enum class IncidenceMethod { Tsvd, Mtsvd };

struct IncidenceOptions {
    IncidenceMethod method = IncidenceMethod::Mtsvd;
    /// MTSVD's smoothing L = α1 L_area + α2 L_thin-plate + α3 L_curvature-variation (as Gram
    /// weights; seed 000 eq. 5). Only their ratios matter.
    double area = 0.0, thinPlate = 1.0, curvatureVariation = 0.0;
    /// Truncation; 0 = the L-curve's corner (of TSVD's L-curve: MTSVD corrects at TSVD's k).
    int k = 0;
};

struct IncidenceResult {
    Surface3d surface;
    int k = 0;       ///< the truncation used
    int corner = 0;  ///< the L-curve's corner
    int rows = 0, cols = 0;  ///< of the regularized (soft) system, after the fixed curves' rows
    int hardRows = 0;
    /// Largest ‖S'(G(t)) − H(t)‖ over dense t of the curves with a target that are not fixed, and of
    /// the fixed ones (model units).
    double residual = 0.0, fixedResidual = 0.0;
    regularization::LCurve lcurve;
    std::vector<Curve2d> domains;  ///< the domain curve of each input curve (given or projected)
};

/// The solve kept across a drag (issue 14 §2: a re-solve from the cached SVD). factor() fixes the
/// domain curves, which curves are fixed, the targets' layouts (degree, knots) and the prior; it
/// stacks the system, factors the fixed curves' rows and the soft system's SVD, chooses k at the
/// L-curve's corner and prepares MTSVD's correction at that k. solve() takes targets of the same
/// layouts (their control points moved, as when a plane carrying them is dragged) and costs their
/// right-hand sides, Uᵀb and two products: no new factorization, k kept.
class IncidenceSolver {
public:
    IncidenceSolver();
    ~IncidenceSolver();
    IncidenceSolver(IncidenceSolver&&) noexcept;
    IncidenceSolver& operator=(IncidenceSolver&&) noexcept;

    /// @throws as solveIncidence.
    void factor(const Surface3d& surface, const std::vector<IncidenceCurve>& curves, const IncidenceOptions& options = {});
    /// Whether `curves` can be solved with the factorization: as many, with targets where they had
    /// them, of the same degrees and knots.
    bool fits(const std::vector<IncidenceCurve>& curves) const;
    /// @throws std::invalid_argument when !fits(curves).
    IncidenceResult solve(const std::vector<IncidenceCurve>& curves) const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

/// The domain curve of a 3D curve near `surface`: its pre-image by global projection, fitted by
/// least squares in `target`'s degree and knots (a closed target's clamped form), so that a curve on
/// an affinely parametrized surface gets its exact pre-image.
Curve2d projectedDomain(const Surface3d& surface, const Curve3d& target);

/// Solves for the surface. @throws GeometryError (a curve outside the domain, a rational input, no
/// curves) and std::invalid_argument (k out of range).
IncidenceResult solveIncidence(const Surface3d& surface, const std::vector<IncidenceCurve>& curves,
                               const IncidenceOptions& options = {});

}  // namespace sculptline::solvers::incidence
