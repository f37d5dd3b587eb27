#pragma once
// Solids in the window: "Make solid" converts the selected surface (or all surfaces) off the GUI
// thread and adds the solid entity as one undo step when the conversion finishes; a solid whose
// surfaces changed is converted again once no drag is in progress (the model marks it due on each
// update, model/solid_job.h). One conversion runs at a time, in a std::thread; the status bar shows
// its progress with a Cancel button, and a cancel stops it within one progress step (OpenVDB's
// interrupter, solvers/volume/progress.h), leaving the model as it was.
#include "model/model.h"
#include "model/solid_job.h"

#include <QObject>
#include <QString>

#include <atomic>
#include <deque>
#include <map>
#include <memory>
#include <thread>

class QProgressBar;
class QStatusBar;
class QTimer;
class QToolButton;

namespace sculptline::ui {

class SketchDocument;

class SolidBuilder : public QObject, public model::ModelObserver {
    Q_OBJECT
public:
    SolidBuilder(SketchDocument& document, QStatusBar* statusBar, QObject* parent = nullptr);
    ~SolidBuilder() override;

    /// Converts the selected surface, or every surface when the selection is none, by `recipe`;
    /// the solid is added (undoable) when it finishes. Returns false, with the reason in
    /// lastMessage(), when nothing can start (no surface, an invalid recipe, a conversion running).
    bool makeSolid(const model::SolidRecipe& recipe);
    /// Stops the running conversion (if any); the model keeps what it had.
    void cancel();
    bool busy() const { return job_ != nullptr; }
    /// The running conversion's progress in [0, 1] (0 when none).
    double progress() const;
    /// What the last conversion ended with ("Solid 12: volume 4172.8 mm³, watertight", an error,
    /// "cancelled"), for the status bar and tests.
    const QString& lastMessage() const { return lastMessage_; }

    /// Shell thickness and voxel size the menu's actions use (model units; voxel 0 = default).
    double thickness() const { return thickness_; }
    void setThickness(double t) { thickness_ = t; }
    double voxelSize() const { return voxelSize_; }
    void setVoxelSize(double v) { voxelSize_ = v; }

    void entityAdded(const model::Entity& entity) override { noteDue(entity); }
    /// A solid or surface the running conversion works for is gone (deleted, a document opened):
    /// the conversion is cancelled.
    void entityRemoved(const model::Entity& entity) override;
    void entityUpdated(const model::Entity& entity) override { noteDue(entity); }

Q_SIGNALS:
    /// A conversion ended (finished, failed or cancelled); `message` as lastMessage().
    void conversionEnded(const QString& message);

private:
    struct Job;
    void noteDue(const model::Entity& entity);
    /// Starts the next due solid's conversion when nothing runs and no drag is in progress.
    void startNext();
    void start(model::SolidJob job, std::vector<int> sourceShapes, std::vector<model::EntityId> sources);
    void finished();
    void showProgress(bool on);

    SketchDocument& document_;
    QStatusBar* statusBar_;
    QProgressBar* bar_ = nullptr;
    QToolButton* cancelButton_ = nullptr;
    QTimer* poll_ = nullptr;
    /// One single-shot timer for "look for due solids": a drag's many updates restart it rather
    /// than queue one look each.
    QTimer* kick_ = nullptr;
    std::shared_ptr<Job> job_;
    std::thread thread_;
    std::deque<model::EntityId> due_;
    /// Solids whose conversion at this sourceVersion failed or was cancelled: not retried until
    /// their surfaces change again (else a failing conversion would loop).
    std::map<model::EntityId, int> declined_;
    QString lastMessage_;
    double thickness_ = 1.0;
    double voxelSize_ = 0.0;
};

}  // namespace sculptline::ui
