#pragma once
// Coin nodes for the kernel's geometry, drawn from the kernel's own tessellation
// (solvers/bspline/tessellation.h) rather than SoNurbs*: the same polyline and mesh the tests check,
// and SoIndexedFaceSet takes Coin's vertex-array fast path (../shared/NOTES.md).
#include "solvers/bspline/bspline_surface.h"
#include "solvers/bspline/tessellation.h"

#include <Inventor/SbColor.h>

class SoCoordinate3;
class SoNormal;
class SoSeparator;

namespace sculptline::scene {

struct CurveStyle {
    SbColor color{1.0f, 0.5f, 0.1f};
    float lineWidth = 3.0f;  ///< pixels
};

struct SurfaceStyle {
    SbColor color{0.35f, 0.62f, 0.9f};
    float shininess = 0.4f;  ///< Coin's [0, 1]
};

/// SoSeparator { SoLightModel(BASE_COLOR) SoBaseColor SoDrawStyle SoCoordinate3 SoLineSet }.
/// Lines carry no normals, so they are drawn unlit in their colour. Returned with reference count
/// 0: the caller adds it to a graph or ref()s it.
SoSeparator* makeCurveNode(const solvers::Curve3d& curve, const CurveStyle& style = {});

/// SoSeparator { SoMaterial SoShapeHints SoCoordinate3 SoNormal SoNormalBinding SoIndexedFaceSet }
/// with the kernel's per-vertex normals; both sides lit. Reference count 0, as above.
SoSeparator* makeSurfaceNode(const solvers::Surface3d& surface, const SurfaceStyle& style = {});
/// The vertex and normal nodes of a surface node, for changing its shape in place (same grid, same
/// indices: a drag) without rebuilding it.
struct SurfaceNodeFields {
    SoCoordinate3* coordinates = nullptr;
    SoNormal* normals = nullptr;
};
/// The same from a mesh of `surface` already made (solvers::tessellate or solvers::meshOnGrid);
/// `fields`, when given, receives its vertex and normal nodes.
SoSeparator* makeSurfaceNode(const solvers::Surface3d& surface, const solvers::GridMesh& mesh, const SurfaceStyle& style = {},
                             SurfaceNodeFields* fields = nullptr);
/// A shaded triangle mesh (per-vertex normals, counter-clockwise triangles): the faces of a surface
/// node without its iso-lines, or a curve network's mesh.
SoSeparator* makeMeshNode(const std::vector<Eigen::Vector3d>& vertices, const std::vector<Eigen::Vector3d>& normals,
                          const std::vector<Eigen::Vector3i>& triangles, const SurfaceStyle& style = {},
                          SurfaceNodeFields* fields = nullptr);

/// The same looks drawn by Coin's own NURBS nodes (SoNurbsCurve / SoNurbsSurface, tessellated by
/// GLU at render time), for measuring the kernel-tessellation path against them (issue 5 §4).
/// Reference count 0.
SoSeparator* makeNurbsCurveNode(const solvers::Curve3d& curve, const CurveStyle& style = {});
SoSeparator* makeNurbsSurfaceNode(const solvers::Surface3d& surface, const SurfaceStyle& style = {});

}  // namespace sculptline::scene
