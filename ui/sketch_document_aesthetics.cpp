// SketchDocument: the aesthetic operators (thesis §7.4, issue 16 §2-3) on the selected curve — applied
// at once from the Aesthetics dock or menu, or dragged by their handle in the viewport, one undo step
// each.
#include "manipulators/aesthetic_drag.h"
#include "ui/sketch_document.h"
#include "ui/undo_commands.h"
#include "solvers/bspline/arc_length.h"

#include <Inventor/nodes/SoSeparator.h>

namespace sculptline::ui {

namespace aes = solvers::aesthetics;

namespace {

QString operatorTitle(aes::Operator op)
{
    const QString name = QString::fromLatin1(aes::operatorName(op));
    return name.left(1).toUpper() + name.mid(1);
}

}  // namespace

QString SketchDocument::applyAesthetic(aes::Operator op, double amount)
{
    const model::Entity* e = model_.find(selection_);
    QString message;
    if (!e || e->kind != model::EntityKind::Curve || !e->local) {
        message = tr("%1: select a curve first").arg(operatorTitle(op));
    } else if (model_.state(e->id) == model::State::Fixed) {
        message = tr("%1: the curve is fixed (Ctrl+Shift+F frees it)").arg(operatorTitle(op));
    } else {
        try {
            aes::PlaneFrame frame;
            const solvers::Curve2d planar = aes::planarCurve(*e->local, 1e-6, &frame);
            // Straighten finds its own amounts (each step moves until its codons are gone): the
            // window's amount is for the other operators, and caps nothing here.
            const aes::OperatorResult r = aes::applyOperator(planar, op, op == aes::Operator::Straighten ? 0.0 : amount);
            const solvers::Curve3d after = aes::spaceCurve(r.curve, frame);
            if (r.nameBefore == r.nameAfter && r.amount == 0.0) {
                message = tr("%1: nothing to do on \"%2\"").arg(operatorTitle(op), QString::fromStdString(r.nameBefore));
            } else {
                auto* command = new ReplaceCurveCommand(*this, e->id, *e->local, after);
                command->setText(tr("%1 curve %2").arg(operatorTitle(op)).arg(e->id));
                undo_.push(command);
                message = tr("%1: \"%2\" -> \"%3\"").arg(operatorTitle(op), QString::fromStdString(r.nameBefore),
                                                         QString::fromStdString(r.nameAfter));
                if (r.insertedKnots > 0) message += tr(", %1 knots inserted for freedom").arg(r.insertedKnots);
                if (!r.message.empty()) message += QStringLiteral("; ") + QString::fromStdString(r.message);
            }
        } catch (const std::exception& ex) {
            message = tr("%1: %2").arg(operatorTitle(op), QString::fromUtf8(ex.what()));
        }
    }
    placeAestheticHandle();
    Q_EMIT aestheticApplied(message);
    Q_EMIT entitiesChanged();
    return message;
}

double SketchDocument::defaultAestheticAmount() const
{
    constexpr double kMenuAmountFraction = 0.02;
    const model::Entity* e = model_.find(selection_);
    if (!e || e->kind != model::EntityKind::Curve || !e->local) return 0.0;
    return kMenuAmountFraction * solvers::arcLength(*e->local);
}

QString SketchDocument::showAestheticHandle(std::optional<aes::Operator> op)
{
    handleOperator_ = op;
    if (!op) {
        aestheticHandle_->hide();
        return {};
    }
    try {
        const manipulators::AestheticOperation o = manipulators::prepareAesthetic(model_, selection_, *op);
        aestheticHandle_->show(o.handle);
        return {};
    } catch (const std::exception& ex) {
        aestheticHandle_->hide();
        return tr("%1: %2").arg(operatorTitle(*op), QString::fromUtf8(ex.what()));
    }
}

void SketchDocument::placeAestheticHandle()
{
    if (!handleOperator_ || aestheticBinding_->active()) return;
    const QString why = showAestheticHandle(handleOperator_);
    (void)why;  // a selection the operator does not apply to simply shows no handle
}

void SketchDocument::aestheticDragFinished(model::EntityId curve, const solvers::Curve3d& before, double amount,
                                           const std::string& message)
{
    const model::Entity* e = model_.find(curve);
    QString text;
    if (e && e->local && e->local->points() != before.points()) {
        auto* command = new ReplaceCurveCommand(*this, curve, before, *e->local);
        command->setText(tr("%1 curve %2").arg(operatorTitle(*handleOperator_)).arg(curve));
        undo_.push(command);
        text = tr("%1: amount %2").arg(operatorTitle(*handleOperator_)).arg(amount, 0, 'g', 4);
    }
    if (!message.empty()) text += QStringLiteral("; ") + QString::fromStdString(message);
    placeAestheticHandle();
    Q_EMIT aestheticApplied(text);
    Q_EMIT entitiesChanged();
}

void SketchDocument::setUpAesthetics()
{
    aestheticHandle_ = std::make_unique<manipulators::AestheticHandle>();
    root_->addChild(aestheticHandle_->root());
    aestheticBinding_ = std::make_unique<manipulators::AestheticDragBinding>(model_, *scheduler_);
    aestheticBinding_->setFinished([this](model::EntityId curve, const solvers::Curve3d& before, double amount, const std::string& m) {
        aestheticDragFinished(curve, before, amount, m);
    });
    aestheticHandle_->setCallbacks(
        [this]() {
            std::string error;
            if (!handleOperator_ || !aestheticBinding_->grab(selection_, *handleOperator_, {}, &error)) {
                Q_EMIT aestheticApplied(QString::fromStdString(error));
            }
        },
        [this](double amount) { aestheticBinding_->moveTo(amount); },
        [this]() { aestheticBinding_->release(); });
    connect(this, &SketchDocument::selectionChanged, this, [this](model::EntityId) { placeAestheticHandle(); });
}

}  // namespace sculptline::ui
