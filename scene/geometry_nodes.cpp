#include "scene/geometry_nodes.h"

#include "scene/eigen_coin.h"
#include "solvers/bspline/tessellation.h"

#include <Inventor/actions/SoAction.h>
#include <Inventor/elements/SoCoordinateElement.h>
#include <Inventor/misc/SoState.h>
#include <Inventor/nodes/SoBaseColor.h>
#include <Inventor/nodes/SoSubNode.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoCoordinate4.h>
#include <Inventor/nodes/SoNurbsCurve.h>
#include <Inventor/nodes/SoNurbsSurface.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoIndexedLineSet.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoNormal.h>
#include <Inventor/nodes/SoNormalBinding.h>
#include <Inventor/nodes/SoPolygonOffset.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShapeHints.h>

#include <algorithm>
#include <vector>

namespace sculptline::scene {
namespace detail {

/// The faces of a live surface node. Its bounding box is the box of the coordinates in the state:
/// every vertex of a grid mesh belongs to a face, so it is the box SoIndexedFaceSet computes by
/// visiting its 4 indices per triangle (256,000 for the 18x135 net's 61x529 grid), at an eighth of
/// the visits. The viewer computes the scene's box for its clipping planes at every frame, and a
/// surface redrawn in place during a drag invalidates its cached box at every event.
class SurfaceFaceSet : public SoIndexedFaceSet {
    SO_NODE_HEADER(SurfaceFaceSet);

public:
    static void initClass() { SO_NODE_INIT_CLASS(SurfaceFaceSet, SoIndexedFaceSet, "IndexedFaceSet"); }
    SurfaceFaceSet() { SO_NODE_CONSTRUCTOR(SurfaceFaceSet); }

    void computeBBox(SoAction* action, SbBox3f& box, SbVec3f& center) override
    {
        const SoCoordinateElement* coords = SoCoordinateElement::getInstance(action->getState());
        if (vertexProperty.getValue() || coordIndex.getNum() == 0 || !coords->is3D() || coords->getNum() == 0) {
            SoIndexedFaceSet::computeBBox(action, box, center);
            return;
        }
        const SbVec3f* p = coords->getArrayPtr3();
        SbVec3f lo = p[0], hi = p[0];
        for (int i = 1; i < coords->getNum(); ++i) {
            for (int k = 0; k < 3; ++k) {
                lo[k] = std::min(lo[k], p[i][k]);
                hi[k] = std::max(hi[k], p[i][k]);
            }
        }
        box.setBounds(lo, hi);
        center = box.getCenter();
    }

private:
    ~SurfaceFaceSet() override = default;
};

SO_NODE_SOURCE(SurfaceFaceSet)

}  // namespace detail

namespace {


/// Iso-lines darken the surface colour by this factor: visible on it, clearly part of it.
constexpr float kIsoLineShade = 0.55f;

bool isKnot(const solvers::KnotVector& knots, double t)
{
    return std::find(knots.begin(), knots.end(), t) != knots.end();
}

/// The grid lines of `mesh` at knot values: the patch boundaries and the knot spans a designer
/// reads the surface's structure from. Tessellation parameters hit knots exactly (they start at
/// the span breaks), so exact comparison is right here.
SoSeparator* makeIsoLines(const solvers::Surface3d& surface, const solvers::GridMesh& mesh, const SbColor& color)
{
    std::vector<int32_t> index;
    const int rows = mesh.rows(), cols = mesh.cols();
    for (int r = 0; r < rows; ++r) {
        if (!isKnot(surface.knotsU(), mesh.u[r])) continue;
        for (int c = 0; c < cols; ++c) index.push_back(r * cols + c);
        index.push_back(SO_END_LINE_INDEX);
    }
    for (int c = 0; c < cols; ++c) {
        if (!isKnot(surface.knotsV(), mesh.v[c])) continue;
        for (int r = 0; r < rows; ++r) index.push_back(r * cols + c);
        index.push_back(SO_END_LINE_INDEX);
    }
    auto* lines = new SoSeparator;
    auto* lightModel = new SoLightModel;
    lightModel->model = SoLightModel::BASE_COLOR;
    lines->addChild(lightModel);
    auto* base = new SoBaseColor;
    base->rgb = color * kIsoLineShade;
    lines->addChild(base);
    auto* set = new SoIndexedLineSet;
    set->coordIndex.setValues(0, static_cast<int>(index.size()), index.data());
    lines->addChild(set);
    return lines;
}

}  // namespace

namespace {

// A separator with the curve's colour and width, unlit: a curve has no normal to shade with.
SoSeparator* curveRoot(const CurveStyle& style)
{
    auto* root = new SoSeparator;
    auto* lightModel = new SoLightModel;
    lightModel->model = SoLightModel::BASE_COLOR;
    root->addChild(lightModel);
    auto* color = new SoBaseColor;
    color->rgb = style.color;
    root->addChild(color);
    auto* drawStyle = new SoDrawStyle;
    drawStyle->lineWidth = style.lineWidth;
    root->addChild(drawStyle);
    return root;
}

// A separator with the surface material and two-sided lighting: UNKNOWN_SHAPE_TYPE makes Coin light
// both sides, since an open patch shows its back to the camera.
SoSeparator* surfaceRoot(const SurfaceStyle& style)
{
    auto* root = new SoSeparator;
    auto* material = new SoMaterial;
    material->diffuseColor = style.color;
    material->ambientColor = style.color * 0.3f;
    material->specularColor = SbColor(0.35f, 0.35f, 0.35f);
    material->shininess = style.shininess;
    root->addChild(material);
    auto* hints = new SoShapeHints;
    hints->vertexOrdering = SoShapeHints::COUNTERCLOCKWISE;
    hints->shapeType = SoShapeHints::UNKNOWN_SHAPE_TYPE;
    root->addChild(hints);
    return root;
}

}  // namespace

SoSeparator* makeCurveNode(const solvers::Curve3d& curve, const CurveStyle& style)
{
    const solvers::Polyline line = solvers::tessellate(curve);

    SoSeparator* root = curveRoot(style);
    auto* coords = new SoCoordinate3;
    setPoints(coords->point, line.points);
    root->addChild(coords);
    auto* lines = new SoLineSet;
    lines->numVertices.setValue(static_cast<int32_t>(line.points.size()));
    root->addChild(lines);
    return root;
}


SoSeparator* makeSurfaceNode(const solvers::Surface3d& surface, const SurfaceStyle& style)
{
    return makeSurfaceNode(surface, solvers::tessellate(surface), style);
}

SoSeparator* makeSurfaceNode(const solvers::Surface3d& surface, const solvers::GridMesh& mesh, const SurfaceStyle& style,
                             SurfaceNodeFields* fields)
{
    SoSeparator* root = makeMeshNode(mesh.vertices, mesh.normals, mesh.triangles, style, fields);
    root->addChild(makeIsoLines(surface, mesh, style.color));
    return root;
}

SoSeparator* makeMeshNode(const std::vector<Eigen::Vector3d>& vertices, const std::vector<Eigen::Vector3d>& normals,
                          const std::vector<Eigen::Vector3i>& triangles, const SurfaceStyle& style,
                          SurfaceNodeFields* fields)
{
    SoSeparator* root = surfaceRoot(style);
    auto* coords = new SoCoordinate3;
    setPoints(coords->point, vertices);
    root->addChild(coords);
    auto* normalNode = new SoNormal;
    setPoints(normalNode->vector, normals);
    root->addChild(normalNode);
    auto* binding = new SoNormalBinding;
    // With normalIndex left at its default, PER_VERTEX_INDEXED reuses coordIndex for the normals.
    binding->value = SoNormalBinding::PER_VERTEX_INDEXED;
    root->addChild(binding);
    // Pushes the faces back in depth so the iso-lines drawn on them are not half hidden.
    root->addChild(new SoPolygonOffset);
    // A live node (fields wanted: its vertices will be rewritten in place) takes the face set whose
    // box costs one visit per vertex; exported and other nodes stay plain SoIndexedFaceSets.
    using detail::SurfaceFaceSet;
    if (fields && SurfaceFaceSet::getClassTypeId() == SoType::badType()) SurfaceFaceSet::initClass();
    SoIndexedFaceSet* faces = fields ? new SurfaceFaceSet : new SoIndexedFaceSet;
    faces->coordIndex.setNum(static_cast<int>(triangles.size() * 4));
    int32_t* index = faces->coordIndex.startEditing();
    for (const Eigen::Vector3i& t : triangles) {
        *index++ = t[0];
        *index++ = t[1];
        *index++ = t[2];
        *index++ = SO_END_FACE_INDEX;
    }
    faces->coordIndex.finishEditing();
    root->addChild(faces);
    if (fields) *fields = {coords, normalNode};
    return root;
}

namespace {

/// Control points as SoCoordinate4 (homogeneous, w = weight), which SoNurbs* read when rational.
SoCoordinate4* homogeneous(const std::vector<Eigen::Vector3d>& points, const std::vector<double>& weights)
{
    auto* coords = new SoCoordinate4;
    coords->point.setNum(static_cast<int>(points.size()));
    SbVec4f* out = coords->point.startEditing();
    for (size_t i = 0; i < points.size(); ++i) {
        const float w = weights.empty() ? 1.0f : static_cast<float>(weights[i]);
        const SbVec3f p = toSb(points[i]);
        out[i] = SbVec4f(p[0] * w, p[1] * w, p[2] * w, w);
    }
    coords->point.finishEditing();
    return coords;
}

void setKnots(SoMFFloat& field, const std::vector<double>& knots)
{
    field.setNum(static_cast<int>(knots.size()));
    float* out = field.startEditing();
    for (size_t i = 0; i < knots.size(); ++i) out[i] = static_cast<float>(knots[i]);
    field.finishEditing();
}

}  // namespace

SoSeparator* makeNurbsCurveNode(const solvers::Curve3d& curve, const CurveStyle& style)
{
    SoSeparator* root = curveRoot(style);
    root->addChild(homogeneous(curve.points(), curve.weights()));
    auto* nurbs = new SoNurbsCurve;
    nurbs->numControlPoints = curve.pointCount();
    setKnots(nurbs->knotVector, curve.knots());
    root->addChild(nurbs);
    return root;
}

SoSeparator* makeNurbsSurfaceNode(const solvers::Surface3d& surface, const SurfaceStyle& style)
{
    SoSeparator* root = surfaceRoot(style);
    // SoNurbsSurface: point (u, v) at index v * numUControlPoints + u; the model's is i * countV + j.
    std::vector<Eigen::Vector3d> points;
    std::vector<double> weights;
    for (int j = 0; j < surface.countV(); ++j) {
        for (int i = 0; i < surface.countU(); ++i) {
            points.push_back(surface.points()[i * surface.countV() + j]);
            if (surface.isRational()) weights.push_back(surface.weights()[i * surface.countV() + j]);
        }
    }
    root->addChild(homogeneous(points, weights));
    auto* nurbs = new SoNurbsSurface;
    nurbs->numUControlPoints = surface.countU();
    nurbs->numVControlPoints = surface.countV();
    setKnots(nurbs->uKnotVector, surface.knotsU());
    setKnots(nurbs->vKnotVector, surface.knotsV());
    root->addChild(nurbs);
    return root;
}

}  // namespace sculptline::scene
