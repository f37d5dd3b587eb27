// MainWindow's File menu: new, open, open recent, save, save as, export .iv, and the prompt before
// unsaved work is lost. Split from main_window.cpp to keep each file one idea: the document's life
// cycle here, the view and its modes there.
#include "ui/main_window.h"

#include "ui/sketch_document.h"

#include <QCloseEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>

#include <iostream>

namespace sculptline::ui {
namespace {

/// Length of File > Open Recent.
constexpr int kMaxRecentFiles = 8;

}  // namespace

void MainWindow::rememberFile(const QString& path)
{
    // An automated run leaves the user's settings alone.
    if (automated_ || path.isEmpty()) return;
    QSettings settings;
    QStringList files = settings.value(QStringLiteral("recentFiles")).toStringList();
    files.removeAll(path);
    files.prepend(path);
    while (files.size() > kMaxRecentFiles) files.removeLast();
    settings.setValue(QStringLiteral("recentFiles"), files);
    updateRecentMenu();
}

void MainWindow::updateRecentMenu()
{
    recentMenu_->clear();
    const QStringList files = QSettings().value(QStringLiteral("recentFiles")).toStringList();
    // Unnamed actions: they change with the user's history, unlike the commands --list-actions names.
    for (const QString& path : files) {
        recentMenu_->addAction(QFileInfo(path).fileName(), this, [this, path]() {
            if (!maybeSave()) return;
            try {
                showDocument(model::loadDocument(path.toStdString()), path);
            } catch (const std::exception& e) {
                QMessageBox::warning(this, tr("Cannot open"), QString::fromStdString(e.what()));
            }
        });
    }
    recentMenu_->setEnabled(!files.isEmpty());
}

bool MainWindow::maybeSave()
{
    if (document_->undoStack()->isClean()) return true;
    if (automated_) {
        std::cerr << "sculptline: automated run: unsaved changes discarded\n";
        return true;
    }
    const auto answer = QMessageBox::question(this, tr("Unsaved changes"), tr("The document has unsaved changes. Save them?"),
                                              QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save) return saveDocument();
    return answer == QMessageBox::Discard;
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (maybeSave()) event->accept();
    else event->ignore();
}

void MainWindow::newDocument()
{
    if (!maybeSave()) return;
    showDocument(model::freshDocument(), QString());
}

void MainWindow::openDocument()
{
    if (!maybeSave() || refuseDialog("file.open")) return;
    const QString path = QFileDialog::getOpenFileName(this, tr("Open document"), QString(), tr("Sculptline documents (*.json)"));
    if (path.isEmpty()) return;
    try {
        showDocument(model::loadDocument(path.toStdString()), path);
        rememberFile(path);
    } catch (const std::exception& e) {
        QMessageBox::warning(this, tr("Cannot open"), QString::fromStdString(e.what()));
    }
}

void MainWindow::reportOpenFailure(const QString& reason)
{
    QMessageBox box(QMessageBox::Warning, tr("Cannot open document"), reason, QMessageBox::Ok, this);
    box.setInformativeText(tr("A new, empty sheet is open instead."));
    box.exec();
}

bool MainWindow::saveTo(const QString& path)
{
    try {
        document_->save(path);
    } catch (const std::exception& e) {
        // The save is atomic (model/atomic_file.h): whatever failed, the old file is whole.
        QMessageBox box(QMessageBox::Warning, tr("Cannot save"), QString::fromStdString(e.what()), QMessageBox::Ok, this);
        box.setInformativeText(tr("The file on disk is unchanged; the work is still open here."));
        box.exec();
        return false;
    }
    updateTitle();
    rememberFile(path);
    statusBar()->showMessage(tr("Saved %1").arg(path));
    return true;
}

bool MainWindow::saveDocument()
{
    return document_->path().isEmpty() ? saveDocumentAs() : saveTo(document_->path());
}

bool MainWindow::saveDocumentAs()
{
    if (refuseDialog("file.saveAs")) return false;
    const QString path = QFileDialog::getSaveFileName(this, tr("Save document"), document_->path(), tr("Sculptline documents (*.json)"));
    return !path.isEmpty() && saveTo(path);
}

void MainWindow::exportDocument()
{
    if (refuseDialog("file.exportIv")) return;
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Open Inventor"), QString(), tr("Open Inventor (*.iv)"));
    if (path.isEmpty()) return;
    try {
        document_->exportIv(path);
    } catch (const std::exception& e) {
        QMessageBox::warning(this, tr("Cannot export"), QString::fromStdString(e.what()));
    }
}

}  // namespace sculptline::ui
