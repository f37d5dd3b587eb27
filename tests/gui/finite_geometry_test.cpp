// No NaN or infinity reaches Coin: the model's geometry is checked where the view turns it into
// nodes (ModelView::drawable, model::hasFiniteGeometry), and a plane never takes a non-finite frame.
// Headless (Coin nodes without a window).
#include "model/model.h"
#include "scene/model_view.h"

#include <Inventor/SoDB.h>
#include <gtest/gtest.h>

#include <limits>

namespace sculptline::scene {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

class FiniteGeometry : public ::testing::Test {
protected:
    static void SetUpTestSuite() { SoDB::init(); }
};

TEST_F(FiniteGeometry, EveryKindWithANonFiniteCoordinateIsReported)
{
    // Given one entity of each kind with a finite and a non-finite coordinate
    model::Entity plane;
    plane.kind = model::EntityKind::Plane;
    model::Entity mesh;
    mesh.kind = model::EntityKind::Mesh;
    mesh.mesh = solvers::surfaces::NetworkMesh{};
    mesh.mesh->vertices = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)};
    mesh.mesh->normals.assign(3, Eigen::Vector3d::UnitZ());
    model::Constraint constraint;
    constraint.type = model::ConstraintType::Position;

    // Then the check tells them apart
    EXPECT_TRUE(model::hasFiniteGeometry(plane));
    EXPECT_TRUE(model::hasFiniteGeometry(mesh));
    EXPECT_TRUE(model::hasFiniteGeometry(constraint));
    plane.frame.origin.x() = kNaN;
    mesh.mesh->normals[1].y() = kInf;
    constraint.value.z() = -kInf;
    EXPECT_FALSE(model::hasFiniteGeometry(plane));
    EXPECT_FALSE(model::hasFiniteGeometry(mesh));
    EXPECT_FALSE(model::hasFiniteGeometry(constraint));
}

TEST_F(FiniteGeometry, APlaneAddedWithANaNOriginIsNotDrawnAndItsCurvesStayFinite)
{
    // Given a view of a model
    model::Model model;
    ModelView view(model);

    // When a plane with a NaN origin is added
    model::PlaneFrame frame;
    frame.origin = Eigen::Vector3d(kNaN, 0, 0);
    model.addPlane(frame);

    // Then the view refused its frame
    EXPECT_EQ(view.nonFiniteRejections(), 1);
}

TEST_F(FiniteGeometry, APlaneIgnoresANonFiniteFrameAndKeepsItsCurves)
{
    // Given a plane with a curve
    model::Model model;
    ModelView view(model);
    const model::EntityId plane = model.addPlane(model::PlaneFrame{});
    const model::EntityId curve = model.addCurve(plane, solvers::Curve3d(1, {0, 0, 1, 1}, {{0, 0, 0}, {10, 0, 0}}));
    const model::PlaneFrame before = model.find(plane)->frame;

    // When a dragger hands over a frame with an infinite origin
    model::PlaneFrame bad = before;
    bad.origin.y() = kInf;
    model.setPlaneFrame(plane, bad);
    model.update();

    // Then nothing moved and nothing non-finite was handed to the view
    EXPECT_TRUE(model.find(plane)->frame == before);
    EXPECT_TRUE(model::hasFiniteGeometry(*model.find(curve)));
    EXPECT_EQ(view.nonFiniteRejections(), 0);
}

}  // namespace
}  // namespace sculptline::scene

namespace sculptline::scene {
namespace {

solvers::Curve3d cubicAround(const Eigen::Vector3d& centre, double spread)
{
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < 4; ++i) points.push_back(centre + spread * Eigen::Vector3d(i, (i * i) % 3, 0));
    return solvers::Curve3d(3, {0, 0, 0, 0, 1, 1, 1, 1}, points);
}

TEST(CurveExtent, ACurveOfRoundOffSizeIsRefusedWithItsSize)
{
    // Given a curve whose control points lie within 1e-14 of each other (a stroke drawn with the
    // camera almost on its plane), and one exactly collapsed
    const solvers::Curve3d tiny = cubicAround(Eigen::Vector3d(12, 34, 0), 1e-14);
    const solvers::Curve3d point = cubicAround(Eigen::Vector3d(12, 34, 0), 0.0);

    // Then both are refused, and the message says how small
    try {
        model::requireCurveExtent(tiny);
        FAIL() << "a 1e-14 curve was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("mm"), std::string::npos) << e.what();
    }
    EXPECT_THROW(model::requireCurveExtent(point), std::invalid_argument);
}

TEST(CurveExtent, ASmallButRealCurveIsAccepted)
{
    // A tenth of a millimetre at a kilometre from the origin: well within what doubles resolve.
    EXPECT_NO_THROW(model::requireCurveExtent(cubicAround(Eigen::Vector3d(1e6, -1e6, 0), 1e-4)));
    EXPECT_NO_THROW(model::requireCurveExtent(cubicAround(Eigen::Vector3d::Zero(), model::kMinCurveExtent)));
}

}  // namespace
}  // namespace sculptline::scene
