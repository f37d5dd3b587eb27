#pragma once
// The solvers of the construction plan's steps, by what they solve (issue 12 §3). Each step of a
// plan (model/plan.h) names a registry key; the registry makes the solver for it. A solver has two
// stages, after geometry-central's pattern: factor() when a drag (or a plan) starts — the expensive
// set-up that depends on the structure only (a factorization, a surface builder's parameterization)
// — and solve() per event, which re-solves with that set-up from the step's current inputs. The
// model owns the solvers and their caches, outside the entities (the undo snapshots).
//
// Built-in keys:
//   placement       a curve's world form from its plane's frame (and its pins' values)
//   least-change    a curve with pins or fixed points: the least-change solver of thesis §6.1
//                   (solvers/editing/curve_manipulation.h), factored once per pull
//   surface-builder a surface's construction (solvers/surfaces/surface_modes.h SurfaceBuilder:
//                   fill, loft and sweep keep their set-up across a drag; gordon rebuilds)
//   network-mesh    a mesh's loop of curves (solvers/surfaces/network_mesh.h)
//   deformation     a sculpt: the base surface deformed onto target curves (thesis ch. 6,
//                   solvers/deformation), factored once per drag of a target's plane
//   solid           a solid's surfaces changed: marks it due for conversion (model/solid_job.h)
//   unsolved        a cluster no registered solver handles yet (coupled constraints between
//                   several free entities): its entities keep their geometry, and the plan says so
#include "model/plan.h"

#include <Eigen/Core>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace sculptline::model {

class Model;
struct Entity;

class StepSolver {
public:
    virtual ~StepSolver() = default;
    /// The set-up that lasts across a drag, from the model as it is now.
    /// @throws std::invalid_argument when the step cannot be solved (the message says why).
    virtual void factor(const Model& model, const PlanStep& step) = 0;
    /// Re-solves the step's entities from their inputs with that set-up, or, with none (never
    /// factored, or reset()), as a fresh build does. A failure is recorded on the entity
    /// (buildError; the last good geometry stays), never thrown.
    virtual void solve(Model& model, const PlanStep& step) = 0;
    /// Forgets the set-up: the next solve() is a fresh build (bit for bit what opening a document
    /// gives, so a model at rest does not depend on the drags it went through).
    virtual void reset() {}
    /// least-change: the pulled point's target for the next solve() (the grip); others ignore it.
    virtual void setGrip(const Eigen::Vector3d&) {}
    /// The last solve's message (a compromise the solver had to make), empty when it met everything.
    virtual std::string message() const { return {}; }

protected:
    /// Write access to the model's entities, for the solvers only.
    static Entity& entity(Model& model, EntityId id);
};

class SolverRegistry {
public:
    using Factory = std::function<std::unique_ptr<StepSolver>()>;
    /// Registers the built-in solvers.
    SolverRegistry();
    /// Adds or replaces the solver for `key`.
    void add(const std::string& key, Factory factory);
    /// A new solver for `key`. @throws std::invalid_argument for an unknown key.
    std::unique_ptr<StepSolver> make(const std::string& key) const;
    /// The key of the solver for `step` of `model`'s plan: what the step solves decides it.
    std::string choose(const Model& model, const PlanStep& step) const;
    /// Solvers whose factor() pays off across a drag (the others are made per event).
    bool caches(const std::string& key) const;

private:
    std::map<std::string, Factory> factories_;
};

/// A pull's solver: least-change with the grip at parameter `u` of the step's curve, its pins held
/// and its fixed points blocked (factor() throws std::invalid_argument when it cannot be pulled).
std::unique_ptr<StepSolver> makePullSolver(double u);

/// Builds `surface`'s geometry from its recipe and the model's present inputs (world curves, the
/// surfaces it is tangent to, the profile plane's frame); what a fresh build gives.
/// @throws std::invalid_argument or GeometryError when it cannot be built.
void buildSurfaceEntity(const Model& model, Entity& surface);
/// Builds `mesh`'s triangles from its loop of curves. @throws when they make no loop.
void buildMeshEntity(const Model& model, Entity& mesh);

}  // namespace sculptline::model
