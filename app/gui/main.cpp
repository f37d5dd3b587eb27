// sculptline: the GUI. Flags act in the order of ../shared/interfaces.md: open the document,
// screenshot, quit. Everything that can fail on input (arguments, the document) is checked before
// Qt starts, so errors exit with status 2 and a message even without a display.
#include "app/gui/gui_options.h"
#include "scene/scene_document.h"
#include "ui/main_window.h"

#include <Inventor/Qt/SoQt.h>

#include <QApplication>
#include <QFileInfo>
#include <QElapsedTimer>
#include <QTimer>
#include <QWindow>

#include <cstdlib>
#include <iostream>
#include <string>

namespace {

/// How often, and for how long at most, to wait for the window to be exposed before rendering.
constexpr int kExposePollMs = 20;
constexpr qint64 kExposeDeadlineMs = 10000;

/// Writes the viewport to `path`; false (with a message) when the image cannot be written.
bool writeScreenshot(sculptline::ui::MainWindow& window, const std::string& path)
{
    const QImage image = window.grabViewport();
    if (image.isNull() || !image.save(QString::fromStdString(path), "PNG")) {
        std::cerr << "sculptline: cannot write screenshot " << path << "\n";
        return false;
    }
    return true;
}

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

}  // namespace

int main(int argc, char** argv)
{
    using namespace sculptline;
    const app::ParseResult parsed = app::parseGuiOptions(argc, argv);
    if (!parsed.options) return parsed.exitStatus;
    const app::GuiOptions& options = *parsed.options;

    scene::SceneDocument document;
    try {
        document = scene::loadDocument(options.document);
    } catch (const std::exception& e) {
        std::cerr << "sculptline: " << e.what() << "\n";
        return 2;
    }

    if (!haveDisplay()) {
        std::cerr << "sculptline: no display (DISPLAY is not set); run it in a desktop session or under xvfb-run\n";
        return 1;
    }

    // CLI11 has consumed the arguments; Qt gets only the program name.
    int qtArgc = 1;
    QApplication application(qtArgc, argv);
    // SoQt only records the top-level widget (used by SoQt::mainLoop, which we do not use).
    SoQt::init(static_cast<QWidget*>(nullptr));
    SoQt::setFatalErrorHandler(&onSoQtFatalError, nullptr);

    ui::MainWindow window;
    window.showDocument(document, QFileInfo(QString::fromStdString(options.document)).fileName());
    window.show();
    if (options.width > 0) window.setViewportSize(options.width, options.height);

    int status = 0;
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
        window.renderViewport();
        if (!options.screenshot.empty() && !writeScreenshot(window, options.screenshot)) {
            status = 1;
            QApplication::exit(status);
            return;
        }
        if (options.quit) QApplication::exit(status);
    });
    poll.start(kExposePollMs);
    const int loopStatus = QApplication::exec();
    return status != 0 ? status : loopStatus;
}
