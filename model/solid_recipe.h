#pragma once
// How a solid entity is made from its surfaces (solvers/volume/solidify.h): the surfaces close up
// into the boundary of a solid, or each open one becomes a shell of a thickness (CAD's thicken).
#include <optional>
#include <string>

namespace sculptline::model {

enum class SolidMode {
    Closed,  ///< the surfaces bound a solid (each closed, or open ones closing up together)
    Shell,   ///< open surfaces become shells `thickness` thick (closed ones still bound solids)
};

struct SolidRecipe {
    SolidMode mode = SolidMode::Closed;
    /// model units; > 0 for a shell, ignored (0) for a closed solid.
    double thickness = 0.0;
    /// model units, >= 0; 0: solidify's default from the model's size (and the thickness).
    double voxelSize = 0.0;
    bool operator==(const SolidRecipe& o) const
    {
        return mode == o.mode && thickness == o.thickness && voxelSize == o.voxelSize;
    }
};

/// "closed" / "shell", as documents and the ui spell them.
const char* solidModeName(SolidMode mode);
std::optional<SolidMode> solidModeFromName(const std::string& name);

/// Empty when the recipe can be converted, else what is wrong ("thickness: a shell needs a
/// thickness > 0, got 0"), naming the field as documents do.
std::string validate(const SolidRecipe& recipe);

}  // namespace sculptline::model
