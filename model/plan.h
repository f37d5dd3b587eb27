#pragma once
// The construction plan (seed 000 §3.2, Fig. 3(b)): the order in which the model's entities are
// evaluated, computed from the constraint graph and the entities' states. One-way recipes (a curve's
// placement on its plane, a surface's construction) come in topological order; entities coupled by
// constraints (a curve on a surface that is built from it, two curves through a common point) form a
// strongly connected component that one solver handles together. Fixed entities are never solved:
// they only feed their dependents. The plan is plain data; the model keeps one and makes a new one
// only when the distribution of freedom changes (model/model.h).
#include "model/constraint.h"

#include <cstddef>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace sculptline::model {

/// One step: entities solved together, by one solver, under these constraints.
struct PlanStep {
    std::vector<EntityId> solve;  ///< ascending ids; one for a recipe, several for a cluster
    std::string solver;           ///< the registry key (model/solver_registry.h)
    std::vector<ConstraintId> constraints;  ///< every constraint consuming freedom of `solve`, ascending
};

struct Plan {
    std::vector<PlanStep> steps;  ///< in evaluation order
    /// Entity -> index of the step that solves it; entities absent here are sources (nothing
    /// constrains them, or they are fixed).
    std::map<EntityId, size_t> stepOf;
};

/// Chooses the solver key of a step (the registry's rule).
using SolverChooser = std::function<std::string(const PlanStep&)>;

/// The plan for `entities` (all of them, ascending), `fixed` among them, and `constraints`.
/// Deterministic: among steps that do not depend on each other the one with the smallest entity id
/// comes first. Linear in entities plus constraint relations (Tarjan's strongly connected
/// components, then Kahn's order on the components).
Plan makePlan(const std::vector<EntityId>& entities, const std::set<EntityId>& fixed,
              const std::vector<const Constraint*>& constraints, const SolverChooser& chooseSolver);

/// The indices of the steps that must run when `changed` entities changed: the steps solving them
/// and every step downstream, ascending (= plan order). `constraintsOn` maps an entity to the
/// constraints that read it or consume its freedom (the model's index, kept as constraints come
/// and go, so a drag event builds none), `constraints` holds them by id.
std::vector<size_t> stepsAfter(const Plan& plan, const std::map<EntityId, std::set<ConstraintId>>& constraintsOn,
                               const std::map<ConstraintId, Constraint>& constraints, const std::set<EntityId>& changed);

}  // namespace sculptline::model
