// AestheticsDock: the operators' row (thesis §7.4, issue 16 §3) — an amount, a button per operator
// applying it to the selected curve (one undo step; the status bar says the name before and after),
// and the operator whose handle sits on the curve's operated point (drag it: the curve follows live,
// one undo step per drag).
#include "ui/aesthetics_dock.h"
#include "ui/sketch_document.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

namespace sculptline::ui {

namespace aes = solvers::aesthetics;

void AestheticsDock::createOperators(QWidget* box)
{
    auto* panel = new QWidget(box);
    auto* grid = new QGridLayout(panel);
    grid->setContentsMargins(0, 0, 0, 0);
    const aes::Operator ops[] = {aes::Operator::Straighten, aes::Operator::Soften,  aes::Operator::Sharpen,
                                 aes::Operator::Convex,     aes::Operator::Concave, aes::Operator::Tension,
                                 aes::Operator::Accelerate};
    const QString tips[] = {
        tr("Remove undulations (smallest first), then redundant extrema: M+0m-0M+ -> M+m+M+ -> M+ (Fig. 7-17)"),
        tr("Lower the curvature of the sharpest M+ or m-, its neighbours' tangents held: no new extrema"),
        tr("Raise the curvature of the sharpest M+ or m-, its neighbours' tangents held: no new extrema"),
        tr("Push the point farthest from the chord out, toward the enclosing half-circle"),
        tr("Pull the point farthest from the chord in"),
        tr("Flatten the curvature minimum between two maxima: more tension"),
        tr("Raise the end's tangent (its handle moves inward), the start static: the bend moves toward the end"),
    };
    int k = 0;
    for (aes::Operator op : ops) {
        const QString name = QString::fromLatin1(aes::operatorName(op));
        auto* b = new QPushButton(name.left(1).toUpper() + name.mid(1), panel);
        b->setObjectName(QStringLiteral("aesthetics.op.") + name);
        b->setToolTip(tips[k]);
        grid->addWidget(b, k / 4, k % 4);
        connect(b, &QPushButton::clicked, this, [this, op]() { document_.applyAesthetic(op, amount_->value()); });
        operatorButtons_[name] = b;
        ++k;
    }
    auto* amountLabel = new QLabel(tr("Amount"), panel);
    amount_ = new QDoubleSpinBox(panel);
    amount_->setObjectName(QStringLiteral("aesthetics.amount"));
    amount_->setDecimals(3);
    amount_->setRange(0.0, 1e6);
    amount_->setSuffix(tr(" mm"));
    amount_->setToolTip(tr("The displacement the buttons apply (straighten finds its own); more than keeps "
                           "the curve's name is limited, and the status bar says so"));
    grid->addWidget(amountLabel, 2, 0);
    grid->addWidget(amount_, 2, 1);
    handle_ = new QComboBox(panel);
    handle_->setObjectName(QStringLiteral("aesthetics.handle"));
    handle_->setToolTip(tr("An arrow on the curve: drag it to set the operator's amount live"));
    handle_->addItem(tr("No handle"));
    for (aes::Operator op : ops) {
        if (op == aes::Operator::Straighten) continue;  // straighten finds its own amounts
        const QString name = QString::fromLatin1(aes::operatorName(op));
        handle_->addItem(tr("Handle: %1").arg(name), static_cast<int>(op));
    }
    grid->addWidget(handle_, 2, 2, 1, 2);
    connect(handle_, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int index) {
        const QVariant v = handle_->itemData(index);
        const QString why = document_.showAestheticHandle(v.isValid() ? std::optional<aes::Operator>(static_cast<aes::Operator>(v.toInt()))
                                                                       : std::nullopt);
        if (!why.isEmpty()) Q_EMIT document_.aestheticApplied(why);
    });
    operators_->addWidget(panel);
}

QPushButton* AestheticsDock::operatorButton(const QString& name) const
{
    const auto it = operatorButtons_.find(name);
    return it == operatorButtons_.end() ? nullptr : it->second;
}

}  // namespace sculptline::ui
