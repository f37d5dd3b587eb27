// The default scene graph (scene/default_scene.h) built without a window: SoDB::init and Coin
// actions only.
#include "scene/default_scene.h"

#include "scene/eigen_coin.h"
#include "solvers/bspline/tessellation.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoNormal.h>
#include <Inventor/nodes/SoNurbsCurve.h>
#include <Inventor/nodes/SoNurbsSurface.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <string>

namespace sculptline::scene {
namespace {

const std::string kDefaultScene = std::string(SCULPTLINE_DATA_DIR) + "/default_scene.json";
/// Bounding boxes are computed in float by Coin: a few ulps at 100 mm.
constexpr float kBoxTolerance = 1e-3f;

class DefaultScene : public testing::Test {
protected:
    void SetUp() override
    {
        SoDB::init();
        doc_ = model::loadDocument(kDefaultScene);
        root_ = buildSceneGraph(doc_);
        refCountAtReturn_ = root_->getRefCount();
        root_->ref();
    }
    void TearDown() override { root_->unref(); }

    /// All paths to nodes of `type` under the node named `under` (the whole scene when empty).
    SoPathList find(SoType type, const char* under = nullptr) const
    {
        SoNode* start = under ? SoNode::getByName(under) : root_;
        SoSearchAction search;
        search.setType(type);
        search.setInterest(SoSearchAction::ALL);
        search.apply(start);
        return search.getPaths();
    }

    SbBox3f boundsOf(const SoPath* path) const
    {
        SoGetBoundingBoxAction bbox(SbViewportRegion(800, 600));
        bbox.apply(const_cast<SoPath*>(path));
        return bbox.getBoundingBox();
    }

    model::SceneDocument doc_;
    SoSeparator* root_ = nullptr;
    int refCountAtReturn_ = -1;
};

TEST_F(DefaultScene, IsReturnedUnreferenced)
{
    // Coin's convention for a new node: the caller decides who owns it.
    EXPECT_EQ(refCountAtReturn_, 0);
}

TEST_F(DefaultScene, CurvesAreLineSetsAndSurfacesAreIndexedFaceSets)
{
    EXPECT_EQ(find(SoLineSet::getClassTypeId(), "Curves").getLength(), 1);
    EXPECT_EQ(find(SoIndexedFaceSet::getClassTypeId(), "Surfaces").getLength(), 1);
    // Drawn from the kernel's tessellation, not through GLU
    EXPECT_EQ(find(SoNurbsCurve::getClassTypeId()).getLength(), 0);
    EXPECT_EQ(find(SoNurbsSurface::getClassTypeId()).getLength(), 0);
    EXPECT_NE(SoNode::getByName("GroundGrid"), nullptr);
    EXPECT_NE(SoNode::getByName("Plane0"), nullptr);
}

TEST_F(DefaultScene, CurveVerticesAreTheKernelTessellation)
{
    const SoPathList coords = find(SoCoordinate3::getClassTypeId(), "Curve0");
    ASSERT_EQ(coords.getLength(), 1);
    const auto* node = static_cast<SoCoordinate3*>(coords[0]->getTail());
    const solvers::Polyline line = solvers::tessellate(doc_.curves[0]);
    ASSERT_EQ(node->point.getNum(), static_cast<int>(line.points.size()));
    for (int i = 0; i < node->point.getNum(); ++i) {
        EXPECT_LT((toEigen(node->point[i]) - line.points[i]).norm(), 1e-4);  // float storage
    }
    const auto* lines = static_cast<SoLineSet*>(find(SoLineSet::getClassTypeId(), "Curve0")[0]->getTail());
    EXPECT_EQ(lines->numVertices[0], node->point.getNum());
}

TEST_F(DefaultScene, SurfaceMeshIsConsistent)
{
    const auto* coords = static_cast<SoCoordinate3*>(find(SoCoordinate3::getClassTypeId(), "Surface0")[0]->getTail());
    const auto* normals = static_cast<SoNormal*>(find(SoNormal::getClassTypeId(), "Surface0")[0]->getTail());
    const auto* faces = static_cast<SoIndexedFaceSet*>(find(SoIndexedFaceSet::getClassTypeId(), "Surface0")[0]->getTail());
    const solvers::GridMesh mesh = solvers::tessellate(doc_.surfaces[0]);
    EXPECT_EQ(coords->point.getNum(), static_cast<int>(mesh.vertices.size()));
    EXPECT_EQ(normals->vector.getNum(), coords->point.getNum());
    ASSERT_EQ(faces->coordIndex.getNum(), static_cast<int>(4 * mesh.triangles.size()));
    for (int i = 0; i < faces->coordIndex.getNum(); ++i) {
        const int32_t index = faces->coordIndex[i];
        if (i % 4 == 3) {
            EXPECT_EQ(index, SO_END_FACE_INDEX);
        } else {
            EXPECT_GE(index, 0);
            EXPECT_LT(index, coords->point.getNum());
        }
    }
}

TEST_F(DefaultScene, BoundsAreTheGridThePlaneAndTheGeometry)
{
    // Given the default document: a 200 mm grid centred on the origin at z = 0, and a 120 mm plane
    // centred at z = 60 (its top edge at z = 120) above everything else.
    SoGetBoundingBoxAction bbox(SbViewportRegion(800, 600));
    bbox.apply(root_);
    const SbBox3f box = bbox.getBoundingBox();
    EXPECT_NEAR(box.getMin()[0], -100.0f, kBoxTolerance);
    EXPECT_NEAR(box.getMin()[1], -100.0f, kBoxTolerance);
    EXPECT_NEAR(box.getMin()[2], 0.0f, kBoxTolerance);
    EXPECT_NEAR(box.getMax()[0], 100.0f, kBoxTolerance);
    EXPECT_NEAR(box.getMax()[1], 100.0f, kBoxTolerance);
    EXPECT_NEAR(box.getMax()[2], 120.0f, kBoxTolerance);

    // The plane alone: 120 x 120 in x and z, flat in y at 95
    SoSearchAction search;
    search.setName("Plane0");
    search.apply(root_);
    ASSERT_NE(search.getPath(), nullptr);
    const SbBox3f plane = boundsOf(search.getPath());
    EXPECT_NEAR(plane.getMin()[0], -60.0f, kBoxTolerance);
    EXPECT_NEAR(plane.getMax()[0], 60.0f, kBoxTolerance);
    EXPECT_NEAR(plane.getMin()[1], 95.0f, kBoxTolerance);
    EXPECT_NEAR(plane.getMax()[1], 95.0f, kBoxTolerance);
    EXPECT_NEAR(plane.getMin()[2], 0.0f, kBoxTolerance);
    EXPECT_NEAR(plane.getMax()[2], 120.0f, kBoxTolerance);
}

TEST_F(DefaultScene, GeometryLiesInsideItsControlHull)
{
    // A B-spline lies in the convex hull of its control points (The NURBS Book, P2.x / P3.x),
    // so the drawn geometry must lie inside the control points' bounding box.
    for (const char* name : {"Curve0", "Surface0"}) {
        SoSearchAction search;
        search.setName(name);
        search.apply(root_);
        ASSERT_NE(search.getPath(), nullptr) << name;
        const SbBox3f drawn = boundsOf(search.getPath());
        SbBox3f hull;
        const auto& points = std::string(name) == "Curve0" ? doc_.curves[0].points() : doc_.surfaces[0].points();
        for (const auto& p : points) hull.extendBy(toSb(p));
        for (int k = 0; k < 3; ++k) {
            EXPECT_GE(drawn.getMin()[k], hull.getMin()[k] - kBoxTolerance) << name;
            EXPECT_LE(drawn.getMax()[k], hull.getMax()[k] + kBoxTolerance) << name;
        }
        EXPECT_GT((drawn.getMax() - drawn.getMin()).length(), 100.0f) << name << " is not degenerate";
    }
}

TEST_F(DefaultScene, PlaneFactoryReplacesStaticPlanes)
{
    // Given a factory (the ui passes one that wraps planes in draggers)
    int calls = 0;
    SoSeparator* graph = buildSceneGraph(doc_, [&calls](const model::PlaneSpec&, size_t) -> SoNode* {
        ++calls;
        return new SoSeparator;
    });
    graph->ref();
    // Then it is asked once per plane and its node is what the graph holds
    EXPECT_EQ(calls, 1);
    SoSearchAction search;
    search.setName("Plane0");
    search.apply(graph);
    ASSERT_NE(search.getPath(), nullptr);
    EXPECT_EQ(search.getPath()->getTail()->getTypeId(), SoSeparator::getClassTypeId());
    EXPECT_EQ(static_cast<SoGroup*>(search.getPath()->getTail())->getNumChildren(), 0);
    graph->unref();
}

}  // namespace
}  // namespace sculptline::scene
