#include "model/entity_kind.h"

#include <cstddef>

namespace sculptline::model {

namespace {

const std::array<EntityKindInfo, 6> kEntityKinds{{
    {EntityKind::Plane, "plane"},
    {EntityKind::Curve, "curve"},
    {EntityKind::Surface, "surface"},
    {EntityKind::Mesh, "mesh"},
    {EntityKind::Point, "point"},
    {EntityKind::Solid, "solid"},
}};

}  // namespace

const std::array<EntityKindInfo, 6>& entityKinds() { return kEntityKinds; }
const EntityKindInfo& describe(EntityKind kind) { return kEntityKinds.at(static_cast<size_t>(kind)); }
const char* kindName(EntityKind kind) { return describe(kind).name; }

const char* stateName(State state)
{
    switch (state) {
    case State::Fixed: return "fixed";
    case State::Free: return "free";
    case State::Changed: return "changed";
    }
    return "?";
}

}  // namespace sculptline::model
