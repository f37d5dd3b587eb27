// The Aesthetics dock, the curvature comb and the inspector's curvature plot with a real display (run
// under Xvfb by ctest). Given the default scene with an S-shaped cubic added on its plane (plane 1,
// y = 95 facing -y), selected: the dock shows the curve's analysis (name and measures as
// solvers::aesthetics::analyzeCurve gives them for the curve in its plane's frame), the comb drawn in
// the scene graph has one tooth per sample and each tooth is scale * kappa long, on the side the
// curve turns to, the plot is signed with the codons marked; a pull (a drag) carries the comb and
// the dock along. Writes the whole window, viewport included, to $SCULPTLINE_AESTHETICS_SHOT (when
// set) so a person can look at them.
#include "model/document.h"
#include "scene/curvature_comb.h"
#include "solvers/aesthetics/curve_analysis.h"
#include "ui/aesthetics_dock.h"
#include "ui/curvature_plot.h"
#include "ui/main_window.h"
#include "ui/sketch_document.h"
#include "tests/gui/window_shot.h"

#include <Inventor/Qt/SoQt.h>
#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoSwitch.h>

#include <QAction>
#include <QApplication>
#include <QDoubleSpinBox>
#include <QMouseEvent>
#include <QPainter>
#include <QSpinBox>
#include <QTableWidget>
#include <QWindow>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

namespace sculptline::ui {
namespace {

namespace aes = solvers::aesthetics;

constexpr model::EntityId kPlane = 1, kSpaceCurve = 2;
/// The dock shows four significant digits: a shown number is within half a unit of the fourth
/// digit of the exact one, 5e-4 relative.
constexpr double kShownRelative = 5e-4;
/// Coin keeps coordinates in single precision: at the test curve's ~100 mm from the origin a
/// coordinate carries ~1e-5 mm of rounding; a tooth (two points) is within 1e-4 mm of exact.
constexpr double kFloatMm = 1e-4;
/// The same double computation done twice (the plot's samples against signedCurvature at the same
/// u; the scale's factor 2): equal to round-off.
constexpr double kRoundOff = 1e-12;
/// Arc lengths by two quadratures (the plot's table and analyzeCurve's) of the same curve agree to
/// kArcLengthRelativeTolerance-level accuracy; 1e-9 relative leaves room for their different panels.
constexpr double kArcLengthRelative = 1e-9;
/// The pointer lands on a whole pixel, and the read-out rounds s to two decimals: the sample read
/// out is within this many pixels' worth of arc length of the one aimed at.
constexpr double kHoverPixels = 2.0;
/// The Frenet curvature vector is perpendicular to the tangent to round-off relative to their sizes.
constexpr double kPerpendicularRelative = 1e-9;


/// An S: up over the first half, down over the second, in the plane's frame (z = 0); three spans.
solvers::Curve3d sCurve(double amplitude = 25.0)
{
    return solvers::Curve3d(3, {0, 0, 0, 0, 1, 2, 3, 3, 3, 3},
                            {{-50, 0, 0}, {-30, amplitude, 0}, {-10, amplitude, 0}, {10, -amplitude, 0}, {30, -amplitude, 0}, {50, 0, 0}});
}

/// The number a label starts with ("0.1234 /mm" -> 0.1234).
double shownNumber(const QString& text) { return text.section(QLatin1Char(' '), 0, 0).toDouble(); }

::testing::AssertionResult shownAs(const QString& text, double exact)
{
    const double shown = shownNumber(text);
    if (std::abs(shown - exact) <= kShownRelative * std::abs(exact) + kRoundOff) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "shown \"" << text.toStdString() << "\", exact " << exact;
}

/// The comb's teeth as drawn: the (base, tip) pairs of the CombTeeth node's coordinates.
std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> drawnTeeth(SoSeparator* root)
{
    SoSearchAction search;
    search.setName("CombTeeth");
    search.apply(root);
    std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> out;
    if (!search.getPath()) return out;
    auto* teeth = static_cast<SoSeparator*>(search.getPath()->getTail());
    for (int k = 0; k < teeth->getNumChildren(); ++k) {
        if (!teeth->getChild(k)->isOfType(SoCoordinate3::getClassTypeId())) continue;
        const SoMFVec3f& p = static_cast<SoCoordinate3*>(teeth->getChild(k))->point;
        for (int i = 0; i + 1 < p.getNum(); i += 2) {
            out.emplace_back(Eigen::Vector3d(p[i][0], p[i][1], p[i][2]), Eigen::Vector3d(p[i + 1][0], p[i + 1][1], p[i + 1][2]));
        }
    }
    return out;
}

struct SCurveWindow {
    MainWindow window;
    model::EntityId curve = 0;
    SCurveWindow()
    {
        window.showDocument(model::loadDocument(SCULPTLINE_DATA_DIR "/default_scene.json"), QString());
        window.resize(1280, 960);
        window.show();
        curve = window.document().model().addCurve(kPlane, sCurve());
        window.document().scheduler().flush();
        window.document().select(curve);
        window.action(QStringLiteral("view.aesthetics"))->trigger();
        QApplication::processEvents();
    }
    model::Model& model() { return window.document().model(); }
    const model::Entity& entity() { return *model().find(curve); }
    AestheticsDock& dock() { return *window.findChild<AestheticsDock*>(); }
    scene::CurvatureComb& comb() { return window.document().comb(); }
    /// The analysis the dock should show: the curve in its plane's frame.
    aes::CurveAnalysis expected() { return aes::analyzeCurve(aes::planarCurve(*entity().local)); }

    /// Every drawn tooth is scale * kappa along the curve's left normal in its plane (signed: a
    /// left turn, kappa > 0, puts the tooth on the left) and has no component out of the plane.
    void expectTeethMatch()
    {
        const solvers::Curve2d planar = aes::planarCurve(*entity().local);
        const model::PlaneFrame& frame = model().find(kPlane)->frame;
        const auto drawn = drawnTeeth(window.sceneRoot());
        ASSERT_EQ(drawn.size(), comb().teeth().size());
        for (size_t i = 0; i < drawn.size(); ++i) {
            const double u = comb().teeth()[i].u;
            const auto d = planar.derivatives(u, 1);
            const Eigen::Vector2d left = Eigen::Vector2d(-d[1].y(), d[1].x()).normalized();
            const Eigen::Vector3d tooth = frame.rotation.conjugate() * (drawn[i].second - drawn[i].first);
            const double expectedLength = comb().scale() * aes::signedCurvature(planar, u);
            EXPECT_NEAR(tooth.head<2>().dot(left), expectedLength, kFloatMm) << "tooth " << i << " at u = " << u;
            EXPECT_NEAR(tooth.norm(), std::abs(expectedLength), kFloatMm) << "tooth " << i;
            EXPECT_NEAR((drawn[i].first - frame.toWorld(Eigen::Vector3d(planar.evaluate(u).x(), planar.evaluate(u).y(), 0))).norm(), 0.0, kFloatMm);
        }
    }

    void expectDockMatches(const aes::CurveAnalysis& a)
    {
        EXPECT_EQ(dock().curve(), curve);
        EXPECT_TRUE(dock().message().isEmpty()) << dock().message().toStdString();
        EXPECT_TRUE(dock().header().endsWith(QString::fromStdString(": " + a.name))) << dock().header().toStdString() << " vs " << a.name;
        const aes::Measures& m = a.measures;
        EXPECT_TRUE(shownAs(dock().measureText(QStringLiteral("acceleration")), m.acceleration));
        EXPECT_TRUE(shownAs(dock().measureText(QStringLiteral("sharpness")), m.sharpness));
        EXPECT_TRUE(shownAs(dock().measureText(QStringLiteral("flatness")), m.flatness));
        EXPECT_TRUE(shownAs(dock().measureText(QStringLiteral("convexity")), m.convexity));
        EXPECT_TRUE(shownAs(dock().measureText(QStringLiteral("crown")), m.crown));
        EXPECT_TRUE(shownAs(dock().measureText(QStringLiteral("kappaMin")), m.curvatureMin));
        EXPECT_TRUE(shownAs(dock().measureText(QStringLiteral("kappaMax")), m.curvatureMax));
        EXPECT_TRUE(shownAs(dock().measureText(QStringLiteral("length")), a.length));
        if (m.tension) EXPECT_TRUE(shownAs(dock().measureText(QStringLiteral("tension")), *m.tension));
        else EXPECT_TRUE(dock().measureText(QStringLiteral("tension")).startsWith(QStringLiteral("—")));
        ASSERT_EQ(dock().pointTable()->rowCount(), static_cast<int>(a.points.size()));
        for (size_t i = 0; i < a.points.size(); ++i) {
            EXPECT_EQ(dock().pointTable()->item(static_cast<int>(i), 0)->text().toStdString(), aes::codon(a.points[i].kind));
            EXPECT_TRUE(shownAs(dock().pointTable()->item(static_cast<int>(i), 2)->text(), a.points[i].curvature));
            EXPECT_TRUE(shownAs(dock().pointTable()->item(static_cast<int>(i), 3)->text(), a.points[i].arcLength));
        }
        for (const aes::Characteristics& c : a.characteristics) {
            const QString shown = dock().pointTable()->item(c.point, 4)->text();
            EXPECT_EQ(shown.contains(QStringLiteral("small visibility")), c.smallVisibility) << shown.toStdString();
            EXPECT_EQ(shown.contains(QStringLiteral("sharp corner")), c.sharpCorner) << shown.toStdString();
            EXPECT_EQ(shown.contains(QStringLiteral("symmetric")), c.symmetric) << shown.toStdString();
            EXPECT_EQ(shown.contains(QStringLiteral("redundant")), c.redundant) << shown.toStdString();
        }
        ASSERT_EQ(dock().lcgTable()->rowCount(), static_cast<int>(a.lcg.size()));
        for (size_t i = 0; i < a.lcg.size(); ++i) EXPECT_TRUE(shownAs(dock().lcgTable()->item(static_cast<int>(i), 2)->text(), a.lcg[i].slope));
    }

    /// `frame`: the camera is first turned to look at it squarely (for the picture only).
    void shoot(const QString& suffix, SoNode* frame = nullptr)
    {
        const char* shot = std::getenv("SCULPTLINE_AESTHETICS_SHOT");
        if (!shot) return;
        if (frame) {
            // Facing the plane (its normal is -y): the camera on the front side, looking along +y.
            SoCamera* camera = window.viewer()->getCamera();
            camera->orientation.setValue(SbRotation(SbVec3f(0, 0, -1), SbVec3f(0, 1, 0)) * SbRotation(SbVec3f(0, 1, 0), 0.0f));
            camera->viewAll(frame, window.viewer()->getViewportRegion(), 1.1f);
        }
        QString path = QString::fromLocal8Bit(shot);
        path.insert(path.endsWith(QStringLiteral(".png")) ? path.size() - 4 : path.size(), suffix);
        guitest::saveWindowShot(window, path);
    }
};

TEST(AestheticsDock, ShowsTheSelectedCurvesAnalysis)
{
    guitest::startApplication("aesthetics_dock_test");
    SCurveWindow w;
    const aes::CurveAnalysis a = w.expected();
    // The S turns both ways: the test means something only if its name has both signs
    ASSERT_NE(a.name.find('+'), std::string::npos) << a.name;
    ASSERT_NE(a.name.find('-'), std::string::npos) << a.name;
    w.expectDockMatches(a);
}

TEST(AestheticsDock, CombTeethAreScaleTimesCurvatureOnTheTurningSide)
{
    guitest::startApplication("aesthetics_dock_test");
    SCurveWindow w;
    // Hidden by default: nothing drawn
    EXPECT_TRUE(drawnTeeth(w.window.sceneRoot()).empty());
    w.window.action(QStringLiteral("view.curvatureComb"))->trigger();
    QApplication::processEvents();
    ASSERT_TRUE(w.comb().visible());
    // Three non-empty spans, kDefaultCombDensity samples each, and the end
    EXPECT_EQ(drawnTeeth(w.window.sceneRoot()).size(), static_cast<size_t>(3 * scene::kDefaultCombDensity + 1));
    w.expectTeethMatch();
    // The default scale: the longest tooth is kCombLengthFraction of the curve's size (its samples' box)
    Eigen::AlignedBox3d box;
    double longest = 0.0;
    for (const auto& [base, tip] : drawnTeeth(w.window.sceneRoot())) {
        box.extend(base);
        longest = std::max(longest, (tip - base).norm());
    }
    EXPECT_NEAR(longest / box.diagonal().norm(), scene::kCombLengthFraction, kFloatMm / box.diagonal().norm());
    w.shoot(QStringLiteral("_comb"), w.comb().root());

    // The dock's controls: twice the scale, twice the teeth; four teeth per span
    const double scale = w.comb().scale();
    w.dock().scaleBox()->setValue(2.0);
    EXPECT_NEAR(w.comb().scale(), 2.0 * scale, kRoundOff * scale);
    w.expectTeethMatch();
    w.dock().densityBox()->setValue(4);
    EXPECT_EQ(drawnTeeth(w.window.sceneRoot()).size(), static_cast<size_t>(3 * 4 + 1));
    w.expectTeethMatch();
}

TEST(AestheticsDock, FollowsAPullOfTheCurve)
{
    guitest::startApplication("aesthetics_dock_test");
    SCurveWindow w;
    w.window.action(QStringLiteral("view.curvatureComb"))->trigger();
    QApplication::processEvents();
    const double scale = w.comb().scale();
    const double kappaMaxBefore = w.expected().measures.curvatureMax;
    const int rebuilds = w.comb().rebuilds(), refreshes = w.dock().refreshes();
    // A pull at three quarters (a drag: the model solves on every pointer event), three events in one
    // turn of the event loop
    w.model().beginPull(w.curve, 2.25);
    for (double up : {5.0, 15.0, 30.0}) {
        const Eigen::Vector3d at = w.entity().local->evaluate(2.25) + Eigen::Vector3d(0, up, 0);
        w.model().pullTo(at);
        w.window.document().scheduler().flush();
    }
    // The comb followed each update, at the scale it had when the drag began
    EXPECT_EQ(w.comb().rebuilds(), rebuilds + 3);
    EXPECT_EQ(w.comb().scale(), scale);
    w.expectTeethMatch();
    // The dock analysed once for the three, after them
    QApplication::processEvents();
    EXPECT_EQ(w.dock().refreshes(), refreshes + 1);
    const aes::CurveAnalysis after = w.expected();
    w.expectDockMatches(after);
    w.model().endDrag();
    w.window.document().scheduler().flush();
    QApplication::processEvents();
    w.expectDockMatches(w.expected());
    // Its plane moved (the curve's shape in the plane unchanged): the comb follows into the world,
    // the dock has nothing new to analyse
    const int settled = w.dock().refreshes(), combBuilds = w.comb().rebuilds();
    model::PlaneFrame moved = w.model().find(kPlane)->frame;
    moved.origin += Eigen::Vector3d(0, -20, 10);
    w.model().setPlaneFrame(kPlane, moved);
    w.window.document().scheduler().flush();
    QApplication::processEvents();
    EXPECT_EQ(w.comb().rebuilds(), combBuilds + 1);
    w.expectTeethMatch();
    EXPECT_EQ(w.dock().refreshes(), settled);
    w.expectDockMatches(w.expected());
    // The drag changed the curve enough to tell a stale dock from a live one
    EXPECT_GT(std::abs(after.measures.curvatureMax - kappaMaxBefore), 100.0 * kShownRelative * std::abs(kappaMaxBefore));
}

TEST(AestheticsDock, PlotIsSignedWithCodons)
{
    guitest::startApplication("aesthetics_dock_test");
    SCurveWindow w;
    const aes::CurveAnalysis a = w.expected();
    auto* plot = w.window.findChild<CurvaturePlot*>();
    ASSERT_NE(plot, nullptr);
    ASSERT_TRUE(plot->isSigned());
    ASSERT_FALSE(plot->samples().empty());
    EXPECT_LT(*std::min_element(plot->samples().begin(), plot->samples().end()), 0.0);
    EXPECT_GT(*std::max_element(plot->samples().begin(), plot->samples().end()), 0.0);
    // Arc length runs from 0 to the curve's length
    EXPECT_EQ(plot->arcLengths().front(), 0.0);
    EXPECT_NEAR(plot->arcLengths().back(), a.length, kArcLengthRelative * a.length);
    QStringList codons;
    for (const auto& p : a.points) codons << QString::fromLatin1(aes::codon(p.kind));
    EXPECT_EQ(plot->codonLabels(), codons);
    EXPECT_TRUE(plot->title().contains(QString::fromStdString(a.name))) << plot->title().toStdString();
    // The read-out under the pointer: the sample's s and kappa
    w.window.findChild<QWidget*>(QStringLiteral("dock.inspector"))->raise();
    QApplication::processEvents();
    const int i = static_cast<int>(plot->samples().size() / 3);
    const QPoint at = plot->pixelOfSample(i);
    QMouseEvent move(QEvent::MouseMove, at, plot->plot()->mapToGlobal(at), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(plot->plot(), &move);
    EXPECT_TRUE(plot->readout().startsWith(QStringLiteral("s = "))) << plot->readout().toStdString();
    // Within a pixel of sample i: its arc length to the read-out's two decimals, give or take a pixel's worth
    const double pixel = plot->arcLengths().back() / plot->plot()->width();
    EXPECT_NEAR(plot->readout().section(QLatin1Char(' '), 2, 2).toDouble(), plot->arcLengths()[static_cast<size_t>(i)], kHoverPixels * pixel);
    w.shoot(QStringLiteral("_plot"));

    // A pull (a drag's frames, no entitiesChanged until it ends): the plot follows the new shape
    w.model().beginPull(w.curve, 2.25);
    w.model().pullTo(w.entity().local->evaluate(2.25) + Eigen::Vector3d(0, 30, 0));
    w.window.document().scheduler().flush();
    QApplication::processEvents();
    const solvers::Curve2d pulled = aes::planarCurve(*w.entity().local);
    const double u1 = pulled.domainEnd();
    const size_t n = plot->samples().size();
    for (size_t k : {n / 4, n / 2, 3 * n / 4}) {
        const double u = u1 * static_cast<double>(k) / static_cast<double>(n - 1);
        EXPECT_NEAR(plot->samples()[k], aes::signedCurvature(pulled, u), kRoundOff) << k;
    }
    EXPECT_NE(aes::signedCurvature(pulled, 0.75 * u1), aes::signedCurvature(aes::planarCurve(sCurve()), 0.75 * u1));
    w.model().endDrag();
}

TEST(AestheticsDock, TellsWhyACurveCannotBeAnalysed)
{
    guitest::startApplication("aesthetics_dock_test");
    SCurveWindow w;
    // The default scene's curve 2 wanders in space
    w.window.document().select(kSpaceCurve);
    QApplication::processEvents();
    EXPECT_TRUE(w.dock().message().contains(QStringLiteral("not planar — analysis needs a planar curve"))) << w.dock().message().toStdString();
    EXPECT_EQ(w.dock().pointTable()->rowCount(), 0);
    EXPECT_TRUE(w.dock().measureText(QStringLiteral("length")).isEmpty());
    auto* plot = w.window.findChild<CurvaturePlot*>();
    EXPECT_FALSE(plot->isSigned());
    EXPECT_TRUE(plot->title().contains(QStringLiteral("not planar")));
    // Its comb is the Frenet one: every tooth along C'' - (C''.T)T, none zero
    w.window.action(QStringLiteral("view.curvatureComb"))->trigger();
    ASSERT_EQ(w.comb().curve(), kSpaceCurve);
    ASSERT_FALSE(w.comb().teeth().empty());
    for (const scene::CombTooth& t : w.comb().teeth()) {
        const auto d = w.model().find(kSpaceCurve)->world->derivatives(t.u, 1);
        EXPECT_NEAR(t.curvatureVector.dot(d[1]), 0.0, kPerpendicularRelative * t.curvatureVector.norm() * d[1].norm()) << t.u;
    }
    // A polyline (degree 1) on the plane
    const model::EntityId line = w.model().addCurve(kPlane, solvers::Curve3d(1, {0, 0, 1, 2, 2}, {{-20, 0, 0}, {0, 10, 0}, {20, 0, 0}}));
    w.window.document().scheduler().flush();
    w.window.document().select(line);
    QApplication::processEvents();
    EXPECT_TRUE(w.dock().message().contains(QStringLiteral("degree 1"))) << w.dock().message().toStdString();
    // And back to a curve it can analyse: the message goes
    w.window.document().select(w.curve);
    QApplication::processEvents();
    EXPECT_TRUE(w.dock().message().isEmpty());
    w.expectDockMatches(w.expected());
}

}  // namespace
}  // namespace sculptline::ui
