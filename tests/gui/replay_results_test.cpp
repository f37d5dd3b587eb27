// Checks what the GUI replay runs wrote (tests/gui/CMakeLists.txt runs `sculptline --replay
// data/sessions/*.json --save/--export-iv/--screenshot` under Xvfb first): documents, exported .iv
// files read back with Coin, and screenshots, as a person would check them. The files are in
// $SCULPTLINE_REPLAY_DIR.
#include "model/model.h"
#include "model/model_document.h"
#include "model/document.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoSeparator.h>
#include <QColor>
#include <QImage>
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

namespace sculptline {
namespace {

/// Plane-local points of the same strokes on the same plane are computed identically.
constexpr double kSameFit = 1e-9;
/// A drag of a few dozen pixels moves the plane by centimetres in this scene.
constexpr double kMinDragMotion = 5.0;
/// Pixels of a sketched curve in an 800x600 view (a 3-pixel line across a third of the plane).
constexpr int kMinCurvePixels = 150;
/// Coin stores coordinates as float.
constexpr double kFloatTolerance = 1e-3;

std::string file(const std::string& name)
{
    const char* dir = std::getenv("SCULPTLINE_REPLAY_DIR");
    return std::string(dir ? dir : ".") + "/" + name;
}

nlohmann::json readJson(const std::string& name)
{
    std::ifstream in(file(name));
    if (!in) return {};
    return nlohmann::json::parse(in, nullptr, false);
}

model::Model readModel(const std::string& name)
{
    model::Model model;
    model::populateModel(model::loadDocument(file(name)), model);
    return model;
}

std::vector<const model::Entity*> curvesOn(const model::Model& model, model::EntityId plane)
{
    std::vector<const model::Entity*> out;
    for (const auto& [id, e] : model.entities()) {
        if (e.kind == model::EntityKind::Curve && e.plane() == plane) out.push_back(&e);
    }
    return out;
}

/// Pixels close to the first sketched curve's colour (id 4: pink 0.95/0.3/0.55; the default
/// scene's curve is orange, scene/model_view.cpp).
int sketchPixels(const QImage& image)
{
    int n = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QColor c(image.pixel(x, y));
            const bool pink = c.red() > 200 && c.green() > 40 && c.green() < 120 && c.blue() > 100 && c.blue() < 180;
            n += pink ? 1 : 0;
        }
    }
    return n;
}

TEST(ReplayResults, TwoStrokesBecomeTwoCubicCurvesOnTheDefaultPlane)
{
    const model::Model model = readModel("sketch.json");
    const auto onPlane = curvesOn(model, 1);
    ASSERT_EQ(onPlane.size(), 2u);
    for (const model::Entity* c : onPlane) {
        EXPECT_EQ(c->local->degree(), 3);
        EXPECT_GE(c->local->pointCount(), 4);
        // Drawn inside the 120 mm plane
        for (const Eigen::Vector3d& p : c->local->points()) {
            EXPECT_LT(p.head<2>().cwiseAbs().maxCoeff(), 70.0);
            EXPECT_EQ(p.z(), 0.0);
        }
    }
    // The plane did not move
    EXPECT_LT((model.find(1)->frame.origin - Eigen::Vector3d(0, 95, 60)).norm(), 1e-9);
    // And a person sees the first (pink) curve on the plane
    const QImage shot = QImage(QString::fromStdString(file("sketch.png"))).convertToFormat(QImage::Format_RGB32);
    ASSERT_FALSE(shot.isNull());
    EXPECT_GE(sketchPixels(shot), kMinCurvePixels);
    // And the replay timed each pen-up to its curve on screen: one stroke_release per stroke (the
    // latencies are reported, not asserted)
    std::ifstream in(file("sketch_stats.json"));
    ASSERT_TRUE(in);
    const nlohmann::json stats = nlohmann::json::parse(in);
    ASSERT_TRUE(stats.contains("stroke_release")) << stats.dump();
    EXPECT_EQ(stats["stroke_release"]["count"].get<int>(), 2);
    // The first pen-up (cold fitter) is reported on its own: one of the samples, so within (0, max]
    ASSERT_TRUE(stats["stroke_release"].contains("first_ms")) << stats.dump();
    EXPECT_GT(stats["stroke_release"]["first_ms"].get<double>(), 0.0);
    EXPECT_LE(stats["stroke_release"]["first_ms"].get<double>(), stats["stroke_release"]["max_ms"].get<double>());
    // Of which the fit: one stroke_fit per stroke, each a part of its release.
    ASSERT_TRUE(stats.contains("stroke_fit")) << stats.dump();
    EXPECT_EQ(stats["stroke_fit"]["count"].get<int>(), 2);
    EXPECT_GT(stats["stroke_fit"]["first_ms"].get<double>(), 0.0);
    EXPECT_LT(stats["stroke_fit"]["first_ms"].get<double>(), stats["stroke_release"]["first_ms"].get<double>());
    EXPECT_LT(stats["stroke_fit"]["max_ms"].get<double>(), stats["stroke_release"]["max_ms"].get<double>());
    std::cout << "sketch: stroke_fit first " << stats["stroke_fit"]["first_ms"].get<double>() << " ms, max "
              << stats["stroke_fit"]["max_ms"].get<double>() << " ms\n";
    std::cout << "sketch: stroke_release first " << stats["stroke_release"]["first_ms"].get<double>() << " ms, p50 "
              << stats["stroke_release"]["p50_ms"].get<double>() << " ms, max "
              << stats["stroke_release"]["max_ms"].get<double>() << " ms\n";
}

TEST(ReplayResults, DraggingThePlaneCarriesItsCurvesRigidly)
{
    const model::Model before = readModel("sketch.json");
    const model::Model after = readModel("drag.json");
    const model::PlaneFrame& f0 = before.find(1)->frame;
    const model::PlaneFrame& f1 = after.find(1)->frame;
    // The plane moved
    EXPECT_GT((f1.origin - f0.origin).norm() + 100.0 * f1.rotation.angularDistance(f0.rotation), kMinDragMotion);
    // Its curves kept their plane-local shape and are where the new frame puts them
    const auto c0 = curvesOn(before, 1), c1 = curvesOn(after, 1);
    ASSERT_EQ(c0.size(), c1.size());
    for (size_t i = 0; i < c0.size(); ++i) {
        ASSERT_EQ(c0[i]->local->pointCount(), c1[i]->local->pointCount());
        for (int k = 0; k < c0[i]->local->pointCount(); ++k) {
            EXPECT_LT((c0[i]->local->points()[k] - c1[i]->local->points()[k]).norm(), kSameFit);
            EXPECT_LT((c1[i]->world->points()[k] - f1.toWorld(c0[i]->local->points()[k])).norm(), kSameFit);
        }
        EXPECT_GT((c1[i]->world->points()[0] - c0[i]->world->points()[0]).norm(), 1.0);
    }
}

TEST(ReplayResults, UndoAndRedoRestoreThePlaneAndTheCurves)
{
    // Session: two strokes, a drag, then undo x3 (drag, stroke, stroke) and redo x1 (first stroke)
    const model::Model sketched = readModel("sketch.json");
    const model::Model model = readModel("undo.json");
    EXPECT_LT((model.find(1)->frame.origin - Eigen::Vector3d(0, 95, 60)).norm(), 1e-9);
    EXPECT_LT(model.find(1)->frame.rotation.angularDistance(sketched.find(1)->frame.rotation), 1e-9);
    const auto curves = curvesOn(model, 1);
    ASSERT_EQ(curves.size(), 1u);
    EXPECT_EQ(curves[0]->local->points(), curvesOn(sketched, 1)[0]->local->points());
}

TEST(ReplayResults, DeletesAreUndoable)
{
    // Session: two strokes; Delete (the second curve); select the plane by its jack; Delete (the
    // plane and the first curve); Ctrl+Z (both back)
    const model::Model sketched = readModel("sketch.json");
    const model::Model model = readModel("delete.json");
    ASSERT_NE(model.find(1), nullptr);
    EXPECT_EQ(model.find(1)->kind, model::EntityKind::Plane);
    const auto curves = curvesOn(model, 1);
    ASSERT_EQ(curves.size(), 1u);
    EXPECT_EQ(curves[0]->id, curvesOn(sketched, 1)[0]->id);
    EXPECT_EQ(curves[0]->local->points(), curvesOn(sketched, 1)[0]->local->points());
    EXPECT_EQ(model.entities().size(), 4u);  // plane, default curve, surface, first stroke
}

TEST(ReplayResults, StrokesFromCurvesGoOntoAuxiliaryPlanes)
{
    // Session: the two strokes of sketch.json (curves 4 and 5 on plane 1), then a stroke from curve
    // 4's start into the air (case 1) and one from curve 4's start to curve 5's start (case 2)
    const model::Model model = readModel("auxiliary.json");
    const model::Entity* curve4 = model.find(4);
    const model::Entity* curve5 = model.find(5);
    ASSERT_TRUE(curve4 && curve5);
    const Eigen::Vector3d a = curve4->world->evaluate(curve4->world->domainStart());
    const Eigen::Vector3d b = curve5->world->evaluate(curve5->world->domainStart());
    const Eigen::Vector3d tangent = curve4->world->derivatives(curve4->world->domainStart(), 1)[1].normalized();
    const Eigen::Vector3d planeNormal = model.find(1)->frame.normal();
    std::vector<const model::Entity*> auxiliary;
    for (const auto& [id, e] : model.entities()) {
        if (e.kind == model::EntityKind::Plane && id != 1) auxiliary.push_back(&e);
    }
    ASSERT_EQ(auxiliary.size(), 2u);
    /// The hand starts within a few pixels of the curve's end: a millimetre or two here.
    constexpr double kOnPlane = 3.0;
    // Case 1: through the curve point, containing the tangent there, one curve on it
    const model::PlaneFrame& p1 = auxiliary[0]->frame;
    EXPECT_LT(std::abs((a - p1.origin).dot(p1.normal())), kOnPlane);
    // The plane holds the tangent at the foot of the pen's first point on the curve
    // (model/auxiliary_plane.cpp), a few pixels from the start: the smallest tilt over the curve's
    // first 2 % (a fit that holds the drawn end samples turns within those pixels by a degree or two;
    // at the start itself this stroke's tangent leaves the plane by 0.0502).
    double tilt = std::abs(tangent.dot(p1.normal()));
    const double u0 = curve4->world->domainStart(), span = curve4->world->domainEnd() - u0;
    for (int k = 1; k <= 20; ++k) {
        const double u = u0 + 0.02 * span * k / 20;
        tilt = std::min(tilt, std::abs(curve4->world->derivatives(u, 1)[1].normalized().dot(p1.normal())));
    }
    EXPECT_LT(tilt, 0.05);
    EXPECT_EQ(curvesOn(model, auxiliary[0]->id).size(), 1u);
    // Case 2: through both points, containing the first curve's binormal (its plane's normal)
    const model::PlaneFrame& p2 = auxiliary[1]->frame;
    EXPECT_LT(std::abs((a - p2.origin).dot(p2.normal())), kOnPlane);
    EXPECT_LT(std::abs((b - p2.origin).dot(p2.normal())), kOnPlane);
    EXPECT_LT(std::abs(planeNormal.dot(p2.normal())), 1e-6);
    const auto onP2 = curvesOn(model, auxiliary[1]->id);
    ASSERT_EQ(onP2.size(), 1u);
    // The curve runs from one curve to the other
    const solvers::Curve3d& c = *onP2[0]->world;
    EXPECT_LT((c.evaluate(c.domainStart()) - a).norm(), 2 * kOnPlane);
    EXPECT_LT((c.evaluate(c.domainEnd()) - b).norm(), 2 * kOnPlane);
}

TEST(ReplayResults, OversketchRedrawsTheMiddleOfACurveAndKeepsItsEnds)
{
    // Session: the two strokes, then in over-sketch mode a straight stroke across curve 4's middle,
    // undone and redone
    const model::Model sketched = readModel("sketch.json");
    const model::Model model = readModel("oversketch.json");
    const solvers::Curve3d& before = *sketched.find(4)->local;
    const solvers::Curve3d& after = *model.find(4)->local;
    EXPECT_EQ(model.find(4)->plane(), 1u);
    EXPECT_NE(after.points(), before.points());
    // Outside the over-drawn part the curve is unchanged: same ends
    constexpr double kKept = 1e-6;
    EXPECT_LT((after.evaluate(after.domainStart()) - before.evaluate(before.domainStart())).norm(), kKept);
    EXPECT_LT((after.evaluate(after.domainEnd()) - before.evaluate(before.domainEnd())).norm(), kKept);
    // And no curve was added
    EXPECT_EQ(curvesOn(model, 1).size(), 2u);
}

TEST(ReplayResults, PullingACurvePointDrawsTheCurveAfterTheHandle)
{
    // Session: the two strokes, then in pull mode curve 4 grabbed at its trough and pulled 45
    // pixels down (about 15 mm on the plane), undone and redone
    const model::Model sketched = readModel("sketch.json");
    const model::Model model = readModel("pull.json");
    const solvers::Curve3d& before = *sketched.find(4)->local;
    const solvers::Curve3d& after = *model.find(4)->local;
    EXPECT_EQ(model.find(4)->plane(), 1u);
    EXPECT_EQ(curvesOn(model, 1).size(), 2u);
    auto lowest = [](const solvers::Curve3d& c) {
        double y = std::numeric_limits<double>::infinity();
        for (int i = 0; i <= 200; ++i) y = std::min(y, c.evaluate(c.domainStart() + (c.domainEnd() - c.domainStart()) * i / 200).y());
        return y;
    };
    /// Well past hand jitter, well short of the 15 mm pulled.
    constexpr double kPulled = 8.0;
    EXPECT_LT(lowest(after), lowest(before) - kPulled);
    // The minimum change: the far end barely moves
    EXPECT_LT((after.points().back() - before.points().back()).norm(), 1.0);
}

TEST(ReplayResults, LiftingAStrokeBetweenTwoCurvesMakesASpaceCurveJoiningThem)
{
    // Session: the two strokes, then in lift mode a stroke from curve 4's start to curve 5's start
    const model::Model model = readModel("lift.json");
    const model::Entity* lifted = model.find(6);
    ASSERT_NE(lifted, nullptr);
    ASSERT_EQ(lifted->kind, model::EntityKind::Curve);
    EXPECT_EQ(lifted->plane(), 0u);  // a space curve, on no plane
    const solvers::Curve3d& c4 = *model.find(4)->world;
    const solvers::Curve3d& c5 = *model.find(5)->world;
    const solvers::Curve3d& c = *lifted->world;
    /// The pen lands within a few pixels of the curve ends.
    constexpr double kJoin = 3.0;
    EXPECT_LT((c.evaluate(c.domainStart()) - c4.evaluate(c4.domainStart())).norm(), kJoin);
    EXPECT_LT((c.evaluate(c.domainEnd()) - c5.evaluate(c5.domainStart())).norm(), kJoin);
}

TEST(ReplayResults, TheRecognizedArcReplacesTheFreeformFitOnRequest)
{
    // Session: the two strokes, then stroke.useRecognized (the arc stroke, curve 5), undo, redo
    const model::Model sketched = readModel("sketch.json");
    const model::Model model = readModel("recognize.json");
    const solvers::Curve3d& freeform = *sketched.find(5)->local;
    const solvers::Curve3d& arc = *model.find(5)->local;
    // The recognizer's exact arc: a rational quadratic, on the same plane, with the stroke's ends
    EXPECT_EQ(arc.degree(), 2);
    EXPECT_TRUE(arc.isRational());
    EXPECT_EQ(model.find(5)->plane(), 1u);
    // The exact arc lies on the least-squares circle, which need not pass through the stroke's
    // ends: within a tenth of the arc's chord of them.
    const double kSameEnds = 0.1 * (freeform.evaluate(freeform.domainEnd()) - freeform.evaluate(freeform.domainStart())).norm();
    EXPECT_LT((arc.evaluate(arc.domainStart()) - freeform.evaluate(freeform.domainStart())).norm(), kSameEnds);
    EXPECT_LT((arc.evaluate(arc.domainEnd()) - freeform.evaluate(freeform.domainEnd())).norm(), kSameEnds);
}

TEST(ReplayResults, SavingAReopenedDocumentWritesTheSameDocument)
{
    const nlohmann::json saved = readJson("drag.json");
    const nlohmann::json resaved = readJson("reopened.json");
    ASSERT_FALSE(saved.is_null());
    EXPECT_EQ(saved, resaved);
}

TEST(ReplayResults, AHundredAndTwelveEditsOfFourKindsAreAllUndone)
{
    // 28 rounds of a stroke, the recognized shape, Delete and a plane drag: the edits changed the
    // document (the plane moved), and as many undos bring back the untouched default scene.
    const nlohmann::json start = readJson("start.json"), edited = readJson("hundred_edits.json"), undone = readJson("hundred_undone.json");
    ASSERT_FALSE(start.is_null());
    ASSERT_FALSE(edited.is_null());
    EXPECT_NE(edited["planes"], start["planes"]);
    EXPECT_EQ(undone, start);
}

TEST(ReplayResults, ANewPlaneFacesTheViewerAndTakesTheStroke)
{
    const model::Model model = readModel("plane.json");
    const model::Entity* plane = model.find(4);  // after plane 1, curve 2 and surface 3
    ASSERT_NE(plane, nullptr);
    ASSERT_EQ(plane->kind, model::EntityKind::Plane);
    // Facing the default view direction (-1, 1.6, -0.9), i.e. its normal points back at the eye
    EXPECT_GT(plane->frame.normal().dot(Eigen::Vector3d(1, -1.6, 0.9).normalized()), 0.99);
    EXPECT_EQ(curvesOn(model, 4).size(), 1u);
}

TEST(ReplayResults, ExportedInventorFileReadsBackInCoinWithTheDraggedCurves)
{
    SoDB::init();
    SoInput in;
    ASSERT_TRUE(in.openFile(file("drag.iv").c_str()));
    SoSeparator* root = SoDB::readAll(&in);
    ASSERT_NE(root, nullptr);
    root->ref();
    // One line set per curve (3) plus the grid and plane lines; the curves sit under "Curves"
    SoSearchAction search;
    search.setName("Curves");
    search.apply(root);
    ASSERT_NE(search.getPath(), nullptr);
    auto* curves = static_cast<SoSeparator*>(search.getPath()->getTail());
    EXPECT_EQ(curves->getNumChildren(), 3);
    // The sketched curves are exported where the dragged plane put them (world coordinates)
    const model::Model model = readModel("drag.json");
    const auto onPlane = curvesOn(model, 1);
    ASSERT_EQ(onPlane.size(), 2u);
    SoSearchAction coords;
    coords.setType(SoCoordinate3::getClassTypeId());
    coords.setInterest(SoSearchAction::ALL);
    coords.apply(curves);
    ASSERT_EQ(coords.getPaths().getLength(), 3);
    // Curve nodes follow entity order: the world curve first, then the two sketched ones.
    for (int i = 0; i < 2; ++i) {
        const auto* c = static_cast<SoCoordinate3*>(coords.getPaths()[i + 1]->getTail());
        const SbVec3f first = c->point[0];
        const Eigen::Vector3d expected = onPlane[i]->world->evaluate(onPlane[i]->world->domainStart());
        EXPECT_LT((Eigen::Vector3d(first[0], first[1], first[2]) - expected).norm(), kFloatTolerance) << i;
    }
    root->unref();
}

}  // namespace
}  // namespace sculptline
