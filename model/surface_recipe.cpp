#include "model/surface_recipe.h"

#include <stdexcept>

namespace sculptline::model {

InputCount surfaceInputCount(const std::string& mode)
{
    if (mode == "fill") return {2, 4};
    if (mode == "revolve") return {2, 2};  // profile, axis
    if (mode == "extrude") return {1, 1};
    if (mode == "sweep") return {2, 2};
    if (mode == "loft") return {2, 64};
    if (mode == "boundary-rotation") return {2, 2};
    if (mode == "rail-rotation") return {3, 3};
    if (mode == "gordon") return {4, 64};  // two families of at least two
    if (mode == "network") return {1, 64};  // one closed loop (a mesh entity, not a surface)
    throw std::invalid_argument("unknown surface mode \"" + mode + "\"");
}

std::string surfaceInputRole(const std::string& mode, int index)
{
    if (mode == "fill") return "boundary " + std::to_string(index + 1);
    if (mode == "revolve") return index == 0 ? "profile" : "axis (a line)";
    if (mode == "extrude") return "profile";
    if (mode == "sweep") return index == 0 ? "profile" : "path";
    if (mode == "loft") return "section " + std::to_string(index + 1);
    if (mode == "boundary-rotation") return index == 0 ? "left outline" : "right outline";
    if (mode == "rail-rotation") return index == 0 ? "rail 1" : index == 1 ? "rail 2" : "profile";
    if (mode == "gordon") return "curve " + std::to_string(index + 1) + " of the network";
    if (mode == "network") return "curve " + std::to_string(index + 1) + " of the loop";
    return "curve " + std::to_string(index + 1);
}

}  // namespace sculptline::model
