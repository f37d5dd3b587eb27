// Solids in the real main window under Xvfb (ui/solid_builder.h, Solid menu): a conversion runs off
// the GUI thread with a progress bar and Cancel; while it runs the event loop keeps turning; a
// cancel leaves the model as it was; a finished conversion adds one solid entity (one undo step),
// watertight, with the volume `sculptline-cli solid` computes for the same surface; when the
// surface changes the solid is converted again. Given / When / Then.
#include "model/document.h"
#include "model/solid_job.h"
#include "solvers/io/geometry_json.h"
#include "tests/gui/window_shot.h"
#include "tests/volume/test_shapes.h"
#include "ui/main_window.h"
#include "ui/sketch_document.h"
#include "ui/solid_builder.h"

#include <QAction>
#include <QApplication>
#include <QElapsedTimer>
#include <QProcess>
#include <QProgressBar>
#include <QTimer>
#include <QUndoStack>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace sculptline::ui {
namespace {

// A voxel that makes the sphere's conversion take seconds (about three million narrow-band
// voxels, README "Solids"), so that the test can watch it run and cancel it halfway.
constexpr double kSlowVoxel = 0.05;
// How long the test watches the event loop, and the timer it counts: a GUI thread blocked by the
// conversion would fire a 10 ms timer once (after the block) or never in 500 ms; a responsive one
// fires it about as often as with no conversion at all. Two cores are shared with the
// conversion's threads (and other builds), so half the idle rate is asked, and at least a few.
constexpr int kWatchMs = 500;
constexpr int kTickMs = 10;
constexpr int kMinTicks = 4;
// What a person waits for a Cancel to take effect at most (the conversion checks every
// interrupter call and every stage; on a loaded machine a stage step can take a second).
constexpr qint64 kCancelDeadlineMs = 3000;
// A default-voxel sphere converts in about a second; generous for two shared cores.
constexpr qint64 kConversionDeadlineMs = 60000;
// The window and the CLI run the same solidify on the same surface; OpenVDB's measures sum over
// TBB threads, whose order may change the last bits.
constexpr double kSameVolume = 1e-9;

void startApplication() { guitest::startApplication("solid_window_test"); }

struct Window {
    MainWindow window;
    Window()
    {
        model::SceneDocument doc = model::freshDocument();
        doc.surfaces.push_back(volume_test::sphere(10.0));
        doc.surfaceIds.push_back(100);
        doc.surfaceStates.push_back(false);
        window.showDocument(doc, QString());
        window.setAutomated(true);
        window.resize(1100, 800);
        window.show();
    }
    SketchDocument& doc() { return window.document(); }
    SolidBuilder& builder() { return *window.findChild<SolidBuilder*>(QStringLiteral("solidBuilder")); }
    int solids()
    {
        int n = 0;
        for (const auto& [id, e] : doc().model().entities()) n += e.kind == model::EntityKind::Solid;
        return n;
    }
    /// Runs the event loop until the builder is idle or the deadline passes; returns the wait.
    qint64 waitIdle(qint64 deadline)
    {
        QElapsedTimer t;
        t.start();
        while (builder().busy() && t.elapsed() < deadline) QApplication::processEvents(QEventLoop::AllEvents, 20);
        return t.elapsed();
    }
};

/// The volume `sculptline-cli solid` reports for the sphere at the default voxel.
double cliVolume()
{
    const nlohmann::json input{{"surfaces", {solvers::io::toJson(volume_test::sphere(10.0))}}};
    QProcess cli;
    cli.start(QStringLiteral(SCULPTLINE_CLI), {QStringLiteral("solid")});
    cli.write(QByteArray::fromStdString(input.dump()));
    cli.closeWriteChannel();
    if (!cli.waitForFinished(static_cast<int>(kConversionDeadlineMs)) || cli.exitCode() != 0) return -1.0;
    return nlohmann::json::parse(cli.readAllStandardOutput().toStdString()).at("volume").get<double>();
}

}  // namespace

TEST(SolidWindow, GivenASlowConversion_WhenTheEventLoopIsWatchedAndCancelIsPressed_ThenItKeptTurningAndTheModelIsUnchanged)
{
    startApplication();
    Window w;
    const size_t entities = w.doc().model().entities().size();
    const int undoSteps = w.doc().undoStack()->count();
    w.builder().setVoxelSize(kSlowVoxel);
    // The window's first pictures are drawn before anything is measured (llvmpipe renders on the CPU).
    guitest::saveWindowShot(w.window, QStringLiteral(SCULPTLINE_SHOT_DIR "/solid_before.png"));
    const auto countTicks = [] {
        int ticks = 0;
        QTimer tick;
        QObject::connect(&tick, &QTimer::timeout, [&ticks]() { ++ticks; });
        tick.start(kTickMs);
        QElapsedTimer watched;
        watched.start();
        while (watched.elapsed() < kWatchMs) QApplication::processEvents(QEventLoop::AllEvents, kTickMs);
        return ticks;
    };
    const int idleTicks = countTicks();

    // When the closed solid is asked for from the menu
    w.window.action(QStringLiteral("solid.closed"))->trigger();
    ASSERT_TRUE(w.builder().busy()) << w.builder().lastMessage().toStdString();
    auto* bar = w.window.findChild<QProgressBar*>(QStringLiteral("solidProgress"));
    ASSERT_TRUE(bar);
    EXPECT_TRUE(bar->isVisible());
    // Then the GUI thread keeps running its timers while the conversion works
    const int ticks = countTicks();
    EXPECT_GE(ticks, std::max(kMinTicks, idleTicks / 2)) << "idle: " << idleTicks;
    EXPECT_GT(bar->value(), 0) << "the bar moves during the level set";
    ASSERT_TRUE(w.builder().busy()) << "the conversion should still run after " << kWatchMs << " ms";
    guitest::saveWindowShot(w.window, QStringLiteral(SCULPTLINE_SHOT_DIR "/solid_converting.png"));

    // When Cancel is pressed
    w.window.action(QStringLiteral("solid.cancel"))->trigger();
    const qint64 waited = w.waitIdle(kCancelDeadlineMs);

    // Then the conversion stops promptly and the model is as it was
    EXPECT_FALSE(w.builder().busy()) << "still converting " << waited << " ms after Cancel";
    EXPECT_EQ(w.builder().lastMessage(), QStringLiteral("Solid conversion cancelled"));
    EXPECT_EQ(w.doc().model().entities().size(), entities);
    EXPECT_EQ(w.solids(), 0);
    EXPECT_EQ(w.doc().undoStack()->count(), undoSteps);
    EXPECT_FALSE(bar->isVisible());
}

TEST(SolidWindow, GivenTheSphere_WhenAClosedSolidIsMade_ThenOneWatertightSolidWithTheClisVolumeIsAddedUndoablyAndFollowsItsSurface)
{
    startApplication();
    Window w;
    const int undoSteps = w.doc().undoStack()->count();

    // When Solid > Make closed solid runs to its end
    w.window.action(QStringLiteral("solid.closed"))->trigger();
    w.waitIdle(kConversionDeadlineMs);

    // Then one solid entity of the sphere, watertight, with the CLI's volume
    ASSERT_FALSE(w.builder().busy());
    ASSERT_EQ(w.solids(), 1) << w.builder().lastMessage().toStdString();
    const model::Entity* solid = nullptr;
    for (const auto& [id, e] : w.doc().model().entities())
        if (e.kind == model::EntityKind::Solid) solid = &e;
    ASSERT_TRUE(solid && solid->solid);
    const model::EntityId id = solid->id;
    EXPECT_EQ(solid->inputs, std::vector<model::EntityId>{100});
    EXPECT_TRUE(solid->solid->watertight);
    const double expected = cliVolume();
    ASSERT_GT(expected, 0.0) << "sculptline-cli solid failed";
    EXPECT_NEAR(solid->solid->volume, expected, kSameVolume * expected);
    EXPECT_EQ(w.doc().undoStack()->count(), undoSteps + 1);
    guitest::saveWindowShot(w.window, QStringLiteral(SCULPTLINE_SHOT_DIR "/solid_made.png"));

    // When it is undone and redone
    w.doc().undoStack()->undo();
    EXPECT_EQ(w.solids(), 0);
    w.doc().undoStack()->redo();
    ASSERT_EQ(w.solids(), 1);
    EXPECT_FALSE(w.doc().model().find(id)->solidStale()) << "redo restores the result, no new conversion";

    // When its surface grows to radius 15 (an edit of the model, then the scheduler's update)
    std::vector<Eigen::Vector3d> points = volume_test::sphere(10.0).points();
    for (Eigen::Vector3d& p : points) p *= 1.5;
    const solvers::Surface3d s10 = volume_test::sphere(10.0);
    w.doc().model().setSurfaceShape(100, solvers::Surface3d(s10.degreeU(), s10.degreeV(), s10.knotsU(), s10.knotsV(), s10.countU(),
                                                            s10.countV(), points, s10.weights()));
    w.doc().scheduler().flush();
    EXPECT_TRUE(w.doc().model().find(id)->solidStale()) << "due, not converted by the update itself";
    // The builder starts on a later turn of the event loop.
    QElapsedTimer started;
    started.start();
    while (!w.builder().busy() && w.doc().model().find(id)->solidStale() && started.elapsed() < kCancelDeadlineMs)
        QApplication::processEvents(QEventLoop::AllEvents, 20);
    w.waitIdle(kConversionDeadlineMs);

    // Then the solid is converted again from the new surface
    const model::Entity& rebuilt = *w.doc().model().find(id);
    EXPECT_FALSE(rebuilt.solidStale());
    const double r15 = 4.0 / 3.0 * M_PI * 15.0 * 15.0 * 15.0;
    EXPECT_NEAR(rebuilt.solid->volume, r15, 0.01 * r15);
    EXPECT_TRUE(rebuilt.solid->watertight);
}

}  // namespace sculptline::ui
