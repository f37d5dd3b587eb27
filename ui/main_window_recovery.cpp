// MainWindow's side of autosave and recovery: starting the autosave, and offering at start-up the
// work a killed or crashed session left behind (ui/autosave.h, ui/recovery_file.h).
#include "ui/main_window.h"

#include "solvers/io/geometry_json.h"
#include "ui/autosave.h"
#include "ui/recovery_file.h"
#include "ui/sketch_document.h"
#include "ui/undo_history.h"

#include <QDateTime>
#include <QLocale>
#include <QFileInfo>
#include <QMessageBox>
#include <QInputDialog>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>

#include <iostream>
#include <nlohmann/json.hpp>

namespace sculptline::ui {
namespace {

/// The longest autosave interval accepted, as for --autosave-interval: a day.
constexpr int kMaxAutosaveInterval = 24 * 3600;

}  // namespace

void MainWindow::enableAutosave(const QString& folder, int seconds)
{
    delete autosaver_;
    recoveryFolder_ = folder;
    autosaver_ = new Autosaver(*document_, *history_, folder, seconds, this);
    if (!autosaver_->error().isEmpty()) {
        statusBar()->showMessage(autosaver_->error());
        std::cerr << "sculptline: " << autosaver_->error().toStdString() << "\n";
    }
    connect(autosaver_, &Autosaver::failed, this, [this](const QString& message) {
        statusBar()->showMessage(message);
        std::cerr << "sculptline: " << message.toStdString() << "\n";
    });
    // A replay's log says when its work became recoverable, and what that cost the GUI thread.
    connect(autosaver_, &Autosaver::written, this, [this](qint64 bytes, double guiMs) {
        if (automated_)
            std::cerr << "sculptline: autosaved " << bytes << " bytes (GUI thread " << guiMs << " ms) to "
                      << autosaver_->recoveryPath().toStdString() << "\n";
    });
}

bool MainWindow::offerRecovery(const QString& folder, bool ask)
{
    std::optional<OrphanedRecovery> orphan = claimOrphanedRecovery(folder);
    if (!orphan) {
        if (!ask) std::cerr << "sculptline: --recover: no unsaved work to recover in " << folder.toStdString() << "\n";
        return false;
    }
    RecoveryData data;
    try {
        data = readRecoveryFile(orphan->path);
    } catch (const std::exception& e) {
        // Kept for a person to look at; the lock goes with `orphan`, so it is offered again.
        std::cerr << "sculptline: cannot recover: " << e.what() << "\n";
        if (ask) QMessageBox::warning(this, tr("Cannot recover"), QString::fromStdString(e.what()));
        return false;
    }
    const QString name = data.document.isEmpty() ? tr("an untitled document") : QFileInfo(data.document).fileName();
    const int count = static_cast<int>(data.history.texts.size());
    const QString steps = count == 1 ? tr("1 step") : tr("%1 steps").arg(count);
    if (ask) {
        QMessageBox box(QMessageBox::Question, tr("Recover unsaved work"),
                        tr("Sculptline ended without saving the work on %1 (%2, autosaved %3).")
                            .arg(name, steps, QLocale::system().toString(QFileInfo(orphan->path).lastModified(), QLocale::ShortFormat)),
                        QMessageBox::NoButton, this);
        box.setInformativeText(tr("Recover it, or discard it for good?"));
        QPushButton* recover = box.addButton(tr("Recover"), QMessageBox::AcceptRole);
        QPushButton* discard = box.addButton(tr("Discard"), QMessageBox::DestructiveRole);
        box.setDefaultButton(recover);
        box.exec();
        if (box.clickedButton() == discard) {
            removeOrphan(*orphan);
            return false;
        }
        if (box.clickedButton() != recover) return false;  // closed: asked again next time
        if (!maybeSave()) return false;  // the work open now comes first
    }
    try {
        const model::SceneDocument state =
            model::documentFromJson(solvers::io::parseJson(*data.history.states[static_cast<size_t>(data.history.index)]));
        showDocument(state, data.document);
        history_->restore(data.history);
    } catch (const std::exception& e) {
        std::cerr << "sculptline: cannot recover " << orphan->path.toStdString() << ": " << e.what() << "\n";
        if (ask) QMessageBox::warning(this, tr("Cannot recover"), QString::fromStdString(e.what()));
        return false;
    }
    updateTitle();
    // The recovered work is this session's now: written at once under its own lock, then the
    // orphan goes.
    if (autosaver_) autosaver_->autosave(true);
    removeOrphan(*orphan);
    statusBar()->showMessage(tr("Recovered the unsaved work on %1").arg(name));
    std::cerr << "sculptline: recovered " << steps.toStdString() << " of unsaved work on " << name.toStdString() << "\n";
    return true;
}

void MainWindow::recoverFromMenu()
{
    if (refuseDialog("file.recover")) return;
    const QString folder = recoveryFolder_.isEmpty() ? recoveryFolder() : recoveryFolder_;
    if (!claimOrphanedRecovery(folder)) {
        statusBar()->showMessage(tr("No unsaved work of an earlier session to recover"));
        return;
    }
    offerRecovery(folder, true);
}

void MainWindow::chooseAutosaveInterval()
{
    if (!autosaver_ || refuseDialog("file.autosaveInterval")) return;
    bool ok = false;
    const int seconds = QInputDialog::getInt(this, tr("Autosave interval"), tr("Seconds between autosaves of unsaved work (0 = off):"),
                                             autosaver_->interval(), 0, kMaxAutosaveInterval, 30, &ok);
    if (!ok) return;
    autosaver_->setInterval(seconds);
    QSettings().setValue(QStringLiteral("autosaveInterval"), seconds);
    statusBar()->showMessage(seconds > 0 ? tr("Autosave every %1 s").arg(seconds) : tr("Autosave off"));
}

int MainWindow::autosaveIntervalSetting(int fallback)
{
    bool ok = false;
    const int seconds = QSettings().value(QStringLiteral("autosaveInterval")).toInt(&ok);
    return ok && seconds >= 0 && seconds <= kMaxAutosaveInterval ? seconds : fallback;
}

}  // namespace sculptline::ui
