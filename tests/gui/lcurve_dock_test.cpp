// The L-curve dock and the state colours with a real display (run under Xvfb by ctest), on
// data/incidence_arches.json: a flat 9 x 9 bicubic sheet (surface 5) with two 12 mm arches on it by
// curve-on-surface constraints, curve 3 free on plane 1 and curve 4 fixed on plane 2 (seed 000 §3.2:
// the fixed one is met exactly, the free one softly at the L-curve's truncation). Writes the whole
// window, viewport included, to $SCULPTLINE_LCURVE_SHOT (when set) so a person can look at the dock.
#include "model/document.h"
#include "scene/model_view.h"
#include "scene/state_colors.h"
#include "ui/entity_list_dock.h"
#include "ui/lcurve_dock.h"
#include "tests/gui/window_shot.h"
#include "ui/main_window.h"
#include "ui/sketch_document.h"

#include <Inventor/Qt/SoQt.h>
#include <Inventor/nodes/SoBaseColor.h>
#include <Inventor/nodes/SoSeparator.h>

#include <QAction>
#include <QApplication>
#include <QGLWidget>
#include <QMouseEvent>
#include <QPainter>
#include <QPushButton>
#include <QToolTip>
#include <QUndoStack>
#include <QWindow>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

namespace sculptline::ui {
namespace {

constexpr model::EntityId kPlane = 1, kFreeCurve = 3, kFixedCurve = 4, kSheet = 5;
/// A point to click must lie this many pixels from every other, so that the click can only mean it.
constexpr double kClickClearance = 4.0;

void startApplication() { guitest::startApplication("lcurve_dock_test"); }

/// The main window on the two arches, shown, with the sheet selected.
struct ArchesWindow {
    MainWindow window;
    ArchesWindow()
    {
        window.showDocument(model::loadDocument(SCULPTLINE_DATA_DIR "/incidence_arches.json"), QString());
        window.resize(1280, 900);
        window.show();
        window.document().select(kSheet);
        QApplication::processEvents();
    }
    LCurveDock& dock() { return *window.findChild<LCurveDock*>(); }
    const model::Entity& sheet() { return *window.document().model().find(kSheet); }
    /// A left click at `pixel` of the plot, as a person's press and release.
    void click(const QPoint& pixel)
    {
        QWidget* plot = dock().plot();
        QMouseEvent press(QEvent::MouseButtonPress, pixel, plot->mapToGlobal(pixel), Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(plot, &press);
        QMouseEvent release(QEvent::MouseButtonRelease, pixel, plot->mapToGlobal(pixel), Qt::LeftButton, Qt::NoButton, Qt::NoModifier);
        QApplication::sendEvent(plot, &release);
        QApplication::processEvents();  // the document's queued entitiesChanged refreshes the dock
    }
    /// Writes the whole window, viewport included, to $SCULPTLINE_LCURVE_SHOT with `suffix` before
    /// its extension (when the variable is set), for a person to look at.
    void shoot(const QString& suffix)
    {
        const char* shot = std::getenv("SCULPTLINE_LCURVE_SHOT");
        if (!shot) return;
        QString path = QString::fromLocal8Bit(shot);
        path.insert(path.endsWith(QStringLiteral(".png")) ? path.size() - 4 : path.size(), suffix);
        guitest::saveWindowShot(window, path);
    }
    /// A k other than the used one and the corner whose point is clear of all others on screen.
    int clearPoint()
    {
        const model::Entity::IncidenceReport& r = *sheet().incidence;
        for (int j = 1; j <= dock().pointCount(); ++j) {
            if (j == r.k || j == r.corner) continue;
            bool clear = true;
            for (int i = 1; i <= dock().pointCount(); ++i) {
                const QPoint d = dock().pixelOf(i) - dock().pixelOf(j);
                if (i != j && std::hypot(d.x(), d.y()) < kClickClearance) clear = false;
            }
            if (clear) return j;
        }
        return 0;
    }
};

QColor toQColor(const scene::Rgb& c) { return QColor::fromRgbF(c[0], c[1], c[2]); }

/// Two colours alike on an 8-bit screen (a swatch's pixmap keeps 8 bits a channel, rounded).
::testing::AssertionResult sameColour(const QColor& a, const QColor& b)
{
    if (a.isValid() && b.isValid() && std::abs(a.red() - b.red()) <= 1 && std::abs(a.green() - b.green()) <= 1 &&
        std::abs(a.blue() - b.blue()) <= 1)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << a.name().toStdString() << " is not " << b.name().toStdString();
}

/// The colour curve `id` is drawn with: its node's SoBaseColor (scene/geometry_nodes.cpp's curveRoot).
QColor viewportColor(MainWindow& window, model::EntityId id)
{
    SoSeparator* node = window.document().view().nodeOf(id);
    for (int k = 0; node && k < node->getNumChildren(); ++k) {
        if (!node->getChild(k)->isOfType(SoBaseColor::getClassTypeId())) continue;
        const SbColor& c = static_cast<SoBaseColor*>(node->getChild(k))->rgb[0];
        return QColor::fromRgbF(c[0], c[1], c[2]);
    }
    return {};
}

TEST(LCurveDock, ShowsTheSelectedSurfacesLCurveWithTheUsedKAtTheCorner)
{
    // Given the sheet, solved by incidence at the L-curve's corner, selected
    startApplication();
    ArchesWindow w;
    ASSERT_TRUE(w.sheet().incidence) << w.sheet().buildError;
    const model::Entity::IncidenceReport& r = *w.sheet().incidence;
    // Then the dock is in front and plots one point per truncation k = 1..r
    EXPECT_TRUE(w.dock().isVisible());
    EXPECT_EQ(w.dock().surface(), kSheet);
    ASSERT_GT(r.rho.size(), 2u);
    EXPECT_EQ(w.dock().pointCount(), static_cast<int>(r.rho.size()));
    // with the used k on the corner's point, and no separate corner marker
    EXPECT_EQ(r.k, r.corner);
    EXPECT_EQ(w.dock().usedMarker(), r.k);
    EXPECT_EQ(w.dock().cornerMarker(), std::nullopt);
    EXPECT_TRUE(w.dock().summary().contains(QStringLiteral("k = %1 of %2 (the corner)").arg(r.k).arg(r.rho.size())))
        << w.dock().summary().toStdString();
    EXPECT_TRUE(w.dock().summary().contains(QStringLiteral("residual"))) << w.dock().summary().toStdString();
    // and the corner's point lies inside the plot, where a person can click it
    EXPECT_TRUE(w.dock().plot()->rect().contains(w.dock().pixelOf(r.corner)));
    // Hovering a point reads out its k, ρ and η
    const QPoint atCorner = w.dock().pixelOf(r.corner);
    QMouseEvent move(QEvent::MouseMove, atCorner, w.dock().plot()->mapToGlobal(atCorner), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(w.dock().plot(), &move);
    EXPECT_TRUE(QToolTip::text().startsWith(QStringLiteral("k = %1 (corner)").arg(r.corner))) << QToolTip::text().toStdString();
    // View > L-curve hides and shows the dock
    QAction* toggle = w.window.action(QStringLiteral("view.lcurve"));
    ASSERT_NE(toggle, nullptr);
    EXPECT_TRUE(toggle->isChecked());
    toggle->trigger();
    EXPECT_TRUE(w.dock().isHidden());
    toggle->trigger();
    EXPECT_FALSE(w.dock().isHidden());
    bool inViewMenu = false;
    for (QWidget* menu : toggle->associatedWidgets()) inViewMenu |= menu->actions().contains(w.window.action(QStringLiteral("view.all")));
    EXPECT_TRUE(inViewMenu);
    w.window.document().select(kSheet);
    QApplication::processEvents();

    w.shoot("");
}

TEST(LCurveDock, ACurveOnTheSurfaceShowsItsLCurveAndNothingSelectedExplains)
{
    startApplication();
    ArchesWindow w;
    // When the free arch is selected, the dock shows the L-curve of the sheet it lies on
    w.window.document().select(kFreeCurve);
    QApplication::processEvents();
    EXPECT_EQ(w.dock().surface(), kSheet);
    EXPECT_GT(w.dock().pointCount(), 2);
    // When nothing is, it plots nothing and says why
    w.window.document().select(0);
    QApplication::processEvents();
    EXPECT_EQ(w.dock().surface(), 0u);
    EXPECT_EQ(w.dock().pointCount(), 0);
    EXPECT_TRUE(w.dock().summary().startsWith(QStringLiteral("No L-curve"))) << w.dock().summary().toStdString();
}

TEST(LCurveDock, AClickOnAPointSolvesAtThatKUndoablyAndTheCornerGoesBack)
{
    // (Each solve starts from the surface's prior F0, its shape before the first curve
    // (model/model.h Entity::prior): the result depends on the curves and k only.)
    startApplication();
    ArchesWindow w;
    ASSERT_TRUE(w.sheet().incidence);
    const int j = w.clearPoint();
    ASSERT_NE(j, 0) << "no point clear of the others";
    const std::vector<Eigen::Vector3d> atCorner = w.sheet().surface->points();
    // When point j is clicked
    w.click(w.dock().pixelOf(j));
    // Then the sheet is solved again truncated at k = j: a different surface, the markers moved
    EXPECT_EQ(w.sheet().incidenceK, j);
    ASSERT_TRUE(w.sheet().incidence);
    EXPECT_EQ(w.sheet().incidence->k, j);
    EXPECT_NE(w.sheet().surface->points(), atCorner);
    EXPECT_EQ(w.dock().usedMarker(), j);
    const int corner = w.sheet().incidence->corner;
    EXPECT_EQ(w.dock().cornerMarker(), corner == j ? std::nullopt : std::optional<int>(corner));
    EXPECT_TRUE(w.dock().summary().contains(QStringLiteral("k = %1 of %2 (chosen; corner %3)").arg(j).arg(w.dock().pointCount()).arg(corner)))
        << w.dock().summary().toStdString();
    w.shoot(QStringLiteral("_chosen"));
    // When it is undone, the sheet follows the corner again (k = 0), the marker on it: the very
    // surface it had (the same solve from the same prior)
    w.window.document().undoStack()->undo();
    QApplication::processEvents();
    EXPECT_EQ(w.sheet().incidenceK, 0);
    EXPECT_EQ(w.sheet().surface->points(), atCorner);
    EXPECT_EQ(w.sheet().incidence->k, w.sheet().incidence->corner);
    EXPECT_EQ(w.dock().usedMarker(), w.sheet().incidence->corner);
    EXPECT_EQ(w.dock().cornerMarker(), std::nullopt);
    // When redone and then the corner's point is clicked, the sheet follows the corner again (k = 0)
    w.window.document().undoStack()->redo();
    QApplication::processEvents();
    ASSERT_EQ(w.sheet().incidenceK, j);
    ASSERT_NE(w.sheet().incidence->corner, j);
    w.click(w.dock().pixelOf(w.sheet().incidence->corner));
    EXPECT_EQ(w.sheet().incidenceK, 0);
    EXPECT_EQ(w.sheet().incidence->k, w.sheet().incidence->corner);
    // and "Use the corner" does the same from another k
    w.click(w.dock().pixelOf(j));
    ASSERT_EQ(w.sheet().incidenceK, j);
    QPushButton* useCorner = nullptr;
    for (QPushButton* b : w.dock().findChildren<QPushButton*>()) {
        if (b->text() == QStringLiteral("Use the corner")) useCorner = b;
    }
    ASSERT_NE(useCorner, nullptr);
    EXPECT_TRUE(useCorner->isEnabled());
    useCorner->click();
    QApplication::processEvents();
    EXPECT_EQ(w.sheet().incidenceK, 0);
    EXPECT_FALSE(useCorner->isEnabled());
    // A click beside every point changes nothing
    const int depth = w.window.document().undoStack()->count();
    w.click(QPoint(2, 2));
    EXPECT_EQ(w.window.document().undoStack()->count(), depth);
}

TEST(StateColours, FixedAndFreeCurvesDifferAlikeInTheListAndTheViewport)
{
    startApplication();
    ArchesWindow w;
    auto* list = w.window.findChild<EntityListDock*>();
    ASSERT_NE(list, nullptr);
    const int freeRow = list->rowOf(QStringLiteral("Curve %1 ").arg(kFreeCurve));
    const int fixedRow = list->rowOf(QStringLiteral("Curve %1 ").arg(kFixedCurve));
    ASSERT_GE(freeRow, 0);
    ASSERT_GE(fixedRow, 0);
    // The fixed arch's swatch is the fixed colour, the free one's its free colour: they differ
    EXPECT_TRUE(sameColour(list->swatchColor(fixedRow), toQColor(scene::fixedColor())));
    EXPECT_TRUE(sameColour(list->swatchColor(freeRow), toQColor(scene::freeCurveColor(kFreeCurve))));
    EXPECT_FALSE(sameColour(list->swatchColor(fixedRow), list->swatchColor(freeRow)));
    // and the viewport draws each arch in its row's colour
    EXPECT_TRUE(sameColour(viewportColor(w.window, kFixedCurve), list->swatchColor(fixedRow)));
    EXPECT_TRUE(sameColour(viewportColor(w.window, kFreeCurve), list->swatchColor(freeRow)));
    // The curve-on-surface constraints are listed, exact for the fixed arch and soft for the free one
    EXPECT_GE(list->rowOf(QStringLiteral("Constraint")), 0);
    bool exact = false, soft = false;
    for (int row = 0; row < 64; ++row) {
        if (list->rowOf(QStringLiteral("Constraint c%1 (curve %2 on surface %3, exact)").arg(row).arg(kFixedCurve).arg(kSheet)) >= 0) exact = true;
        if (list->rowOf(QStringLiteral("Constraint c%1 (curve %2 on surface %3, soft)").arg(row).arg(kFreeCurve).arg(kSheet)) >= 0) soft = true;
    }
    EXPECT_TRUE(exact);
    EXPECT_TRUE(soft);
    // When the free arch is fixed too, both places show it fixed
    w.window.document().model().setFixed(kFreeCurve, true);
    w.window.document().model().update();
    list->refresh(w.window.document().model(), 0);
    EXPECT_TRUE(sameColour(list->swatchColor(list->rowOf(QStringLiteral("Curve %1 ").arg(kFreeCurve))), toQColor(scene::fixedColor())));
    EXPECT_TRUE(sameColour(viewportColor(w.window, kFreeCurve), toQColor(scene::fixedColor())));
}

TEST(StateColours, ADragShowsTheCurvesItMovesChangedUntilItEnds)
{
    startApplication();
    ArchesWindow w;
    w.window.document().select(0);  // the selection's white would hide the state's colour
    QApplication::processEvents();
    model::Model& model = w.window.document().model();
    auto* list = w.window.findChild<EntityListDock*>();
    // When the free arch's plane is dragged 4 mm
    model.beginDrag(kPlane);
    model::PlaneFrame moved = model.find(kPlane)->frame;
    moved.origin.y() += 4.0;
    model.setPlaneFrame(kPlane, moved);
    model.update();
    // Then, during the drag, the arch it carries shows changed in the viewport and the list, the
    // fixed arch stays fixed
    EXPECT_EQ(scene::shownState(model, kFreeCurve), model::State::Changed);
    EXPECT_TRUE(sameColour(viewportColor(w.window, kFreeCurve), toQColor(scene::changedColor())));
    EXPECT_TRUE(sameColour(viewportColor(w.window, kFixedCurve), toQColor(scene::fixedColor())));
    list->refresh(model, 0);
    EXPECT_TRUE(sameColour(list->swatchColor(list->rowOf(QStringLiteral("Curve %1 ").arg(kFreeCurve))), toQColor(scene::changedColor())));
    // When the drag ends, it is free again
    model.endDrag();
    model.update();
    w.window.document().view().refineSurfaces();
    EXPECT_EQ(scene::shownState(model, kFreeCurve), model::State::Free);
    EXPECT_TRUE(sameColour(viewportColor(w.window, kFreeCurve), toQColor(scene::freeCurveColor(kFreeCurve))));
}

}  // namespace
}  // namespace sculptline::ui
