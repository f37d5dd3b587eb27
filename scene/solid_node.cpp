#include "scene/solid_node.h"

#include <Eigen/Geometry>
#include <Inventor/nodes/SoPolygonOffset.h>
#include <Inventor/nodes/SoSeparator.h>

namespace sculptline::scene {

SurfaceStyle solidStyle()
{
    SurfaceStyle style;
    style.color = SbColor(0.82f, 0.50f, 0.30f);
    style.shininess = 0.2f;  // matte, as a printed part
    return style;
}

std::vector<Eigen::Vector3d> vertexNormals(const solvers::volume::TriangleMesh& mesh)
{
    std::vector<Eigen::Vector3d> normals(mesh.vertices.size(), Eigen::Vector3d::Zero());
    for (const Eigen::Vector3i& t : mesh.triangles) {
        // The cross product's length is twice the area: the sum weighs each face by its area.
        const Eigen::Vector3d n = (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
        for (int c = 0; c < 3; ++c) normals[t[c]] += n;
    }
    for (Eigen::Vector3d& n : normals) {
        const double length = n.norm();
        n = length > 0.0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
    }
    return normals;
}

SoSeparator* makeSolidNode(const solvers::volume::TriangleMesh& mesh)
{
    SoSeparator* node = makeMeshNode(mesh.vertices, vertexNormals(mesh), mesh.triangles, solidStyle());
    // A closed solid lies on its source surfaces to within a voxel: without an offset the two depth-
    // fight and the surfaces' blue covers most of the solid. Pulled one depth unit toward the eye, the
    // solid is what shows where they coincide; a shell (offset ± t/2) covers its surface anyway.
    auto* offset = new SoPolygonOffset;
    offset->factor = -1.0f;
    offset->units = -1.0f;
    node->insertChild(offset, 0);
    return node;
}

}  // namespace sculptline::scene
