#include "model/surface_recipe.h"

#include <stdexcept>

namespace sculptline::model {

namespace {

using solvers::surfaces::SurfaceMode;

const std::array<ConstructionInfo, 10> kConstructions{{
    {Construction::Fill, "fill", 2, 4, {"boundary", nullptr, nullptr}, true, kTangentsOption, SurfaceMode::Fill, false},
    {Construction::Revolve, "revolve", 2, 2, {"profile", "axis (a line)", nullptr}, false, kAngleOption, SurfaceMode::Revolve, false},
    {Construction::Extrude, "extrude", 1, 1, {"profile", nullptr, nullptr}, false, kDirectionOption, SurfaceMode::Extrude, false},
    {Construction::Sweep, "sweep", 2, 2, {"profile", "path", nullptr}, false, kToleranceOption, SurfaceMode::Sweep, false},
    {Construction::Loft, "loft", 2, 64, {"section", nullptr, nullptr}, true, 0u, SurfaceMode::Loft, false},
    {Construction::BoundaryRotation, "boundary-rotation", 2, 2, {"left outline", "right outline", nullptr}, false, kToleranceOption,
     SurfaceMode::BoundaryRotation, false},
    {Construction::RailRotation, "rail-rotation", 3, 3, {"rail 1", "rail 2", "profile"}, false, kToleranceOption,
     SurfaceMode::RailRotation, false},
    // Two families of at least two curves each (seed 004 §4).
    {Construction::Gordon, "gordon", 4, 64, {"curve", nullptr, nullptr}, true, kToleranceOption | kUCurvesOption, std::nullopt, false},
    // One closed loop of curves, filled by a triangle mesh.
    {Construction::Network, "network", 1, 64, {"curve", nullptr, nullptr}, true, 0u, std::nullopt, true},
    // A base surface and 1 to 63 target curves (thesis §5.2.3, §6.2.2).
    {Construction::Sculpt, "sculpt", 2, 64, {"base surface", "target curve", nullptr}, false, kStiffnessOption, std::nullopt, false, true},
}};

}  // namespace

const std::array<ConstructionInfo, 10>& constructions() { return kConstructions; }

const ConstructionInfo& describe(Construction mode) { return kConstructions.at(static_cast<size_t>(mode)); }

const char* constructionName(Construction mode) { return describe(mode).name; }

std::optional<Construction> constructionFromName(const std::string& name)
{
    for (const ConstructionInfo& info : kConstructions) {
        if (name == info.name) return info.mode;
    }
    return std::nullopt;
}

InputCount surfaceInputCount(Construction mode)
{
    const ConstructionInfo& info = describe(mode);
    return {info.minInputs, info.maxInputs};
}

std::string surfaceInputRole(Construction mode, int index)
{
    const ConstructionInfo& info = describe(mode);
    if (info.numberedRoles) {
        std::string role = std::string(info.roles[0]) + " " + std::to_string(index + 1);
        if (mode == Construction::Gordon) role += " of the network";
        if (mode == Construction::Network) role += " of the loop";
        return role;
    }
    if (mode == Construction::Sculpt) return index == 0 ? info.roles[0] : std::string(info.roles[1]) + " " + std::to_string(index);
    if (index >= 0 && index < static_cast<int>(info.roles.size()) && info.roles[static_cast<size_t>(index)])
        return info.roles[static_cast<size_t>(index)];
    return "curve " + std::to_string(index + 1);
}

bool inputLiesOnSurface(Construction mode, int index)
{
    if (mode == Construction::Revolve || mode == Construction::Sweep) return index == 0;
    if (mode == Construction::Sculpt) return false;  // targets are approached, not lain on
    return !describe(mode).makesMesh;
}

}  // namespace sculptline::model
