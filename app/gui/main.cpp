// sculptline: the GUI. Flags act in the order of ../shared/interfaces.md: open the document (or
// recover unsaved work), replay, save/export, screenshot, stats, quit. Everything that can fail on
// input (arguments, the document, the session) is checked before Qt starts, so errors exit with
// status 2 and a message even without a display; only a person at a desktop gets the default
// scene and a dialog instead of a bad document (app/gui/start_document.h).
#include "app/gui/gui_options.h"
#include "app/gui/start_document.h"
#include "model/document.h"
#include "solvers/stroke/prime.h"
#include "ui/main_window.h"
#include "ui/recovery_file.h"
#include "ui/reference_set.h"
#include "ui/replay_session.h"
#include "ui/replayer.h"
#include "ui/sketch_document.h"
#include "ui/stereo_menu.h"

#include <Inventor/Qt/SoQt.h>

#include <QAction>
#include <QApplication>
#include <QElapsedTimer>
#include <QTimer>
#include <QWindow>

#include <csignal>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace {

/// How often, and for how long at most, to wait for the window to be exposed before rendering.
constexpr int kExposePollMs = 20;
constexpr qint64 kExposeDeadlineMs = 10000;

/// Qt aborts (SIGABRT) when its default X11 platform finds no display; say why and exit instead.
bool haveDisplay()
{
    const char* platform = std::getenv("QT_QPA_PLATFORM");
    if (platform && *platform && std::string(platform).rfind("xcb", 0) != 0) return true;  // offscreen, wayland, ...
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (display && *display) || (wayland && *wayland);
}

/// SoQt's default reaction to a failed OpenGL set-up is a modal dialog, which blocks forever where
/// nobody can click it (a headless run); report and leave instead.
void onSoQtFatalError(const SbString message, SoQt::FatalErrors, void*)
{
    std::cerr << "sculptline: " << message.getString() << "\n";
    std::exit(1);
}

/// The flags that act after the replay; returns the exit status (0, or 1 when a file could not
/// be written).
int finish(sculptline::ui::MainWindow& window, const sculptline::app::GuiOptions& options, const sculptline::ui::Replayer* replayer)
{
    using sculptline::ui::SketchDocument;
    int status = 0;
    SketchDocument& doc = window.document();
    auto attempt = [&status](const std::string& what, auto&& action) {
        try {
            action();
        } catch (const std::exception& e) {
            std::cerr << "sculptline: " << what << ": " << e.what() << "\n";
            status = 1;
        }
    };
    if (!options.save.empty()) attempt("--save", [&]() { doc.save(QString::fromStdString(options.save)); });
    if (!options.exportIv.empty()) attempt("--export-iv", [&]() { doc.exportIv(QString::fromStdString(options.exportIv)); });
    using sculptline::solvers::exchange::Format;
    const std::pair<const std::string*, Format> exports[] = {{&options.exportStep, Format::Step}, {&options.exportIges, Format::Iges},
                                                             {&options.exportStl, Format::Stl}, {&options.exportObj, Format::Obj}};
    for (const auto& [path, format] : exports) {
        if (path->empty()) continue;
        attempt(std::string("--export-") + sculptline::solvers::exchange::formatName(format),
                [&]() { doc.exportGeometry(QString::fromStdString(*path), format); });
    }
    if (!options.screenshot.empty()) {
        const QImage image = window.grabViewport();
        if (image.isNull() || !image.save(QString::fromStdString(options.screenshot), "PNG")) {
            std::cerr << "sculptline: cannot write screenshot " << options.screenshot << "\n";
            status = 1;
        }
    }
    if (!options.stats.empty()) {
        sculptline::ui::LatencyStats empty;
        const sculptline::ui::LatencyStats& stats = replayer ? replayer->stats() : empty;
        const nlohmann::json extra = {
            {"definition",
             "event: ms from dispatching a replayed input event until the model update it caused "
             "has run and the viewport has been rendered (event_update: until the model is solved, event_render: the "
             "frame); drag_move / stroke_move: pointer moves during a plane drag / a stroke; stroke_release: the "
             "release that ends a stroke, until its fitted, recognized curve is drawn; stroke_fit: of which the "
             "fit and recognition of the stroke (solvers/stroke recognizeStroke); model_update: ms per "
             "coalesced model update; first_ms: a series' first sample (the session's first pen-up, say, "
             "with the fitter's code and heap still cold)"},
            {"model_updates", doc.scheduler().updates()}};
        if (!stats.write(options.stats, extra)) {
            std::cerr << "sculptline: cannot write statistics " << options.stats << "\n";
            status = 1;
        }
    }
    return status;
}

/// --stereo and --vr act as their View menu entries do; what the display cannot give is said on
/// stderr (the status bar says it too) and the run goes on, mono and on the desktop.
void applyImmersiveFlags(sculptline::ui::MainWindow& window, const sculptline::app::GuiOptions& options)
{
    using sculptline::ui::StereoMenu;
    auto* menu = window.findChild<StereoMenu*>();
    if (!menu) return;
    if (const auto mode = sculptline::ui::stereoModeFromName(options.stereo)) {
        const QString message = menu->select(*mode);
        if (!message.isEmpty()) std::cerr << "sculptline: --stereo " << options.stereo << ": " << message.toStdString() << "\n";
    }
    if (options.vr) std::cerr << "sculptline: --vr: " << menu->startVr().toStdString() << "\n";
}

}  // namespace

int main(int argc, char** argv)
{
    using namespace sculptline;
    const app::ParseResult parsed = app::parseGuiOptions(argc, argv);
    if (!parsed.options) return parsed.exitStatus;
    const app::GuiOptions& options = *parsed.options;

    // A file size limit must make a save fail with a message, not kill the program and the work
    // with it (the save is atomic: the old document stays).
    std::signal(SIGXFSZ, SIG_IGN);

    const app::StartDocument start = app::openStartDocument(options, haveDisplay() && !options.scripted() && !options.listActions);
    if (start.exitStatus != 0) return start.exitStatus;
    std::optional<ui::ReplaySession> session;
    std::optional<ui::Reference> reference;
    try {
        if (!options.importReference.empty()) reference = ui::ReferenceSet::load(QString::fromStdString(options.importReference));
    } catch (const std::exception& e) {
        std::cerr << "sculptline: --import-reference: " << e.what() << "\n";
        return 2;
    }
    try {
        if (!options.replay.empty()) session = ui::loadReplaySession(options.replay);
    } catch (const std::exception& e) {
        std::cerr << "sculptline: " << e.what() << "\n";
        return 2;
    }

    // Listing the actions draws nothing: without a display it runs on Qt's offscreen platform,
    // with a window that has no 3D viewer.
    const bool listOnly = options.listActions && !haveDisplay();
    if (listOnly) qputenv("QT_QPA_PLATFORM", "offscreen");
    if (!haveDisplay()) {
        std::cerr << "sculptline: no display (DISPLAY is not set); run it in a desktop session or under xvfb-run\n";
        return 1;
    }

    // CLI11 has consumed the arguments; Qt gets only the program name.
    int qtArgc = 1;
    QApplication application(qtArgc, argv);
    QApplication::setOrganizationName(QStringLiteral("Sculptline"));
    QApplication::setApplicationName(QStringLiteral("Sculptline"));
    // SoQt only records the top-level widget (used by SoQt::mainLoop, which we do not use).
    SoQt::init(static_cast<QWidget*>(nullptr));
    SoQt::setFatalErrorHandler(&onSoQtFatalError, nullptr);

    ui::MainWindow window(nullptr, !listOnly);
    window.setAutomated(session.has_value());
    if (options.nurbsNodes) window.document().setNurbsNodes(true);
    if (options.listActions) {
        for (QAction* action : window.namedActions()) {
            std::cout << action->objectName().toStdString();
            if (!action->shortcut().isEmpty()) std::cout << "\t" << action->shortcut().toString().toStdString();
            std::cout << "\t" << action->text().remove('&').toStdString() << "\n";
        }
        return 0;
    }
    // The default scene (or the fresh sheet that replaces a document that cannot be opened) opens
    // untitled, so that File > Save asks where instead of overwriting it.
    window.showDocument(start.document, QString::fromStdString(start.path));
    const QString habitsFile =
        QString::fromStdString(app::userModelPath(options, ui::SketchDocument::defaultUserModelPath().toStdString()));
    const QString habitsMessage = window.document().openUserModel(habitsFile);
    if (!habitsMessage.isEmpty()) std::cerr << "sculptline: " << habitsMessage.toStdString() << "\n";
    const QString recovery = ui::recoveryFolder();
    // A script gets the flag or the default, never a person's setting: its runs must repeat.
    const int interval = options.autosaveIntervalGiven || options.scripted() ? options.autosaveInterval
                                                                             : ui::MainWindow::autosaveIntervalSetting(options.autosaveInterval);
    window.enableAutosave(recovery, interval);
    std::unique_ptr<ui::Replayer> replayer;
    if (session) {
        replayer = std::make_unique<ui::Replayer>(window, *session);
        if (const QString error = replayer->check(); !error.isEmpty()) {
            std::cerr << "sculptline: " << options.replay << ": " << error.toStdString() << "\n";
            return 2;
        }
    }
    // The first pen-up should cost what later ones do: the fitter's code and heap are touched here,
    // once, not when the designer lifts the pen (solvers/stroke/prime.h; about 1.5 ms).
    solvers::stroke::primeStrokeFit();
    window.show();
    // After show(): the quad-buffer and interleaved modes recreate the GL widget with another format.
    applyImmersiveFlags(window, options);
    // Before the replay, so that a script may continue recovered work.
    if (options.recover) {
        window.offerRecovery(recovery, false);
    } else if (options.scripted()) {
        if (std::optional<ui::OrphanedRecovery> orphan = ui::claimOrphanedRecovery(recovery))
            std::cerr << "sculptline: unsaved work of an earlier session is in " << orphan->path.toStdString()
                      << "; start with --recover to reopen it\n";
    } else {
        if (!start.error.empty()) window.reportOpenFailure(QString::fromStdString(start.error));
        window.offerRecovery(recovery, true);
    }
    // After the document (and recovered work), before the replay: a replay's Ctrl+Z takes it back.
    if (reference) {
        window.document().addReference(*reference);
        std::cerr << "sculptline: reference " << options.importReference << ": " << reference->summary.toStdString() << "\n";
    }
    const int width = options.width > 0 ? options.width : session ? session->width : 0;
    const int height = options.width > 0 ? options.height : session ? session->height : 0;

    int status = 0;
    auto afterReplay = [&]() {
        status = finish(window, options, replayer.get());
        if (options.quit) QApplication::exit(status);
    };
    // Act once the window is exposed (mapped, with a drawable for the GL context): rendering earlier
    // draws into nothing and the grab reads black. Under Xvfb no expose-driven paint may follow
    // either, hence the explicit render (../shared/NOTES.md). Polling, because Qt has no signal for
    // "exposed"; the deadline keeps a display that never maps the window from hanging the program.
    QTimer poll;
    QElapsedTimer waited;
    waited.start();
    QObject::connect(&poll, &QTimer::timeout, &window, [&]() {
        QWindow* handle = window.windowHandle();
        const bool exposed = handle && handle->isExposed();
        if (!exposed && waited.elapsed() < kExposeDeadlineMs) return;
        poll.stop();
        if (!exposed) std::cerr << "sculptline: the window was never exposed; rendering anyway\n";
        if (width > 0) window.setViewportSize(width, height);
        window.renderViewport();
        if (replayer) replayer->play(afterReplay);
        else afterReplay();
    });
    poll.start(kExposePollMs);
    const int loopStatus = QApplication::exec();
    return status != 0 ? status : loopStatus;
}
