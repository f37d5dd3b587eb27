#pragma once
// CAD exchange: STEP AP214 and IGES 5.3 with the exact B-spline geometry (through OpenCASCADE),
// binary STL and Wavefront OBJ at the kernel's tessellation. This header names no OpenCASCADE type,
// so that Qt code can include it (OCCT's headers stay in this target's sources).
#include "solvers/bspline/bspline_surface.h"

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace sculptline::solvers::exchange {

/// A triangle mesh as in ../shared/interfaces.md ("Mesh"): indices into vertices, counter-clockwise
/// seen from the outside.
struct TriangleMesh {
    std::vector<Eigen::Vector3d> vertices;
    std::vector<Eigen::Vector3i> triangles;
};

/// What one file holds.
struct ExchangeContent {
    std::vector<Curve3d> curves;
    std::vector<Surface3d> surfaces;
    std::vector<TriangleMesh> meshes;
    bool empty() const { return curves.empty() && surfaces.empty() && meshes.empty(); }
};

enum class Format { Step, Iges, Stl, Obj };

/// "step", "iges", "stl", "obj" (lower case, as in interfaces.md); nullopt for anything else.
std::optional<Format> formatFromName(const std::string& name);
const char* formatName(Format format);

/// Content a format cannot carry, or a file that cannot be written. what() is one line that starts
/// with the field it concerns ("path: ...", "meshes: ...", "surfaces[2]: ...").
class ExchangeError : public std::runtime_error {
public:
    explicit ExchangeError(const std::string& what) : std::runtime_error(what) {}
};

/// Checks that `format` can carry `content` (throws ExchangeError naming the field otherwise):
/// - STEP and IGES carry curves and surfaces exactly (B_SPLINE_CURVE_WITH_KNOTS / IGES 126 and
///   their surface forms, rational or not); they refuse meshes.
/// - STL carries triangles only: surfaces (tessellated) and meshes; curves are refused when nothing
///   else is given and skipped otherwise (a sketch's curves beside its surfaces).
/// - OBJ carries surfaces and meshes as faces and curves as polylines ("l").
/// Empty content is refused by every format.
void checkContent(const ExchangeContent& content, Format format);

/// The file's bytes. STEP/IGES: model units written as millimetres (interfaces.md). STL/OBJ:
/// surfaces at tessellate()'s default tolerances (solvers/bspline/tessellation.h), curves (OBJ)
/// likewise. @throws ExchangeError as checkContent, or when OpenCASCADE refuses the geometry.
std::string encode(const ExchangeContent& content, Format format);

/// encode() written to `path` (created or replaced). Returns the number of bytes written.
/// @throws ExchangeError "path: ..." when the path is empty, a directory, or cannot be written.
std::uintmax_t writeFile(const ExchangeContent& content, Format format, const std::string& path);

}  // namespace sculptline::solvers::exchange
