#include "scene/entity_path.h"

#include <Inventor/SbName.h>
#include <Inventor/SoPath.h>
#include <Inventor/nodes/SoNode.h>

#include <algorithm>
#include <array>
#include <limits>

namespace sculptline::scene {
namespace {

constexpr std::array<model::EntityKind, 6> kKinds{model::EntityKind::Plane, model::EntityKind::Curve,
                                                  model::EntityKind::Surface, model::EntityKind::Mesh,
                                                  model::EntityKind::Point, model::EntityKind::Solid};

/// The word an entity's node name starts with.
const char* nodeWord(model::EntityKind kind)
{
    switch (kind) {
    case model::EntityKind::Plane: return "Plane";
    case model::EntityKind::Curve: return "Curve";
    case model::EntityKind::Surface: return "Surface";
    case model::EntityKind::Mesh: return "Mesh";
    case model::EntityKind::Point: return "Point";
    case model::EntityKind::Solid: return "Solid";
    }
    return "";
}

/// `digits` as an id: decimal digits only, not 0, within EntityId's range.
std::optional<model::EntityId> parseId(const std::string& digits)
{
    if (digits.empty() || digits.size() > std::numeric_limits<model::EntityId>::digits10 + 1) return std::nullopt;
    unsigned long long value = 0;
    for (const char c : digits) {
        if (c < '0' || c > '9') return std::nullopt;
        value = value * 10 + static_cast<unsigned long long>(c - '0');
    }
    if (value == 0 || value > std::numeric_limits<model::EntityId>::max()) return std::nullopt;
    return static_cast<model::EntityId>(value);
}

}  // namespace

std::string entityNodeName(model::EntityKind kind, model::EntityId id) { return nodeWord(kind) + std::to_string(id); }

std::string constraintNodeName(model::ConstraintId id) { return "Constraint" + std::to_string(id); }

std::optional<EntityRef> entityOfName(const std::string& name)
{
    for (const model::EntityKind kind : kKinds) {
        const std::string word = nodeWord(kind);
        if (name.compare(0, word.size(), word) != 0) continue;
        if (const auto id = parseId(name.substr(word.size()))) return EntityRef{*id, kind};
    }
    return std::nullopt;
}

std::optional<EntityRef> entityAt(const SoPath* path, const std::vector<model::EntityKind>& kinds)
{
    if (!path) return std::nullopt;
    for (int i = path->getLength() - 1; i >= 0; --i) {
        const std::optional<EntityRef> ref = entityOfName(path->getNode(i)->getName().getString());
        if (ref && (kinds.empty() || std::find(kinds.begin(), kinds.end(), ref->kind) != kinds.end())) return ref;
    }
    return std::nullopt;
}

}  // namespace sculptline::scene
