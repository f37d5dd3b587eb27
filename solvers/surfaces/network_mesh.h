#pragma once
// Curve networks → triangle meshes (seed 004 §4, "Surface Generation"): closed loops of curves are
// filled by topological triangulation, with boundary normals interpolated by SLERP between corner
// frames and interior vertices placed by tangent-plane fairing.
#include "solvers/bspline/bspline_curve.h"

#include <Eigen/Core>
#include <vector>

namespace sculptline::solvers::surfaces {

struct NetworkOptions {
    /// Target boundary edge length (model units); <= 0 means the curves' total length / (16 × curves).
    double edgeLength = 0.0;
    /// Curve ends closer than this (model units) are one corner; <= 0 means 1e-4 × the network's size
    /// (as kDefaultMeetRelative for fill).
    double meetTolerance = 0.0;
    /// Fairing passes over all interior vertices, the first made while triangulating (seed 004:
    /// "further iterations reduce the noise").
    int fairingIterations = 3;
    /// Largest move of a vertex in one fairing step, as a multiple of its mean distance to its ring
    /// neighbours (seed 004's damping of outliers, "a user-defined parameter").
    double damping = 2.0;
};

struct NetworkMesh {
    std::vector<Eigen::Vector3d> vertices;
    std::vector<Eigen::Vector3d> normals;  ///< unit, one per vertex
    std::vector<Eigen::Vector3i> triangles;  ///< counter-clockwise seen from the normal side
    int boundaryVertexCount = 0;  ///< vertices [0, boundaryVertexCount) lie on the curves
};

/// Meshes every loop. A loop lists curve indices that chain end to end (any orientation; the
/// first curve's direction orients the loop, and so its normals: counter-clockwise seen from the
/// normal side). Curves shared by loops share their boundary vertices, so adjacent patches join.
/// Topological triangulation (seed 004 Fig. 4): each pass puts a new vertex at every other vertex
/// of the current ring (initially at the centroid of its three ring neighbours and the loop's
/// centroid), joins consecutive new vertices, and makes them the next ring, halving it, until at
/// most kFanRing vertices remain; a fan closes the hole. Fairing: each new vertex moves along its
/// normal (the normalized mean of its ring neighbours' normals) to the median of the intersections
/// of that line with the neighbours' tangent planes, damped.
/// @throws GeometryError "loops[k]: ..." when a loop's curves do not chain into a closed loop, and
///         "curves[i]: ..." for an index out of range.
NetworkMesh meshNetwork(const std::vector<Curve3d>& curves, const std::vector<std::vector<int>>& loops,
                        const NetworkOptions& options = {});

/// Rings of at most this many vertices are closed by a fan (seed 004 used 10 segments; 6 keeps the
/// fan centre's neighbours close enough for the fairing estimate on curved patches).
constexpr int kFanRing = 6;

}  // namespace sculptline::solvers::surfaces
