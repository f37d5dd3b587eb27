#include "scene/curvature_comb.h"

#include "scene/eigen_coin.h"
#include "scene/overlay_nodes.h"
#include "solvers/aesthetics/curve_analysis.h"

#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoSwitch.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace sculptline::scene {
namespace {

/// Teeth in a light violet no curve state uses (scene/state_colors.h), thin so the curve reads
/// through them; the envelope in the same hue, brighter and wider.
const SbColor kTeethColor(0.72f, 0.52f, 0.95f);
const SbColor kEnvelopeColor(0.9f, 0.7f, 1.0f);
constexpr float kTeethWidth = 1.0f;
constexpr float kEnvelopeWidth = 2.0f;

/// kappa N = (C'' - (C'' . T) T) / |C'|^2, the second derivative by arc length (do Carmo §1-5):
/// zero where the curve stops.
Eigen::Vector3d curvatureVector(const Eigen::Vector3d& d1, const Eigen::Vector3d& d2)
{
    const double speed2 = d1.squaredNorm();
    if (!(speed2 > 0.0)) return Eigen::Vector3d::Zero();
    return (d2 - d1 * (d1.dot(d2) / speed2)) / speed2;
}

}  // namespace

std::vector<CombTooth> combTeeth(const solvers::Curve3d& curve, int density, double scale)
{
    density = std::max(density, 1);
    // The distinct knots inside the domain: each non-empty span gets `density` samples.
    std::vector<double> breaks;
    const double u0 = curve.domainStart(), u1 = curve.domainEnd();
    for (double k : curve.knots()) {
        if (k >= u0 && k <= u1 && (breaks.empty() || k > breaks.back())) breaks.push_back(k);
    }
    std::vector<CombTooth> teeth;
    teeth.reserve(breaks.size() * static_cast<size_t>(density) + 1);
    auto add = [&](double u) {
        const auto d = curve.derivatives(u, 2);
        CombTooth t;
        t.u = u;
        t.base = d[0];
        t.curvatureVector = curvatureVector(d[1], d[2]);
        t.tip = t.base + scale * t.curvatureVector;
        teeth.push_back(t);
    };
    for (size_t i = 0; i + 1 < breaks.size(); ++i) {
        for (int k = 0; k < density; ++k) add(breaks[i] + (breaks[i + 1] - breaks[i]) * k / density);
    }
    add(u1);
    return teeth;
}

double defaultCombScale(const std::vector<CombTooth>& teeth)
{
    Eigen::AlignedBox3d box;
    double largest = 0.0;
    for (const CombTooth& t : teeth) {
        box.extend(t.base);
        largest = std::max(largest, t.curvatureVector.norm());
    }
    if (box.isEmpty() || !(largest > 0.0) || !std::isfinite(largest)) return 0.0;
    return kCombLengthFraction * box.diagonal().norm() / largest;
}

solvers::Curve2d planarForm(const model::Entity& e)
{
    if (e.plane() != 0 && e.local) return solvers::aesthetics::planarCurve(*e.local);
    return solvers::aesthetics::planarCurve(*e.world);
}

CurvatureComb::CurvatureComb(model::Model& model) : model_(model)
{
    root_ = makeOverlayRoot();
    root_->ref();
    root_->setName("CurvatureComb");
    switch_ = new SoSwitch;
    switch_->setName("CombSwitch");
    switch_->whichChild = SO_SWITCH_NONE;
    root_->addChild(switch_);
    auto* teeth = new SoSeparator;
    teeth->setName("CombTeeth");
    teethCoords_ = addStyledCoordinates(teeth, kTeethColor, 0.0f, kTeethWidth);
    teethLines_ = new SoLineSet;
    teethLines_->numVertices.setNum(0);
    teeth->addChild(teethLines_);
    switch_->addChild(teeth);
    auto* envelope = new SoSeparator;
    envelope->setName("CombEnvelope");
    envelopeCoords_ = addStyledCoordinates(envelope, kEnvelopeColor, 0.0f, kEnvelopeWidth);
    envelopeLine_ = new SoLineSet;
    envelopeLine_->numVertices.setNum(0);
    envelope->addChild(envelopeLine_);
    switch_->addChild(envelope);
    model_.addObserver(this);
}

CurvatureComb::~CurvatureComb()
{
    model_.removeObserver(this);
    root_->unref();
}

void CurvatureComb::setCurve(model::EntityId id)
{
    const model::Entity* e = model_.find(id);
    id = e && e->kind == model::EntityKind::Curve ? id : 0;
    if (id == curve_) return;
    curve_ = id;
    scaled_ = false;
    rebuild(true);
}

void CurvatureComb::setVisible(bool visible)
{
    if (visible == visible_) return;
    visible_ = visible;
    switch_->whichChild = visible ? SO_SWITCH_ALL : SO_SWITCH_NONE;
    rebuild(!scaled_);
}

void CurvatureComb::setDensity(int density)
{
    density = std::max(density, 1);
    if (density == density_) return;
    density_ = density;
    rebuild(false);
}

void CurvatureComb::setScaleFactor(double factor)
{
    if (!(factor > 0.0) || factor == factor_) return;
    factor_ = factor;
    rebuild(false);
}

void CurvatureComb::entityRemoved(const model::Entity& e)
{
    if (e.id != curve_) return;
    curve_ = 0;
    scaled_ = false;
    clear();
}

void CurvatureComb::entityUpdated(const model::Entity& e)
{
    // During a drag the scale stays as it was at the press, so the teeth's lengths compare frame to
    // frame; a change at rest (an over-sketch, an undo) is scaled anew.
    if (e.id == curve_) rebuild(model_.dragged() == 0);
}

void CurvatureComb::clear()
{
    // Already empty (a hidden comb's curve updated): no field write, no redraw notification.
    if (teeth_.empty() && teethCoords_->point.getNum() == 0) return;
    teeth_.clear();
    teethCoords_->point.setNum(0);
    teethLines_->numVertices.setNum(0);
    envelopeCoords_->point.setNum(0);
    envelopeLine_->numVertices.setNum(0);
}

void CurvatureComb::rebuild(bool rescale)
{
    const model::Entity* e = model_.find(curve_);
    if (!visible_ || !e || !e->world || !model::hasFiniteGeometry(*e)) {
        clear();
        return;
    }
    ++rebuilds_;
    teeth_ = combTeeth(*e->world, density_, 0.0);
    if (rescale || !scaled_) {
        baseScale_ = defaultCombScale(teeth_);
        scaled_ = true;
    }
    for (CombTooth& t : teeth_) t.tip = t.base + scale() * t.curvatureVector;
    const int n = static_cast<int>(teeth_.size());
    teethCoords_->point.setNum(2 * n);
    SbVec3f* points = teethCoords_->point.startEditing();
    for (int i = 0; i < n; ++i) {
        points[2 * i] = toSb(teeth_[static_cast<size_t>(i)].base);
        points[2 * i + 1] = toSb(teeth_[static_cast<size_t>(i)].tip);
    }
    teethCoords_->point.finishEditing();
    if (teethLines_->numVertices.getNum() != n) {
        teethLines_->numVertices.setNum(n);
        int32_t* counts = teethLines_->numVertices.startEditing();
        std::fill(counts, counts + n, 2);
        teethLines_->numVertices.finishEditing();
    }
    envelopeCoords_->point.setNum(n);
    SbVec3f* tips = envelopeCoords_->point.startEditing();
    for (int i = 0; i < n; ++i) tips[i] = toSb(teeth_[static_cast<size_t>(i)].tip);
    envelopeCoords_->point.finishEditing();
    if (envelopeLine_->numVertices.getNum() != 1 || envelopeLine_->numVertices[0] != n) envelopeLine_->numVertices.setValue(n);
}

}  // namespace sculptline::scene
