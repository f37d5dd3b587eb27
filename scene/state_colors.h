#pragma once
// The colours of the entities' states (seed 000 §3.2: fixed, free, changed), one definition for the
// viewport (scene/model_view.cpp) and the entity list (ui/entity_list_dock.cpp) so that both say the
// same thing. A fixed curve is met exactly by an incidence solve (a hard constraint); a free one is
// soft (met in the least-squares sense at the L-curve's truncation); a changed one moves with the
// drag in progress.
#include "model/model.h"

#include <array>

namespace sculptline::scene {

/// Red, green, blue in [0, 1].
using Rgb = std::array<float, 3>;

/// Fixed: a violet that neither the warm free curves, the blue surfaces, the cyan marked inputs nor
/// the red pins use.
Rgb fixedColor();
/// Changed by the drag in progress: a lime green, brighter than a sculpt's bound.
Rgb changedColor();
/// A free curve: the warm palette by id (orange, yellow, pink), so that neighbours differ.
Rgb freeCurveColor(model::EntityId id);
/// Curve `id` drawn in state `state`.
Rgb curveColor(model::EntityId id, model::State state);

/// The state shown for entity `id`: fixed when the designer fixed it; changed when it is edited and
/// not yet updated (Model::state) or lies downstream of the entity being dragged (the dragged one
/// included, fixed ones excepted: solves never change them); free otherwise.
model::State shownState(const model::Model& model, model::EntityId id);

}  // namespace sculptline::scene
