#include "model/solid_recipe.h"

#include <cmath>

namespace sculptline::model {

const char* solidModeName(SolidMode mode) { return mode == SolidMode::Shell ? "shell" : "closed"; }

std::optional<SolidMode> solidModeFromName(const std::string& name)
{
    if (name == "closed") return SolidMode::Closed;
    if (name == "shell") return SolidMode::Shell;
    return std::nullopt;
}

std::string validate(const SolidRecipe& r)
{
    if (!std::isfinite(r.voxelSize) || r.voxelSize < 0.0) return "voxel_size: must be a finite number >= 0 (0: the default)";
    if (!std::isfinite(r.thickness) || r.thickness < 0.0) return "thickness: must be a finite number >= 0";
    if (r.mode == SolidMode::Shell && !(r.thickness > 0.0)) return "thickness: a shell needs a thickness > 0";
    return {};
}

}  // namespace sculptline::model
