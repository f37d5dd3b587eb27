#pragma once
// The Coin node of a solid entity (model/model.h, EntityKind::Solid): its level-set mesh in a
// material of its own, so that a solid reads apart from the surfaces it was made from.
#include "solvers/volume/surface_mesh.h"
#include "scene/geometry_nodes.h"

class SoSeparator;

namespace sculptline::scene {

/// A warm clay colour: far in hue from the surfaces' blue (geometry_nodes.h), the planes and the
/// state colours (state_colors.h), and the colour of a printed part people expect.
SurfaceStyle solidStyle();

/// Area-weighted vertex normals of a triangle mesh (unit; zero where a vertex has no area).
std::vector<Eigen::Vector3d> vertexNormals(const solvers::volume::TriangleMesh& mesh);

/// makeMeshNode() of the solid's mesh with vertexNormals() and solidStyle(). Reference count 0.
SoSeparator* makeSolidNode(const solvers::volume::TriangleMesh& mesh);

}  // namespace sculptline::scene
