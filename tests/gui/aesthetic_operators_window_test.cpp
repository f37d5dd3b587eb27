// The aesthetic operators in the real window (run under Xvfb by ctest): thesis Fig. 7-17's curve
// ("M+0m-0M+", y = x^4 - x^2/2 scaled 40 times) on the default scene's plane 1, selected. The
// Aesthetics dock's Straighten button makes it "M+" in one undo step (the status bar says the names),
// Ctrl+Z gives the curve back exactly; the Aesthetics menu's entries apply the same operators; the
// handle combo puts the operator's arrow on the operated point, and dragging it (the dragger's own
// event path, simulated through Coin) moves the curve live and leaves one undo step. Writes the window
// to $SCULPTLINE_OPERATORS_SHOT (when set) so a person can look at it.
#include "manipulators/aesthetic_drag.h"
#include "model/document.h"
#include "solvers/aesthetics/curve_operators.h"
#include "tests/aesthetics/graph_curves.h"
#include "tests/gui/coin_mouse.h"
#include "tests/gui/window_shot.h"
#include "ui/aesthetics_dock.h"
#include "ui/main_window.h"
#include "ui/sketch_document.h"

#include <Inventor/draggers/SoTranslate1Dragger.h>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QStatusBar>
#include <QUndoStack>
#include <gtest/gtest.h>

#include <cstdlib>

namespace sculptline::ui {
namespace {

namespace aes = solvers::aesthetics;

constexpr model::EntityId kPlane = 1;
// Ends and undone shapes: round-off of the 50 mm coordinates.
constexpr double kRoundOff = 1e-9;

// Fig. 7-17's curve, an exact quartic in 8 spans, 40 times y = x^4 - x^2/2 on [-1.2, 1.2].
solvers::Curve3d wCurve() { return aes::spaceCurve(testcurves::figure717(40.0), aes::PlaneFrame{}); }

struct WWindow {
    MainWindow window;
    model::EntityId curve = 0;
    WWindow()
    {
        window.showDocument(model::loadDocument(SCULPTLINE_DATA_DIR "/default_scene.json"), QString());
        window.resize(1280, 960);
        window.show();
        curve = window.document().model().addCurve(kPlane, wCurve());
        window.document().scheduler().flush();
        window.document().select(curve);
        window.action(QStringLiteral("view.aesthetics"))->trigger();
        QApplication::processEvents();
    }
    SketchDocument& doc() { return window.document(); }
    AestheticsDock& dock() { return *window.findChild<AestheticsDock*>(); }
    const solvers::Curve3d& local() { return *doc().model().find(curve)->local; }
    std::string name() { return aes::analyzeCurve(aes::planarCurve(local())).name; }

    void shoot()
    {
        if (const char* shot = std::getenv("SCULPTLINE_OPERATORS_SHOT")) guitest::saveWindowShot(window, QString::fromLocal8Bit(shot));
    }
};

double maxDistance(const solvers::Curve3d& a, const solvers::Curve3d& b)
{
    double d = 0.0;
    for (int k = 0; k <= 100; ++k) d = std::max(d, (a.evaluate(k / 100.0) - b.evaluate(k / 100.0)).norm());
    return d;
}

TEST(AestheticOperatorsWindow, StraightenInTheDockIsOneUndoStepFromMplus0mminus0MplusToMplus)
{
    guitest::startApplication("aesthetic_operators_window_test");
    WWindow w;
    ASSERT_EQ(w.name(), "M+0m-0M+");
    const solvers::Curve3d before = w.local();
    const int steps = w.doc().undoStack()->count();
    // When Straighten is pressed in the dock
    QPushButton* straighten = w.dock().operatorButton(QStringLiteral("straighten"));
    ASSERT_NE(straighten, nullptr);
    straighten->click();
    QApplication::processEvents();
    // Then the curve is "M+" (Fig. 7-17), its ends where they were, in one undo step, and the status
    // bar says the names
    EXPECT_EQ(w.name(), "M+");
    EXPECT_LT((w.local().evaluate(0.0) - before.evaluate(0.0)).norm(), kRoundOff);
    EXPECT_LT((w.local().evaluate(1.0) - before.evaluate(1.0)).norm(), kRoundOff);
    EXPECT_EQ(w.doc().undoStack()->count(), steps + 1);
    const QString status = w.window.statusBar()->currentMessage();
    EXPECT_TRUE(status.contains(QStringLiteral("M+0m-0M+")) && status.contains(QStringLiteral("\"M+\""))) << status.toStdString();
    EXPECT_TRUE(w.dock().header().endsWith(QStringLiteral(": M+"))) << w.dock().header().toStdString();
    w.shoot();
    // And Ctrl+Z gives the curve back
    w.doc().undoStack()->undo();
    QApplication::processEvents();
    EXPECT_LT(maxDistance(w.local(), before), kRoundOff);
    EXPECT_EQ(w.name(), "M+0m-0M+");
}

TEST(AestheticOperatorsWindow, TheMenuAppliesAnOperatorAndSaysWhenItLimitsTheAmount)
{
    guitest::startApplication("aesthetic_operators_window_test");
    WWindow w;
    const solvers::Curve3d before = w.local();
    const int steps = w.doc().undoStack()->count();
    // When Aesthetics > Soften is chosen (a fiftieth of the curve's length)
    w.window.action(QStringLiteral("aesthetic.soften"))->trigger();
    QApplication::processEvents();
    // Then the curve changed, keeps its name and ends, in one undo step
    EXPECT_GT(maxDistance(w.local(), before), 1e-3);
    EXPECT_EQ(w.name(), "M+0m-0M+");
    EXPECT_EQ(w.doc().undoStack()->count(), steps + 1);
    // And a huge amount from the dock is limited to what keeps the name, and said so
    w.dock().amountBox()->setValue(50.0);
    w.dock().operatorButton(QStringLiteral("sharpen"))->click();
    QApplication::processEvents();
    EXPECT_EQ(w.name(), "M+0m-0M+");
    EXPECT_TRUE(w.window.statusBar()->currentMessage().contains(QStringLiteral("limited"))) << w.window.statusBar()->currentMessage().toStdString();
}

TEST(AestheticOperatorsWindow, TheHandleSitsOnTheOperatedPointAndADragOfItIsOneUndoStep)
{
    guitest::startApplication("aesthetic_operators_window_test");
    WWindow w;
    const solvers::Curve3d before = w.local();
    const int steps = w.doc().undoStack()->count();
    // When the dock's handle combo picks "tension"
    QComboBox* combo = w.dock().handleBox();
    const int index = combo->findData(static_cast<int>(aes::Operator::Tension));
    ASSERT_GE(index, 0);
    combo->setCurrentIndex(index);
    QApplication::processEvents();
    // Then no arrow: tension acts on an m+ or M- (a curvature minimum between maxima) and the W
    // ("M+0m-0M+") has none; the status bar says why
    const manipulators::AestheticHandle& handle = w.doc().aestheticHandle();
    EXPECT_FALSE(handle.visible());
    EXPECT_TRUE(w.window.statusBar()->currentMessage().contains(QStringLiteral("tension"))) << w.window.statusBar()->currentMessage().toStdString();
    // When "sharpen" is picked instead: on the sharpest M+
    combo->setCurrentIndex(combo->findData(static_cast<int>(aes::Operator::Sharpen)));
    QApplication::processEvents();
    ASSERT_TRUE(handle.visible());
    const manipulators::AestheticOperation op = manipulators::prepareAesthetic(w.doc().model(), w.curve, aes::Operator::Sharpen);
    // And dragged along its arrow through the dragger's own event path (Coin events on the handle's
    // scene, seen from an orthographic camera)
    guitest::CoinMouse mouse({w.doc().aestheticHandle().root()});
    const SbVec2s from = mouse.pixelOf(op.handle.point);
    const SbVec2s to = mouse.pixelOf(op.handle.point + op.handle.size * 0.5 * op.handle.direction);
    mouse.press(from);
    for (int i = 1; i <= 8; ++i) {
        mouse.move(SbVec2s(static_cast<short>(from[0] + (to[0] - from[0]) * i / 8), static_cast<short>(from[1] + (to[1] - from[1]) * i / 8)));
        w.doc().scheduler().flush();
    }
    mouse.release(to);
    QApplication::processEvents();
    // Then the curve followed, sharper, its ends kept, and the drag is one undo step
    EXPECT_GT(maxDistance(w.local(), before), 1e-3);
    EXPECT_LT((w.local().evaluate(0.0) - before.evaluate(0.0)).norm(), kRoundOff);
    EXPECT_EQ(w.doc().undoStack()->count(), steps + 1);
    EXPECT_EQ(w.doc().model().dragged(), 0u);
    w.doc().undoStack()->undo();
    QApplication::processEvents();
    EXPECT_LT(maxDistance(w.local(), before), kRoundOff);
}

}  // namespace
}  // namespace sculptline::ui
