#pragma once
// The document a scene is built from: projection planes, a ground grid, curves and surfaces, read
// from JSON (data/default_scene.json is the default). Plain data: no Coin types, so the parsing and
// its error messages are testable on their own.
#include "model/constraint.h"
#include "model/solid_recipe.h"
#include "model/surface_recipe.h"
#include "solvers/bspline/bspline_surface.h"
#include "solvers/volume/solidify.h"

#include <Eigen/Geometry>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

namespace sculptline::model {

/// A square projection plane.
struct PlaneSpec {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< centre, model units
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit after reading
    double size = 200.0;  ///< edge length, model units, > 0
    /// The plane's local X axis (in-plane rotation); zero = the shortest arc from +Z (PlaneFrame).
    Eigen::Vector3d xAxis = Eigen::Vector3d::Zero();
    int id = 0;  ///< referred to by curves' "plane"; the document's position + 1 when absent
    /// The exact local -> world rotation as saved ("rotation": [x, y, z, w]); it wins over normal
    /// and xAxis, which are then checked against it. Saving it makes a reopened plane bit-identical.
    std::optional<Eigen::Quaterniond> rotation;
    bool fixed = false;  ///< "state": "fixed"
};

/// The ground grid in the plane z = 0, centred on the origin.
struct GridSpec {
    double size = 200.0;  ///< edge length, model units, > 0
    double spacing = 10.0;  ///< distance between lines, model units, in (0, size]
};

/// A reference .iv file drawn to sketch over (not part of the model): saved as its path, absolute
/// and relative to the document's folder ("relative", tried first: a folder moved with its files).
struct ReferenceSpec {
    std::string path;
    std::string relative;  ///< empty when not saved with one
};

struct SceneDocument {
    GridSpec grid;
    std::vector<PlaneSpec> planes;
    std::vector<solvers::Curve3d> curves;
    /// Per curve: the id of the plane it lies on (its points are then plane-local, z = 0), or 0 for
    /// a curve in world coordinates.
    std::vector<int> curvePlanes;
    /// Per curve and per surface: the entity id saved with it ("id"), or 0 (numbered on opening).
    std::vector<int> curveIds;
    std::vector<int> surfaceIds;
    std::vector<solvers::Surface3d> surfaces;
    /// Surfaces built from curves: a surface entry with "construction": {"mode", "curves": [curve
    /// ids], "angle", "direction", "tolerance"}; its geometry is optional (rebuilt on opening).
    struct ConstructedSurface {
        int id = 0;
        SurfaceRecipe recipe;
        std::vector<int> curves;
        std::optional<solvers::Surface3d> saved;  ///< the geometry as saved, if it was
        bool fixed = false;
    };
    std::vector<ConstructedSurface> constructed;
    /// Per curve: the control points held fixed when it is pulled ("fixed": [indices]).
    std::vector<std::vector<int>> curveFixed;
    /// The designer's constraints (model/constraint.h): a pin as always written, {"curve": curve
    /// id, "type": "position"|"tangent", "u"}, or any type as {"type", "targets": [entity ids],
    /// "sources"?: [ids], "u"?, "uv"?: [u, v], "indices"?: [..], "value"?: [x, y, z], "weight"?,
    /// "preimage"?: a curve-on-surface's domain curve, a curve whose points are [u, v, 0]}.
    /// An "id" is read but not kept (constraints are numbered apart from entities): the records'
    /// ids are 0, the model numbers them.
    std::vector<Constraint> constraints;
    /// Curve-network meshes: {"id", "curves": [curve ids of one closed loop, in order]}; the mesh
    /// itself is rebuilt from the curves on opening.
    struct MeshSpec {
        int id = 0;
        std::vector<int> curves;
        bool fixed = false;
    };
    /// Per curve and per static surface: "state": "fixed" (seed 000 §3.2); absent or "free": free.
    std::vector<bool> curveStates;
    std::vector<bool> surfaceStates;
    /// Per static surface: the designer's incidence truncation ("incidence_k", 0 or absent = the
    /// L-curve's corner).
    std::vector<int> surfaceIncidenceK;
    /// Per static surface: its incidence prior ("incidence_prior": a surface of the same layout),
    /// the shape its curves bend (model/model.h Entity::prior).
    std::vector<std::optional<solvers::Surface3d>> surfacePriors;
    std::vector<MeshSpec> meshes;
    /// Points (a sculpt's handles): {"id", "position": [x, y, z], "rotation"?: [x, y, z, w],
    /// "state"?}; ids are required (a sculpt names its points).
    struct PointSpec {
        int id = 0;
        Eigen::Vector3d position = Eigen::Vector3d::Zero();
        Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
        bool fixed = false;
    };
    std::vector<PointSpec> points;
    /// "references": [{"path", "relative"?}] (the GUI reads and validates the files).
    std::vector<ReferenceSpec> references;
    /// Solids (model/document_solids.h): made from surfaces by a recipe, with their last result.
    struct SolidSpec {
        int id = 0;
        std::vector<int> surfaces;
        SolidRecipe recipe;
        std::optional<solvers::volume::Solid> result;
        bool fixed = false;
    };
    std::vector<SolidSpec> solids;
};

/// The document format this program writes: "format": "sculptline", "version": kDocumentVersion.
/// Documents without a version (written before it existed) read as version 1.
constexpr const char* kDocumentFormat = "sculptline";
constexpr int kDocumentVersion = 1;

/// Reads a document object: {"grid": {..}, "planes": [..], "curves": [..], "surfaces": [..]}; every
/// member is optional (absent = default grid / none), curves and surfaces use the JSON geometry of
/// ../shared/interfaces.md. A plane may carry "id" (positive, unique) and "xAxis"; a curve may carry
/// "plane": the id of the plane it lies on, its points then 2D (or z = 0) in that plane's frame.
/// Curves and surfaces may carry "id" too; ids are unique across the document, and a curve's id is
/// greater than its plane's (entities are created in id order, inputs first). Coordinates and sizes
/// must lie within 1e6 model units (Coin draws in float); a constructed surface's saved geometry is
/// exempt: it is rebuilt from its curves, and may reach beyond them.
/// A "version" above kDocumentVersion is refused ("made by a newer Sculptline (version 2); this
/// one reads up to 1"), as is a "format" other than kDocumentFormat.
/// @throws solvers::io::InputError naming the field ("planes[0].normal: must not be zero").
SceneDocument documentFromJson(const nlohmann::json& j);

/// Reads and parses the file at `path`.
/// @throws solvers::io::InputError whose message starts with the path ("x.json: cannot open file").
SceneDocument loadDocument(const std::string& path);

/// A fresh sheet (File > New, and what a person gets when the document asked for cannot be
/// opened): the ground grid and one vertical plane facing the default view, nothing drawn yet.
SceneDocument freshDocument();

}  // namespace sculptline::model
