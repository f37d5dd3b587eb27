#pragma once
// Shared by the window tests that run a MainWindow under Xvfb: one QApplication and SoQt for the
// process, and the whole window (viewport included) written to a PNG for a person to look at.
#include "ui/main_window.h"

#include <Inventor/Qt/SoQt.h>
#include <QApplication>
#include <QElapsedTimer>
#include <QPainter>
#include <QWindow>

namespace sculptline::guitest {

/// QApplication and SoQt, made once per process (later calls do nothing).
inline void startApplication(const char* programName)
{
    static int argc = 1;
    static char name[64] = {};
    static char* argv[] = {name, nullptr};
    static QApplication* app = nullptr;
    if (app) return;
    qstrncpy(name, programName, sizeof(name));
    app = new QApplication(argc, argv);
    SoQt::init(static_cast<QWidget*>(nullptr));
}

/// How long a picture waits for the window to be mapped: rendering before the window is exposed
/// draws into nothing (app/gui/main.cpp waits alike).
constexpr qint64 kExposeDeadlineMs = 5000;

/// Renders the viewport and saves the whole window to `path`. QWidget::grab() is black for the GL
/// area, so the viewport's framebuffer is painted over it.
inline void saveWindowShot(ui::MainWindow& window, const QString& path)
{
    QElapsedTimer waited;
    waited.start();
    while (!(window.windowHandle() && window.windowHandle()->isExposed()) && waited.elapsed() < kExposeDeadlineMs)
        QApplication::processEvents(QEventLoop::AllEvents, 50);
    window.renderViewport();
    QApplication::processEvents();
    const QImage viewport = window.grabViewport();
    QImage image = window.grab().toImage();
    QPainter painter(&image);
    painter.drawImage(window.viewport()->mapTo(&window, QPoint(0, 0)), viewport);
    painter.end();
    image.save(path);
}

}  // namespace sculptline::guitest
