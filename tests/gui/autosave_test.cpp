// Autosave and the undo history in one process (run under Xvfb by ctest): the recovery file exists
// exactly while there is unsaved work, it carries the whole undo history, and a window that
// restores it can undo and redo through the steps of the session that wrote it. Also the dialogs
// a person sees at start-up, written to $SCULPTLINE_DIALOG_SHOTS (when set) to be looked at.
#include "manipulators/stroke_input.h"
#include "model/model_document.h"
#include "model/document.h"
#include "ui/autosave.h"
#include "ui/main_window.h"
#include "ui/recovery_file.h"
#include "ui/sketch_document.h"
#include "ui/undo_history.h"

#include <Inventor/Qt/SoQt.h>

#include <QAbstractButton>
#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QInputDialog>
#include <QMessageBox>
#include <QStatusBar>
#include <QAction>
#include <QTimer>
#include <QUndoStack>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>

namespace sculptline::ui {
namespace {

void startApplication()
{
    static int argc = 1;
    static char name[] = "autosave_test";
    static char* argv[] = {name, nullptr};
    static QApplication* app = nullptr;
    if (app) return;
    // The settings File > Autosave Interval writes go to a private folder, not the user's.
    qputenv("XDG_CONFIG_HOME", QByteArray::fromStdString(testing::TempDir() + "sculptline_autosave_config"));
    app = new QApplication(argc, argv);
    SoQt::init(static_cast<QWidget*>(nullptr));
}

QString freshFolder(const char* name)
{
    QDir dir(QString::fromStdString(testing::TempDir()) + QStringLiteral("sculptline_autosave_") + QLatin1String(name));
    dir.removeRecursively();
    QDir().mkpath(dir.path());
    return dir.path();
}

std::string stateOf(SketchDocument& doc)
{
    doc.scheduler().flush();
    return model::modelToJson(doc.model(), doc.grid()).dump();
}

/// A stroke on plane 1 of the default scene, as the stroke input delivers it: a half circle
/// of radius `r` (the recognizer's arc), or a flat wave when `wave`.
manipulators::FinishedStroke strokeOn(SketchDocument& doc, double r, bool wave)
{
    const model::PlaneFrame frame = doc.model().find(1)->frame;
    manipulators::FinishedStroke stroke;
    stroke.frame = frame;
    for (int i = 0; i < 40; ++i) {
        const double a = 3.14159265358979 * i / 39.0;
        stroke.points.emplace_back(wave ? -r + 2.0 * r * i / 39.0 : r * std::cos(a), wave ? 5.0 * std::sin(4.0 * a) : r * std::sin(a), 0.0);
        stroke.times.push_back(0.01 * i);
        stroke.rayTimes.push_back(0.01 * i);
        stroke.rayOrigins.push_back(frame.toWorld(stroke.points.back()) + 100.0 * frame.normal());
        stroke.rayDirections.push_back(-frame.normal());
    }
    return stroke;
}

/// Edits of every kind a test can make without the mouse: strokes, planes, fixed points, the
/// recognized shape, lofted surfaces, deletes (the surface with its curve). Returns the document state after each (index 0: before any).
std::vector<std::string> editSeveralWays(MainWindow& window, int rounds)
{
    SketchDocument& doc = window.document();
    std::vector<std::string> states{stateOf(doc)};
    const int before = doc.undoStack()->count();
    for (int i = 0; i < rounds; ++i) {
        doc.select(1);
        doc.addStroke(strokeOn(doc, 20.0 + i, false));
        const model::EntityId curve = doc.selection();
        states.push_back(stateOf(doc));
        doc.setFixedPoints(curve, {0});
        states.push_back(stateOf(doc));
        if (doc.recognitionChoiceAvailable()) {
            doc.chooseRecognized(true);
            states.push_back(stateOf(doc));
        }
        doc.select(1);
        doc.addStroke(strokeOn(doc, 30.0 + i, false));  // a concentric arc: the loft is a flat band
        const model::EntityId outer = doc.selection();
        states.push_back(stateOf(doc));
        doc.setSurfaceMode(model::Construction::Loft);
        doc.pickSurfaceInput(curve);
        doc.pickSurfaceInput(outer);
        EXPECT_TRUE(doc.buildSurface()) << "the loft of round " << i;
        states.push_back(stateOf(doc));
        doc.addPlane(doc.model().find(1)->frame);
        states.push_back(stateOf(doc));
        doc.select(curve);
        doc.deleteSelection();
        states.push_back(stateOf(doc));
    }
    EXPECT_EQ(doc.undoStack()->count() - before, static_cast<int>(states.size()) - 1) << "an edit that is not an undo step";
    return states;
}

model::SceneDocument defaultScene() { return model::loadDocument(SCULPTLINE_DATA_DIR "/default_scene.json"); }

TEST(Autosave, TheRecoveryFileExistsExactlyWhileWorkIsUnsaved)
{
    startApplication();
    const QString folder = freshFolder("unsaved");
    const QString document = folder + QStringLiteral("/doc.json");
    MainWindow window;
    window.showDocument(defaultScene(), QString());
    window.enableAutosave(folder, 0);
    Autosaver& autosaver = *window.autosaver();
    ASSERT_TRUE(autosaver.error().isEmpty()) << autosaver.error().toStdString();
    // Nothing changed: nothing written
    autosaver.autosave(true);
    EXPECT_FALSE(QFile::exists(autosaver.recoveryPath()));
    // An edit: written, with its step and the document it belongs to (untitled)
    window.document().addPlane(window.document().model().find(1)->frame);
    autosaver.autosave(true);
    ASSERT_TRUE(QFile::exists(autosaver.recoveryPath()));
    RecoveryData data = readRecoveryFile(autosaver.recoveryPath());
    EXPECT_TRUE(data.document.isEmpty());
    EXPECT_EQ(data.history.texts.size(), 1u);
    // Saved: the recovery file goes
    window.document().save(document);
    EXPECT_FALSE(QFile::exists(autosaver.recoveryPath()));
    // Another edit: written again, now naming the saved document, whose step 1 is clean
    window.document().addPlane(window.document().model().find(1)->frame);
    autosaver.autosave(true);
    data = readRecoveryFile(autosaver.recoveryPath());
    EXPECT_EQ(data.document, document);
    EXPECT_EQ(data.history.cleanIndex, 1);
    // Another live session's orphan scan does not take it
    EXPECT_FALSE(claimOrphanedRecovery(folder));
    // Replaced by another document (the changes discarded): gone
    window.showDocument(defaultScene(), QString());
    EXPECT_FALSE(QFile::exists(autosaver.recoveryPath()));
}

TEST(Autosave, ARecoveredHistoryUndoesAndRedoesLikeTheOriginal)
{
    startApplication();
    // Given a session with edits of several kinds, saved half-way, with its last step undone
    MainWindow original;
    original.showDocument(defaultScene(), QString());
    const std::vector<std::string> states = editSeveralWays(original, 3);
    QUndoStack* stack = original.document().undoStack();
    const int steps = stack->count();
    ASSERT_GE(steps, 12);
    stack->setIndex(steps / 2);
    original.document().save(freshFolder("history") + QStringLiteral("/saved.json"));
    stack->setIndex(steps - 1);
    // When its history goes through a recovery file into another window
    QElapsedTimer clock;
    clock.start();
    const HistorySnapshot snapshot = original.history().snapshot();
    const double snapshotMs = clock.nsecsElapsed() / 1e6;
    RecoveryData written;
    written.history = snapshot;
    const std::string text = recoveryText(written);
    std::cout << "recovery file of " << steps << " steps: " << text.size() << " bytes; snapshot on the GUI thread " << snapshotMs << " ms\n";
    const std::string path = testing::TempDir() + "sculptline_history_recovery.json";
    std::ofstream(path) << text;
    const RecoveryData read = readRecoveryFile(QString::fromStdString(path));
    MainWindow recovered;
    recovered.showDocument(model::documentFromJson(nlohmann::json::parse(*read.history.states[read.history.index])), QString());
    recovered.history().restore(read.history);
    // Then it has the same steps, texts, position and clean mark
    SketchDocument& doc = recovered.document();
    QUndoStack* restored = doc.undoStack();
    ASSERT_EQ(restored->count(), steps);
    EXPECT_EQ(restored->index(), steps - 1);
    EXPECT_EQ(restored->cleanIndex(), steps / 2);
    EXPECT_EQ(restored->undoText(), stack->undoText());
    EXPECT_EQ(stateOf(doc), states[steps - 1]);
    // And redo, then undo back to the start, pass through every original state
    restored->redo();
    EXPECT_EQ(stateOf(doc), states[steps]);
    for (int i = steps - 1; i >= 0; --i) {
        restored->undo();
        EXPECT_EQ(stateOf(doc), states[i]) << "after undoing to step " << i;
    }
    EXPECT_TRUE(restored->isClean() == (steps / 2 == 0));
    // And new edits after the recovered ones are undoable as usual
    restored->setIndex(steps);
    doc.addPlane(doc.model().find(1)->frame);
    restored->undo();
    EXPECT_EQ(stateOf(doc), states[steps]);
}

TEST(Autosave, RecordingTheHistoryCostsLittlePerEdit)
{
    // Measured, not asserted: the GUI thread's cost of keeping the history of a larger document
    startApplication();
    MainWindow window;
    window.showDocument(model::loadDocument(SCULPTLINE_DATA_DIR "/bench_20_curves_5_planes.json"), QString());
    QElapsedTimer clock;
    clock.start();
    constexpr int kEdits = 20;
    for (int i = 0; i < kEdits; ++i) window.document().addPlane(window.document().model().find(1)->frame);
    const double perEdit = clock.nsecsElapsed() / 1e6 / kEdits;
    clock.restart();
    const std::string state = stateOf(window.document());
    const double perState = clock.nsecsElapsed() / 1e6;
    clock.restart();
    const std::string text = recoveryText(RecoveryData{QString(), window.history().snapshot()});
    const double writerMs = clock.nsecsElapsed() / 1e6;
    std::cout << "20 curves on 5 planes: " << perEdit << " ms per edit (command and state), of which the state " << perState
              << " ms (" << state.size() << " bytes); the writer thread joins " << kEdits + 1 << " states in " << writerMs << " ms\n";
    EXPECT_EQ(window.history().snapshot().states.size(), static_cast<size_t>(kEdits + 1));
}

/// Clicks `button` on the next message box once it is shown, after saving a picture of it to
/// $SCULPTLINE_DIALOG_SHOTS/<shot>.png; its text goes to `text`.
void answerNextBox(const QString& button, const QString& shot, QString* text)
{
    QTimer::singleShot(50, [button, shot, text]() {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box) {
            answerNextBox(button, shot, text);
            return;
        }
        *text = box->text() + QLatin1Char('\n') + box->informativeText();
        if (const char* dir = std::getenv("SCULPTLINE_DIALOG_SHOTS")) box->grab().save(QString::fromLocal8Bit(dir) + "/" + shot + ".png");
        for (QAbstractButton* b : box->buttons()) {
            if (b->text() == button) b->click();
        }
    });
}

/// The recovery file of a session that died with one step of work on kettle.json (written, then
/// its lock let go), as `folder`/session-dead.json.
void leaveOrphan(const QString& folder)
{
    MainWindow dead;
    dead.showDocument(defaultScene(), QStringLiteral("/home/designer/kettle.json"));
    dead.enableAutosave(folder, 0);
    dead.document().addPlane(dead.document().model().find(1)->frame);
    dead.autosaver()->autosave(true);
    QFile::copy(dead.autosaver()->recoveryPath(), folder + QStringLiteral("/session-dead.json"));
}

TEST(Autosave, AtStartUpAPersonIsAskedAndDiscardRemovesTheWork)
{
    startApplication();
    // Given the recovery file of a session that died
    const QString folder = freshFolder("ask");
    leaveOrphan(folder);
    // When a new window offers it and the person picks Discard
    MainWindow window;
    window.showDocument(defaultScene(), QString());
    window.show();
    QString asked;
    answerNextBox(QStringLiteral("Discard"), QStringLiteral("recover_dialog"), &asked);
    EXPECT_FALSE(window.offerRecovery(folder, true));
    // Then the question named the document and the work, and the file is gone
    EXPECT_TRUE(asked.contains(QStringLiteral("kettle.json"))) << asked.toStdString();
    EXPECT_TRUE(asked.contains(QStringLiteral("1 step"))) << asked.toStdString();
    EXPECT_FALSE(QFile::exists(folder + QStringLiteral("/session-dead.json")));
    EXPECT_EQ(window.document().undoStack()->count(), 0);
}

TEST(Autosave, TheFileMenuRecoversWorkWhoseQuestionWasClosed)
{
    startApplication();
    const QString folder = freshFolder("menu");
    leaveOrphan(folder);
    MainWindow window;
    window.showDocument(defaultScene(), QString());
    window.enableAutosave(folder, 0);
    window.show();
    // When File > Recover Unsaved Work is answered "Recover"
    QString asked;
    answerNextBox(QStringLiteral("Recover"), QStringLiteral("recover_menu_dialog"), &asked);
    window.action(QStringLiteral("file.recover"))->trigger();
    // Then the work is open, unsaved, under its document's name, with its step undoable
    SketchDocument& doc = window.document();
    EXPECT_EQ(doc.path(), QStringLiteral("/home/designer/kettle.json"));
    EXPECT_EQ(doc.undoStack()->count(), 1);
    EXPECT_FALSE(doc.undoStack()->isClean());
    EXPECT_TRUE(window.isWindowModified());
    // And it is this session's recovery file that holds it now; the orphan is gone
    EXPECT_FALSE(QFile::exists(folder + QStringLiteral("/session-dead.json")));
    EXPECT_TRUE(QFile::exists(window.autosaver()->recoveryPath()));
    // Undone, the document is kettle.json as saved: clean, and no recovery file is needed
    const size_t entities = doc.model().entities().size();
    doc.undoStack()->undo();
    EXPECT_EQ(doc.model().entities().size(), entities - 1);
    EXPECT_TRUE(doc.undoStack()->isClean());
    EXPECT_FALSE(QFile::exists(window.autosaver()->recoveryPath()));
    // And with nothing left, the menu says so instead of asking
    window.action(QStringLiteral("file.recover"))->trigger();
    EXPECT_TRUE(window.statusBar()->currentMessage().contains(QStringLiteral("No unsaved work")));
}

TEST(Autosave, TheIntervalIsASettingOfTheWindow)
{
    startApplication();
    MainWindow window;
    window.showDocument(defaultScene(), QString());
    window.enableAutosave(freshFolder("interval"), 120);
    window.show();
    // When File > Autosave Interval is answered with 45 seconds
    QTimer::singleShot(50, []() {
        auto* dialog = qobject_cast<QInputDialog*>(QApplication::activeModalWidget());
        ASSERT_NE(dialog, nullptr);
        dialog->setIntValue(45);
        dialog->accept();
    });
    window.action(QStringLiteral("file.autosaveInterval"))->trigger();
    // Then the autosave runs every 45 s, and the next start will too
    EXPECT_EQ(window.autosaver()->interval(), 45);
    EXPECT_EQ(MainWindow::autosaveIntervalSetting(120), 45);
}

TEST(Autosave, ADocumentThatCannotBeOpenedIsExplainedInADialog)
{
    startApplication();
    MainWindow window;
    window.showDocument(defaultScene(), QString());
    window.show();
    QString shown;
    answerNextBox(QStringLiteral("OK"), QStringLiteral("open_failure_dialog"), &shown);
    window.reportOpenFailure(QStringLiteral("kettle.json: made by a newer Sculptline (version 2); this one reads up to 1"));
    EXPECT_TRUE(shown.contains(QStringLiteral("newer Sculptline (version 2)"))) << shown.toStdString();
    EXPECT_TRUE(shown.contains(QStringLiteral("empty sheet is open instead"))) << shown.toStdString();
}

}  // namespace
}  // namespace sculptline::ui
