#include "ui/inspector_dock.h"

#include "ui/curvature_plot.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QSlider>
#include <QVBoxLayout>
#include <QTextStream>
#include <QTimer>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace sculptline::ui {
namespace {

QString point(const Eigen::Vector3d& p) { return QStringLiteral("(%1, %2, %3)").arg(p.x(), 0, 'f', 2).arg(p.y(), 0, 'f', 2).arg(p.z(), 0, 'f', 2); }

QString knots(const std::vector<double>& k)
{
    QStringList parts;
    for (double t : k) parts << QString::number(t, 'g', 6);
    return parts.join(QStringLiteral(", "));
}

}  // namespace

InspectorDock::InspectorDock(QWidget* parent) : QDockWidget(tr("Inspector"), parent)
{
    setObjectName(QStringLiteral("dock.inspector"));
    auto* box = new QWidget(this);
    auto* layout = new QVBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    text_ = new QPlainTextEdit(box);
    text_->setReadOnly(true);
    layout->addWidget(text_, 1);
    points_ = new QListWidget(box);
    points_->setToolTip(tr("Checked control points stay fixed when the curve is pulled"));
    layout->addWidget(points_, 1);
    connect(points_, &QListWidget::itemChanged, this, [this]() {
        if (filling_ || curve_ == 0) return;
        std::vector<int> fixed;
        for (int row = 0; row < points_->count(); ++row) {
            if (points_->item(row)->checkState() == Qt::Checked) fixed.push_back(row);
        }
        Q_EMIT fixedPointsEdited(curve_, fixed);
    });
    // Thesis eq. 6-20, Fig. 6-8 (λ = 1, 0.8, 0.5): how far a sculpt goes to its targets. One undo
    // step per release (no tracking), 5 % to 100 %.
    stiffness_ = new QSlider(Qt::Horizontal, box);
    stiffness_->setObjectName(QStringLiteral("inspector.stiffness"));
    stiffness_->setRange(5, 100);
    stiffness_->setTracking(false);
    stiffness_->setToolTip(tr("Stiffness: how far the sculpted surface goes to its target curves"));
    stiffness_->setVisible(false);
    layout->addWidget(stiffness_);
    connect(stiffness_, &QSlider::valueChanged, this, [this](int percent) {
        if (filling_ || sculpt_ == 0) return;
        Q_EMIT stiffnessEdited(sculpt_, percent / 100.0);
    });
    // Thesis Fig. 6-5 c–d: a handle holds its point only, or its normal too (turned with the point).
    holdNormals_ = new QCheckBox(tr("Hold normals at handles"), box);
    holdNormals_->setObjectName(QStringLiteral("inspector.holdNormals"));
    holdNormals_->setToolTip(tr("Checked: the surface's normal at each handle turns with the handle; unchecked: only the point is held"));
    holdNormals_->setVisible(false);
    layout->addWidget(holdNormals_);
    connect(holdNormals_, &QCheckBox::toggled, this, [this](bool on) {
        if (filling_ || sculpt_ == 0) return;
        Q_EMIT holdNormalsEdited(sculpt_, on);
    });
    // The sculpt's distance constraints, one value each (undoable, the surface re-solves).
    distanceBox_ = new QWidget(box);
    distanceBox_->setObjectName(QStringLiteral("inspector.distances"));
    distanceForm_ = new QFormLayout(distanceBox_);
    distanceForm_->setContentsMargins(0, 0, 0, 0);
    distanceBox_->setVisible(false);
    layout->addWidget(distanceBox_);
    plot_ = new CurvaturePlot(box);
    layout->addWidget(plot_);
    setWidget(box);
}

QString InspectorDock::text() const { return text_->toPlainText(); }

void InspectorDock::followCurve(const model::Model& model, model::EntityId id)
{
    // Hidden: show() draws it afresh when the drag ends (the document's entitiesChanged). A plane or
    // a surface has no plot.
    const model::Entity* e = model.find(id);
    if (plotPending_ || !plot_->isVisible() || !e || e->kind != model::EntityKind::Curve) return;
    plotPending_ = true;
    QTimer::singleShot(0, this, [this, &model, id]() {
        plotPending_ = false;
        const model::Entity* now = model.find(id);
        plot_->setCurve(now && now->kind == model::EntityKind::Curve ? now : nullptr);
    });
}

void InspectorDock::show(const model::Model& model, model::EntityId id)
{
    const model::Entity* e = model.find(id);
    plot_->setCurve(e && e->kind == model::EntityKind::Curve ? e : nullptr);
    filling_ = true;
    sculpt_ = e && e->recipe && e->recipe->mode == model::Construction::Sculpt ? id : 0;
    stiffness_->setVisible(sculpt_ != 0);
    if (sculpt_ != 0) stiffness_->setValue(static_cast<int>(std::lround(100.0 * e->recipe->stiffness)));
    const bool handles = sculpt_ != 0 && !e->recipe->handles.empty();
    holdNormals_->setVisible(handles);
    if (handles) {
        const bool all = std::all_of(e->recipe->handles.begin(), e->recipe->handles.end(), [](const auto& h) { return h.holdNormal; });
        holdNormals_->setChecked(all);
    }
    const size_t distanceCount = sculpt_ != 0 ? e->recipe->distances.size() : 0;
    if (distances_.size() != distanceCount) {
        while (distanceForm_->rowCount() > 0) distanceForm_->removeRow(0);
        distances_.clear();
        for (size_t k = 0; k < distanceCount; ++k) {
            auto* spin = new QDoubleSpinBox(distanceBox_);
            spin->setObjectName(QStringLiteral("inspector.distance%1").arg(k + 1));
            spin->setRange(0.0, 1e5);
            spin->setDecimals(2);
            spin->setSuffix(QStringLiteral(" mm"));
            spin->setKeyboardTracking(false);  // one undo step per value, not per digit typed
            const int index = static_cast<int>(k);
            connect(spin, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this, index](double value) {
                if (filling_ || sculpt_ == 0) return;
                Q_EMIT distanceEdited(sculpt_, index, value);
            });
            distanceForm_->addRow(tr("Distance %1").arg(k + 1), spin);
            distances_.push_back(spin);
        }
    }
    for (size_t k = 0; k < distanceCount; ++k) distances_[k]->setValue(e->recipe->distances[k].distance);
    distanceBox_->setVisible(distanceCount > 0);
    points_->clear();
    curve_ = e && e->kind == model::EntityKind::Curve ? id : 0;
    points_->setVisible(curve_ != 0);
    if (curve_ != 0) {
        const solvers::Curve3d& c = *e->local;
        // A closed curve's last `degree` points repeat its first: one box per unique point.
        const int unique = c.isClosed() ? c.pointCount() - c.degree() : c.pointCount();
        for (int i = 0; i < unique; ++i) {
            const std::vector<int> held = model.fixedPoints(id);
            const bool fixed = std::binary_search(held.begin(), held.end(), i);
            auto* item = new QListWidgetItem(QStringLiteral("%1: %2").arg(i).arg(point(c.points()[i])), points_);
            item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
            item->setCheckState(fixed ? Qt::Checked : Qt::Unchecked);
        }
    }
    filling_ = false;
    if (!e) {
        text_->setPlainText(tr("Nothing selected.\nPick an entity in the list, or click a curve in select mode."));
        return;
    }
    QString out;
    QTextStream s(&out);
    s << tr("Type: %1 %2").arg(model::kindName(e->kind)).arg(id) << "\n";
    // Seed 000 §3.2: its state, and the freedom its constraints leave it.
    const model::Dof dof = model.dof(id);
    s << tr("State: %1; freedom: %2 of %3 left").arg(QString::fromLatin1(model::stateName(model.state(id)))).arg(dof.free()).arg(dof.total) << "\n";
    if (e->kind == model::EntityKind::Plane) {
        s << tr("Origin: %1").arg(point(e->frame.origin)) << "\n";
        s << tr("Normal: %1").arg(point(e->frame.normal())) << "\n";
        s << tr("X axis: %1").arg(point(e->frame.xAxis())) << "\n";
        s << tr("Size: %1 mm").arg(e->frame.size) << "\n";
        s << tr("Curves on it: %1").arg(model.dependents(id).size()) << "\n";
    } else if (e->kind == model::EntityKind::Curve) {
        const solvers::Curve3d& c = *e->local;
        s << (e->plane() != 0 ? tr("On plane %1 (control points in its frame)").arg(e->plane()) : tr("In space")) << "\n";
        s << tr("Degree: %1%2%3").arg(c.degree()).arg(c.isRational() ? tr(", rational") : QString()).arg(c.isClosed() ? tr(", closed") : QString()) << "\n";
        s << tr("Knots (%1): %2").arg(c.knots().size()).arg(knots(c.knots())) << "\n";
        s << tr("Control points (%1), %2 fixed, the rest free (check boxes below):").arg(c.pointCount()).arg(model.fixedPoints(id).size()) << "\n";
        for (model::ConstraintId k : model.constraintsOn(id)) {
            const model::Constraint* c = model.findConstraint(k);
            if (c->type != model::ConstraintType::Position && c->type != model::ConstraintType::Tangent) continue;
            s << tr("Constraint c%1: keeps the %2 at u = %3 (at %4) while it is pulled")
                     .arg(k)
                     .arg(c->type == model::ConstraintType::Position ? tr("point") : tr("tangent"))
                     .arg(c->parameters.front(), 0, 'g', 5)
                     .arg(point(c->value))
              << "\n";
        }
    } else if (e->kind == model::EntityKind::Mesh) {
        QStringList curves;
        for (model::EntityId c : e->inputs) curves << QString::number(c);
        s << tr("Curve network loop: curves %1").arg(curves.join(QStringLiteral(", "))) << "\n";
        s << tr("Vertices: %1, triangles: %2").arg(e->mesh->vertices.size()).arg(e->mesh->triangles.size()) << "\n";
        if (!e->buildError.empty()) s << tr("Not rebuilt: %1").arg(QString::fromStdString(e->buildError)) << "\n";
    } else if (e->kind == model::EntityKind::Solid) {
        QStringList surfaces;
        for (model::EntityId k : e->inputs) surfaces << QString::number(k);
        const model::SolidRecipe& r = *e->solidRecipe;
        s << tr("Solid of surfaces %1: %2").arg(surfaces.join(QStringLiteral(", "))).arg(
                 r.mode == model::SolidMode::Shell ? tr("shells %1 mm thick").arg(r.thickness) : tr("closed"))
          << "\n";
        if (e->solid) {
            s << tr("Volume %1 mm³, area %2 mm², voxel %3 mm, %4 triangles, %5")
                     .arg(e->solid->volume, 0, 'f', 2)
                     .arg(e->solid->area, 0, 'f', 2)
                     .arg(e->solid->voxelSize, 0, 'g', 4)
                     .arg(e->solid->mesh.triangles.size())
                     .arg(e->solid->watertight ? tr("watertight") : tr("NOT watertight"))
              << "\n";
        }
        if (e->solidStale()) s << (e->failed() ? tr("Not converted: %1").arg(QString::fromStdString(e->buildError)) : tr("Converting...")) << "\n";
    } else if (e->kind == model::EntityKind::Point) {
        s << tr("At %1").arg(point(e->position)) << "\n";
        const Eigen::AngleAxisd turn(e->rotation);
        s << tr("Turned %1 degrees about %2").arg(turn.angle() * 180.0 / M_PI, 0, 'f', 1).arg(point(turn.axis())) << "\n";
    } else {
        if (e->recipe) {
            QStringList inputs;
            for (model::EntityId c : e->curveInputs()) inputs << QString::number(c);
            s << tr("Made by: %1 of curves %2").arg(QString::fromLatin1(model::constructionName(e->recipe->mode)), inputs.join(QStringLiteral(", "))) << "\n";
            for (const model::SurfaceRecipe::Tangent& t : e->recipe->tangents)
                s << tr("Tangent (G1) to surface %1 along curve %2").arg(t.surface).arg(e->inputs[static_cast<size_t>(t.boundary)]) << "\n";
            if (e->recipe->mode == model::Construction::Sculpt) {
                // Its constraints beside the target curves (thesis Table 6-1).
                for (const model::SurfaceRecipe::Handle& h : e->recipe->handles)
                    s << tr("Handle: point %1 at (u, v) = (%2, %3)%4").arg(h.point).arg(h.uv.x(), 0, 'f', 3).arg(h.uv.y(), 0, 'f', 3)
                             .arg(h.holdNormal ? tr(", normal held") : QString()) << "\n";
                if (!e->recipe->bound.empty()) s << tr("Bound: a polygon of %1 points").arg(e->recipe->bound.size()) << "\n";
                if (!e->recipe->blocked.empty()) {
                    QStringList blocked;
                    for (const auto& ij : e->recipe->blocked) blocked << QStringLiteral("(%1, %2)").arg(ij[0]).arg(ij[1]);
                    s << tr("Blocked control points: %1").arg(blocked.join(QStringLiteral(", "))) << "\n";
                }
                for (const model::SurfaceRecipe::Distance& d : e->recipe->distances)
                    s << tr("Distance %1 mm between (%2, %3) and (%4, %5)").arg(d.distance, 0, 'f', 2).arg(d.uv.x(), 0, 'f', 3).arg(d.uv.y(), 0, 'f', 3)
                             .arg(d.uv2.x(), 0, 'f', 3).arg(d.uv2.y(), 0, 'f', 3) << "\n";
            }
            if (e->maxTangentAngle >= 0.0) s << tr("Largest normal angle across those: %1 degrees").arg(e->maxTangentAngle, 0, 'g', 2) << "\n";
            if (e->maxDeviation >= 0.0) s << tr("Deviation from the construction: %1 mm").arg(e->maxDeviation, 0, 'g', 3) << "\n";
            if (e->recipe->mode == model::Construction::Sculpt) {
                // What the sculpt holds beside its target curves (thesis ch. 6).
                const model::SurfaceRecipe& r = *e->recipe;
                s << tr("Sculpt of surface %1: %2 handles, %3, %4 blocked points, %5 distances, %6 curve tangents")
                         .arg(e->inputs.front())
                         .arg(r.handles.size())
                         .arg(r.bound.empty() ? tr("no bound") : tr("bound of %1 points").arg(r.bound.size()))
                         .arg(r.blocked.size())
                         .arg(r.distances.size())
                         .arg(r.curveTangents.size())
                  << "\n";
            }
            if (!e->solveMessage.empty()) s << tr("Solver: %1").arg(QString::fromStdString(e->solveMessage)) << "\n";
            if (e->failed() && e->surface) s << tr("Not rebuilt (the last surface is shown): %1").arg(QString::fromStdString(e->buildError)) << "\n";
            if (e->failed() && !e->surface) s << tr("Failed: %1").arg(QString::fromStdString(e->buildError)) << "\n";
        } else {
            s << tr("Geometry only (not built from curves)") << "\n";
        }
        if (!e->surface) {
            s << tr("No geometry: it is rebuilt when its curves allow") << "\n";
            text_->setPlainText(out);
            return;
        }
        const solvers::Surface3d& f = *e->surface;
        s << tr("Degree: %1 x %2").arg(f.degreeU()).arg(f.degreeV()) << "\n";
        s << tr("Control points: %1 x %2").arg(f.countU()).arg(f.countV()) << "\n";
        s << tr("Knots U: %1").arg(knots(f.knotsU())) << "\n";
        s << tr("Knots V: %1").arg(knots(f.knotsV())) << "\n";
    }
    text_->setPlainText(out);
}

}  // namespace sculptline::ui
