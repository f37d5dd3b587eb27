#pragma once
// The kinds of the model's entities and their states (seed 000 §3.2), with one descriptor table:
// kept apart from model.h so that constraints and documents can name kinds without the model.
#include <array>
#include <cstdint>

namespace sculptline::model {

using EntityId = std::uint32_t;  ///< 0 is "none"

/// Mesh: a closed loop of curves filled by a triangle mesh (seed 004 §4, curve networks).
/// Point: a point in space (the crossing of two curves, seed 000 Fig. 2), for point constraints.
/// Solid: the watertight solid of a set of surfaces (closed, or shells of a thickness), through
/// level sets (solvers/volume/solidify.h; model/solid_recipe.h).
enum class EntityKind { Plane, Curve, Surface, Mesh, Point, Solid };

/// One row of the entity-kind table.
struct EntityKindInfo {
    EntityKind kind;
    const char* name;  ///< as documents, the CLI and the ui spell it
};
const std::array<EntityKindInfo, 6>& entityKinds();
const EntityKindInfo& describe(EntityKind kind);
const char* kindName(EntityKind kind);

/// Seed 000 §3.2: what the designer marked an element as. A fixed element is never changed by a
/// solve or an edit (its dependents still follow what it is); a free one takes whatever the plan's
/// solvers give it; a changed one was just edited and its dependents are due (Model::state).
enum class State { Fixed, Free, Changed };
const char* stateName(State state);

}  // namespace sculptline::model
