#pragma once
// Binary STL and Wavefront OBJ of tessellated surfaces, meshes and (OBJ) curve polylines.
#include "solvers/exchange/exchange.h"

namespace sculptline::solvers::exchange {

/// Size of a binary STL header and of one facet record (12 little-endian floats and a 16-bit
/// attribute count), bytes (the format as 3D Systems defined it; no other layout exists).
constexpr std::size_t kStlHeaderBytes = 80;
constexpr std::size_t kStlFacetBytes = 50;

/// Binary STL: the 80-byte header, the facet count (uint32), then per triangle its unit normal and
/// three vertices as float32. Surfaces at tessellate()'s grid (triangle count = its triangles),
/// then meshes; curves are not written. A facet's normal is its own (right-hand rule); a
/// zero-area facet of a surface takes the mean of its vertices' surface normals, one of a mesh
/// the zero vector (the format's "compute it yourself").
std::string encodeStl(const ExchangeContent& content);

/// OBJ: per object ("o curve_0", "o surface_0", "o mesh_0") its vertices ("v", 17 significant
/// digits), surfaces with their unit normals ("vn", faces "f a//a b//b c//c"), meshes as "f a b c",
/// curves as one polyline "l" through tessellate()'s points.
std::string encodeObj(const ExchangeContent& content);

}  // namespace sculptline::solvers::exchange
