#pragma once
// How a surface (or mesh) entity is built from its input curves (issue 6 §2): the construction mode
// and its options, as plain data the document saves. Options that refer to geometry are kept
// relative to the inputs so that they follow a drag: the revolve axis is a curve the designer drew
// (its two ends), and an extrusion's direction lives in the frame of the profile's plane.
//
// The modes are an enum with one descriptor table (name, inputs and their roles, options): the
// document reader, the CLI, the ui's status texts and the model's checks all read the table, and
// nothing compares mode names.
#include "solvers/surfaces/surface_modes.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sculptline::model {

/// Every way the model builds a surface or mesh from curves.
/// Sculpt (thesis ch. 6): an existing surface (the base, first input) deformed so that its nearest
/// surface curves move onto target curves and its handle points onto Point entities (the other
/// inputs), within a bound, solvers/deformation.
enum class Construction { Fill, Revolve, Extrude, Sweep, Loft, BoundaryRotation, RailRotation, Gordon, Network, Sculpt };

/// Options a construction reads (bits of ConstructionInfo::options).
enum ConstructionOption : unsigned {
    kAngleOption = 1u << 0,      ///< revolve: sweep angle
    kDirectionOption = 1u << 1,  ///< extrude: direction and distance
    kToleranceOption = 1u << 2,  ///< approximating modes: model units
    kTangentsOption = 1u << 3,   ///< fill: G1 to adjacent surfaces
    kUCurvesOption = 1u << 4,    ///< gordon: size of the first family
    kStiffnessOption = 1u << 5,  ///< sculpt: how far the surface goes to its targets, and the objective
};

/// One row of the construction table.
struct ConstructionInfo {
    Construction mode;
    const char* name;  ///< as documents, the CLI and the ui's actions spell it
    int minInputs;     ///< input curves, in order
    int maxInputs;
    /// Role of each input for status messages; for modes with a variable count, the role of every
    /// input, numbered ("boundary 1", "section 2").
    std::array<const char*, 3> roles;
    bool numberedRoles;  ///< roles[0] followed by the input's number
    unsigned options;    ///< ConstructionOption bits
    /// The solver mode that builds it (solvers/surfaces/surface_modes.h); none for gordon and
    /// network, which have their own builders.
    std::optional<solvers::surfaces::SurfaceMode> solverMode;
    bool makesMesh;  ///< network: a mesh entity, not a surface
    bool baseSurface = false;  ///< sculpt: the first input is a surface (the base), the rest curves
};

/// The whole table, in enum order.
const std::array<ConstructionInfo, 10>& constructions();
const ConstructionInfo& describe(Construction mode);
const char* constructionName(Construction mode);
/// The mode named `name`, or nothing.
std::optional<Construction> constructionFromName(const std::string& name);

struct SurfaceRecipe {
    Construction mode = Construction::Fill;
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
    /// sculpt: λ in (0, 1] (thesis eq. 6-20), the share of the way to the targets.
    double stiffness = 1.0;
    /// sculpt: least change of the net's forces (smooth fall-off, the default) or of the control points.
    bool displacementObjective = false;

    // Sculpt constraints beside its target curves (thesis ch. 6, Table 6-1). Parameters (u, v) are in
    // the base surface's domain; they locate a constraint and stay put while its value moves.
    /// A point handle (Fig. 6-5 c–d): S(uv) goes to the Point entity `point` (one of the inputs);
    /// with `holdNormal`, the tangent plane there turns with the point's rotation (S_u, S_v become
    /// R S_u°, R S_v° of the base: the normal tilts by R).
    struct Handle {
        std::uint32_t point = 0;
        Eigen::Vector2d uv = Eigen::Vector2d::Zero();
        bool holdNormal = true;
    };
    std::vector<Handle> handles;
    /// A bound curve as a closed polygon in the domain (eq. 6-22, §6.3): control points whose
    /// Greville abscissae lie outside never move, and target curves act only inside. Empty = none.
    std::vector<Eigen::Vector2d> bound;
    /// Control points (i, j) of the base's net that never move (Fig. 6-7).
    std::vector<std::array<int, 2>> blocked;
    /// Two surface points held `distance` apart.
    struct Distance {
        Eigen::Vector2d uv = Eigen::Vector2d::Zero();
        Eigen::Vector2d uv2 = Eigen::Vector2d::Zero();
        double distance = 0.0;
    };
    std::vector<Distance> distances;
    /// Along a target curve (`curve`, one of the inputs), the surface's tangent across it points
    /// along `direction` (world; Fig. 6-4 d).
    struct CurveTangent {
        std::uint32_t curve = 0;
        Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
    };
    std::vector<CurveTangent> curveTangents;
};

/// Input curves each mode takes, in order: [min, max]. Revolve's last input is its axis (a line
/// between the curve's ends).
struct InputCount {
    int min = 0;
    int max = 0;
};
InputCount surfaceInputCount(Construction mode);

/// What each input means, for status messages ("profile", "axis", "path", ...); `index` from 0.
std::string surfaceInputRole(Construction mode, int index);

/// Whether input `index` lies on the surface it builds (every input but a revolve's axis and a
/// sweep's path): a G1 fill can be tangent to a surface along such a curve.
bool inputLiesOnSurface(Construction mode, int index);

}  // namespace sculptline::model
