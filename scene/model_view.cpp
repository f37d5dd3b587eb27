#include "scene/solid_node.h"
#include "scene/model_view.h"

#include "scene/eigen_coin.h"
#include "scene/entity_path.h"
#include "scene/overlay_nodes.h"
#include "scene/state_colors.h"

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoBaseColor.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoNormal.h>
#include <Inventor/nodes/SoPointSet.h>
#include <Inventor/nodes/SoSwitch.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoTransform.h>

#include <algorithm>
#include <array>
#include <string>

namespace sculptline::scene {
namespace {

// Curves in their state's colour (scene/state_colors.h: free ones warm, fixed violet, changed lime),
// surfaces in cool ones (as in the default scene), the selection in white.
const SbColor kHighlight(1.0f, 1.0f, 1.0f);
/// Constraint pins: the pen's red, larger than the stroke feedback's corners so they read as objects.
const SbColor kConstraintColor(1.0f, 0.25f, 0.2f);
constexpr float kConstraintSize = 11.0f;
/// Curves picked as the inputs of a surface being made: a cool cyan no curve colour uses.
const SbColor kMarked(0.3f, 0.9f, 1.0f);
/// Control polygons in a muted light grey: readable over planes and surfaces, never taken for a curve.
const SbColor kPolygonColor(0.75f, 0.78f, 0.85f);
constexpr float kPolygonPointSize = 5.0f;
constexpr float kHighlightWidth = 5.0f;

/// A sculpt's bound (a polyline on the surface) and its blocked control points (Fig. 6-7).
const SbColor kBoundColor(0.2f, 0.95f, 0.45f);
constexpr float kBoundWidth = 3.0f;
const SbColor kBlockedColor(0.95f, 0.1f, 0.1f);
constexpr float kBlockedSize = 9.0f;
/// Overlays on a surface are drawn lifted off it to both sides by this fraction of its extent, so
/// the depth test neither hides them nor makes them flicker against the shading.
constexpr double kLiftFraction = 0.004;
/// Points of the bound polyline per edge of its polygon (it bends with the surface).
constexpr int kBoundSamplesPerEdge = 4;

/// During a drag a surface is drawn with at most this many grid vertices (about twice as many
/// triangles): on software GL (llvmpipe) a frame of the 18 x 135 sculpt's resting 61 x 529 grid
/// alone takes 17-25 ms, over a 60 Hz frame. Its knot lines stay (the iso-lines are drawn on them,
/// and each span keeps its polynomial piece's ends); the lines between them are thinned evenly. At
/// the release the resting surface is tessellated adaptively again.
constexpr size_t kDragVertexBudget = 12000;

/// The grid lines `lines` thinned for a drag: every knot line (`knots`), and every `stride`-th line
/// between two knot lines.
std::vector<double> thinned(const std::vector<double>& lines, const solvers::KnotVector& knots, int stride)
{
    std::vector<double> out;
    int since = 0;
    for (size_t k = 0; k < lines.size(); ++k) {
        const bool knot = k == 0 || k + 1 == lines.size() || std::binary_search(knots.begin(), knots.end(), lines[k]);
        if (knot || ++since % stride == 0) {
            out.push_back(lines[k]);
            if (knot) since = 0;
        }
    }
    return out;
}

/// The sculpt's marks: its bound polygon (domain of the base, which the sculpt shares) evaluated on
/// the sculpted surface, and its blocked control points; an unpickable overlay.
SoSeparator* makeSculptMarks(const model::Entity& e)
{
    auto* marks = makeOverlayRoot();
    marks->setName("SculptMarks");
    const solvers::Surface3d& s = *e.surface;
    Eigen::AlignedBox3d box;
    for (const Eigen::Vector3d& p : s.points()) box.extend(p);
    const double lift = kLiftFraction * box.diagonal().norm();
    auto normalAt = [&s](double u, double v) {
        const Eigen::Vector3d n = s.normal(u, v);
        return n.allFinite() && n.norm() > 0.0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero();
    };
    const std::vector<Eigen::Vector2d>& bound = e.recipe->bound;
    if (bound.size() >= 3) {
        const double u0 = s.domainStart(solvers::Direction::U), u1 = s.domainEnd(solvers::Direction::U);
        const double v0 = s.domainStart(solvers::Direction::V), v1 = s.domainEnd(solvers::Direction::V);
        std::vector<Eigen::Vector3d> on, normals;
        for (size_t k = 0; k < bound.size(); ++k) {
            const Eigen::Vector2d& a = bound[k];
            const Eigen::Vector2d& b = bound[(k + 1) % bound.size()];
            for (int i = 0; i < kBoundSamplesPerEdge; ++i) {
                const Eigen::Vector2d uv = a + (b - a) * (static_cast<double>(i) / kBoundSamplesPerEdge);
                const double u = std::clamp(uv.x(), u0, u1), v = std::clamp(uv.y(), v0, v1);
                on.push_back(s.evaluate(u, v));
                normals.push_back(normalAt(u, v));
            }
        }
        on.push_back(on.front());
        normals.push_back(normals.front());
        auto* group = new SoSeparator;
        SoCoordinate3* coords = addStyledCoordinates(group, kBoundColor, 0.0f, kBoundWidth);
        auto* lines = new SoLineSet;
        const int n = static_cast<int>(on.size());
        for (int side = 0; side < 2; ++side) {
            for (int k = 0; k < n; ++k) coords->point.set1Value(side * n + k, toSb(on[k] + (side == 0 ? lift : -lift) * normals[k]));
            lines->numVertices.set1Value(side, n);
        }
        group->addChild(lines);
        group->setName("SculptBound");
        marks->addChild(group);
    }
    if (!e.recipe->blocked.empty()) {
        auto* group = new SoSeparator;
        group->setName("SculptBlocked");
        SoCoordinate3* coords = addStyledCoordinates(group, kBlockedColor, kBlockedSize, 0.0f);
        int n = 0;
        for (const auto& ij : e.recipe->blocked) {
            if (ij[0] < 0 || ij[1] < 0 || ij[0] >= s.countU() || ij[1] >= s.countV()) continue;
            const Eigen::Vector3d p = s.point(ij[0], ij[1]);
            if (!p.allFinite()) continue;
            // Lifted along the net's local normal (the cross of its neighbouring edges).
            const Eigen::Vector3d du = s.point(std::min(ij[0] + 1, s.countU() - 1), ij[1]) - s.point(std::max(ij[0] - 1, 0), ij[1]);
            const Eigen::Vector3d dv = s.point(ij[0], std::min(ij[1] + 1, s.countV() - 1)) - s.point(ij[0], std::max(ij[1] - 1, 0));
            Eigen::Vector3d normal = du.cross(dv);
            normal = normal.norm() > 0.0 && normal.allFinite() ? Eigen::Vector3d(normal.normalized()) : Eigen::Vector3d::Zero();
            coords->point.set1Value(n++, toSb(p + lift * normal));
            coords->point.set1Value(n++, toSb(p - lift * normal));
        }
        group->addChild(new SoPointSet);
        marks->addChild(group);
    }
    return marks;
}

void setFrame(SoTransform* transform, const model::PlaneFrame& frame)
{
    transform->translation = toSb(frame.origin);
    transform->rotation = toSb(frame.rotation);
}

}  // namespace

ModelView::ModelView(model::Model& model, bool nurbsNodes) : model_(model), nurbsNodes_(nurbsNodes)
{
    root_ = new SoSeparator;
    root_->ref();
    root_->setName("Model");
    surfaces_ = new SoGroup;
    surfaces_->setName("Surfaces");
    root_->addChild(surfaces_);
    curves_ = new SoGroup;
    curves_->setName("Curves");
    root_->addChild(curves_);
    planeCurves_ = new SoGroup;
    planeCurves_->setName("PlaneCurves");
    root_->addChild(planeCurves_);
    constraints_ = makeOverlayRoot();
    constraints_->setName("Constraints");
    root_->addChild(constraints_);
    for (const auto& [id, e] : model_.entities()) entityAdded(e);
    model_.addObserver(this);
}

ModelView::~ModelView()
{
    model_.removeObserver(this);
    root_->unref();
}

SoSeparator* ModelView::nodeOf(model::EntityId id) const
{
    const auto it = nodes_.find(id);
    return it == nodes_.end() ? nullptr : it->second;
}

CurveStyle ModelView::curveStyle(model::EntityId id) const
{
    CurveStyle style;
    const model::Entity* e = model_.find(id);
    const model::State state = e && e->fixed                                                  ? model::State::Fixed
                               : changedInDrag_.count(id) || model_.state(id) == model::State::Changed ? model::State::Changed
                                                                                                       : model::State::Free;
    const Rgb color = curveColor(id, state);
    style.color.setValue(color[0], color[1], color[2]);
    if (std::find(marked_.begin(), marked_.end(), id) != marked_.end()) {
        style.color = kMarked;
        style.lineWidth = kHighlightWidth;
    }
    if (id == highlighted_) {
        style.color = kHighlight;
        style.lineWidth = kHighlightWidth;
    }
    return style;
}

SoSeparator* ModelView::planeGroup(model::EntityId plane) { return nodes_.at(plane); }

bool ModelView::drawable(const model::Entity& e)
{
    if (model::hasFiniteGeometry(e)) return true;
    ++nonFiniteRejections_;
    return false;
}

SoSeparator* ModelView::makeCurveWithPolygon(const model::Entity& e)
{
    if (!drawable(e)) return new SoSeparator;
    SoSeparator* node = nurbsNodes_ ? makeNurbsCurveNode(*e.local, curveStyle(e.id)) : makeCurveNode(*e.local, curveStyle(e.id));
    // The control polygon under a switch, so that showing it is a field change, not a rebuild.
    auto* polygon = new SoSwitch;
    polygon->setName("ControlPolygon");
    polygon->whichChild = polygonsVisible_ ? SO_SWITCH_ALL : SO_SWITCH_NONE;
    auto* color = new SoBaseColor;
    color->rgb = kPolygonColor;
    polygon->addChild(color);
    auto* style = new SoDrawStyle;
    style->lineWidth = 1.0f;
    style->pointSize = kPolygonPointSize;
    polygon->addChild(style);
    auto* coords = new SoCoordinate3;
    setPoints(coords->point, e.local->points());
    polygon->addChild(coords);
    auto* legs = new SoLineSet;
    legs->numVertices = e.local->pointCount();
    polygon->addChild(legs);
    polygon->addChild(new SoPointSet);
    node->addChild(polygon);
    return node;
}

void ModelView::setControlPolygonsVisible(bool visible)
{
    polygonsVisible_ = visible;
    SoSearchAction search;
    search.setName("ControlPolygon");
    search.setInterest(SoSearchAction::ALL);
    search.apply(root_);
    for (int i = 0; i < search.getPaths().getLength(); ++i) {
        static_cast<SoSwitch*>(search.getPaths()[i]->getTail())->whichChild = visible ? SO_SWITCH_ALL : SO_SWITCH_NONE;
    }
}

void ModelView::addCurveNode(const model::Entity& e)
{
    SoSeparator* node = makeCurveWithPolygon(e);
    ++nodeBuilds_;
    node->setName(entityNodeName(model::EntityKind::Curve, e.id).c_str());
    // Kept in creation order inside its group so that the picture does not depend on history.
    SoGroup* parent = e.plane() != 0 ? static_cast<SoGroup*>(planeGroup(e.plane())) : curves_;
    parent->addChild(node);
    nodes_[e.id] = node;
    builtShape_[e.id] = e.shapeVersion;
}

void ModelView::rebuildCurveNode(const model::Entity& e)
{
    SoGroup* parent = e.plane() != 0 ? static_cast<SoGroup*>(planeGroup(e.plane())) : curves_;
    SoSeparator* node = makeCurveWithPolygon(e);
    ++nodeBuilds_;
    node->setName(entityNodeName(model::EntityKind::Curve, e.id).c_str());
    parent->replaceChild(parent->findChild(nodes_.at(e.id)), node);
    nodes_[e.id] = node;
    builtShape_[e.id] = e.shapeVersion;
}

void ModelView::entityAdded(const model::Entity& e)
{
    switch (e.kind) {
    case model::EntityKind::Plane: {
        auto* group = new SoSeparator;
        group->setName((entityNodeName(model::EntityKind::Plane, e.id) + "Curves").c_str());
        auto* frame = new SoTransform;
        if (drawable(e)) setFrame(frame, e.frame);
        group->addChild(frame);
        planeCurves_->addChild(group);
        nodes_[e.id] = group;
        frames_[e.id] = frame;
        break;
    }
    case model::EntityKind::Curve: addCurveNode(e); break;
    case model::EntityKind::Surface:
        surfaces_->addChild(makeSurfaceEntityNode(e));
        refreshSculptBase(e);
        break;
    case model::EntityKind::Mesh: surfaces_->addChild(makeMeshEntityNode(e)); break;
    case model::EntityKind::Point: break;  // drawn with the constraints that make them (later issues)
    case model::EntityKind::Solid: surfaces_->addChild(makeSolidEntityNode(e)); break;
    }
}

SoSeparator* ModelView::makeSurfaceEntityNode(const model::Entity& e, bool reuseGrid)
{
    SoSeparator* node = nullptr;
    if (!e.surface || !drawable(e) || sculptedAway(e, hiddenIgnoring_)) {
        node = new SoSeparator;  // a construction that never built (or a sculpt's base): nothing to draw
        grids_.erase(e.id);
    } else if (nurbsNodes_) {
        const solvers::Surface3d& s = *e.surface;
        node = makeNurbsSurfaceNode(s);
    } else {
        const solvers::Surface3d& s = *e.surface;
        // During a drag a rebuilt surface keeps its parameter domain (the curves move, the
        // construction's parameterization does not): re-evaluating it on its last adaptive grid
        // costs one evaluation per vertex, where the adaptive refinement probes every grid line
        // several times (about 10x more). The knots may change meanwhile (an approximating mode
        // adds sections); the grid still samples the whole domain, and refineSurfaces() adapts it
        // again when the drag ends.
        auto it = grids_.find(e.id);
        const bool sameDomain = it != grids_.end() && it->second.u.front() == s.domainStart(solvers::Direction::U) &&
                                it->second.u.back() == s.domainEnd(solvers::Direction::U) &&
                                it->second.v.front() == s.domainStart(solvers::Direction::V) &&
                                it->second.v.back() == s.domainEnd(solvers::Direction::V);
        if (reuseGrid && sameDomain) {
            SurfaceGrid& grid = it->second;
            if (model_.dragged() != 0) {
                // Thinned for the drag (kDragVertexBudget): the fewest halvings that fit; three
                // leave only the knot lines.
                for (int pass = 0; pass < 3 && grid.u.size() * grid.v.size() > kDragVertexBudget; ++pass) {
                    grid.u = thinned(grid.u, s.knotsU(), 2);
                    grid.v = thinned(grid.v, s.knotsV(), 2);
                }
            }
            node = makeSurfaceNode(s, solvers::meshOnGrid(s, grid.u, grid.v), {}, &grid.fields);
            grid.adaptive = false;
            grid.node = node;
            grid.basis.reset();  // the knots changed (or may have): made anew when next needed
            ++gridReuses_;
        } else {
            solvers::GridMesh mesh = solvers::tessellate(s);
            SurfaceGrid grid;
            node = makeSurfaceNode(s, mesh, {}, &grid.fields);
            grid.u = std::move(mesh.u);
            grid.v = std::move(mesh.v);
            grid.node = node;
            grids_[e.id] = std::move(grid);
        }
    }
    if (e.surface && drawable(e) && e.recipe && e.recipe->mode == model::Construction::Sculpt && node->getNumChildren() > 0 &&
        (!e.recipe->bound.empty() || !e.recipe->blocked.empty()))
        node->addChild(makeSculptMarks(e));
    ++nodeBuilds_;
    node->setName(entityNodeName(model::EntityKind::Surface, e.id).c_str());
    nodes_[e.id] = node;
    builtShape_[e.id] = e.shapeVersion;
    applySurfaceDisplay(e);
    return node;
}

bool ModelView::sculptedAway(const model::Entity& surface, model::EntityId ignoring) const
{
    for (model::EntityId d : model_.dependents(surface.id)) {
        const model::Entity* s = model_.find(d);
        if (d != ignoring && s && s->recipe && s->recipe->mode == model::Construction::Sculpt && s->inputs.front() == surface.id) return true;
    }
    return false;
}

void ModelView::refreshSculptBase(const model::Entity& e, model::EntityId ignoring)
{
    if (e.kind != model::EntityKind::Surface || !e.recipe || e.recipe->mode != model::Construction::Sculpt) return;
    const model::Entity* base = model_.find(e.inputs.front());
    const auto node = base ? nodes_.find(base->id) : nodes_.end();
    if (node == nodes_.end()) return;
    SoSeparator* old = node->second;  // makeSurfaceEntityNode replaces the map's entry
    hiddenIgnoring_ = ignoring;
    surfaces_->replaceChild(surfaces_->findChild(old), makeSurfaceEntityNode(*base));
    hiddenIgnoring_ = 0;
}

void ModelView::entityRemoved(const model::Entity& e)
{
    refreshSculptBase(e, e.id);  // its base shows again
    const auto it = nodes_.find(e.id);
    if (it == nodes_.end()) return;
    SoGroup* parent = e.kind == model::EntityKind::Plane        ? planeCurves_
                      : e.kind == model::EntityKind::Surface || e.kind == model::EntityKind::Mesh ||
                                e.kind == model::EntityKind::Solid
                          ? surfaces_
                      : e.plane() != 0                ? static_cast<SoGroup*>(planeGroup(e.plane()))
                                                      : curves_;
    parent->removeChild(it->second);
    nodes_.erase(it);
    frames_.erase(e.id);
    builtShape_.erase(e.id);
    grids_.erase(e.id);
    analysis_->remove(e.id);
    displays_.erase(e.id);
    if (highlighted_ == e.id) highlighted_ = 0;
    marked_.erase(std::remove(marked_.begin(), marked_.end(), e.id), marked_.end());
}

void ModelView::recolorCurve(model::EntityId id)
{
    // The curve's own SoBaseColor (curveRoot in scene/geometry_nodes.cpp): a field write, not a
    // re-tessellation, so that a drag's first event stays cheap however many curves it moves.
    const auto it = nodes_.find(id);
    if (it == nodes_.end()) return;
    for (int k = 0; k < it->second->getNumChildren(); ++k) {
        if (!it->second->getChild(k)->isOfType(SoBaseColor::getClassTypeId())) continue;
        auto* base = static_cast<SoBaseColor*>(it->second->getChild(k));
        const SbColor color = curveStyle(id).color;
        if (base->rgb.getNum() != 1 || base->rgb[0] != color) base->rgb = color;  // no needless notification
        return;
    }
}

void ModelView::settleChangedCurves()
{
    const std::set<model::EntityId> changed = std::move(changedInDrag_);
    changedInDrag_.clear();
    for (model::EntityId id : changed) recolorCurve(id);
}

void ModelView::entityUpdated(const model::Entity& e)
{
    // Curves a drag moves show it (seed 000 §3.2's changed state) until the drag ends; a fixed or
    // a changed curve's state may have changed too (setFixed).
    if (model_.dragged() == 0 && !changedInDrag_.empty()) settleChangedCurves();
    if (e.kind == model::EntityKind::Curve) {
        if (model_.dragged() != 0 && !e.fixed) changedInDrag_.insert(e.id);
        recolorCurve(e.id);
    }
    // A curve moved with its plane changes only its world form; its node is in plane-local
    // coordinates and stays as it is. A new shape (over-sketch) is re-tessellated. A plane's
    // update is one transform write.
    if (e.kind == model::EntityKind::Curve && builtShape_[e.id] != e.shapeVersion) rebuildCurveNode(e);
    if (e.kind == model::EntityKind::Mesh && builtShape_[e.id] != e.shapeVersion) {
        SoSeparator* old = nodes_.at(e.id);
        surfaces_->replaceChild(surfaces_->findChild(old), makeMeshEntityNode(e));
    }
    if (e.kind == model::EntityKind::Solid && builtShape_[e.id] != e.shapeVersion) {
        SoSeparator* old = nodes_.at(e.id);
        surfaces_->replaceChild(surfaces_->findChild(old), makeSolidEntityNode(e));
    }
    if (e.kind == model::EntityKind::Surface && builtShape_[e.id] != e.shapeVersion && !updateSurfaceInPlace(e)) {
        // A built surface follows its curves: re-tessellated once per update that rebuilt it.
        SoSeparator* old = nodes_.at(e.id);
        surfaces_->replaceChild(surfaces_->findChild(old), makeSurfaceEntityNode(e, true));
    }
    if (e.kind != model::EntityKind::Plane || !drawable(e)) return;
    setFrame(frames_.at(e.id), e.frame);
    ++transformWrites_;
}

bool ModelView::updateSurfaceInPlace(const model::Entity& e)
{
    // Only the control points (or weights) moved, as in a drag: the grid, the triangles, the
    // iso-lines and the basis of every grid line stay; the vertices and normals are a dense product
    // of the kept basis with the new net, written into the node's fields. Anything else (new
    // knots or net size, a node drawn differently, nothing drawn) takes the rebuild.
    if (nurbsNodes_ || !e.surface) return false;
    const auto it = grids_.find(e.id);
    const auto node = nodes_.find(e.id);
    if (it == grids_.end() || node == nodes_.end()) return false;
    SurfaceGrid& grid = it->second;
    if (grid.node != node->second || !grid.fields.coordinates || !grid.fields.normals) return false;
    // A drag's first event on a grid too fine to draw at the pointer's pace: rebuilt thinned.
    if (model_.dragged() != 0 && grid.u.size() * grid.v.size() > kDragVertexBudget) return false;
    const solvers::Surface3d& s = *e.surface;
    if (grid.basis && !grid.basis->fits(s)) return false;
    if (!model::hasFiniteGeometry(e) || sculptedAway(e)) return false;  // the rebuild counts or hides it
    if (!grid.basis) {
        // The kept grid came from this surface's knots: a surface with other knots (an
        // approximating mode added sections) has a domain the grid may not sample.
        if (grid.u.empty() || grid.v.empty() || grid.u.front() != s.domainStart(solvers::Direction::U) ||
            grid.u.back() != s.domainEnd(solvers::Direction::U) || grid.v.front() != s.domainStart(solvers::Direction::V) ||
            grid.v.back() != s.domainEnd(solvers::Direction::V))
            return false;
        grid.basis = std::make_shared<solvers::GridBasis>(s, grid.u, grid.v);
    }
    grid.basis->evaluate(s, grid.vertices, grid.normals);
    const int count = static_cast<int>(grid.vertices.size());
    if (grid.fields.coordinates->point.getNum() != count || grid.fields.normals->vector.getNum() != count) return false;
    SbVec3f* points = grid.fields.coordinates->point.startEditing();
    for (int i = 0; i < count; ++i) points[i] = toSb(grid.vertices[static_cast<size_t>(i)]);
    grid.fields.coordinates->point.finishEditing();
    SbVec3f* normals = grid.fields.normals->vector.startEditing();
    for (int i = 0; i < count; ++i) normals[i] = toSb(grid.normals[static_cast<size_t>(i)]);
    grid.fields.normals->vector.finishEditing();
    grid.adaptive = false;
    // A sculpt's marks (its bound, its blocked points) lie on its surface and follow its recipe:
    // made anew beside the rewritten mesh (a polyline and a few points).
    SoSeparator* surfaceNode = node->second;
    for (int k = surfaceNode->getNumChildren() - 1; k >= 0; --k) {
        if (surfaceNode->getChild(k)->getName() == SbName("SculptMarks")) surfaceNode->removeChild(k);
    }
    if (e.recipe && e.recipe->mode == model::Construction::Sculpt && (!e.recipe->bound.empty() || !e.recipe->blocked.empty()))
        surfaceNode->addChild(makeSculptMarks(e));
    builtShape_[e.id] = e.shapeVersion;
    ++gridReuses_;
    ++inPlaceUpdates_;
    applySurfaceDisplay(e);
    return true;
}

void ModelView::applySurfaceDisplay(const model::Entity& e)
{
    const auto grid = grids_.find(e.id);
    const auto node = nodes_.find(e.id);
    const bool meshed = e.surface && grid != grids_.end() && node != nodes_.end() && grid->second.node == node->second;
    if (!meshed) {
        analysis_->remove(e.id);  // nothing drawn from the kernel's mesh (failed, hidden, NURBS nodes)
        return;
    }
    analysis_->apply(e.id, node->second, grid->second.fields, *e.surface, grid->second.u, grid->second.v, surfaceDisplay(e.id));
}

void ModelView::setSurfaceDisplay(model::EntityId id, SurfaceDisplay mode)
{
    if (id == 0) {
        defaultDisplay_ = mode;
        displays_.clear();
    } else {
        displays_[id] = mode;
    }
    for (const auto& [eid, e] : model_.entities())
        if (e.kind == model::EntityKind::Surface && (id == 0 || eid == id)) applySurfaceDisplay(e);
}

SurfaceDisplay ModelView::surfaceDisplay(model::EntityId id) const
{
    const auto it = displays_.find(id);
    return it != displays_.end() ? it->second : defaultDisplay_;
}

void ModelView::constraintAdded(const model::Constraint& c)
{
    // A pin at C(u), in world coordinates: it moves with the curve's updates.
    if (c.type != model::ConstraintType::Position && c.type != model::ConstraintType::Tangent) return;
    auto* node = new SoSeparator;
    node->setName(constraintNodeName(c.id).c_str());
    SoCoordinate3* point = addStyledCoordinates(node, kConstraintColor, kConstraintSize, 0.0f);
    if (model::hasFiniteGeometry(c)) point->point.setValue(toSb(c.value));
    else ++nonFiniteRejections_;
    node->addChild(new SoPointSet);
    constraints_->addChild(node);
    pins_[c.id] = {node, point};
}

void ModelView::constraintRemoved(const model::Constraint& c)
{
    const auto it = pins_.find(c.id);
    if (it == pins_.end()) return;
    constraints_->removeChild(it->second.first);
    pins_.erase(it);
}

void ModelView::constraintUpdated(const model::Constraint& c)
{
    const auto it = pins_.find(c.id);
    if (it == pins_.end()) return;
    if (model::hasFiniteGeometry(c)) it->second.second->point.setValue(toSb(c.value));
    else ++nonFiniteRejections_;
}

SoSeparator* ModelView::makeMeshEntityNode(const model::Entity& e)
{
    SoSeparator* node = drawable(e) ? makeMeshNode(e.mesh->vertices, e.mesh->normals, e.mesh->triangles) : new SoSeparator;
    ++nodeBuilds_;
    node->setName(entityNodeName(model::EntityKind::Mesh, e.id).c_str());
    nodes_[e.id] = node;
    builtShape_[e.id] = e.shapeVersion;
    return node;
}

SoSeparator* ModelView::makeSolidEntityNode(const model::Entity& e)
{
    // Its last conversion (kept while a new one runs); nothing before the first one finished.
    SoSeparator* node = e.solid && drawable(e) ? makeSolidNode(e.solid->mesh) : new SoSeparator;
    ++nodeBuilds_;
    node->setName(entityNodeName(model::EntityKind::Solid, e.id).c_str());
    nodes_[e.id] = node;
    builtShape_[e.id] = e.shapeVersion;
    return node;
}

int ModelView::refineSurfaces()
{
    settleChangedCurves();  // the drag ended
    int rebuilt = 0;
    for (auto& [id, grid] : grids_) {
        if (grid.adaptive) continue;
        const model::Entity* e = model_.find(id);
        if (!e) continue;
        SoSeparator* old = nodes_.at(id);
        surfaces_->replaceChild(surfaces_->findChild(old), makeSurfaceEntityNode(*e, false));
        ++rebuilt;
    }
    return rebuilt;
}

void ModelView::setMarked(const std::vector<model::EntityId>& ids)
{
    if (ids == marked_) return;
    std::vector<model::EntityId> changed = marked_;
    changed.insert(changed.end(), ids.begin(), ids.end());
    marked_ = ids;
    for (model::EntityId id : changed) {
        const model::Entity* e = model_.find(id);
        if (e && e->kind == model::EntityKind::Curve) rebuildCurveNode(*e);
    }
}

void ModelView::setHighlighted(model::EntityId id)
{
    if (id == highlighted_) return;
    const model::EntityId previous = highlighted_;
    highlighted_ = id;
    // Rebuilding the one or two curves involved is cheaper to read than a style node per curve.
    for (model::EntityId changed : {previous, id}) {
        const model::Entity* e = model_.find(changed);
        if (!e || e->kind != model::EntityKind::Curve) continue;
        rebuildCurveNode(*e);
    }
}

}  // namespace sculptline::scene
