// MainWindow's reference geometry: File > Import Reference, Edit > Remove References, View >
// References (ui/reference_set.h), and what the window says about references a document names but
// that cannot be read.
#include "ui/main_window.h"

#include "ui/reference_set.h"
#include "ui/sketch_document.h"

#include <QAction>
#include <QApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QStatusBar>
#include <QTimer>

#include <iostream>

namespace sculptline::ui {

void MainWindow::createReferenceActions(QMenu* file, QMenu* edit, QMenu* view)
{
    auto* import = new QAction(tr("Import &Reference (.iv)..."), this);
    import->setObjectName(QStringLiteral("file.importReference"));
    connect(import, &QAction::triggered, this, [this]() { importReference(); });
    file->insertAction(action(QStringLiteral("file.recover")), import);

    auto* remove = new QAction(tr("Remove &References"), this);
    remove->setObjectName(QStringLiteral("edit.removeReferences"));
    connect(remove, &QAction::triggered, this, [this]() {
        statusBar()->showMessage(document_->removeReferences() ? tr("References removed; Ctrl+Z brings them back.") : tr("No reference to remove."),
                                 5000);
    });
    edit->addAction(remove);

    // A view setting like hiding planes: not an edit, not undone, not saved.
    auto* show = new QAction(tr("&References (imported .iv)"), this);
    show->setObjectName(QStringLiteral("view.references"));
    show->setCheckable(true);
    show->setChecked(true);
    show->setShortcut(QKeySequence(QStringLiteral("Ctrl+Shift+R")));
    connect(show, &QAction::toggled, this, [this](bool on) { document_->references().setVisible(on); });
    view->addAction(show);

    connect(document_, &SketchDocument::replaced, this, [this, show]() {
        show->setChecked(true);
        const QStringList& problems = document_->referenceProblems();
        if (problems.isEmpty()) return;
        for (const QString& p : problems) std::cerr << "sculptline: " << p.toStdString() << "\n";
        // After showDocument's own status text (updateStatus runs once load() returns).
        QTimer::singleShot(0, this, [this, text = problems.join(QStringLiteral("; "))]() { statusBar()->showMessage(text); });
        if (!automated_ && isVisible()) QMessageBox::warning(this, tr("Reference not shown"), problems.join(QStringLiteral("\n")));
    });
}

void MainWindow::importReference()
{
    if (refuseDialog("file.importReference")) return;
    const QString path = QFileDialog::getOpenFileName(this, tr("Import Reference"), QString(), tr("Open Inventor (*.iv)"));
    if (path.isEmpty()) return;
    // Validation and Coin's reader run here, on the GUI thread (Coin's reader and node constructors
    // share global name tables with the scene on screen): a 1 M-triangle file takes about 8 s. Say
    // so before the window stops answering, and show the wait cursor until it answers again.
    statusBar()->showMessage(tr("Importing %1 (%2 MB)...").arg(QFileInfo(path).fileName()).arg(QFileInfo(path).size() / 1.0e6, 0, 'f', 1));
    statusBar()->repaint();
    QApplication::setOverrideCursor(Qt::WaitCursor);
    QString summary, error;
    try {
        summary = document_->importReference(path);
    } catch (const std::exception& e) {
        error = QString::fromStdString(e.what());
    }
    QApplication::restoreOverrideCursor();
    if (!error.isEmpty()) {
        statusBar()->clearMessage();
        QMessageBox::warning(this, tr("Cannot import reference"), error);
        return;
    }
    statusBar()->showMessage(tr("Reference %1: %2. Ctrl+Z removes it; View > References hides it.").arg(QFileInfo(path).fileName(), summary));
}

}  // namespace sculptline::ui
