// No NaN or infinity reaches Coin: the model's geometry is checked where the view turns it into
// nodes (ModelView::drawable, hasFiniteGeometry), and a plane never takes a non-finite frame.
// Headless (Coin nodes without a window).
#include "scene/model/model.h"
#include "scene/model/model_view.h"

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
    Entity plane;
    plane.kind = EntityKind::Plane;
    Entity mesh;
    mesh.kind = EntityKind::Mesh;
    mesh.mesh = solvers::surfaces::NetworkMesh{};
    mesh.mesh->vertices = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)};
    mesh.mesh->normals.assign(3, Eigen::Vector3d::UnitZ());
    Entity constraint;
    constraint.kind = EntityKind::Constraint;

    // Then the check tells them apart
    EXPECT_TRUE(hasFiniteGeometry(plane));
    EXPECT_TRUE(hasFiniteGeometry(mesh));
    EXPECT_TRUE(hasFiniteGeometry(constraint));
    plane.frame.origin.x() = kNaN;
    mesh.mesh->normals[1].y() = kInf;
    constraint.anchor.z() = -kInf;
    EXPECT_FALSE(hasFiniteGeometry(plane));
    EXPECT_FALSE(hasFiniteGeometry(mesh));
    EXPECT_FALSE(hasFiniteGeometry(constraint));
}

TEST_F(FiniteGeometry, APlaneAddedWithANaNOriginIsNotDrawnAndItsCurvesStayFinite)
{
    // Given a view of a model
    Model model;
    ModelView view(model);

    // When a plane with a NaN origin is added
    PlaneFrame frame;
    frame.origin = Eigen::Vector3d(kNaN, 0, 0);
    model.addPlane(frame);

    // Then the view refused its frame
    EXPECT_EQ(view.nonFiniteRejections(), 1);
}

TEST_F(FiniteGeometry, APlaneIgnoresANonFiniteFrameAndKeepsItsCurves)
{
    // Given a plane with a curve
    Model model;
    ModelView view(model);
    const EntityId plane = model.addPlane(PlaneFrame{});
    const EntityId curve = model.addCurve(plane, solvers::Curve3d(1, {0, 0, 1, 1}, {{0, 0, 0}, {10, 0, 0}}));
    const PlaneFrame before = model.find(plane)->frame;

    // When a dragger hands over a frame with an infinite origin
    PlaneFrame bad = before;
    bad.origin.y() = kInf;
    model.setPlaneFrame(plane, bad);
    model.update();

    // Then nothing moved and nothing non-finite was handed to the view
    EXPECT_TRUE(model.find(plane)->frame == before);
    EXPECT_TRUE(hasFiniteGeometry(*model.find(curve)));
    EXPECT_EQ(view.nonFiniteRejections(), 0);
}

}  // namespace
}  // namespace sculptline::scene
