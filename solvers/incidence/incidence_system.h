#pragma once
// Several curve constraints on one surface stacked into one linear system A F = H (seed 000 §4.1:
// "a concatenation of several curve constraints for one surface"): each curve's exact composition
// rows with its request curve brought into the same space, fixed curves' rows flagged to be met
// exactly, and a point-incidence row where two domain curves cross. The system is what the
// regularized solve (TSVD / MTSVD with the smoothing functionals) takes; it is not solved here.
#include "solvers/incidence/compatibility.h"
#include "solvers/incidence/curve_crossings.h"

namespace sculptline::solvers::incidence {

/// One curve constraint: the surface should pass through `request` along the domain curve.
struct CurveRequest {
    Curve2d domain;     ///< G, non-rational, inside the surface's domain
    Curve3d request;    ///< H', non-rational, over G's domain, degree <= (p + q) * G's degree
    bool fixed = false; ///< a fixed curve's rows are hard constraints (met exactly)
};

/// Where in the stacked system a curve's or a crossing's rows are.
struct RowBlock {
    enum class Kind { Curve, Crossing };
    Kind kind = Kind::Curve;
    int firstRow = 0;
    int rowCount = 0;
    int curve = 0;        ///< the curve (the first of the two for a crossing)
    int otherCurve = -1;  ///< a crossing's second curve
    double t = 0.0;       ///< a crossing's parameter on `curve`
    double tOther = 0.0;  ///< and on `otherCurve`
    double mismatch = 0.0;  ///< a crossing's |H'_1(t) - H'_2(tOther)| (requests that disagree there)
};

struct IncidenceSystem {
    SparseRows matrix;         ///< rows x (countU * countV)
    ControlMatrix rhs;         ///< rows x 3: the requests in the rows' spaces, the crossings' points
    std::vector<bool> hard;    ///< per row: to be met exactly (rows of fixed curves and their crossings)
    std::vector<RowBlock> blocks;
    std::vector<Composition> compositions;  ///< per curve: A and H's space
    /// Row indices of the hard (exact) and of the soft (regularized) rows.
    std::vector<int> hardRows() const;
    std::vector<int> softRows() const;
};

/// Options of stackIncidences.
struct StackOptions {
    /// Add one point-incidence row per crossing of two domain curves: S(G1(t1)) = the requests'
    /// point there (the fixed curve's if one is fixed, else the mean of the two). On a fixed curve
    /// the row repeats what that curve's rows impose (a dependent hard row, consistent with them).
    bool crossingRows = true;
    /// Compose each curve in the smaller space of its continuity (reduceMultiplicities): fewer rows.
    /// A request must then be at least as smooth as H at G's knots and the crossings (a cubic
    /// request with simple knots is; H itself in Bezier form is not).
    bool reduceMultiplicities = false;
};

/// The stacked system for the curves on a surface of structure `surface`. Each request's interior
/// knots are made breakpoints of its composition, so it is brought into H's space exactly.
/// @throws GeometryError as compose() and compatibilityMatrix() do.
IncidenceSystem stackIncidences(const SurfaceStructure& surface, const std::vector<CurveRequest>& curves,
                                const StackOptions& options = {});

}  // namespace sculptline::solvers::incidence
