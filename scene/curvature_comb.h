#pragma once
// The curvature comb (porcupine) of the selected curve: at samples along it a tooth from C(u) along
// the curvature vector K = d^2C/ds^2 = kappa N, of length scale * |kappa|, and the envelope polyline
// through the tips (Farin, Curves and Surfaces for CAGD, §23.3 "curvature plots"). For a planar
// curve kappa N points into the plane's turning side, so the comb shows the signed curvature (the
// envelope crosses the curve at inflections); for a space curve it is the Frenet normal. Drawn as an
// unpickable, unlit overlay in world coordinates; kept in step with the curve as a model observer:
// one update per model update of that curve (a drag's frame), its cost proportional to the teeth.
//   SoSeparator "CurvatureComb" { pick style, light model, SoSwitch "CombSwitch" {
//     SoSeparator "CombTeeth" { colour, style, SoCoordinate3 (base, tip)*, SoLineSet (2)* }
//     SoSeparator "CombEnvelope" { colour, style, SoCoordinate3 tips, SoLineSet } } }
#include "model/model.h"
#include "solvers/bspline/bspline_curve.h"

#include <Eigen/Core>

#include <optional>
#include <vector>

class SoCoordinate3;
class SoLineSet;
class SoSeparator;
class SoSwitch;

namespace sculptline::scene {

/// Samples per knot span by default: enough for a cubic's curvature (a rational function of
/// degree <= 6 per span) to read as a smooth envelope.
constexpr int kDefaultCombDensity = 12;
/// The comb's longest tooth as a fraction of the curve's size (its bounding box's diagonal) at
/// scale factor 1: long enough to read, short enough not to cross the neighbouring curves.
constexpr double kCombLengthFraction = 0.15;

struct CombTooth {
    double u = 0.0;
    Eigen::Vector3d base = Eigen::Vector3d::Zero();  ///< C(u), world coordinates
    Eigen::Vector3d tip = Eigen::Vector3d::Zero();   ///< base + scale * kappa N
    Eigen::Vector3d curvatureVector = Eigen::Vector3d::Zero();  ///< kappa N, 1 / model unit
};

/// The teeth at `density` samples per non-empty knot span (span ends included once), tips at
/// scale * kappa N. Where the curve stops (|C'| = 0) the tooth has length 0.
/// @param density samples per span, >= 1.
/// @param scale   model units squared (a tooth's length per unit of curvature), >= 0.
std::vector<CombTooth> combTeeth(const solvers::Curve3d& curve, int density, double scale);

/// The scale at which the longest of `teeth` (made with any scale) is kCombLengthFraction of the
/// size of the curve they sample (the bounding box of their bases); 0 for a straight curve.
double defaultCombScale(const std::vector<CombTooth>& teeth);

/// A curve entity in its own plane, for signed curvature: a curve on a plane in the plane's frame
/// (its turning sense as seen from the plane's front, the side its normal points to), other curves
/// by solvers::aesthetics::planarCurve of the world form.
/// @throws solvers::GeometryError when the curve is not planar.
solvers::Curve2d planarForm(const model::Entity& curve);

class CurvatureComb : public model::ModelObserver {
public:
    /// Observes `model`; the model must outlive the comb. Hidden, and showing no curve, at first.
    explicit CurvatureComb(model::Model& model);
    ~CurvatureComb() override;
    CurvatureComb(const CurvatureComb&) = delete;
    CurvatureComb& operator=(const CurvatureComb&) = delete;

    /// The graph root (ref()ed by the comb; add it to a scene).
    SoSeparator* root() const { return root_; }

    /// The curve whose comb is drawn (0 or a non-curve: none). A new curve gets the default scale.
    void setCurve(model::EntityId id);
    model::EntityId curve() const { return curve_; }
    void setVisible(bool visible);
    bool visible() const { return visible_; }
    /// Samples per knot span, >= 1.
    void setDensity(int density);
    int density() const { return density_; }
    /// The scale as a factor on the default one (defaultCombScale), > 0.
    void setScaleFactor(double factor);
    double scaleFactor() const { return factor_; }
    /// The scale the teeth are drawn at (model units squared), 0 when nothing is drawn.
    double scale() const { return factor_ * baseScale_; }
    /// The teeth drawn (empty while hidden or without a curve).
    const std::vector<CombTooth>& teeth() const { return teeth_; }
    /// Comb rebuilds since construction (tests: one per model update of the curve while shown).
    int rebuilds() const { return rebuilds_; }

    void entityAdded(const model::Entity&) override {}
    void entityRemoved(const model::Entity& entity) override;
    void entityUpdated(const model::Entity& entity) override;

private:
    /// Recomputes the teeth and rewrites the nodes; `rescale`: the default scale is taken anew
    /// (a new curve, or the curve changed outside a drag).
    void rebuild(bool rescale);
    void clear();

    model::Model& model_;
    SoSeparator* root_ = nullptr;
    SoSwitch* switch_ = nullptr;
    SoCoordinate3* teethCoords_ = nullptr;
    SoLineSet* teethLines_ = nullptr;
    SoCoordinate3* envelopeCoords_ = nullptr;
    SoLineSet* envelopeLine_ = nullptr;
    model::EntityId curve_ = 0;
    bool visible_ = false;
    int density_ = kDefaultCombDensity;
    double factor_ = 1.0;
    double baseScale_ = 0.0;
    bool scaled_ = false;  ///< baseScale_ belongs to curve_
    std::vector<CombTooth> teeth_;
    int rebuilds_ = 0;
};

}  // namespace sculptline::scene
