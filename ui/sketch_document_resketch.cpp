// SketchDocument's re-sketch of a parameter line (seed 001_08db50965017e161 §5.2, Figs. 9-10, the
// jug's mouth), Sculpt mode's Re-sketch tool: a first stroke over the surface (the marking) picks the
// nearest u- or v-curve, and the view shows it with the auxiliary ruled strip through it; the next
// stroke drawn over the strip is the line's new shape, and the surface follows (one undo step).
// The numbers are solvers/deformation/parameter_line.h's.
#include "ui/sketch_document.h"

#include "manipulators/stroke_input.h"
#include "scene/eigen_coin.h"
#include "scene/overlay_nodes.h"
#include "solvers/deformation/parameter_line.h"
#include "ui/undo_commands.h"

#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShapeHints.h>

#include <algorithm>

namespace sculptline::ui {

namespace deformation = solvers::deformation;

/// What the Re-sketch tool holds between its strokes, and the nodes that show it.
struct ResketchState {
    model::EntityId surface = 0;
    std::optional<deformation::ParameterLine> line;
    deformation::RulingKind rulings = deformation::RulingKind::Normal;
    Eigen::Vector3d viewDirection = -Eigen::Vector3d::UnitZ();
    std::optional<deformation::RuledStrip> strip;
    double halfWidth = 1.0;
    std::function<SoCamera*()> camera;
    SoSeparator* node = nullptr;  ///< ref()ed; a child of the document's root while a line is picked
    SoCoordinate3* lineCoords = nullptr;
    SoCoordinate3* stripCoords = nullptr;
    SoIndexedFaceSet* stripFaces = nullptr;
    SoLineSet* lineSet = nullptr;

    ~ResketchState()
    {
        if (node) node->unref();
    }
};

namespace {

/// The strip reaches this fraction of the surface's size on each side of the line: wide enough to
/// draw a mouth's lip on (Fig. 10), narrow enough not to hide the surface.
constexpr double kStripHalfWidth = 0.25;
/// Rays of a marking farther than this fraction of the surface's size from it do not count.
constexpr double kMarkingReach = 0.05;
/// Samples of the line and the strip along it (display only).
constexpr int kDisplaySamples = 96;
/// The preview plane's least size (model units), as the auxiliary planes of sketch_document_input.cpp.
constexpr double kMinPreviewSize = 40.0;

double surfaceSize(const solvers::Surface3d& s)
{
    Eigen::Vector3d lo = s.points().front(), hi = lo;
    for (const auto& p : s.points()) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    return (hi - lo).norm();
}

QString rulingName(deformation::RulingKind kind)
{
    switch (kind) {
    case deformation::RulingKind::Normal: return QObject::tr("the surface normal");
    case deformation::RulingKind::Across: return QObject::tr("across the line (the surface continued)");
    case deformation::RulingKind::Constant: return QObject::tr("the view direction");
    }
    return {};
}

QString lineName(const deformation::ParameterLine& line)
{
    return line.fixed == solvers::Direction::U ? QObject::tr("v-curve at u = %1").arg(line.value, 0, 'f', 3)
                                               : QObject::tr("u-curve at v = %1").arg(line.value, 0, 'f', 3);
}

}  // namespace

ResketchState& SketchDocument::resketchState()
{
    if (!resketch_) resketch_ = std::make_shared<ResketchState>();
    return *resketch_;
}

void SketchDocument::clearResketch()
{
    if (!resketch_) return;
    ResketchState& r = *resketch_;
    r.line.reset();
    r.strip.reset();
    r.surface = 0;
    if (r.node && root_->findChild(r.node) >= 0) root_->removeChild(r.node);
}

void SketchDocument::setResketchCamera(std::function<SoCamera*()> camera) { resketchState().camera = std::move(camera); }

void SketchDocument::cycleResketchRulings()
{
    ResketchState& r = resketchState();
    using K = deformation::RulingKind;
    r.rulings = r.rulings == K::Normal ? K::Across : r.rulings == K::Across ? K::Constant : K::Normal;
    if (r.rulings == K::Constant) {
        // The view as it is now: the designer turns the camera to where the lip should move, then
        // presses the key.
        SoCamera* camera = r.camera ? r.camera() : nullptr;
        if (camera) {
            SbVec3f d;
            camera->orientation.getValue().multVec(SbVec3f(0, 0, -1), d);
            r.viewDirection = scene::toEigen(d);
        }
    }
    lastStroke_ = {};
    lastStroke_.message = tr("Re-sketch: the strip's rulings follow %1.").arg(rulingName(r.rulings));
    if (r.line) {
        try {
            showResketchStrip();
            lastStroke_.message += tr(" Draw the %1's new shape over the strip.").arg(lineName(*r.line));
        } catch (const std::invalid_argument& error) {  // rulings along the line: no strip
            if (r.node && root_->findChild(r.node) >= 0) root_->removeChild(r.node);
            lastStroke_.message = tr("Re-sketch: %1; press Alt+A again, or turn the view first").arg(QString::fromStdString(error.what()));
        }
    }
    Q_EMIT strokeFinished();
}

QString SketchDocument::resketchGuidance() const
{
    const ResketchState* r = resketch_.get();
    if (sculptBase_ == 0) return tr("Re-sketch: select a surface first (E, then click it), then Alt+R.");
    if (!r || !r->line || r->surface != sculptBase_)
        return tr("Re-sketch surface %1: draw a marking along the parameter line to change (over the surface); "
                  "Alt+A turns the strip's rulings (now: %2).")
            .arg(sculptBase_)
            .arg(rulingName(r ? r->rulings : deformation::RulingKind::Normal));
    return tr("Re-sketch surface %1: draw the %2's new shape over the red strip; a stroke over the surface picks another line; "
              "Alt+A turns the strip (now: %3).")
        .arg(sculptBase_)
        .arg(lineName(*r->line))
        .arg(rulingName(r->rulings));
}

std::optional<model::PlaneFrame> SketchDocument::resketchPlane(const manipulators::StrokeHit& start)
{
    // Only the rays count; the preview is drawn in the view plane through the surface's middle.
    const model::Entity* e = model_.find(sculptBase_);
    Eigen::Vector3d centre = start.point;
    double size = kMinPreviewSize;
    if (e && e->surface) {
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        for (const auto& p : e->surface->points()) sum += p;
        centre = sum / static_cast<double>(e->surface->points().size());
        size = std::max(size, surfaceSize(*e->surface));
    }
    return model::PlaneFrame::fromNormal(centre, -start.view, size);
}

void SketchDocument::showResketchStrip()
{
    ResketchState& r = resketchState();
    const model::Entity* e = model_.find(r.surface);
    r.strip.reset();
    if (!r.line || !e || !e->surface) return;
    r.strip = deformation::makeRuledStrip(*e->surface, *r.line, r.rulings, r.viewDirection);
    r.halfWidth = kStripHalfWidth * surfaceSize(*e->surface);
    if (!r.node) {
        r.node = new SoSeparator;
        r.node->ref();
        r.node->setName("ResketchStrip");
        SoSeparator* lineGroup = scene::makeOverlayRoot();
        r.lineCoords = scene::addStyledCoordinates(lineGroup, SbColor(1.0f, 0.85f, 0.1f), 0.0f, 4.0f);
        r.lineSet = new SoLineSet;
        lineGroup->addChild(r.lineSet);
        SoSeparator* stripGroup = scene::makeOverlayRoot();
        auto* hints = new SoShapeHints;
        hints->vertexOrdering = SoShapeHints::UNKNOWN_ORDERING;  // seen from both sides
        stripGroup->addChild(hints);
        auto* material = new SoMaterial;
        material->diffuseColor.setValue(0.9f, 0.15f, 0.1f);
        material->transparency = 0.6f;  // Fig. 9: "red transparent surface"
        stripGroup->addChild(material);
        r.stripCoords = new SoCoordinate3;
        stripGroup->addChild(r.stripCoords);
        r.stripFaces = new SoIndexedFaceSet;
        stripGroup->addChild(r.stripFaces);
        r.node->addChild(stripGroup);
        r.node->addChild(lineGroup);
    }
    const solvers::Curve3d& c = r.strip->base;
    std::vector<Eigen::Vector3d> line, strip;
    std::vector<int32_t> faces;
    for (int k = 0; k <= kDisplaySamples; ++k) {
        const double t = c.domainStart() + (c.domainEnd() - c.domainStart()) * k / kDisplaySamples;
        line.push_back(c.evaluate(t));
        strip.push_back(r.strip->at(t, -r.halfWidth));
        strip.push_back(r.strip->at(t, r.halfWidth));
        if (k > 0) faces.insert(faces.end(), {2 * k - 2, 2 * k - 1, 2 * k + 1, 2 * k, -1});
    }
    scene::setPoints(r.lineCoords->point, line);
    r.lineSet->numVertices.setValue(static_cast<int32_t>(line.size()));
    scene::setPoints(r.stripCoords->point, strip);
    r.stripFaces->coordIndex.setValues(0, static_cast<int>(faces.size()), faces.data());
    r.stripFaces->coordIndex.setNum(static_cast<int>(faces.size()));
    if (root_->findChild(r.node) < 0) root_->addChild(r.node);
}

void SketchDocument::resketchSurfaceUpdated(model::EntityId surface)
{
    if (!resketch_ || !resketch_->line || resketch_->surface != surface) return;
    try {
        showResketchStrip();
    } catch (const std::invalid_argument&) {  // no strip on the surface as it is now
        clearResketch();
    }
}

void SketchDocument::resketchStroke(const manipulators::FinishedStroke& stroke, int hooks)
{
    lastStroke_ = {};
    lastStroke_.samples = static_cast<int>(stroke.rayOrigins.size());
    ResketchState& r = resketchState();
    const model::Entity* e = model_.find(sculptBase_);
    try {
        if (!e || !e->surface) {
            lastStroke_.message = tr("Re-sketch: select a surface first (E, then click it), then Alt+R");
        } else if (e->recipe) {
            lastStroke_.message = tr("Re-sketch edits a free-form surface; surface %1 is built from curves (its %2): edit its curves instead")
                                      .arg(e->id)
                                      .arg(QString::fromUtf8(model::constructionName(e->recipe->mode)));
        } else {
            const solvers::Surface3d& surface = *e->surface;
            if (r.surface != e->id) clearResketch();
            // Over the strip (most of its rays meet it): the new shape. Otherwise: a marking.
            std::vector<Eigen::Vector3d> onStrip;
            if (r.line && r.strip) onStrip = deformation::projectRaysOntoStrip(*r.strip, stroke.rayOrigins, stroke.rayDirections, r.halfWidth);
            if (r.line && r.strip && onStrip.size() >= 2 && 2 * onStrip.size() >= stroke.rayOrigins.size()) {
                const deformation::ResketchResult fit = deformation::resketchLine(r.strip->base, onStrip);
                const solvers::Surface3d after = deformation::followParameterLine(surface, *r.line, fit.curve);
                lastStroke_.fitted = true;
                lastStroke_.controlPoints = fit.movedPoints;
                lastStroke_.maxError = fit.oversketchError + fit.knotFitError;
                undo_.push(new ReplaceSurfaceCommand(*this, e->id, surface, after,
                                                     tr("Re-sketch the %1 of surface %2").arg(lineName(*r.line)).arg(e->id)));
                lastStroke_.message =
                    tr("Surface %1 follows its re-sketched %2: %3 of its control points moved, the line is within "
                       "%4 mm of the stroke (knot vector kept). Draw again to refine, or over the surface to pick "
                       "another line.")
                        .arg(e->id)
                        .arg(lineName(*r.line))
                        .arg(fit.movedPoints)
                        .arg(lastStroke_.maxError, 0, 'f', 3) +
                    noteHooks(hooks);
            } else {
                const double size = surfaceSize(surface);
                const auto uv = deformation::markingOnSurface(surface, stroke.rayOrigins, stroke.rayDirections, kMarkingReach * size);
                r.surface = e->id;
                r.line = deformation::pickParameterLine(surface, uv);
                showResketchStrip();
                lastStroke_.fitted = true;
                lastStroke_.message = tr("Surface %1: picked its %2; the strip's rulings follow %3 (Alt+A turns them). "
                                         "Now draw the line's new shape over the red strip.")
                                          .arg(e->id)
                                          .arg(lineName(*r.line))
                                          .arg(rulingName(r.rulings));
            }
        }
    } catch (const std::invalid_argument& error) {  // GeometryError
        lastStroke_.message = tr("Re-sketch: %1").arg(QString::fromStdString(error.what()));
    }
    Q_EMIT strokeFinished();
}

}  // namespace sculptline::ui
