// Surface analysis display (scene/surface_analysis_display.h) on the model view's surface nodes,
// headless: the curvature colours are the diverging map of K or H at each vertex's parameters, the
// zebra's texture coordinates are the reflected eye ray's elevation, both follow geometry changes
// (in-place drag updates and rebuilds) and the zebra follows the camera.
#include "model/model.h"
#include "scene/model_view.h"
#include "scene/surface_analysis_display.h"
#include "solvers/bspline/surface_curvature.h"
#include "solvers/math_constants.h"

#include <Inventor/SoDB.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoNormal.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoTextureCoordinate2.h>
#include <Inventor/sensors/SoSensorManager.h>
#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace sculptline::scene {
namespace {

/// Colours are stored as floats: 1e-6 is float rounding of a value in [0, 1], far below one step
/// of an 8-bit display channel (1/255).
constexpr float kColourTolerance = 1e-6f;
/// Texture coordinates are floats of magnitude up to kMaxZebraStripes: a few float ulps.
constexpr float kCoordinateTolerance = 1e-4f;

solvers::Curve3d cubic(std::initializer_list<Eigen::Vector3d> points)
{
    return solvers::Curve3d(3, {0, 0, 0, 0, 1, 1, 1, 1}, std::vector<Eigen::Vector3d>(points));
}

model::PlaneFrame verticalFrame(const Eigen::Vector3d& origin)
{
    return model::PlaneFrame::fromNormal(origin, -Eigen::Vector3d::UnitY(), 200.0, Eigen::Vector3d::UnitX());
}

/// A bottle-like revolved surface: a profile with a bulge and a neck (K changes sign) about an axis.
struct Bottle {
    model::Model model;
    model::EntityId plane = 0, profile = 0, axis = 0, surface = 0;
    Bottle()
    {
        plane = model.addPlane(verticalFrame(Eigen::Vector3d(0, 0, 50)));
        profile = model.addCurve(plane, cubic({{20, -40, 0}, {35, -10, 0}, {10, 10, 0}, {12, 40, 0}}));
        axis = model.addCurve(plane, cubic({{0, -45, 0}, {0, -15, 0}, {0, 15, 0}, {0, 45, 0}}));
        model::SurfaceRecipe revolve;
        revolve.mode = model::Construction::Revolve;
        surface = model.addSurface({profile, axis}, revolve);
    }
};

template <typename Node>
Node* find(SoNode* root, const char* under = nullptr)
{
    SoSearchAction search;
    if (under) search.setName(under);
    else search.setType(Node::getClassTypeId());
    search.setInterest(SoSearchAction::FIRST);
    search.apply(root);
    if (!search.getPath()) return nullptr;
    if (!under) return static_cast<Node*>(search.getPath()->getTail());
    SoSearchAction inner;
    inner.setType(Node::getClassTypeId());
    inner.apply(search.getPath()->getTail());
    return inner.getPath() ? static_cast<Node*>(inner.getPath()->getTail()) : nullptr;
}

/// Checks every vertex colour of surface `id` against the colour map of K or H at its parameters.
void expectCurvatureColours(const ModelView& view, ModelView& mutableView, const model::Entity& e, bool gaussian)
{
    SurfaceAnalysisDisplay& analysis = mutableView.surfaceAnalysis();
    auto* material = find<SoMaterial>(view.nodeOf(e.id), "SurfaceAnalysis");
    ASSERT_NE(material, nullptr);
    const std::vector<double>& u = *analysis.gridU(e.id);
    const std::vector<double>& v = *analysis.gridV(e.id);
    const CurvatureLegend& legend = *analysis.legend(e.id);
    ASSERT_EQ(material->diffuseColor.getNum(), static_cast<int>(u.size() * v.size()));
    std::vector<double> defined;
    int checked = 0;
    for (size_t r = 0; r < u.size(); ++r)
        for (size_t c = 0; c < v.size(); ++c) {
            const solvers::SurfaceCurvature k = solvers::surfaceCurvature(*e.surface, u[r], v[c]);
            if (!k.defined) continue;
            const double value = gaussian ? k.gaussian : k.mean;
            defined.push_back(value);
            const SbColor expected = divergingColor(value / legend.range);
            const SbColor drawn = material->diffuseColor[static_cast<int>(r * v.size() + c)];
            for (int ch = 0; ch < 3; ++ch) ASSERT_NEAR(drawn[ch], expected[ch], kColourTolerance) << r << " " << c;
            ++checked;
        }
    EXPECT_GT(checked, static_cast<int>(u.size() * v.size()) / 2);
    EXPECT_DOUBLE_EQ(legend.range, robustRange(defined));
}

}  // namespace

TEST(SurfaceAnalysis, DivergingMapIsBlueWhiteRedAndClamps)
{
    EXPECT_EQ(divergingColor(0.0), SbColor(1, 1, 1));
    EXPECT_EQ(divergingColor(1.0), divergingColor(7.0));
    EXPECT_EQ(divergingColor(-1.0), divergingColor(-3.0));
    const SbColor red = divergingColor(1.0), blue = divergingColor(-1.0);
    EXPECT_GT(red[0], 0.9f);
    EXPECT_LT(red[2], 0.2f);
    EXPECT_GT(blue[2], 0.9f);
    EXPECT_LT(blue[0], 0.2f);
    const SbColor half = divergingColor(0.5);
    EXPECT_NEAR(half[1], (1.0f + red[1]) / 2, kColourTolerance);
}

TEST(SurfaceAnalysis, GivenOneSpike_WhenTheRangeIsTaken_ThenItDoesNotWashTheMapOut)
{
    // 99 values in [-1, 1] and one spike of 1e6: the 95th percentile of |x| stays below 1.
    std::vector<double> values;
    for (int i = 0; i < 99; ++i) values.push_back(std::sin(0.37 * i));
    values.push_back(1e6);
    const double range = robustRange(values);
    EXPECT_LE(range, 1.0);
    EXPECT_GT(range, 0.9);
    EXPECT_EQ(robustRange({}), 0.0);
    EXPECT_EQ(robustRange({NAN, -2.0}), 2.0);
}

TEST(SurfaceAnalysis, GivenAMirrorTiltedByTheta_WhenItsZebraCoordinateIsTaken_ThenTheReflectedRayRisesByTwoTheta)
{
    // An orthographic camera looking down -z with +y up sees a mirror whose normal is tilted by
    // theta from +z towards +y: r = e - 2 (e.n) n = (0, sin 2theta, cos 2theta), elevation 2 theta
    // (the law of reflection), so s = stripes (2 theta / pi + 1/2).
    ZebraView view;
    view.direction = SbVec3f(0, 0, -1);
    view.up = SbVec3f(0, 1, 0);
    view.perspective = false;
    const int stripes = 10;
    for (double theta : {0.0, 0.1, 0.3, -0.5, 0.7}) {
        const SbVec3f n(0, static_cast<float>(std::sin(theta)), static_cast<float>(std::cos(theta)));
        const float expected = static_cast<float>(stripes * (2 * theta / solvers::kPi + 0.5));
        EXPECT_NEAR(zebraCoordinate(SbVec3f(3, 4, 5), n, view, stripes), expected, kCoordinateTolerance) << theta;
        // Either side of the surface reflects alike (two-sided, like its shading)
        EXPECT_NEAR(zebraCoordinate(SbVec3f(3, 4, 5), -n, view, stripes), expected, kCoordinateTolerance) << theta;
    }
    // A tilt sideways (about the view's up axis) keeps the elevation: the stripes run horizontally
    const SbVec3f sideways(static_cast<float>(std::sin(0.4)), 0, static_cast<float>(std::cos(0.4)));
    EXPECT_NEAR(zebraCoordinate(SbVec3f(0, 0, 0), sideways, view, stripes), stripes / 2.0f, kCoordinateTolerance);
}

TEST(SurfaceAnalysis, GivenARevolvedSurface_WhenGaussianThenMean_ThenEachVertexHasTheMapsColourOfItsCurvature)
{
    SoDB::init();
    Bottle b;
    ModelView view(b.model);
    view.setSurfaceDisplay(b.surface, SurfaceDisplay::Gaussian);
    ASSERT_EQ(view.surfaceAnalysis().mode(b.surface), SurfaceDisplay::Gaussian);
    expectCurvatureColours(view, view, *b.model.find(b.surface), true);
    // The bottle's bulge is elliptic (K > 0) and its neck hyperbolic (K < 0): both colours show.
    const CurvatureLegend& legend = *view.surfaceAnalysis().legend(b.surface);
    EXPECT_LT(legend.min, 0.0);
    EXPECT_GT(legend.max, 0.0);
    view.setSurfaceDisplay(b.surface, SurfaceDisplay::Mean);
    expectCurvatureColours(view, view, *b.model.find(b.surface), false);
}

TEST(SurfaceAnalysis, GivenCurvatureColours_WhenThePlaneIsDraggedOrTheProfileReshaped_ThenTheColoursFollow)
{
    SoDB::init();
    Bottle b;
    ModelView view(b.model);
    view.setSurfaceDisplay(0, SurfaceDisplay::Gaussian);  // every surface
    const int before = view.surfaceAnalysis().recolours();
    // When the profile's plane is dragged (an in-place update on the kept grid)
    b.model.beginDrag(b.plane);
    b.model.setPlaneFrame(b.plane, verticalFrame(Eigen::Vector3d(5, 0, 60)));
    b.model.update();
    EXPECT_EQ(view.inPlaceUpdates(), 1);
    EXPECT_EQ(view.surfaceAnalysis().recolours(), before + 1);
    expectCurvatureColours(view, view, *b.model.find(b.surface), true);
    b.model.endDrag();
    view.refineSurfaces();
    // When the profile gets a new shape (a flatter bulge): the colours are those of the new K
    const std::vector<double> oldValues = *view.surfaceAnalysis().values(b.surface);
    b.model.setCurveShape(b.profile, cubic({{20, -40, 0}, {22, -10, 0}, {18, 10, 0}, {12, 40, 0}}));
    b.model.update();
    expectCurvatureColours(view, view, *b.model.find(b.surface), true);
    EXPECT_NE(*view.surfaceAnalysis().values(b.surface), oldValues);
    // And Shaded puts the plain node back
    view.setSurfaceDisplay(0, SurfaceDisplay::Shaded);
    SoSearchAction search;
    search.setName("SurfaceAnalysis");
    search.apply(view.root());
    EXPECT_EQ(search.getPath(), nullptr);
    EXPECT_NE(find<SoIndexedFaceSet>(view.nodeOf(b.surface)), nullptr);
}

TEST(SurfaceAnalysis, GivenZebra_WhenStripesOrCameraChange_ThenTheTextureCoordinatesFollowTheReflectedRay)
{
    SoDB::init();
    Bottle b;
    ModelView view(b.model);
    auto* camera = new SoPerspectiveCamera;
    camera->ref();
    camera->position = SbVec3f(0, -300, 50);
    camera->pointAt(SbVec3f(0, 0, 50), SbVec3f(0, 0, 1));
    view.surfaceAnalysis().setCamera(camera);
    view.setSurfaceDisplay(b.surface, SurfaceDisplay::Zebra);
    auto* coords = find<SoTextureCoordinate2>(view.nodeOf(b.surface), "SurfaceAnalysis");
    ASSERT_NE(coords, nullptr);
    const auto* points = find<SoCoordinate3>(view.nodeOf(b.surface));
    const auto* normals = find<SoNormal>(view.nodeOf(b.surface));
    ASSERT_EQ(coords->point.getNum(), points->point.getNum());
    auto view0 = [&]() {
        ZebraView z;
        z.eye = camera->position.getValue();
        camera->orientation.getValue().multVec(SbVec3f(0, 0, -1), z.direction);
        camera->orientation.getValue().multVec(SbVec3f(0, 1, 0), z.up);
        z.perspective = true;
        return z;
    };
    auto stripeIndices = [&]() {
        std::set<int> seen;
        for (int i = 0; i < coords->point.getNum(); ++i) seen.insert(static_cast<int>(std::floor(coords->point[i][0])));
        return seen.size();
    };
    // Then each vertex's coordinate is the elevation of its reflected eye ray
    for (int i = 0; i < points->point.getNum(); ++i)
        ASSERT_NEAR(coords->point[i][0], zebraCoordinate(points->point[i], normals->vector[i], view0(), kDefaultZebraStripes),
                    kCoordinateTolerance);
    // When the stripes are doubled, the bottle shows twice as many stripe periods: a span L of
    // coordinates meets n in [L, L + 1] integers, 2L meets [2L, 2L + 1], so 2n - 2 <= n' <= 2n + 1
    const size_t periods = stripeIndices();
    EXPECT_GE(periods, 3u);
    view.surfaceAnalysis().setStripes(2 * kDefaultZebraStripes);
    EXPECT_GE(stripeIndices(), 2 * periods - 2);
    EXPECT_LE(stripeIndices(), 2 * periods + 1);
    // When the camera turns (the sensor fires from the delay queue), the stripes move with it
    const float first = coords->point[0][0];
    camera->position = SbVec3f(300, -200, 150);
    camera->pointAt(SbVec3f(0, 0, 50), SbVec3f(0, 0, 1));
    SoDB::getSensorManager()->processDelayQueue(FALSE);
    EXPECT_GE(view.surfaceAnalysis().cameraUpdates(), 1);
    EXPECT_NE(coords->point[0][0], first);
    for (int i = 0; i < points->point.getNum(); ++i)
        ASSERT_NEAR(coords->point[i][0], zebraCoordinate(points->point[i], normals->vector[i], view0(), 2 * kDefaultZebraStripes),
                    kCoordinateTolerance);
    view.surfaceAnalysis().setCamera(nullptr);
    camera->unref();
}

}  // namespace sculptline::scene
