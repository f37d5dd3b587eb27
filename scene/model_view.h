#pragma once
// The model drawn with Coin nodes, kept in step with it as a model::ModelObserver:
//   SoSeparator "Model" {
//     SoGroup "Surfaces"   { SoSeparator "Surface<id>" .. }
//     SoGroup "Curves"     { SoSeparator "Curve<id>" .. }              world-space curves
//     SoGroup "PlaneCurves" {
//       SoSeparator "Plane<id>Curves" { SoTransform frame, SoSeparator "Curve<id>" .. } .. } }
// The names are scene/entity_path.h's entityNodeName(): entityAt() maps a pick path back to the entity.
// A curve on a plane is tessellated once, in the plane's local frame, and placed by the plane's one
// SoTransform: a plane drag rewrites two fields, however many curves the plane carries.
#include "scene/geometry_nodes.h"
#include "scene/surface_analysis_display.h"
#include "model/model.h"

#include <map>
#include <memory>
#include <set>
#include <vector>

class SoCoordinate3;
class SoGroup;
class SoSeparator;
class SoTransform;

namespace sculptline::scene {

class ModelView : public model::ModelObserver {
public:
    /// Observes `model` (and shows what it already holds); the model must outlive this view.
    /// @param nurbsNodes draw with SoNurbsCurve / SoNurbsSurface instead of the kernel's
    ///        tessellation: only to measure the two against each other (issue 5 §4).
    explicit ModelView(model::Model& model, bool nurbsNodes = false);
    ~ModelView() override;
    ModelView(const ModelView&) = delete;
    ModelView& operator=(const ModelView&) = delete;

    /// The graph root (ref()ed by this view; add it to a scene).
    SoSeparator* root() const { return root_; }
    /// The node of an entity (a curve's or surface's separator, a plane's curve group), or null.
    SoSeparator* nodeOf(model::EntityId id) const;
    /// Curve and surface nodes built (tessellations) since construction: a plane drag adds none.
    int nodeBuilds() const { return nodeBuilds_; }
    /// Plane transforms written since construction.
    int transformWrites() const { return transformWrites_; }

    /// Shows or hides every curve's control polygon (points and legs), drawn with the curve in
    /// its plane's frame, so it follows drags for free.
    void setControlPolygonsVisible(bool visible);
    bool controlPolygonsVisible() const { return polygonsVisible_; }

    /// Re-tessellates adaptively every surface whose node was last built on a reused grid (see
    /// entityUpdated), and draws the curves the drag moved in their resting state's colour again;
    /// call when a drag ends. Returns how many surfaces were rebuilt.
    int refineSurfaces();
    /// Surface nodes built on a reused parameter grid since construction.
    int gridReuses() const { return gridReuses_; }
    /// Live rebuilds drawn by rewriting the surface node's vertices and normals in place (same
    /// grid, same knots: no node, index or basis made anew); each also counts as a grid reuse.
    int inPlaceUpdates() const { return inPlaceUpdates_; }
    /// Entities not drawn (or not moved) because a coordinate was not finite (model::hasFiniteGeometry).
    int nonFiniteRejections() const { return nonFiniteRejections_; }

    /// Draws curve `id` highlighted (selection); 0 = none.
    void setHighlighted(model::EntityId id);
    /// Draws these curves marked (the inputs picked for a surface so far).
    void setMarked(const std::vector<model::EntityId>& ids);
    const std::vector<model::EntityId>& marked() const { return marked_; }

    /// Surface display mode (scene/surface_analysis_display.h) of surface `id`; id 0 sets it for
    /// every surface, present and future, and drops the per-surface choices. Kept through rebuilds
    /// and drags; a view setting, not saved.
    void setSurfaceDisplay(model::EntityId id, SurfaceDisplay mode);
    SurfaceDisplay surfaceDisplay(model::EntityId id) const;
    SurfaceAnalysisDisplay& surfaceAnalysis() { return *analysis_; }

    void entityAdded(const model::Entity& entity) override;
    void entityRemoved(const model::Entity& entity) override;
    void entityUpdated(const model::Entity& entity) override;
    void constraintAdded(const model::Constraint& constraint) override;
    void constraintRemoved(const model::Constraint& constraint) override;
    void constraintUpdated(const model::Constraint& constraint) override;

private:
    /// The one gate between the model's geometry and Coin: false (and counted) when a coordinate
    /// of `entity` is not finite; its node is then left empty or unmoved.
    bool drawable(const model::Entity& entity);
    /// A surface a sculpt deforms (its base) is not drawn: the sculpt shows it. `ignoring`: a sculpt
    /// being removed.
    bool sculptedAway(const model::Entity& surface, model::EntityId ignoring = 0) const;
    /// Rebuilds the node of the base of sculpt `e` (shown or hidden as it now is).
    void refreshSculptBase(const model::Entity& e, model::EntityId ignoring = 0);
    SoSeparator* planeGroup(model::EntityId plane);
    void addCurveNode(const model::Entity& entity);
    void rebuildCurveNode(const model::Entity& entity);
    SoSeparator* makeCurveWithPolygon(const model::Entity& entity);
    /// A surface's node, named and registered (nodes_, builtShape_). `reuseGrid`: evaluate on the
    /// last adaptive grid when the surface's domain is unchanged (a live rebuild).
    SoSeparator* makeSurfaceEntityNode(const model::Entity& entity, bool reuseGrid = false);
    /// A curve network mesh's node, named and registered.
    SoSeparator* makeMeshEntityNode(const model::Entity& entity);
    SoSeparator* makeSolidEntityNode(const model::Entity& entity);

    /// Rewrites the vertices and normals of surface `e`'s node on its kept grid when only its
    /// control points (or weights) changed; false (nothing done) when it cannot.
    bool updateSurfaceInPlace(const model::Entity& entity);

    /// Draws surface `e`'s node in its display mode (after every build or in-place rewrite).
    void applySurfaceDisplay(const model::Entity& e);

    /// The parameter grid a surface was last tessellated on.
    struct SurfaceGrid {
        std::vector<double> u, v;
        bool adaptive = true;  ///< false: the node was built on a reused grid
        SoSeparator* node = nullptr;  ///< the node drawn on this grid, and its vertex and normal nodes
        SurfaceNodeFields fields;
        std::shared_ptr<solvers::GridBasis> basis;  ///< made at the first in-place update
        std::vector<Eigen::Vector3d> vertices, normals;  ///< scratch of the in-place updates
    };
    /// A curve's colour and width: its state's colour (scene/state_colors.h), marked, highlighted.
    CurveStyle curveStyle(model::EntityId id) const;
    /// Rewrites curve `id`'s colour field for its current style.
    void recolorCurve(model::EntityId id);
    /// The curves a finished drag moved, drawn in their resting state's colour again.
    void settleChangedCurves();

    model::Model& model_;
    SoSeparator* root_ = nullptr;
    SoGroup* surfaces_ = nullptr;
    SoGroup* curves_ = nullptr;
    SoGroup* planeCurves_ = nullptr;
    std::map<model::EntityId, SoSeparator*> nodes_;
    std::map<model::EntityId, SoTransform*> frames_;
    SoSeparator* constraints_ = nullptr;
    /// A pin's node and its point, by constraint id.
    std::map<model::ConstraintId, std::pair<SoSeparator*, SoCoordinate3*>> pins_;
    std::map<model::EntityId, SurfaceGrid> grids_;
    int gridReuses_ = 0;
    int inPlaceUpdates_ = 0;
    int nonFiniteRejections_ = 0;
    model::EntityId hiddenIgnoring_ = 0;  ///< a sculpt being removed, while its base is redrawn
    std::map<model::EntityId, int> builtShape_;  ///< a curve's or surface's shapeVersion its node was built from
    model::EntityId highlighted_ = 0;
    std::vector<model::EntityId> marked_;
    /// Curves the drag in progress moved (drawn changed until it ends).
    std::set<model::EntityId> changedInDrag_;
    std::unique_ptr<SurfaceAnalysisDisplay> analysis_ = std::make_unique<SurfaceAnalysisDisplay>();
    SurfaceDisplay defaultDisplay_ = SurfaceDisplay::Shaded;
    std::map<model::EntityId, SurfaceDisplay> displays_;  ///< per-surface choices over the default
    bool nurbsNodes_ = false;
    bool polygonsVisible_ = false;
    int nodeBuilds_ = 0;
    int transformWrites_ = 0;
};

}  // namespace sculptline::scene
