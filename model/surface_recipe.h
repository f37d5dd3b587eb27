#pragma once
// How a surface entity is built from its input curves (issue 6 §2): the surface mode and its
// options, as plain data the document saves. Options that refer to geometry are kept relative to
// the inputs so that they follow a drag: the revolve axis is a curve the designer drew (its two
// ends), and an extrusion's direction lives in the frame of the profile's plane.
#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace sculptline::model {

struct SurfaceRecipe {
    /// A mode name of solvers/surfaces (fill, revolve, extrude, sweep, loft, boundary-rotation,
    /// rail-rotation, gordon).
    std::string mode;
    /// revolve: sweep angle in degrees, (0, 360].
    double angleDegrees = 360.0;
    /// extrude: the direction and distance (model units), in the frame of the profile's plane (world
    /// axes when the profile lies on no plane), so that turning the plane turns the extrusion.
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();
    /// Approximating modes (sweep, boundary- and rail-rotation): model units; 0 = the solver's
    /// default, relative to the curves' size.
    double tolerance = 0.0;
    /// fill: boundaries made G1 (tangent-continuous) to an adjacent surface: boundary index (into
    /// the curve inputs) and that surface's entity id. The fill then depends on those surfaces too.
    struct Tangent {
        int boundary = 0;
        std::uint32_t surface = 0;
    };
    std::vector<Tangent> tangents;
    /// gordon: how many of the curve inputs (the first ones) are the u family; the rest are v.
    int uCurves = 0;
};

/// Input curves each mode takes, in order: [min, max]. Revolve's last input is its axis (a line
/// between the curve's ends).
struct InputCount {
    int min = 0;
    int max = 0;
};
/// @throws std::invalid_argument for an unknown mode name.
InputCount surfaceInputCount(const std::string& mode);

/// What each input means, for status messages ("profile", "axis", "path", ...); `index` from 0.
std::string surfaceInputRole(const std::string& mode, int index);

}  // namespace sculptline::model
