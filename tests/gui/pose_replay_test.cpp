// Checks the 6-DOF sessions replayed under Xvfb through the real program (tests/gui/CMakeLists.txt
// runs `sculptline --replay tests/gui/pose_sessions/pose_*.json --save` first; make_pose_sessions.py
// writes the sessions): a helix drawn in space is a non-planar curve within tolerance of the recorded
// path; a stroke between two space curves ends on both (snapped); a plane carried by the second hand
// moves, the strokes drawn meanwhile lie on it (mouse and pointer, the two-hands rule) and the whole
// carry is one undo step. The recorded paths are read from the sessions by the program's own parser.
#include "tests/gui/replayed_model.h"

#include "model/document.h"
#include "model/model.h"
#include "model/model_document.h"
#include "solvers/bspline/projection.h"
#include "solvers/editing/oversketch.h"
#include "tests/stroke/fit_checks.h"
#include "solvers/stroke/conditioning.h"
#include "solvers/stroke/stroke_fitter.h"
#include "solvers/stroke/stroke_synthesis.h"
#include "ui/replay_session.h"

#include <QImage>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace sculptline {
namespace {

using Vec3 = Eigen::Vector3d;
using solvers::stroke::distanceToPolyline;
using stroketest::distanceFromBestPlane;

/// A snapped end lies on its curve: the fit interpolates the end point, which was put on the curve
/// by projection (Newton, converged to ~1e-12 mm); 1e-6 mm is far below any visible gap and far
/// above that round-off.
constexpr double kOnCurve = 1e-6;
/// Plane frames and plane-local z are written and read back as doubles: only round-off may differ.
constexpr double kExact = 1e-9;
/// A mouse stroke's points come from pixels: the session names model points, the replay rounds
/// their pixels (about 0.4 mm of the default scene per pixel at 800 x 600, more on a tilted plane);
/// 2 mm is a few pixels.
constexpr double kPixelSlack = 2.0;
/// The program's snapping distance (SketchDocument::kSpaceSnapDistance, documented in the README):
/// the most a snapped end may move the stroke.
constexpr double kSnapDistance = 5.0;

std::string sessionPath(const std::string& name) { return std::string(SCULPTLINE_POSE_SESSIONS) + "/" + name; }

/// The pointer positions of each stroke (trigger held), in session order, with the plane pose
/// current at each sample (the last "plane" pose before it).
struct RecordedStroke {
    std::vector<Vec3> points;
    std::vector<Eigen::Quaterniond> planeRotation;
    std::vector<Vec3> planeOrigin;
};

std::vector<RecordedStroke> recordedStrokes(const std::string& session)
{
    const ui::ReplaySession s = ui::loadReplaySession(sessionPath(session));
    std::vector<RecordedStroke> out;
    bool down = false;
    Vec3 origin = Vec3::Zero();
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
    for (const ui::ReplayEvent& e : s.events) {
        if (e.type != ui::ReplayEvent::Type::Pose) continue;
        if (e.pose.device == ui::PoseEvent::Device::Plane) {
            origin = e.pose.position;
            rotation = e.pose.orientation;
        }
        if (e.pose.device != ui::PoseEvent::Device::Pointer) continue;
        if (e.pose.trigger && !down) out.emplace_back();
        down = e.pose.trigger;
        if (!down) continue;
        out.back().points.push_back(e.pose.position);
        out.back().planeOrigin.push_back(origin);
        out.back().planeRotation.push_back(rotation);
    }
    return out;
}

model::Model defaultModel()
{
    model::Model m;
    model::populateModel(model::loadDocument(std::string(SCULPTLINE_DATA_DIR) + "/default_scene.json"), m);
    return m;
}

/// The curves a session added (ids above the default scene's), in the order they were made.
std::vector<const model::Entity*> newCurves(const model::Model& m)
{
    const model::Model start = defaultModel();
    const model::EntityId last = start.entities().rbegin()->first;
    std::vector<const model::Entity*> out;
    for (const auto& [id, e] : m.entities()) {
        if (id > last && e.kind == model::EntityKind::Curve) out.push_back(&e);
    }
    return out;
}

const model::Entity* defaultPlane(const model::Model& m)
{
    for (const auto& [id, e] : m.entities()) {
        if (e.kind == model::EntityKind::Plane) return &e;
    }
    return nullptr;
}

/// The curve in world coordinates (a curve on a plane is stored in its frame; B-splines are affine
/// invariant, so the frame moves the control points).
solvers::Curve3d worldCurve(const model::Model& m, const model::Entity& curve)
{
    const model::Entity* plane = m.find(curve.plane());
    if (!plane) return *curve.local;
    std::vector<Vec3> pts;
    for (const Vec3& p : curve.local->points()) pts.push_back(plane->frame.toWorld(p));
    return solvers::Curve3d(curve.local->degree(), curve.local->knots(), pts, curve.local->weights(), curve.local->isClosed());
}

std::vector<Vec3> dense(const solvers::Curve3d& c)
{
    std::vector<Vec3> pts;
    for (int i = 0; i <= 1000; ++i) pts.push_back(c.evaluate(c.domainStart() + (c.domainEnd() - c.domainStart()) * i / 1000));
    return pts;
}

double maxDistanceToCurve(const solvers::Curve3d& c, const std::vector<Vec3>& pts)
{
    const solvers::CurveProjector<3> projector(c);
    double worst = 0.0;
    for (const Vec3& p : pts) worst = std::max(worst, projector.project(p).distance);
    return worst;
}

double maxDistanceToPath(const solvers::Curve3d& c, const std::vector<Vec3>& path)
{
    double worst = 0.0;
    for (const Vec3& p : dense(c)) worst = std::max(worst, distanceToPolyline(p, path, false));
    return worst;
}

/// The tolerance the fitter used for this recorded stroke (its default: relative to the extent).
double fitTolerance(const std::vector<Vec3>& path)
{
    return solvers::stroke::kDefaultRelativeTolerance * solvers::stroke::strokeExtent(path);
}

/// How far the recorded samples may lie from the fitted curve: the fitter meets its tolerance on
/// the conditioned samples, which the mean filter (ConditioningOptions::smoothingPasses = 2 passes
/// of p_i <- (p_{i-1} + p_i + p_{i+1}) / 3) moved by (p_{i-1} - 2 p_i + p_{i+1}) / 3 per pass; a
/// pass cannot enlarge the largest second difference (the filter is an average), so a sample moved
/// by at most 2/3 of the largest second difference of the recording. Triangle inequality: recorded
/// sample to curve <= tolerance + that shift.
double fitBound(const std::vector<Vec3>& path)
{
    double secondDifference = 0.0;
    for (size_t i = 1; i + 1 < path.size(); ++i) secondDifference = std::max(secondDifference, (path[i - 1] - 2.0 * path[i] + path[i + 1]).norm());
    return fitTolerance(path) + 2.0 / 3.0 * secondDifference;
}

TEST(PoseReplay, GivenHelixDrawnInSpace_WhenReplayed_ThenOneNonPlanarCurveWithinToleranceOfTheRecordedPath)
{
    const model::Model m = guitest::readReplayedModel("pose_helix.json");
    const std::vector<RecordedStroke> strokes = recordedStrokes("pose_helix.json");
    ASSERT_EQ(strokes.size(), 1u);
    const std::vector<Vec3>& path = strokes[0].points;
    const std::vector<const model::Entity*> curves = newCurves(m);
    ASSERT_EQ(curves.size(), 1u);
    EXPECT_EQ(curves[0]->plane(), 0u) << "a space curve has no plane";
    const solvers::Curve3d c = worldCurve(m, *curves[0]);
    const double tol = fitTolerance(path), bound = fitBound(path);
    EXPECT_LE(maxDistanceToCurve(c, path), bound);
    EXPECT_LE(maxDistanceToPath(c, path), bound);
    EXPECT_GT(distanceFromBestPlane(dense(c)), 20.0 * tol);
    std::printf("helix: tolerance %.3f mm (bound %.3f), recorded-to-curve %.3f, curve-to-path %.3f, off-plane %.1f mm, %d control points\n", tol, bound,
                maxDistanceToCurve(c, path), maxDistanceToPath(c, path), distanceFromBestPlane(dense(c)), c.pointCount());
}

TEST(PoseReplay, GivenStrokeBetweenTwoSpaceCurves_WhenReplayed_ThenItsEndsAreOnThemAndItIsNonPlanar)
{
    const model::Model m = guitest::readReplayedModel("pose_bridge.json");
    const std::vector<RecordedStroke> strokes = recordedStrokes("pose_bridge.json");
    ASSERT_EQ(strokes.size(), 3u);
    const std::vector<const model::Entity*> curves = newCurves(m);
    ASSERT_EQ(curves.size(), 3u);
    const solvers::Curve3d a = worldCurve(m, *curves[0]), b = worldCurve(m, *curves[1]), bridge = worldCurve(m, *curves[2]);
    // The recorded ends stop 3 mm short of the curves: within the snapping distance, not on them.
    const std::vector<Vec3>& path = strokes[2].points;
    EXPECT_GT(solvers::projectToCurve(a, path.front()).distance, 1.0);
    EXPECT_LT(solvers::projectToCurve(a, path.front()).distance, 5.0);
    // The curve's ends are on the curves,
    const Vec3 start = bridge.evaluate(bridge.domainStart()), end = bridge.evaluate(bridge.domainEnd());
    EXPECT_LT(solvers::projectToCurve(a, start).distance, kOnCurve);
    EXPECT_LT(solvers::projectToCurve(b, end).distance, kOnCurve);
    // it follows the recorded path away from the ends (the snap fades out over the last 15 % of
    // the stroke) within tolerance, and everywhere within tolerance plus the 5 mm snapping distance,
    const double tol = fitTolerance(path), bound = fitBound(path);
    std::vector<Vec3> middle(path.begin() + static_cast<long>(path.size() / 5), path.end() - static_cast<long>(path.size() / 5));
    EXPECT_LE(maxDistanceToCurve(bridge, middle), bound);
    EXPECT_LE(maxDistanceToCurve(bridge, path), bound + kSnapDistance);
    // and it is a space curve.
    EXPECT_GT(distanceFromBestPlane(dense(bridge)), 20.0 * tol);
    // The two curves it joins are space curves within tolerance of their own paths.
    EXPECT_LE(maxDistanceToCurve(a, strokes[0].points), fitBound(strokes[0].points));
    EXPECT_LE(maxDistanceToCurve(b, strokes[1].points), fitBound(strokes[1].points));
    std::printf("bridge: ends %.2g / %.2g mm from the curves, middle within %.3f of tolerance %.3f, off-plane %.1f mm\n",
                solvers::projectToCurve(a, start).distance, solvers::projectToCurve(b, end).distance, maxDistanceToCurve(bridge, middle), tol,
                distanceFromBestPlane(dense(bridge)));
}

TEST(PoseReplay, GivenHelixDrawnInSpace_WhenUndone_ThenNoCurveIsLeft)
{
    const model::Model m = guitest::readReplayedModel("pose_helix_undo.json");
    EXPECT_TRUE(newCurves(m).empty()) << "the space curve is one undo step";
}

/// Pixels of the live stroke's cyan (ui/pose_input.cpp kLiveColor, unlit: (26, 230, 230) up to
/// line smoothing); no curve, surface, grid or selection colour comes within 40 of it per channel.
int cyanPixels(const std::string& name)
{
    const QImage image(QString::fromStdString(guitest::replayFile(name)));
    int count = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QRgb c = image.pixel(x, y);
            if (std::abs(qRed(c) - 26) < 40 && std::abs(qGreen(c) - 230) < 40 && std::abs(qBlue(c) - 230) < 40) ++count;
        }
    }
    return count;
}

TEST(PoseReplay, GivenTriggerStillHeld_WhenReplayed_ThenTheStrokeShowsLiveAndNoCurveYet)
{
    // The helix drawn to its end with the trigger still down: the polyline on screen, nothing in the
    // model; after the release (pose_helix.png) the polyline is gone and the curve is there.
    EXPECT_TRUE(newCurves(guitest::readReplayedModel("pose_live.json")).empty());
    const int live = cyanPixels("pose_live.png");
    // Two turns of 30 mm radius span well over 500 pixels of line at this framing.
    EXPECT_GT(live, 500);
    EXPECT_LT(cyanPixels("pose_helix.png"), 10);
    std::printf("live polyline: %d cyan pixels while drawing, %d after the release\n", live, cyanPixels("pose_helix.png"));
}

const model::Entity* defaultCurve(const model::Model& m)
{
    for (const auto& [id, e] : m.entities()) {
        if (e.kind == model::EntityKind::Curve) return &e;
    }
    return nullptr;
}

TEST(PoseReplay, GivenPointerStrokeOverASpaceCurveInOversketchMode_WhenReplayed_ThenTheCurveFollowsItAndKeepsItsEnds)
{
    const model::Model m = guitest::readReplayedModel("pose_oversketch.json");
    const model::Model start = defaultModel();
    const std::vector<RecordedStroke> strokes = recordedStrokes("pose_oversketch.json");
    ASSERT_EQ(strokes.size(), 1u);
    EXPECT_TRUE(newCurves(m).empty()) << "an over-sketch changes the curve, it adds none";
    const model::Entity* after = defaultCurve(m);
    const model::Entity* before = defaultCurve(start);
    ASSERT_TRUE(after && before);
    const solvers::Curve3d& a = *after->local;
    const solvers::Curve3d& b = *before->local;
    ASSERT_EQ(a.domainStart(), b.domainStart());
    ASSERT_EQ(a.domainEnd(), b.domainEnd());
    // The stroke covered u in [1.1, 1.9] of [0, 3]; the default curve has three knot spans, so the
    // transitions reach across its interior (locality at the scale of the spans is checked on a
    // finer curve in oversketch_3d_test), but its ends stay where they are (1e-9 of a 200 mm curve:
    // evaluation round-off, far below anything visible),
    for (const double u : {a.domainStart(), a.domainEnd()}) EXPECT_LT((a.evaluate(u) - b.evaluate(u)).norm(), 1e-9) << "u = " << u;
    // the curve follows the stroke (the over-sketch tolerance is relative to the stroke's length;
    // the stroke is fitted as recorded, without smoothing),
    const std::vector<Vec3>& path = strokes[0].points;
    double length = 0.0;
    for (size_t i = 1; i < path.size(); ++i) length += (path[i] - path[i - 1]).norm();
    EXPECT_LE(maxDistanceToCurve(a, path), solvers::editing::OversketchOptions{}.tolerance * length);
    // and moved where it was drawn over (the stroke is 4 mm above it there).
    EXPECT_GT(solvers::projectToCurve(b, a.evaluate(1.5)).distance, 3.0);
}

/// The pose the session's plane ends in (make_pose_sessions.py: PLANE_MID, PLANE_Q2).
Eigen::Quaterniond lastPlaneRotation(const std::vector<RecordedStroke>& strokes) { return strokes[1].planeRotation.back(); }

TEST(PoseReplay, GivenPlaneCarriedWhileStrokesAreDrawn_WhenReplayed_ThenThePlaneMovedAndTheStrokesLieOnIt)
{
    const model::Model m = guitest::readReplayedModel("pose_plane.json");
    const std::vector<RecordedStroke> strokes = recordedStrokes("pose_plane.json");
    ASSERT_EQ(strokes.size(), 3u);  // pointer: on the plane, on the turning plane, in the air
    const model::Entity* plane = defaultPlane(m);
    ASSERT_NE(plane, nullptr);
    // The plane went where the hand let go of it.
    const ui::ReplaySession session = ui::loadReplaySession(sessionPath("pose_plane.json"));
    Vec3 origin = Vec3::Zero();
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
    for (const ui::ReplayEvent& e : session.events) {
        if (e.type == ui::ReplayEvent::Type::Pose && e.pose.device == ui::PoseEvent::Device::Plane && e.pose.grip) {
            origin = e.pose.position;
            rotation = e.pose.orientation;
        }
    }
    EXPECT_LT((plane->frame.origin - origin).norm(), kExact);
    EXPECT_LT(plane->frame.rotation.angularDistance(rotation), kExact);
    EXPECT_LT(lastPlaneRotation(strokes).angularDistance(rotation), kExact);
    const std::vector<const model::Entity*> curves = newCurves(m);
    ASSERT_EQ(curves.size(), 4u);  // mouse, pointer on the plane, pointer on the turning plane, pointer in the air
    // The three strokes drawn while the plane was carried are on it (its local z = 0).
    for (size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(curves[k]->plane(), plane->id) << "curve " << k;
        double z = 0.0;
        for (const Vec3& p : curves[k]->local->points()) z = std::max(z, std::abs(p.z()));
        EXPECT_LE(z, kExact) << "curve " << k;
    }
    // The pointer strokes are the recorded positions projected onto the plane as it was at each
    // sample (the two-hands rule), within the fit's tolerance, in the plane's frame (they move with it).
    for (size_t k = 0; k < 2; ++k) {
        const RecordedStroke& r = strokes[k];
        std::vector<Vec3> local;
        double offPlane = 0.0;
        for (size_t i = 0; i < r.points.size(); ++i) {
            Vec3 q = r.planeRotation[i].conjugate() * (r.points[i] - r.planeOrigin[i]);
            offPlane = std::max(offPlane, std::abs(q.z()));
            q.z() = 0.0;
            local.push_back(q);
        }
        EXPECT_GT(offPlane, 4.0) << "the pointer was held off the plane";
        const double bound = fitBound(local);
        EXPECT_LE(maxDistanceToCurve(*curves[k + 1]->local, local), bound) << "pointer stroke " << k;
        EXPECT_LE(maxDistanceToPath(*curves[k + 1]->local, local), bound) << "pointer stroke " << k;
    }
    // The mouse stroke: drawn at model points on the carried plane (the session's "at" points), in
    // the plane's frame as it was then.
    std::vector<Vec3> wave;
    {
        model::PlaneFrame then = plane->frame;
        for (const ui::ReplayEvent& e : session.events) {
            if (e.type == ui::ReplayEvent::Type::Pose && e.pose.device == ui::PoseEvent::Device::Plane) {
                then.origin = e.pose.position;
                then.rotation = e.pose.orientation;
            }
            if (e.at) wave.push_back(then.toLocal(*e.at));
        }
    }
    ASSERT_GT(wave.size(), 10u);
    EXPECT_LE(maxDistanceToCurve(*curves[0]->local, wave), kPixelSlack);
    // The stroke after the hand let go is a free space curve.
    EXPECT_EQ(curves[3]->plane(), 0u);
    const double tol = fitTolerance(strokes[2].points);
    EXPECT_LE(maxDistanceToCurve(*curves[3]->local, strokes[2].points), fitBound(strokes[2].points));
    EXPECT_GT(distanceFromBestPlane(dense(*curves[3]->local)), 20.0 * tol);
}

TEST(PoseReplay, GivenPlaneCarried_WhenUndone_ThenTheWholeCarryIsOneStepAndTheStrokesStayOnThePlane)
{
    // The same session, then two undos: the air stroke, and the carry (one step for the grip).
    const model::Model m = guitest::readReplayedModel("pose_plane_undo.json");
    const model::Model start = defaultModel();
    const model::Entity* plane = defaultPlane(m);
    const model::Entity* before = defaultPlane(start);
    ASSERT_TRUE(plane && before);
    EXPECT_LT((plane->frame.origin - before->frame.origin).norm(), kExact);
    EXPECT_LT(plane->frame.rotation.angularDistance(before->frame.rotation), kExact);
    const std::vector<const model::Entity*> curves = newCurves(m);
    ASSERT_EQ(curves.size(), 3u);
    for (const model::Entity* c : curves) EXPECT_EQ(c->plane(), plane->id);
}

}  // namespace
}  // namespace sculptline
