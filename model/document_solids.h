#pragma once
// The "solids" of a document (model/document.h): read, checked and written apart from the other
// entities, in their own file. A solid entry:
//   {"id", "surfaces": [surface ids, each smaller than the solid's], "mode": "closed"|"shell",
//    "thickness"?: t (a shell's, > 0), "voxel_size"?: v (0 or absent: the default),
//    "result"?: {"mesh": M, "volume", "area", "voxel_size", "watertight"}, "state"?}
// "result" is the last conversion, saved so that a document opens without converting again; a
// solid without one is converted after opening. Readers before solids ignore the member.
#include "model/model.h"

#include <nlohmann/json_fwd.hpp>
#include <set>

namespace sculptline::model {

/// Most vertices or triangles of a saved solid mesh: a 1 GiB conversion (solidify.h's memory
/// limit) makes a few million triangles; more is not a document this program wrote.
constexpr size_t kMaxSolidMeshElements = size_t{1} << 24;

struct SceneDocument;

/// Reads j["solids"] (optional) into doc.solids. `usedIds` holds every entity id read so far.
/// @throws solvers::io::InputError naming the field ("solids[0].surfaces[1]: no surface has id 7").
void readSolids(const nlohmann::json& j, SceneDocument& doc, std::set<int>& usedIds);

/// The document entry of a solid entity.
nlohmann::json solidToJson(const Entity& solid);

}  // namespace sculptline::model
