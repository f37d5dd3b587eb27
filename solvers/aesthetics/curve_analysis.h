#pragma once
// Aesthetic analysis of planar curves (thesis ch. 7): the characteristic points of Leyton's process
// grammar (curvature extrema and inflections, found exactly per polynomial piece), the curve's name,
// the quantitative characteristics of each extremum (§7.3.2) and the FIORES measures (§7.3.3), with
// the slope of the logarithmic curvature graph of each monotone-curvature segment (log-aesthetic
// curves: Harada, Yoshida & Saito). Conventions: ../shared/interfaces.md, `analyze`.
#include "solvers/bspline/bspline_curve.h"

#include <optional>
#include <string>
#include <vector>

namespace sculptline::solvers::aesthetics {

/// M: a local maximum of signed curvature, m: a local minimum, followed by the sign of kappa there;
/// Inflection: kappa changes sign ("0").
enum class PointKind { MaxPositive, MinPositive, MaxNegative, MinNegative, Inflection };

/// "M+", "m+", "M-", "m-" or "0".
const char* codon(PointKind kind);
/// The kind of the same point on the reversed curve (kappa changes sign: M+ <-> m-, m+ <-> M-).
PointKind reversed(PointKind kind);

struct CharacteristicPoint {
    double u = 0.0;
    PointKind kind = PointKind::Inflection;
    double curvature = 0.0;  ///< signed, 1 / model unit
    double arcLength = 0.0;  ///< from the domain start
};

/// The quantitative characteristics of one extremum (§7.3.2, Fig. 7-10). Left/right follow the
/// parameter; a neighbour is the adjacent characteristic point (inflections included), or the
/// curve's end on an open curve where there is none.
struct Characteristics {
    int point = 0;             ///< index into CurveAnalysis::points
    double dkLeft = 0.0;       ///< kappa(point) - kappa(left neighbour)
    double dkRight = 0.0;
    double dLeft = 0.0;        ///< arc length to the left neighbour
    double dRight = 0.0;
    double rangeLeft = 0.0;    ///< arc length from the point to where kappa = kappa(point) - dkLeft / 2
    double rangeRight = 0.0;
    bool smallVisibility = false;
    bool sharpCorner = false;
    bool symmetric = false;
    bool redundant = false;
};

/// Thresholds of the properties (§7.3.2), in model units. Unset ones default relative to the curve's
/// arc length L: gamma = 0.05 L (a detail is shorter than a twentieth of the curve), beta = 5 / L
/// (less than the change from a straight line to a circle of radius L / 5, whose full turn would
/// be 1.3 times the curve's length), mu = 50 / L (a corner: ten times beta, a radius of L / 50).
struct Thresholds {
    std::optional<double> distance;   ///< gamma
    std::optional<double> curvature;  ///< beta
    std::optional<double> sharp;      ///< mu
};

constexpr double kDefaultDistanceFraction = 0.05;
constexpr double kDefaultCurvatureTimesLength = 5.0;
constexpr double kDefaultSharpTimesLength = 50.0;

/// The FIORES measures (§7.3.3), over the whole curve, ends included. `tension` is absent where the
/// average curvature vanishes (an s-curve whose turns cancel: the ratio has no meaning there).
struct Measures {
    double curvatureMin = 0.0;
    double curvatureMax = 0.0;
    double curvatureAverage = 0.0;  ///< integral of kappa ds / L
    double acceleration = 0.0;      ///< (kappa_max - kappa_min) / the arc length between them
    double sharpness = 0.0;         ///< max |kappa|
    double flatness = 0.0;          ///< 1 - d_min / d_max of the minimum-area enclosing rectangle
    double convexity = 0.0;         ///< signed area between curve and chord (CCW > 0) * d_min / d_max
    std::optional<double> tension;  ///< (kappa_max - kappa_min) / kappa_avg
    double crown = 0.0;             ///< signed largest distance from the chord (left of it > 0)
};

/// A segment between consecutive curvature extrema (or ends) over which |kappa| is monotone, and the
/// slope of its logarithmic curvature graph: x = log(rho), y = log(rho / |d rho / d s|) sampled along the
/// segment, fitted by a line (slope alpha, with the fit's r^2). A clothoid has alpha = -1, a logarithmic
/// spiral 1, a circle involute 2 (Yoshida & Saito 2006). Segments where kappa changes sign or reaches
/// zero are split at the inflection and measured on each side.
struct LcgSegment {
    double u0 = 0.0, u1 = 0.0;
    double slope = 0.0;
    double r2 = 0.0;
    int samples = 0;
};

struct CurveAnalysis {
    std::string name;  ///< codons in parameter order; closed curves: the canonical rotation/reversal
    std::vector<CharacteristicPoint> points;
    std::vector<Characteristics> characteristics;
    Measures measures;
    std::vector<LcgSegment> lcg;
    double length = 0.0;
    double gamma = 0.0, beta = 0.0, mu = 0.0;  ///< the thresholds used
    bool closed = false;
};

/// kappa' of a rational curve of degree p is a polynomial of degree 8p - 6 per span: 90 at degree 12,
/// where the Bernstein products' binomial weights still keep double precision; designers' curves are
/// cubic to quintic.
constexpr int kMaxAnalysisDegree = 12;
/// The most control points analysed: 10,000 take about 0.2 s (a 200-point curve 4 ms), so a
/// hostile input cannot hold a caller for long; a sketched curve has tens.
constexpr int kMaxAnalysisPoints = 10000;

/// Signed curvature (x'y'' - y'x'') / |C'|^3 at u; 0 where the curve stops.
double signedCurvature(const Curve2d& curve, double u);

/// The characteristic points only (no measures), in parameter order.
std::vector<CharacteristicPoint> characteristicPoints(const Curve2d& curve);

/// The name alone (no arc lengths, characteristics or measures): what the operators test while they
/// search for an amount. @throws GeometryError as characteristicPoints.
std::string nameOf(const Curve2d& curve);

/// The full analysis.
/// @throws GeometryError for degree < 2 ("degree": a polyline has no curvature) or above
///         kMaxAnalysisDegree, more than kMaxAnalysisPoints control points ("points"), a collapsed curve,
///         or non-positive thresholds ("thresholds.distance", ...).
CurveAnalysis analyzeCurve(const Curve2d& curve, const Thresholds& thresholds = {});

/// The name of a sequence of kinds; closed: the lexicographically smallest over all rotations of the
/// sequence and of its reversal (§7.1: a closed curve has no first point and no direction).
std::string curveName(const std::vector<PointKind>& kinds, bool closed);

/// The plane a planar curve was read in: a point of it and two orthonormal axes, right-handed with the
/// normal the curve's turning sense is seen from.
struct PlaneFrame {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    Eigen::Vector3d e1 = Eigen::Vector3d::UnitX(), e2 = Eigen::Vector3d::UnitY();
};

/// A 3D curve in its own plane: z-constant curves by (x, y); others in their best-fit plane's (U, V)
/// axes, with the normal's orientation chosen so that a curve in the xy plane keeps its turning sense
/// (normal along +z where it has a z component, else the fit's normal).
/// @param flatness  largest allowed distance from the plane, relative to the curve's size.
/// @param frame     receives the plane, for spaceCurve.
/// @throws GeometryError "curve: not planar (...)" when a control point is farther than that.
Curve2d planarCurve(const Curve3d& curve, double flatness = 1e-6, PlaneFrame* frame = nullptr);

/// A planar curve put back into its plane in space (the inverse of planarCurve).
Curve3d spaceCurve(const Curve2d& curve, const PlaneFrame& frame);

}  // namespace sculptline::solvers::aesthetics
