#pragma once
// Which model entity a Coin path leads to. The model view (scene/model_view.h) and the plane
// draggers (manipulators/plane_binding.h) name an entity's node "<Kind><id>" ("Curve7", "Plane3");
// entityNodeName() writes those names and entityAt() reads them back, so naming and parsing live in
// one place. Group nodes ("Curves", "Surfaces", "Plane3Curves") name no entity.
#include "model/model.h"

#include <optional>
#include <string>
#include <vector>

class SoPath;

namespace sculptline::scene {

/// An entity a path leads to: its id (never 0) and kind.
struct EntityRef {
    model::EntityId id = 0;
    model::EntityKind kind = model::EntityKind::Plane;
};

/// The node name of entity `id` of `kind`: "Plane3", "Curve7", "Surface9", "Mesh4", "Point5".
std::string entityNodeName(model::EntityKind kind, model::EntityId id);
/// The node name of a constraint's marker (a pin): "Constraint5" (constraints are numbered apart
/// from entities, and entityOfName() names no entity for it).
std::string constraintNodeName(model::ConstraintId id);
/// The entity a node name names, or empty: the kind's word followed by the decimal id alone (no
/// sign, no suffix, not 0, within EntityId's range).
std::optional<EntityRef> entityOfName(const std::string& name);
/// The deepest node on `path` whose name names an entity of one of `kinds` (empty = any kind):
/// a curve inside a plane's group is the curve, a part of a plane's dragger is the plane. Empty
/// for a null path or when no such node lies on it.
std::optional<EntityRef> entityAt(const SoPath* path, const std::vector<model::EntityKind>& kinds = {});

}  // namespace sculptline::scene
