#pragma once
// Triangle meshes of B-spline surfaces for solids: welded tessellations, their boundary edges,
// thickened shells with square edges, and the watertightness and measures of a mesh.
// Plain C++ and Eigen: no OpenVDB here (that is level_set.cpp's business).
#include "solvers/bspline/bspline_surface.h"
#include "solvers/bspline/tessellation.h"

#include <Eigen/Core>
#include <array>
#include <vector>

namespace sculptline::solvers::volume {

/// An indexed triangle mesh; vertex normals optional (empty, or one unit vector per vertex).
struct TriangleMesh {
    std::vector<Eigen::Vector3d> vertices;
    std::vector<Eigen::Vector3i> triangles;
    std::vector<Eigen::Vector3d> normals;
};

/// An edge (a, b) of a triangle, directed as the triangle runs through it.
using Edge = std::array<int, 2>;

/// The tessellation of `surface` (tessellation.h) with a chord tolerance in model units, its
/// coincident vertices merged (a revolve's seam, a collapsed pole) and the triangles that collapse
/// with them dropped. Normals are the surface's, averaged where vertices merged; where the surface
/// has none (a degenerate point), the area-weighted normal of the triangles around the vertex.
/// @param chordTolerance model units, > 0.
/// @param weldTolerance  model units, >= 0: vertices closer than this become one.
/// @param maxVertices    the tessellation's vertex budget (TessellationTolerance::maxVertices).
TriangleMesh surfaceMesh(const Surface3d& surface, double chordTolerance, double weldTolerance,
                         int maxVertices = kMaxTessellationVertices);

/// Merges vertices closer than `tolerance` (a spatial hash with cells of that size), drops
/// triangles with a repeated vertex, averages normals of merged vertices (when present).
TriangleMesh weld(const TriangleMesh& mesh, double tolerance);

/// The edges used by exactly one triangle, directed as that triangle runs through them.
std::vector<Edge> boundaryEdges(const TriangleMesh& mesh);

/// True when every edge of the mesh is shared by exactly two triangles (closed and 2-manifold at
/// its edges). An empty mesh is not watertight.
bool isWatertight(const std::vector<Eigen::Vector3i>& triangles);

/// Sum of the triangle areas, model units².
double area(const TriangleMesh& mesh);

/// Signed volume enclosed by a closed, consistently oriented mesh (divergence theorem; positive when
/// the triangles wind counter-clockwise seen from outside), model units³.
double enclosedVolume(const TriangleMesh& mesh);

/// The solid shell of an open surface mesh, `thickness` thick, as CAD's thicken makes it: the mesh
/// offset by +thickness/2 and -thickness/2 along its vertex normals, closed along every boundary
/// edge by a wall of two triangles running along the normal (square edges, not the rounded rim of a
/// distance field). The result is closed and consistently oriented (outward when the input winds
/// counter-clockwise about its normals).
/// @param mesh      welded, with unit normals (surfaceMesh()).
/// @param thickness model units, > 0.
/// @note Where the surface curves tighter than thickness/2 the offsets cross themselves; the level
///       set conversion tolerates that (MeshToVolume supports self-intersections), the wall shape
///       there is then not CAD's.
TriangleMesh thicken(const TriangleMesh& mesh, double thickness);

/// Axis-aligned bounds of a point set (min, max); both zero for an empty set.
std::pair<Eigen::Vector3d, Eigen::Vector3d> bounds(const std::vector<Eigen::Vector3d>& points);

}  // namespace sculptline::solvers::volume
