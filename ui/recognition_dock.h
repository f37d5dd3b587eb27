#pragma once
// Stroke-recognition feedback for the last stroke (issue 3's recognizer, solvers/stroke): the
// recognized shape, the ranked candidates with their scores, fit error and control point count; two
// buttons choose between the recognized (regularized) shape and the freeform fit, undoably.
#include <QDockWidget>

class QLabel;
class QListWidget;
class QAction;

namespace sculptline::ui {

class SketchDocument;

class RecognitionDock : public QDockWidget {
    Q_OBJECT

public:
    RecognitionDock(SketchDocument& document, QAction* useShape, QAction* useFreeform, QWidget* parent = nullptr);
    /// Shows the document's last stroke report.
    void refresh();

private:
    SketchDocument& document_;
    QLabel* summary_ = nullptr;
    QLabel* habit_ = nullptr;  ///< shown when one of the designer's habits decided the shape
    QListWidget* candidates_ = nullptr;
    QAction* useShape_ = nullptr;
    QAction* useFreeform_ = nullptr;
};

}  // namespace sculptline::ui
