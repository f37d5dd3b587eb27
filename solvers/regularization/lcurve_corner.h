#pragma once
// The corner of a discrete L-curve (log ρ_k, log η_k), k = 1..r: the truncation that balances the
// fit against the growth of the solution (Hansen, "The L-curve and its use in the numerical
// treatment of inverse problems", 2001).
#include "solvers/regularization/tsvd.h"

#include <string>
#include <vector>

namespace sculptline::solvers::regularization {

enum class CornerMethod {
    /// Seed 000 §4.2: a cubic spline through the log-log points (a C0 cubic: the polyline elevated),
    /// knots removed by ranking their removal errors (Lyche & Mørken 1987, with The NURBS Book A5.8
    /// as the removal step) while the threshold grows, until the remaining knots' errors lie within
    /// one decade, |log10 ε_max − log10 ε_min| <= 1. The knots left are the sharp turns, each measured
    /// over a window of 5 % of the curve's length (a corner left as a cluster of knots turns as a
    /// whole); the corner is among them one turning the L-curve's way, and of several, the one with
    /// the smallest η.
    KnotRemoval,
    /// Hansen, Jensen & Rodriguez, "An adaptive pruning algorithm for the discrete L-curve
    /// criterion", J. Comput. Appl. Math. 198 (2007) 483–492 (Regularization Tools 4.x `corner`).
    AdaptivePruning,
};

/// The method used unless told, per regularizer (README "Regularization", the validation on Hansen's
/// five test problems, 2 noise levels × 3 tuning seeds): for TSVD knot removal (16 of 30 cases within
/// 1.5× of the best k's error, against 12 by pruning), for MTSVD adaptive pruning (14 of 30, against
/// 12). On 5 held-out seeds: TSVD 29 against 22 of 50, MTSVD 21 and 21.
CornerMethod defaultCornerMethod(bool mtsvd = false);
std::string cornerMethodName(CornerMethod method);

struct CornerResult {
    int k = 0;                    ///< 1-based truncation at the corner
    std::vector<int> candidates;  ///< the candidate corners considered (1-based), ascending
};

/// The corner of the L-curve. Points with ρ or η zero or non-finite, or ρ at round-off (below 1e3 ε of
/// the largest ρ), are skipped.
/// @throws std::invalid_argument for an empty L-curve (or rho and eta of different lengths).
/// @note With fewer than 3 usable points there is no corner: the first k that fits b exactly (ρ at
/// round-off) is returned, else the largest usable k.
CornerResult lcurveCorner(const LCurve& lcurve, CornerMethod method);

CornerResult cornerByKnotRemoval(const LCurve& lcurve);
CornerResult cornerByAdaptivePruning(const LCurve& lcurve);

}  // namespace sculptline::solvers::regularization
