// MainWindow's Solid menu: closed solids and shells of the selected surface (or of all surfaces),
// converted off the GUI thread by SolidBuilder (progress and Cancel in the status bar), each one
// undo step; and the shell thickness and voxel size the conversions use.
#include "ui/main_window.h"

#include "ui/sketch_document.h"
#include "ui/solid_builder.h"

#include <QAction>
#include <QInputDialog>
#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>

#include <cstdio>

namespace sculptline::ui {

namespace {

/// Bounds of the dialogs' values, model units (mm): a micrometre to a metre. The conversion itself
/// refuses what its memory estimate or resolution checks cannot take (solvers/volume/solidify.h).
constexpr double kMinDialogValue = 0.001;
constexpr double kMaxDialogValue = 1000.0;

}  // namespace

void MainWindow::createSolidMenu()
{
    solids_ = new SolidBuilder(*document_, statusBar(), this);
    QMenu* menu = menuBar()->addMenu(tr("S&olid"));
    const auto add = [this, menu](const char* name, const QString& text, auto slot) {
        auto* a = new QAction(text, this);
        a->setObjectName(QString::fromLatin1(name));
        connect(a, &QAction::triggered, this, slot);
        menu->addAction(a);
        return a;
    };
    add("solid.closed", tr("Make &closed solid (selected surface, or all surfaces)"), [this]() {
        model::SolidRecipe r;
        r.mode = model::SolidMode::Closed;
        r.voxelSize = solids_->voxelSize();
        solids_->makeSolid(r);
    });
    add("solid.shell", tr("Make &shell solid (selected surface, or all surfaces)"), [this]() {
        model::SolidRecipe r;
        r.mode = model::SolidMode::Shell;
        r.thickness = solids_->thickness();
        r.voxelSize = solids_->voxelSize();
        solids_->makeSolid(r);
    });
    add("solid.cancel", tr("C&ancel the running conversion"), [this]() { solids_->cancel(); });
    menu->addSeparator();
    add("solid.thickness", tr("Shell &thickness..."), [this]() {
        if (automated_) {
            std::fprintf(stderr, "sculptline: solid.thickness needs a dialog, which an automated run cannot answer\n");
            return;
        }
        bool ok = false;
        const double t = QInputDialog::getDouble(this, tr("Shell thickness"), tr("Thickness (mm):"), solids_->thickness(),
                                                 kMinDialogValue, kMaxDialogValue, 3, &ok);
        if (ok) solids_->setThickness(t);
    });
    add("solid.voxelSize", tr("&Voxel size... (0: from the model's size)"), [this]() {
        if (automated_) {
            std::fprintf(stderr, "sculptline: solid.voxelSize needs a dialog, which an automated run cannot answer\n");
            return;
        }
        bool ok = false;
        const double v = QInputDialog::getDouble(this, tr("Voxel size"), tr("Voxel size (mm, 0 = default):"), solids_->voxelSize(),
                                                 0.0, kMaxDialogValue, 4, &ok);
        if (ok) solids_->setVoxelSize(v < kMinDialogValue ? 0.0 : v);
    });
}

}  // namespace sculptline::ui
