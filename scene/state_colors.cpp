#include "scene/state_colors.h"

#include <set>
#include <vector>

namespace sculptline::scene {
namespace {

// The warm curve palette of scene/default_scene.cpp.
constexpr std::array<Rgb, 3> kFreeCurveColors{Rgb{1.0f, 0.5f, 0.1f}, Rgb{0.95f, 0.85f, 0.2f}, Rgb{0.95f, 0.3f, 0.55f}};
constexpr Rgb kFixed{0.7f, 0.4f, 1.0f};
constexpr Rgb kChanged{0.6f, 1.0f, 0.2f};

}  // namespace

Rgb fixedColor() { return kFixed; }
Rgb changedColor() { return kChanged; }

Rgb freeCurveColor(model::EntityId id)
{
    // Offset so that the default scene's curve (id 2, after its plane) keeps the first colour.
    return kFreeCurveColors[(id + 1) % kFreeCurveColors.size()];
}

Rgb curveColor(model::EntityId id, model::State state)
{
    switch (state) {
    case model::State::Fixed: return kFixed;
    case model::State::Changed: return kChanged;
    case model::State::Free: break;
    }
    return freeCurveColor(id);
}

model::State shownState(const model::Model& model, model::EntityId id)
{
    const model::State state = model.state(id);
    if (state != model::State::Free || model.dragged() == 0) return state;
    // Downstream of the dragged entity: a walk over the direct dependents.
    std::vector<model::EntityId> open{model.dragged()};
    std::set<model::EntityId> seen{model.dragged()};
    while (!open.empty()) {
        const model::EntityId at = open.back();
        open.pop_back();
        if (at == id) return model::State::Changed;
        for (model::EntityId d : model.dependents(at)) {
            if (seen.insert(d).second) open.push_back(d);
        }
    }
    return model::State::Free;
}

}  // namespace sculptline::scene
