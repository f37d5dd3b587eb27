// MainWindow's File > Export STEP/IGES/STL/OBJ: a file dialog per format, then the document's
// world geometry through solvers/exchange (OpenCASCADE stays behind exchange.h, away from Qt).
#include "ui/main_window.h"

#include "ui/sketch_document.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QStatusBar>

namespace sculptline::ui {
namespace {

struct FormatUi {
    const char* action;
    const char* title;
    const char* filter;
    const char* suffix;
};

FormatUi formatUi(solvers::exchange::Format format)
{
    using solvers::exchange::Format;
    switch (format) {
    case Format::Step: return {"file.exportStep", "Export STEP", "STEP AP214 (*.step *.stp)", "step"};
    case Format::Iges: return {"file.exportIges", "Export IGES", "IGES (*.iges *.igs)", "iges"};
    case Format::Stl: return {"file.exportStl", "Export STL", "Binary STL (*.stl)", "stl"};
    case Format::Obj: return {"file.exportObj", "Export OBJ", "Wavefront OBJ (*.obj)", "obj"};
    }
    return {"file.export", "Export", "*", ""};
}

}  // namespace

void MainWindow::exportGeometry(solvers::exchange::Format format)
{
    const FormatUi ui = formatUi(format);
    if (refuseDialog(ui.action)) return;
    QString path = QFileDialog::getSaveFileName(this, tr(ui.title), QString(), tr(ui.filter));
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".") + QString::fromLatin1(ui.suffix);
    try {
        const std::uintmax_t bytes = document_->exportGeometry(path, format);
        statusBar()->showMessage(tr("Exported %1 (%2 bytes)").arg(path).arg(static_cast<qulonglong>(bytes)), 5000);
    } catch (const std::exception& e) {
        QMessageBox::warning(this, tr("Cannot export"), QString::fromStdString(e.what()));
    }
}

}  // namespace sculptline::ui
