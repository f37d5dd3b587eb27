#pragma once
// Over-sketching: a stroke drawn over a curve replaces the part it covers, with smooth transitions.
// Two methods: `local-c2` (seed 001_08db50965017e161, Kim & Kim, Alg. 1-1/1-2, eqs. 1-2) and
// `blend` (thesis 002_d9515b9d07f9cfd1 §4.2, eqs. 4-23..4-26; seed 003 §4).
#include "solvers/bspline/bspline_curve.h"
#include "solvers/bspline/projection.h"

#include <Eigen/Core>
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace sculptline::solvers::editing {

enum class OversketchMethod {
    LocalC2,  ///< constrained least squares on [t_k, t_l]: exact outside, C2, adds only needed knots
    Blend,    ///< control point replacement with scale factor and length/tangent transitions
};

/// "local-c2" or "blend"; nullopt otherwise.
std::optional<OversketchMethod> parseOversketchMethod(const std::string& name);

struct OversketchOptions {
    /// The default, chosen by measurement (see oversketch.cpp and bench/editing_bench.cpp).
    OversketchMethod method = OversketchMethod::LocalC2;
    /// Fit tolerance as a fraction of the stroke's length (local-c2: Alg. 1-1's ε; blend: the
    /// tolerance of the stroke's own least-squares fit). (0, 1).
    double tolerance = 0.002;
    /// The input's resolution, model units (>= 0; 0 = unknown): the fit's tolerance is never below
    /// it. A window stroke's samples are whole pixels, and a tolerance below one pixel's footprint
    /// follows their staircase (as stroke::FitOptions::resolution for a sketched stroke).
    double resolution = 0.0;
    /// Blend: eq. 4-23's scale in [0, 1]; 1 follows the stroke, 0 leaves the curve as it is.
    double scale = 1.0;
    /// Local-c2: transition length as a multiple of the stroke end's distance from the curve
    /// (seed 001 §3: d1 = 3|C(u_s) - h_0|, "we could choose a value larger than three").
    double transitionFactor = 3.0;
    /// Local-c2: the transition is at least this fraction of the stroke's length, so a stroke that
    /// starts exactly on the curve still gets a blend (d1 = 0 in the paper would give a kink).
    double minTransition = 0.1;
};

/// Over-sketches `curve` (open or closed, rational or not) with `stroke` (in the curve's space).
/// Rational curves: the untouched parts keep their points and weights; the new points get weights
/// interpolated between those of the kept points next to them.
/// A stroke drawn against the curve's direction is reversed first. Open curves: a stroke running
/// past an end extends the curve (local-c2) or replaces the end (blend). Closed curves: the stroke
/// replaces the arc it covers, however long (the uncovered arc is refined by exact knot insertion
/// when it holds too few control points for the transitions and an untouched span).
/// @param span receives the new curve's parameter interval that was replaced.
/// @param maxError receives the fit's max deviation in model units, measured at the fit parameters
///        (an upper bound of the distance): over the whole target h̄ for local-c2, over the stroke
///        for blend (before the scale of eq. 4-23 is applied).
/// @throws GeometryError naming "stroke" (fewer than two distinct points, non-finite, or covering a
///         whole closed curve), "scale" or "tolerance" (out of range).
/// @note Any degree works; local-c2 then pins `degree` points per side and is C^{degree-1}.
template <int Dim>
BSplineCurve<Dim> oversketch(const BSplineCurve<Dim>& curve, const std::vector<Eigen::Matrix<double, Dim, 1>>& stroke,
                             const OversketchOptions& options = {}, std::pair<double, double>* span = nullptr,
                             double* maxError = nullptr);

/// Repeated over-sketching of one curve (the interactive loop): holds the current curve and the
/// options between strokes. Each stroke re-projects onto the current curve (the curve changes with
/// every stroke, so there is no factorization to keep).
template <int Dim>
class OversketchSolver {
public:
    explicit OversketchSolver(BSplineCurve<Dim> curve, OversketchOptions options = {});
    /// Applies one stroke; returns the replaced parameter span of the new curve.
    std::pair<double, double> apply(const std::vector<Eigen::Matrix<double, Dim, 1>>& stroke);
    const BSplineCurve<Dim>& curve() const { return curve_; }

private:
    BSplineCurve<Dim> curve_;
    OversketchOptions options_;
};

namespace detail {

/// The stroke, cleaned (duplicates dropped) and oriented along the curve, with the parameters of
/// its ends' projections (closed curves: u_e may exceed the domain end, u_e - u_s < period).
template <int Dim>
struct StrokeOnCurve {
    std::vector<Eigen::Matrix<double, Dim, 1>> points;
    double us = 0.0, ue = 0.0;
    double length = 0.0;
};

/// The fit's tolerance in model units: OversketchOptions::tolerance of the stroke's length, never
/// below OversketchOptions::resolution.
inline double fitTolerance(const OversketchOptions& o, double strokeLength)
{
    return std::max(o.tolerance * strokeLength, o.resolution);
}

template <int Dim>
StrokeOnCurve<Dim> placeStroke(const BSplineCurve<Dim>& curve,
                               const std::vector<Eigen::Matrix<double, Dim, 1>>& stroke);

template <int Dim>
BSplineCurve<Dim> oversketchLocalC2(const BSplineCurve<Dim>& curve, const StrokeOnCurve<Dim>& s,
                                    const OversketchOptions& o, std::pair<double, double>& span, double& maxError);

template <int Dim>
BSplineCurve<Dim> oversketchBlend(const BSplineCurve<Dim>& curve, const StrokeOnCurve<Dim>& s,
                                  const OversketchOptions& o, std::pair<double, double>& span, double& maxError);

}  // namespace detail
}  // namespace sculptline::solvers::editing
