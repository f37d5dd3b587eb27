// SketchDocument's Sculpt mode (thesis ch. 6): targets and handles added to one sculpt, its bound
// from a closed stroke, the curve tangents held along its targets. Split from
// sketch_document_input.cpp, which turns strokes into curves.
#include "ui/sketch_document.h"

#include "solvers/bspline/projection.h"
#include "ui/undo_commands.h"

#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <limits>

namespace sculptline::ui {
namespace {

/// A bound stroke is closed when its ends lie within this fraction of its extent (a hand-drawn
/// loop rarely meets itself exactly; a C-shape leaves a third of its size or more open).
constexpr double kClosedStrokeFraction = 0.15;
/// Points of a bound polygon at most: a stroke has a few hundred samples, and the bound is tested
/// once per control point and key point when a sculpt is factored.
constexpr size_t kMaxBoundPoints = 128;

/// The Greville abscissae of a knot vector: where each control point "sits" in the domain.
std::vector<double> greville(const std::vector<double>& knots, int degree, int count)
{
    std::vector<double> out(static_cast<size_t>(count), 0.0);
    for (int i = 0; i < count; ++i) {
        double sum = 0.0;
        for (int k = 1; k <= degree; ++k) sum += knots[static_cast<size_t>(i + k)];
        out[static_cast<size_t>(i)] = degree > 0 ? sum / degree : knots[static_cast<size_t>(i)];
    }
    return out;
}

/// Relative mismatch below which a surface's tangents at a point count as the base's turned.
constexpr double kRigidTolerance = 1e-9;

/// The rotation R that best carries the base's tangents S_u°, S_v° at `uv` onto the surface's S_u,
/// S_v (least squares, Kabsch): identity where the surface is the base. `mismatch`: what is left,
/// ‖R [S_u° S_v°] − [S_u S_v]‖ / ‖[S_u S_v]‖ (0 where the surface is only turned there).
Eigen::Quaterniond tangentRotation(const solvers::Surface3d& base, const solvers::Surface3d& surface, const Eigen::Vector2d& uv,
                                   double& mismatch)
{
    mismatch = 0.0;
    const auto a = base.derivatives(uv.x(), uv.y(), 1);
    const auto b = surface.derivatives(uv.x(), uv.y(), 1);
    Eigen::Matrix<double, 3, 2> from, to;
    from << a[1][0], a[0][1];
    to << b[1][0], b[0][1];
    if (from == to || !from.allFinite() || !to.allFinite()) return Eigen::Quaterniond::Identity();
    const Eigen::Matrix3d h = from * to.transpose();
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
    d(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
    const Eigen::Matrix3d r = svd.matrixV() * d * svd.matrixU().transpose();
    if (!r.allFinite()) {
        mismatch = 1.0;
        return Eigen::Quaterniond::Identity();
    }
    mismatch = (r * from - to).norm() / std::max(to.norm(), 1e-300);
    return Eigen::Quaterniond(r).normalized();
}

}  // namespace

const model::Entity* SketchDocument::currentSculpt() const
{
    const model::Entity* e = model_.find(sculptBase_);
    return e && e->recipe && e->recipe->mode == model::Construction::Sculpt && e->surface ? e : nullptr;
}

void SketchDocument::sculptClick(model::EntityId surface, const Eigen::Vector3d& point)
{
    if (sculptTool_ == SculptTool::Target || sculptTool_ == SculptTool::Bound || sculptTool_ == SculptTool::Resketch) return;  // stroke tools
    lastStroke_ = {};
    const model::Entity* base = model_.find(sculptBase_);
    const model::Entity* sculpt = currentSculpt();
    if (sculpt) base = model_.find(sculpt->inputs.front());
    const model::Entity* clicked = model_.find(surface);
    if (!base || !base->surface || !clicked || !clicked->surface || (clicked->id != base->id && (!sculpt || clicked->id != sculpt->id))) {
        lastStroke_.message = base ? tr("Click on surface %1 (the surface being sculpted)").arg(sculpt ? sculpt->id : base->id)
                                   : tr("Sculpt: select a surface first, then press Y");
        Q_EMIT strokeFinished();
        return;
    }
    // (u, v) where the click is, on the surface that was clicked: a sculpt keeps its base's knots
    // (the deformation moves control points only), so its domain is the base's, and the point on
    // the sculpt under the pointer is S(u, v) of the sculpt as it is now (a handle dropped there
    // holds the surface where it is, nothing jumps).
    const solvers::SurfaceProjection at = solvers::SurfaceProjector(*clicked->surface).project(point);
    const Eigen::Vector2d uv(at.u, at.v);
    switch (sculptTool_) {
    case SculptTool::Handle: {
        model::Entity p;
        p.kind = model::EntityKind::Point;
        p.position = at.point;
        // Turned as the clicked surface is turned from the base there (the rotation that carries the
        // base's S_u, S_v onto the clicked surface's), so that a handle dropped on a sculpted region
        // holds its tangent plane where it is; on the base itself, unturned.
        double mismatch = 0.0;
        p.rotation = tangentRotation(*base->surface, *clicked->surface, uv, mismatch);
        // Its normal held as the sculpt's other handles' (the inspector's check box is for all of
        // them), unless the sculpt is stretched there: held tangents are the base's turned (S_u, S_v
        // = R S_u°, R S_v°), and no turn gives the stretched ones, so the surface would jump.
        bool hold = mismatch < kRigidTolerance;
        if (sculpt) {
            for (const auto& h : sculpt->recipe->handles) hold = hold && h.holdNormal;
        }
        const model::EntityId made = sculptWith({p}, [uv, hold](model::SurfaceRecipe& r) { r.handles.push_back({kPreviousEntity, uv, hold}); },
                                                tr("Drop a handle on surface %1").arg(clicked->id));
        const model::Entity* s = model_.find(made);
        lastStroke_.message = !s ? tr("No handle: nothing to sculpt")
                              : hold ? tr("Handle at (u, v) = (%1, %2) on sculpt %3: drag its jack to pull the surface, turn its axes to tilt it")
                                           .arg(uv.x(), 0, 'f', 3).arg(uv.y(), 0, 'f', 3).arg(made)
                                     : tr("Handle at (u, v) = (%1, %2) on sculpt %3 holds its point only (the surface is stretched there, or "
                                          "the normals are released): check \"Hold normals at handles\" to hold them")
                                           .arg(uv.x(), 0, 'f', 3).arg(uv.y(), 0, 'f', 3).arg(made);
        break;
    }
    case SculptTool::Block: {
        if (!sculpt) {
            lastStroke_.message = tr("Blocking needs a sculpt: draw a target curve (Alt+T) or drop a handle (Alt+H) on surface %1 first").arg(base->id);
            break;
        }
        const solvers::Surface3d& b = *base->surface;
        const std::vector<double> gu = greville(b.knotsU(), b.degreeU(), b.countU());
        const std::vector<double> gv = greville(b.knotsV(), b.degreeV(), b.countV());
        // Nearest by Greville abscissae, each direction measured relative to its domain's length.
        const double su = b.domainEnd(solvers::Direction::U) - b.domainStart(solvers::Direction::U);
        const double sv = b.domainEnd(solvers::Direction::V) - b.domainStart(solvers::Direction::V);
        int bi = 0, bj = 0;
        double best = std::numeric_limits<double>::infinity();
        for (int i = 0; i < b.countU(); ++i) {
            for (int j = 0; j < b.countV(); ++j) {
                const double du = (gu[static_cast<size_t>(i)] - uv.x()) / su, dv = (gv[static_cast<size_t>(j)] - uv.y()) / sv;
                if (du * du + dv * dv < best) {
                    best = du * du + dv * dv;
                    bi = i;
                    bj = j;
                }
            }
        }
        model::SurfaceRecipe after = *sculpt->recipe;
        const std::array<int, 2> ij{bi, bj};
        auto it = std::find(after.blocked.begin(), after.blocked.end(), ij);
        const bool block = it == after.blocked.end();
        if (block) after.blocked.push_back(ij);
        else after.blocked.erase(it);
        undo_.push(new SetRecipeCommand(*this, sculpt->id, *sculpt->recipe, after,
                                        block ? tr("Block control point (%1, %2)").arg(bi).arg(bj) : tr("Free control point (%1, %2)").arg(bi).arg(bj)));
        lastStroke_.message = block ? tr("Control point (%1, %2) of surface %3 blocked: it never moves").arg(bi).arg(bj).arg(base->id)
                                    : tr("Control point (%1, %2) of surface %3 free again").arg(bi).arg(bj).arg(base->id);
        break;
    }
    case SculptTool::Distance: {
        if (!sculpt) {
            lastStroke_.message = tr("A distance needs a sculpt: draw a target curve (Alt+T) or drop a handle (Alt+H) on surface %1 first").arg(base->id);
            break;
        }
        if (!pendingDistance_) {
            pendingDistance_ = uv;
            lastStroke_.message = tr("Distance: first end at (u, v) = (%1, %2); click the second").arg(uv.x(), 0, 'f', 3).arg(uv.y(), 0, 'f', 3);
            break;
        }
        const Eigen::Vector2d first = *pendingDistance_;
        pendingDistance_.reset();
        const double d = (sculpt->surface->evaluate(first.x(), first.y()) - sculpt->surface->evaluate(uv.x(), uv.y())).norm();
        model::SurfaceRecipe after = *sculpt->recipe;
        after.distances.push_back({first, uv, d});
        undo_.push(new SetRecipeCommand(*this, sculpt->id, *sculpt->recipe, after, tr("Hold a distance of %1 mm").arg(d, 0, 'f', 2)));
        lastStroke_.message = tr("Distance of %1 mm held on sculpt %2 (change it in the inspector)").arg(d, 0, 'f', 2).arg(sculpt->id);
        break;
    }
    case SculptTool::Target:
    case SculptTool::Bound:
    case SculptTool::Resketch: break;
    }
    notifyChanged();
    Q_EMIT strokeFinished();
}

void SketchDocument::setSculptHoldNormals(model::EntityId sculpt, bool hold)
{
    const model::Entity* e = model_.find(sculpt);
    if (!e || !e->recipe || e->recipe->mode != model::Construction::Sculpt || e->recipe->handles.empty()) return;
    model::SurfaceRecipe after = *e->recipe;
    for (auto& h : after.handles) h.holdNormal = hold;
    if (after.handles.size() == e->recipe->handles.size() &&
        std::equal(after.handles.begin(), after.handles.end(), e->recipe->handles.begin(), [](const auto& a, const auto& b) { return a.holdNormal == b.holdNormal; }))
        return;
    undo_.push(new SetRecipeCommand(*this, sculpt, *e->recipe, after, hold ? tr("Hold normals at handles") : tr("Release normals at handles")));
}

void SketchDocument::setSculptDistance(model::EntityId sculpt, int index, double distance)
{
    const model::Entity* e = model_.find(sculpt);
    if (!e || !e->recipe || e->recipe->mode != model::Construction::Sculpt || index < 0 ||
        index >= static_cast<int>(e->recipe->distances.size()) || !(distance >= 0.0) || e->recipe->distances[static_cast<size_t>(index)].distance == distance)
        return;
    model::SurfaceRecipe after = *e->recipe;
    after.distances[static_cast<size_t>(index)].distance = distance;
    undo_.push(new SetRecipeCommand(*this, sculpt, *e->recipe, after, tr("Distance %1 set to %2 mm").arg(index + 1).arg(distance, 0, 'f', 2)));
}

model::EntityId SketchDocument::sculptWith(std::vector<model::Entity> added, const std::function<void(model::SurfaceRecipe&)>& edit,
                                           const QString& text)
{
    const model::Entity* base = model_.find(sculptBase_);
    if (!base || added.empty()) return 0;
    const bool extend = base->recipe && base->recipe->mode == model::Construction::Sculpt && model_.dependents(base->id).empty();
    model::Entity sculpted;
    sculpted.kind = model::EntityKind::Surface;
    model::SurfaceRecipe recipe;
    recipe.mode = model::Construction::Sculpt;
    if (extend) {
        recipe = *base->recipe;
        sculpted.inputs = base->inputs;
    } else {
        sculpted.inputs = {sculptBase_};
        recipe.bound = pendingBound_;  // drawn before the first target
    }
    pendingBound_.clear();
    // Target curves before handle points, as documents list them.
    if (added.back().kind == model::EntityKind::Curve) {
        auto at = std::find_if(sculpted.inputs.begin() + 1, sculpted.inputs.end(), [this](model::EntityId id) {
            const model::Entity* e = model_.find(id);
            return e && e->kind == model::EntityKind::Point;
        });
        sculpted.inputs.insert(at, kPreviousEntity);
    } else {
        sculpted.inputs.push_back(kPreviousEntity);
    }
    if (edit) edit(recipe);
    sculpted.recipe = recipe;
    added.push_back(std::move(sculpted));
    const model::EntityId old = sculptBase_;
    undo_.beginMacro(text);
    // The old sculpt goes first (nothing depends on it), then the target and the sculpt with it.
    if (extend) undo_.push(new DeleteEntityCommand(*this, old));
    undo_.push(new AddEntitiesCommand(*this, std::move(added), text));
    undo_.endMacro();
    const model::Entity* made = model_.find(selection_);
    if (!made || made->kind != model::EntityKind::Surface) return 0;
    sculptBase_ = made->id;
    return made->id;
}

void SketchDocument::setSculptBound(const std::vector<Eigen::Vector3d>& world)
{
    const model::Entity* sculpt = model_.find(sculptBase_);
    lastStroke_ = {};
    lastStroke_.samples = static_cast<int>(world.size());
    if (!sculpt || world.size() < 3) {
        lastStroke_.message = tr("Bound not used: select a surface to sculpt first, then draw a closed loop over it");
        return;
    }
    Eigen::AlignedBox3d box;
    for (const Eigen::Vector3d& p : world) box.extend(p);
    const double extent = box.diagonal().norm();
    if (extent == 0.0 || (world.front() - world.back()).norm() > kClosedStrokeFraction * extent) {
        lastStroke_.message = tr("Bound not used: the stroke is not closed (its ends are %1 mm apart); draw a loop around the region")
                                  .arg((world.front() - world.back()).norm(), 0, 'f', 1);
        return;
    }
    // The bound lies in the domain of the surface the sculpt deforms: its base.
    const bool isSculpt = sculpt->recipe && sculpt->recipe->mode == model::Construction::Sculpt;
    const model::Entity* base = isSculpt ? model_.find(sculpt->inputs.front()) : sculpt;
    if (!base || !base->surface) return;
    const solvers::SurfaceProjector projector(*base->surface);
    const size_t step = (world.size() + kMaxBoundPoints - 1) / kMaxBoundPoints;
    std::vector<Eigen::Vector2d> bound;
    for (size_t k = 0; k < world.size(); k += step) {
        const solvers::SurfaceProjection f = projector.project(world[k]);
        bound.emplace_back(f.u, f.v);
    }
    if (isSculpt) {
        model::SurfaceRecipe after = *sculpt->recipe;
        after.bound = bound;
        undo_.push(new SetRecipeCommand(*this, sculpt->id, *sculpt->recipe, after, tr("Bound sculpt %1").arg(sculpt->id)));
    } else {
        // A surface not sculpted yet: the bound waits for the first target or handle (a sculpt
        // has one at least), and that sculpt takes it.
        lastStroke_.message = tr("Bound drawn on surface %1: draw target curves or drop handles inside it").arg(sculpt->id);
        pendingBound_ = bound;
        Q_EMIT strokeFinished();
        return;
    }
    lastStroke_.message = tr("Bound of %1 points set on sculpt %2: only the region inside deforms").arg(bound.size()).arg(sculpt->id);
    Q_EMIT strokeFinished();
}

void SketchDocument::setSculptCurveTangent(model::EntityId sculpt, model::EntityId curve, bool hold)
{
    const model::Entity* e = model_.find(sculpt);
    const model::Entity* c = model_.find(curve);
    if (!e || !e->recipe || e->recipe->mode != model::Construction::Sculpt || !c || !c->world || !e->surface) return;
    model::SurfaceRecipe after = *e->recipe;
    auto& tangents = after.curveTangents;
    tangents.erase(std::remove_if(tangents.begin(), tangents.end(), [curve](const auto& t) { return t.curve == curve; }), tangents.end());
    if (hold) {
        // The direction the surface has across the curve now, at its middle (the sculpt as it is).
        const solvers::SurfaceProjector projector(*e->surface);
        const solvers::Curve3d& g = *c->world;
        const solvers::SurfaceProjection f = projector.project(g.evaluate(0.5 * (g.domainStart() + g.domainEnd())));
        const auto der = e->surface->derivatives(f.u, f.v, 1);
        const Eigen::Vector3d along = g.derivatives(0.5 * (g.domainStart() + g.domainEnd()), 1)[1];
        const Eigen::Vector3d normal = der[1][0].cross(der[0][1]);
        Eigen::Vector3d across = normal.cross(along);
        if (across.norm() == 0.0 || !across.allFinite()) return;
        tangents.push_back({curve, across.normalized()});
    }
    undo_.push(new SetRecipeCommand(*this, sculpt, *e->recipe, after,
                                    hold ? tr("Hold the tangent along curve %1").arg(curve) : tr("Release the tangent along curve %1").arg(curve)));
}

}  // namespace sculptline::ui
