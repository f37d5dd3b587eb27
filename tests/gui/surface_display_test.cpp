// View > Surface display in the real window under Xvfb, on a revolved bottle with a neck and a
// swept handle (data/models/bottle_surfaces.json: the bottle replay's result; surfaces 8 and 9
// revolved, 10 swept). The curvature colours are the map of K or H at each vertex and show on
// screen where the surface is seen; the zebra's stripes multiply with the setting, on screen too;
// after the profile changes, the colours are those of the new surface.
#include "model/document.h"
#include "scene/model_view.h"
#include "scene/surface_analysis_display.h"
#include "solvers/bspline/surface_curvature.h"
#include "ui/main_window.h"
#include "ui/sketch_document.h"
#include "ui/surface_display_menu.h"

#include <Inventor/Qt/SoQt.h>
#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>
#include <Inventor/SoDB.h>
#include <Inventor/SoPickedPoint.h>
#include <Inventor/actions/SoRayPickAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoTextureCoordinate2.h>
#include <Inventor/sensors/SoSensorManager.h>

#include <QAction>
#include <QApplication>
#include <QElapsedTimer>
#include <QKeySequence>
#include <QWindow>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>

namespace sculptline::ui {
namespace {

constexpr model::EntityId kBottle = 8, kNeck = 9, kHandle = 10, kProfile = 4;
constexpr qint64 kExposeDeadlineMs = 5000;
/// Float colours against the map's doubles: far below an 8-bit step.
constexpr float kColourTolerance = 1e-6f;
/// A ray pick through a vertex's pixel lands within this of the vertex when the vertex is what is
/// seen there (mm; the bottle is about 80 mm across, a pixel about 0.2 mm at this framing).
constexpr float kSeenDistance = 0.6f;
/// On screen, a saturated red or blue vertex differs from the other hue by at least this (of 255):
/// the map's ends differ by 0.85 * 255 = 217; the neighbouring vertices' interpolation and a
/// pixel's rounding take at most half of it where |t| >= 0.8.
constexpr int kHueMargin = 80;
/// Luminance thresholds of the zebra's black and white on screen (unlit, 0 and 255 texels).
constexpr int kDark = 70, kBright = 185;
/// Long enough for the delay queue (camera sensor) and a redraw (0.1-2 s a frame under Xvfb).
constexpr qint64 kIdleMs = 1500;

void startApplication()
{
    static int argc = 1;
    static char name[] = "surface_display_test";
    static char* argv[] = {name, nullptr};
    static QApplication* app = nullptr;
    if (app) return;
    app = new QApplication(argc, argv);
    SoQt::init(static_cast<QWidget*>(nullptr));
}

struct BottleWindow {
    MainWindow window;
    BottleWindow()
    {
        window.showDocument(model::loadDocument(SCULPTLINE_DATA_DIR "/models/bottle_surfaces.json"), QString());
        // Landscape: MainWindow::pixelOf() projects without the taller view volume Coin's
        // ADJUST_CAMERA mapping renders a portrait viewport with.
        window.setViewportSize(960, 720);
        window.show();
        QElapsedTimer waited;
        waited.start();
        while (!(window.windowHandle() && window.windowHandle()->isExposed()) && waited.elapsed() < kExposeDeadlineMs)
            QApplication::processEvents(QEventLoop::AllEvents, 50);
        trigger("view.hidePlanes");  // the translucent planes would tint the colours behind them
        window.renderViewport();
        QApplication::processEvents();
    }
    void trigger(const char* name)
    {
        QAction* a = window.action(QString::fromLatin1(name));
        ASSERT_NE(a, nullptr) << name;
        a->trigger();
        QApplication::processEvents();
    }
    scene::SurfaceAnalysisDisplay& analysis() { return window.document().view().surfaceAnalysis(); }
    const model::Entity& entity(model::EntityId id) { return *window.document().model().find(id); }
    SoSeparator* node(model::EntityId id) { return window.document().view().nodeOf(id); }
    /// The viewport's picture; also written to $SCULPTLINE_SURFACE_DISPLAY_SHOT with `suffix`
    /// before its extension (when set), for a person to look at.
    QImage frame(const QString& suffix = QString())
    {
        window.renderViewport();
        QImage image = window.grabViewport();
        const char* shot = std::getenv("SCULPTLINE_SURFACE_DISPLAY_SHOT");
        if (shot && !suffix.isEmpty()) {
            QString path = QString::fromLocal8Bit(shot);
            path.insert(path.endsWith(QStringLiteral(".png")) ? path.size() - 4 : path.size(), suffix);
            image.scaledToWidth(800, Qt::SmoothTransformation).save(path);
        }
        return image;
    }
    /// True when the vertex at `p` is what the viewport shows at its pixel.
    /// Draws no curve from now on: a curve lying on a surface covers, a line's width around it, the
    /// colour of the vertices it runs over (at 960 x 720 the profile covers one of the bottle's).
    void hideCurves()
    {
        for (const auto& [id, entity] : window.document().model().entities()) {
            if (entity.kind != model::EntityKind::Curve) continue;
            auto* invisible = new SoDrawStyle;
            invisible->style = SoDrawStyle::INVISIBLE;
            invisible->setOverride(TRUE);  // over the curve's own draw style
            node(id)->insertChild(invisible, 0);
        }
    }
    bool seen(const SbVec3f& p)
    {
        const QPoint pixel = window.pixelOf(Eigen::Vector3d(p[0], p[1], p[2]));
        const SbViewportRegion& region = window.viewer()->getViewportRegion();
        const short height = region.getViewportSizePixels()[1];
        SoRayPickAction pick(region);
        pick.setPoint(SbVec2s(static_cast<short>(pixel.x()), static_cast<short>(height - 1 - pixel.y())));
        pick.apply(window.viewer()->getSceneManager()->getSceneGraph());
        const SoPickedPoint* hit = pick.getPickedPoint();
        return hit && (hit->getPoint() - p).length() < kSeenDistance;
    }
};

template <typename Node>
Node* findIn(SoNode* root, const char* name)
{
    SoSearchAction byName;
    byName.setName(name);
    byName.apply(root);
    if (!byName.getPath()) return nullptr;
    SoSearchAction byType;
    byType.setType(Node::getClassTypeId());
    byType.apply(byName.getPath()->getTail());
    return byType.getPath() ? static_cast<Node*>(byType.getPath()->getTail()) : nullptr;
}

/// Every vertex colour of surface `id` is the map's colour of K (or H) at the vertex's parameters.
void expectColoursOfCurvature(BottleWindow& w, model::EntityId id, bool gaussian)
{
    const auto* material = findIn<SoMaterial>(w.node(id), "SurfaceAnalysis");
    ASSERT_NE(material, nullptr);
    const std::vector<double>& u = *w.analysis().gridU(id);
    const std::vector<double>& v = *w.analysis().gridV(id);
    const double range = w.analysis().legend(id)->range;
    ASSERT_EQ(material->diffuseColor.getNum(), static_cast<int>(u.size() * v.size()));
    int checked = 0;
    for (size_t r = 0; r < u.size(); ++r)
        for (size_t c = 0; c < v.size(); ++c) {
            const solvers::SurfaceCurvature k = solvers::surfaceCurvature(*w.entity(id).surface, u[r], v[c]);
            if (!k.defined) continue;
            const SbColor expected = scene::divergingColor((gaussian ? k.gaussian : k.mean) / range);
            const SbColor drawn = material->diffuseColor[static_cast<int>(r * v.size() + c)];
            for (int ch = 0; ch < 3; ++ch) ASSERT_NEAR(drawn[ch], expected[ch], kColourTolerance) << id << ": " << r << ", " << c;
            ++checked;
        }
    EXPECT_GT(checked, static_cast<int>(u.size() * v.size() * 9 / 10));
}

/// Dark-to-bright and bright-to-dark changes along the frame's column x between rows y0 and y1.
int stripeEdges(const QImage& image, int x, int y0, int y1)
{
    int edges = 0, last = -1;
    for (int y = std::max(0, y0); y <= std::min(image.height() - 1, y1); ++y) {
        const int l = qGray(image.pixel(x, y));
        const int state = l < kDark ? 0 : l > kBright ? 1 : -1;
        if (state < 0) continue;
        if (last >= 0 && state != last) ++edges;
        last = state;
    }
    return edges;
}

}  // namespace

TEST(SurfaceDisplay, ShortcutsOfAllNamedActionsAreDistinct)
{
    startApplication();
    MainWindow window(nullptr, false);
    std::map<QString, QString> owner;
    for (QAction* a : window.namedActions())
        for (const QKeySequence& key : a->shortcuts()) {
            const QString text = key.toString();
            EXPECT_TRUE(owner.emplace(text, a->objectName()).second)
                << text.toStdString() << ": " << owner[text].toStdString() << " and " << a->objectName().toStdString();
        }
    EXPECT_EQ(window.action(QStringLiteral("view.surfaceZebra"))->shortcut(), QKeySequence(QStringLiteral("Alt+2")));
}

TEST(SurfaceDisplay, GivenNothingSelected_WhenGaussian_ThenEverySurfaceIsColouredByKAndTheScreenShowsIt)
{
    startApplication();
    BottleWindow w;
    w.window.document().select(0);
    w.trigger("view.surfaceGaussian");
    for (model::EntityId id : {kBottle, kNeck, kHandle}) {
        EXPECT_EQ(w.analysis().mode(id), scene::SurfaceDisplay::Gaussian) << id;
        expectColoursOfCurvature(w, id, true);
    }
    // The bottle's bulb is elliptic (red), its waist into the neck hyperbolic (blue): on screen,
    // where a saturated vertex is what is seen, its pixel has the hue of its colour.
    w.hideCurves();
    const QImage image = w.frame(QStringLiteral("_gaussian"));
    SoSearchAction search;
    search.setType(SoCoordinate3::getClassTypeId());
    search.apply(w.node(kBottle));
    const auto* coords = static_cast<SoCoordinate3*>(search.getPath()->getTail());
    const std::vector<double>& values = *w.analysis().values(kBottle);
    const double range = w.analysis().legend(kBottle)->range;
    // Vertices on knot lines are under the iso-lines (drawn in a darker surface colour): skipped.
    const solvers::Surface3d& bottle = *w.entity(kBottle).surface;
    const std::vector<double>& u = *w.analysis().gridU(kBottle);
    const std::vector<double>& v = *w.analysis().gridV(kBottle);
    auto onKnot = [](const solvers::KnotVector& knots, double t) { return std::find(knots.begin(), knots.end(), t) != knots.end(); };
    int red = 0, blue = 0;
    for (int i = 0; i < coords->point.getNum(); ++i) {
        const double t = values[static_cast<size_t>(i)] / range;
        const size_t r = static_cast<size_t>(i) / v.size(), c = static_cast<size_t>(i) % v.size();
        if (std::abs(t) < 0.8 || onKnot(bottle.knotsU(), u[r]) || onKnot(bottle.knotsV(), v[c]) || !w.seen(coords->point[i])) continue;
        const QPoint pixel = w.window.pixelOf(Eigen::Vector3d(coords->point[i][0], coords->point[i][1], coords->point[i][2]));
        // The hue of most of the 3 x 3 pixels around it (an iso-line may pass one pixel away).
        int agree = 0;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const QColor p = image.pixelColor(pixel + QPoint(dx, dy));
                agree += (t > 0 ? p.red() - p.blue() : p.blue() - p.red()) > kHueMargin;
            }
        EXPECT_GE(agree, 5) << i << " t " << t << " at " << pixel.x() << ", " << pixel.y() << ": "
                            << image.pixelColor(pixel).name().toStdString();
        ++(t > 0 ? red : blue);
    }
    EXPECT_GT(red, 0);
    EXPECT_GT(blue, 0);
    // The legend says what the colours stand for
    const SurfaceDisplayMenu* menu = w.window.findChild<SurfaceDisplayMenu*>();
    ASSERT_NE(menu, nullptr);
    EXPECT_TRUE(menu->legendText().contains(QStringLiteral("Gaussian"))) << menu->legendText().toStdString();
}

TEST(SurfaceDisplay, GivenTheBottleSelected_WhenZebraAndMoreStripes_ThenOnlyItIsStripedAndTheStripesMultiply)
{
    startApplication();
    BottleWindow w;
    w.window.document().select(0);
    w.trigger("view.surfaceMean");
    w.window.document().select(kBottle);
    w.trigger("view.surfaceZebra");
    EXPECT_EQ(w.analysis().mode(kBottle), scene::SurfaceDisplay::Zebra);
    EXPECT_EQ(w.analysis().mode(kNeck), scene::SurfaceDisplay::Mean);  // the others keep theirs
    EXPECT_TRUE(w.window.action(QStringLiteral("view.surfaceZebra"))->isChecked());
    auto* texture = findIn<SoTextureCoordinate2>(w.node(kBottle), "SurfaceAnalysis");
    ASSERT_NE(texture, nullptr);
    // The stripes follow the viewer's camera: still while it is still, restriped when it turns.
    auto idle = [](qint64 ms) {
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < ms) QApplication::processEvents(QEventLoop::AllEvents, 20);
    };
    w.frame();
    idle(kIdleMs);
    const int updates = w.analysis().cameraUpdates();
    const SbVec2f first = texture->point[0];
    w.frame();
    idle(kIdleMs);
    EXPECT_EQ(w.analysis().cameraUpdates(), updates);
    SoCamera* camera = w.window.viewer()->getCamera();
    const SbRotation turned = camera->orientation.getValue() * SbRotation(SbVec3f(0, 0, 1), 0.3f);
    camera->orientation = turned;
    idle(kIdleMs);
    EXPECT_GT(w.analysis().cameraUpdates(), updates);
    EXPECT_NE(texture->point[0], first);
    camera->orientation = turned * SbRotation(SbVec3f(0, 0, 1), -0.3f);
    idle(kIdleMs);
    auto periods = [&]() {
        std::set<int> seen;
        for (int i = 0; i < texture->point.getNum(); ++i) seen.insert(static_cast<int>(std::floor(texture->point[i][0])));
        return static_cast<int>(seen.size());
    };
    // The bulb's middle column on screen, from above the bulb to below it
    const solvers::Surface3d& bottle = *w.entity(kBottle).surface;
    auto onAxis = [&](double u) { return Eigen::Vector3d((bottle.evaluate(u, 0.0) + bottle.evaluate(u, 0.5)) / 2); };
    const Eigen::Vector3d top = onAxis(0.9), bottom = onAxis(0.1);
    const int x = w.window.pixelOf(onAxis(0.4)).x();

    const int y0 = std::min(w.window.pixelOf(top).y(), w.window.pixelOf(bottom).y());
    const int y1 = std::max(w.window.pixelOf(top).y(), w.window.pixelOf(bottom).y());
    const int stripes = w.analysis().stripes();
    const int before = periods();
    const int edgesBefore = stripeEdges(w.frame(QStringLiteral("_zebra")), x, y0, y1);
    w.trigger("view.zebraMoreStripes");
    w.trigger("view.zebraMoreStripes");
    EXPECT_EQ(w.analysis().stripes(), static_cast<int>(std::lround(std::lround(stripes * 1.5) * 1.5)));
    const double factor = static_cast<double>(w.analysis().stripes()) / stripes;
    // A span L of coordinates meets between L and L + 1 integers (see surface_analysis_test).
    EXPECT_GE(periods(), static_cast<int>(std::floor((before - 1) * factor)));
    const int edgesAfter = stripeEdges(w.frame(QStringLiteral("_zebra_more")), x, y0, y1);
    EXPECT_GE(edgesBefore, 4);
    // On screen the column crosses about factor (2.25) times as many edges; at least 1.5 times
    // (an edge at the column's ends may be lost or gained, and thin stripes merge near silhouettes).
    EXPECT_GE(edgesAfter, edgesBefore * 3 / 2) << edgesBefore << " -> " << edgesAfter;
    // And back to shaded: the plain node
    w.trigger("view.surfaceShaded");
    EXPECT_EQ(w.analysis().mode(kBottle), scene::SurfaceDisplay::Shaded);
    EXPECT_EQ(findIn<SoTextureCoordinate2>(w.node(kBottle), "SurfaceAnalysis"), nullptr);
}

TEST(SurfaceDisplay, GivenMeanCurvature_WhenTheProfileChanges_ThenTheColoursFollowTheNewSurface)
{
    startApplication();
    BottleWindow w;
    w.window.document().select(kBottle);
    w.trigger("view.surfaceMean");
    const std::vector<double> before = *w.analysis().values(kBottle);
    // When the profile's control points move out by 10% (in its plane's frame)
    model::Model& model = w.window.document().model();
    const solvers::Curve3d& local = *model.find(kProfile)->local;
    std::vector<Eigen::Vector3d> points = local.points();
    for (Eigen::Vector3d& p : points) p.x() *= 1.1;
    model.setCurveShape(kProfile, solvers::Curve3d(local.degree(), local.knots(), points, local.weights()));
    model.update();
    QApplication::processEvents();
    // Then the colours are those of the new surface's H
    expectColoursOfCurvature(w, kBottle, false);
    EXPECT_NE(*w.analysis().values(kBottle), before);
}

TEST(SurfaceDisplay, GivenZebraOnAllSurfaces_WhenTheDocumentIsOpenedAgain_ThenItsSurfacesAreStripedThroughTheNewCamera)
{
    startApplication();
    BottleWindow w;
    w.window.document().select(0);
    w.trigger("view.surfaceZebra");
    // When the same document is opened again (new entities, a new camera in the viewer)
    w.window.showDocument(model::loadDocument(SCULPTLINE_DATA_DIR "/models/bottle_surfaces.json"), QString());
    QApplication::processEvents();
    // Then the all-surfaces mode stays, and the zebra looks through the viewer's camera of now
    EXPECT_EQ(w.analysis().mode(kBottle), scene::SurfaceDisplay::Zebra);
    EXPECT_TRUE(w.window.action(QStringLiteral("view.surfaceZebra"))->isChecked());
    SoCamera* camera = w.window.viewer()->getCamera();
    ASSERT_NE(camera, nullptr);
    EXPECT_EQ(w.analysis().camera(), camera);
    auto* texture = findIn<SoTextureCoordinate2>(w.node(kBottle), "SurfaceAnalysis");
    ASSERT_NE(texture, nullptr);
    const SbVec2f first = texture->point[0];
    const int updates = w.analysis().cameraUpdates();
    camera->orientation = camera->orientation.getValue() * SbRotation(SbVec3f(0, 0, 1), 0.3f);
    SoDB::getSensorManager()->processDelayQueue(FALSE);
    EXPECT_GT(w.analysis().cameraUpdates(), updates);
    EXPECT_NE(texture->point[0], first);
}

}  // namespace sculptline::ui
