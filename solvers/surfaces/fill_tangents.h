#pragma once
// G1 conditions for the Coons fill (coons_fill.h): the fill's cross-boundary derivative is made to
// lie in the tangent plane of an adjacent (reference) surface along chosen boundaries, by the least
// change of the control points next to those boundaries (constrained least squares on the inner
// rows; cf. Farin, "Curves and Surfaces for CAGD", §22.5 on cross-boundary derivatives, and The
// NURBS Book §9.4.4 on constrained fitting). Used by FillBuilder; not a public entry point.
#include "solvers/bspline/bspline_surface.h"
#include "solvers/bspline/projection.h"
#include "solvers/surfaces/compatible_curves.h"

#include <array>
#include <memory>
#include <vector>

namespace sculptline::solvers::surfaces {

/// Parameters on a reference surface of points along a curve that lies on it: global projection
/// for the first point (and whenever tracking fails), then Gauss-Newton from the previous point's
/// parameters (points on the surface: the residual vanishes, so convergence is quadratic).
class ReferenceTracker {
public:
    explicit ReferenceTracker(const Surface3d& reference);
    /// Parameters of each point; `worst` receives the largest distance from the surface and
    /// `normals` (if given) the unit normals there. A call with as many points as the previous one
    /// starts each point from its previous parameters (a dragged curve moves little per event).
    std::vector<Eigen::Vector2d> locate(const std::vector<Eigen::Vector3d>& points, double* worst,
                                        std::vector<Eigen::Vector3d>* normals = nullptr);
    /// Unit normal of the reference at (u, v); zero where it is undefined.
    Eigen::Vector3d normal(const Eigen::Vector2d& uv) const;
    const Surface3d& surface() const { return *reference_; }

private:
    /// Gauss-Newton from uv; returns the distance reached and sets the normal there.
    double refine(const Eigen::Vector3d& x, Eigen::Vector2d& uv, Eigen::Vector3d& normal) const;

    std::shared_ptr<const Surface3d> reference_;
    double size_ = 1.0;  // control-box diagonal (model units)
    std::vector<Eigen::Vector2d> last_;  // parameters found by the previous locate()
    std::shared_ptr<const SurfaceProjector> projector_;  // built on first need
};

/// One patch side with a G1 condition: side 0 is v = 0, 1 is u = 1, 2 is v = 1, 3 is u = 0 (the
/// Coons patch's sides), its boundary curve on [0, 1] in the patch's direction, and the tracker.
struct G1Side {
    int side = 0;
    int tangentIndex = 0;  ///< index in FillOptions::tangents, for messages
    int curveIndex = 0;    ///< index in the fill's curves, for messages
    std::shared_ptr<ReferenceTracker> tracker;
    std::vector<double> samples;         ///< parameters along the side (ends included)
    std::vector<Eigen::Vector3d> normals;  ///< reference normals there (filled by locateSamples)
};

/// Samples per knot span of a G1 side: the constraint rows and the angle measurement share them.
/// Six interior points per span pin a cubic cross-derivative's deviation from the plane between
/// them to a small fraction of its value at the samples.
constexpr int kG1SamplesPerSpan = 6;

/// Sets g.samples for the side's layout and the reference normals at the side's points.
/// @throws GeometryError "tangents[k]: curves[c] does not lie on its reference surface ..." when a
///         sample is farther than `tolerance` from the reference.
void locateSamples(G1Side& g, const Curve3d& side, const CurveLayout& layout, double tolerance);

/// Moves the control points next to each G1 side (rows/columns 1 and n - 2; boundaries untouched)
/// by the smallest change that puts the cross-boundary derivative into the reference tangent plane
/// at the samples: min |δ|² subject to n_s · S_cross(t_s) = 0 in the least-squares sense, solved as
/// the regularized normal equations (sparse LDLT). `pts` is the nu × nv net, row-major in u.
void applyG1(std::vector<Eigen::Vector3d>& pts, int nu, int nv, const std::array<CurveLayout, 2>& layouts,
             const std::vector<G1Side>& sides);

/// Largest angle (degrees) between the surface normal and the reference normal over the samples of
/// every G1 side (lines, not orientations: 0..90); points where the surface normal is undefined
/// (a collapsed side) are skipped.
double maxG1AngleDegrees(const Surface3d& surface, const std::vector<G1Side>& sides);

}  // namespace sculptline::solvers::surfaces
