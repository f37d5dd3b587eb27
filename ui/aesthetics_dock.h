#pragma once
// The aesthetic analysis of the selected curve (thesis ch. 7), live: its name on Leyton's process
// grammar, the FIORES measures, the characteristic points with their codons and the properties of
// each extremum (§7.3.2), the slope of the logarithmic curvature graph of each monotone segment; and
// the controls of the viewport's curvature comb (scene/curvature_comb.h). Follows the curve while it
// changes (a drag's frames: one analysis per event-loop turn, however many model updates came).
// Curves the analysis cannot take (a space curve, a polyline) are named with the reason.
#include "model/model.h"
#include "solvers/aesthetics/curve_analysis.h"

#include <QDockWidget>
#include <QString>

#include <map>
#include <optional>

class QAction;
class QCheckBox;
class QDoubleSpinBox;
class QComboBox;
class QPushButton;
class QHBoxLayout;
class QLabel;
class QSpinBox;
class QTableWidget;

namespace sculptline::ui {

class SketchDocument;

class AestheticsDock : public QDockWidget {
    Q_OBJECT

public:
    explicit AestheticsDock(SketchDocument& document, QWidget* parent = nullptr);

    /// Analyses the selection now and shows it.
    void refresh();

    /// View > Curvature comb (Shift+C): shows the selected curve's comb; checkable.
    QAction* combAction() const { return combAction_; }
    /// View > Aesthetics (Ctrl+Shift+A): shows this dock and brings it to the front of its tabs.
    QAction* showAction() const { return showAction_; }
    /// The row under the curve's name where operators on the analysed curve (straighten, soften,
    /// ...) put their buttons; empty until they do.
    QHBoxLayout* operatorRow() const { return operators_; }
    /// The operators (aesthetics_dock_operators.cpp): the amount (model units) the buttons apply,
    /// a button per operator ("aesthetics.op.<name>"), and which operator's handle is on the curve.
    QDoubleSpinBox* amountBox() const { return amount_; }
    QPushButton* operatorButton(const QString& name) const;
    QComboBox* handleBox() const { return handle_; }

    /// What is shown (tests read it): the curve, the header ("Curve 5: M+0m-"), the error message
    /// (empty when the analysis ran), the analysis, a measure's text by its key ("tension",
    /// "acceleration", "sharpness", "flatness", "convexity", "crown", "kappaMin", "kappaMax", "length").
    model::EntityId curve() const { return curve_; }
    QString header() const;
    QString message() const;
    const std::optional<solvers::aesthetics::CurveAnalysis>& analysis() const { return analysis_; }
    QString measureText(const QString& key) const;
    QTableWidget* pointTable() const { return points_; }
    QTableWidget* lcgTable() const { return lcg_; }
    QSpinBox* densityBox() const { return density_; }
    QDoubleSpinBox* scaleBox() const { return scale_; }
    /// Analyses run since construction.
    int refreshes() const { return refreshes_; }

private:
    /// One refresh after the current event (a drag's updates come several per frame); skipped when
    /// the curve's shape in its plane is the one analysed (its plane moved: the analysis is the same).
    void scheduleRefresh();
    void showAnalysis(const model::Entity& e);
    void clearAnalysis();
    void updateScaleNote();
    void createOperators(QWidget* box);

    SketchDocument& document_;
    QAction* combAction_ = nullptr;
    QAction* showAction_ = nullptr;
    QLabel* header_ = nullptr;
    QLabel* message_ = nullptr;
    QHBoxLayout* operators_ = nullptr;
    QDoubleSpinBox* amount_ = nullptr;
    QComboBox* handle_ = nullptr;
    std::map<QString, QPushButton*> operatorButtons_;
    std::map<QString, QLabel*> measures_;
    QTableWidget* points_ = nullptr;
    QTableWidget* lcg_ = nullptr;
    QCheckBox* combBox_ = nullptr;
    QSpinBox* density_ = nullptr;
    QDoubleSpinBox* scale_ = nullptr;
    QLabel* scaleNote_ = nullptr;
    model::EntityId curve_ = 0;
    int analysedVersion_ = -1;  ///< the shapeVersion of curve_ shown, -1: none
    std::optional<solvers::aesthetics::CurveAnalysis> analysis_;
    bool pending_ = false;
    bool stale_ = false;  ///< a change came while the dock was hidden
    int refreshes_ = 0;
};

}  // namespace sculptline::ui
