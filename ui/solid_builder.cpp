#include "ui/solid_builder.h"

#include "ui/sketch_document.h"
#include "ui/undo_commands.h"

#include <QProgressBar>
#include <QStatusBar>
#include <QTimer>
#include <QToolButton>
#include <QUndoStack>

#include <algorithm>
#include <optional>

namespace sculptline::ui {

namespace {

/// How often the GUI thread looks at a running conversion: often enough for a smooth bar and a
/// prompt result, rare enough to cost nothing (the conversion itself runs on another thread).
constexpr int kPollMs = 50;
/// A solid that becomes due while a drag is in progress waits this long before looking again:
/// the conversion starts after the drag ends, not per drag event.
constexpr int kDragRetryMs = 200;
constexpr int kProgressSteps = 1000;

}  // namespace

/// The state a conversion thread shares with the GUI thread: atomics while it runs; the result
/// fields are written before `done` is set (release) and read after it is seen (acquire).
struct SolidBuilder::Job {
    model::SolidJob job;
    std::vector<model::EntityId> sources;  ///< a new solid's surfaces (empty: a rebuild)
    std::vector<int> sourceShapes;         ///< their shapeVersion when the job was taken
    std::atomic<bool> cancel{false};
    std::atomic<int> progress{0};  ///< in kProgressSteps
    std::atomic<bool> done{false};
    std::optional<solvers::volume::Solid> result;
    std::string error;
    bool cancelled = false;
};

SolidBuilder::SolidBuilder(SketchDocument& document, QStatusBar* statusBar, QObject* parent)
    : QObject(parent), document_(document), statusBar_(statusBar)
{
    setObjectName(QStringLiteral("solidBuilder"));
    poll_ = new QTimer(this);
    poll_->setInterval(kPollMs);
    connect(poll_, &QTimer::timeout, this, [this]() {
        if (!job_) return;
        if (bar_) bar_->setValue(job_->progress.load());
        if (job_->done.load(std::memory_order_acquire)) finished();
    });
    kick_ = new QTimer(this);
    kick_->setSingleShot(true);
    connect(kick_, &QTimer::timeout, this, [this]() { startNext(); });
    if (statusBar_) {
        bar_ = new QProgressBar(statusBar_);
        bar_->setObjectName(QStringLiteral("solidProgress"));
        bar_->setRange(0, kProgressSteps);
        bar_->setMaximumWidth(160);
        bar_->setFormat(tr("Solid %p%"));
        cancelButton_ = new QToolButton(statusBar_);
        cancelButton_->setObjectName(QStringLiteral("solidCancel"));
        cancelButton_->setText(tr("Cancel"));
        connect(cancelButton_, &QToolButton::clicked, this, [this]() { cancel(); });
        statusBar_->addPermanentWidget(bar_);
        statusBar_->addPermanentWidget(cancelButton_);
        showProgress(false);
    }
    document_.model().addObserver(this);
    // Solids of an opened document that were saved without a result.
    for (const auto& [id, e] : document_.model().entities()) noteDue(e);
}

SolidBuilder::~SolidBuilder()
{
    document_.model().removeObserver(this);
    if (job_) job_->cancel = true;
    if (thread_.joinable()) thread_.join();
}

double SolidBuilder::progress() const
{
    return job_ ? static_cast<double>(job_->progress.load()) / kProgressSteps : 0.0;
}

void SolidBuilder::showProgress(bool on)
{
    if (bar_) bar_->setVisible(on);
    if (cancelButton_) cancelButton_->setVisible(on);
}

bool SolidBuilder::makeSolid(const model::SolidRecipe& recipe)
{
    if (job_) {
        lastMessage_ = tr("A solid is being converted; wait for it or cancel it");
        if (statusBar_) statusBar_->showMessage(lastMessage_, 5000);
        return false;
    }
    const model::Model& m = document_.model();
    std::vector<model::EntityId> surfaces;
    const model::Entity* selected = m.find(document_.selection());
    if (selected && selected->kind == model::EntityKind::Surface) {
        surfaces.push_back(selected->id);
    } else {
        for (const auto& [id, e] : m.entities())
            if (e.kind == model::EntityKind::Surface && e.surface) surfaces.push_back(id);
    }
    try {
        if (surfaces.empty()) throw std::invalid_argument("there is no surface to make a solid of");
        model::SolidJob job = model::solidJob(m, surfaces, recipe);
        std::vector<int> shapes;
        for (model::EntityId id : surfaces) shapes.push_back(m.find(id)->shapeVersion);
        start(std::move(job), std::move(shapes), std::move(surfaces));
        return true;
    } catch (const std::exception& error) {
        lastMessage_ = tr("Cannot make a solid: %1").arg(QString::fromStdString(error.what()));
        if (statusBar_) statusBar_->showMessage(lastMessage_, 8000);
        Q_EMIT conversionEnded(lastMessage_);
        return false;
    }
}

void SolidBuilder::cancel()
{
    if (job_) job_->cancel = true;
    due_.clear();  // a cancelled rebuild waits for the next change of its surfaces
}

void SolidBuilder::entityRemoved(const model::Entity& e)
{
    due_.erase(std::remove(due_.begin(), due_.end(), e.id), due_.end());
    if (!job_) return;
    const std::vector<model::EntityId>& sources = job_->sources;
    if (job_->job.solid == e.id || std::find(sources.begin(), sources.end(), e.id) != sources.end()) job_->cancel = true;
}

void SolidBuilder::noteDue(const model::Entity& e)
{
    if (!e.solidStale()) return;
    if (const auto d = declined_.find(e.id); d != declined_.end() && d->second == e.sourceVersion) return;
    if (std::find(due_.begin(), due_.end(), e.id) == due_.end()) due_.push_back(e.id);
    // Not from inside the model's notification: the model may be mid-update.
    if (!kick_->isActive()) kick_->start(0);
}

void SolidBuilder::startNext()
{
    if (job_) return;
    model::Model& m = document_.model();
    if (m.dragged() != 0 || document_.dragging()) {
        kick_->start(kDragRetryMs);
        return;
    }
    while (!due_.empty()) {
        const model::EntityId id = due_.front();
        due_.pop_front();
        const model::Entity* e = m.find(id);
        if (!e || !e->solidStale()) continue;
        try {
            start(model::solidJob(m, id), {}, {});
        } catch (const std::exception& error) {
            declined_[id] = e->sourceVersion;
            m.setSolidError(id, e->sourceVersion, error.what());
            continue;
        }
        return;
    }
}

void SolidBuilder::start(model::SolidJob job, std::vector<int> sourceShapes, std::vector<model::EntityId> sources)
{
    auto state = std::make_shared<Job>();
    state->job = std::move(job);
    state->sourceShapes = std::move(sourceShapes);
    state->sources = std::move(sources);
    job_ = state;
    if (thread_.joinable()) thread_.join();  // the previous one has ended (done was seen)
    thread_ = std::thread([state]() {
        try {
            state->result = model::runSolidJob(state->job, [&state](double fraction) {
                state->progress = static_cast<int>(std::clamp(fraction, 0.0, 1.0) * kProgressSteps);
                return !state->cancel.load();
            });
        } catch (const solvers::volume::Cancelled&) {
            state->cancelled = true;
        } catch (const std::exception& error) {
            state->error = error.what();
        }
        state->done.store(true, std::memory_order_release);
    });
    if (bar_) bar_->setValue(0);
    showProgress(true);
    if (statusBar_) statusBar_->showMessage(tr("Converting to a solid..."));
    poll_->start();
}

void SolidBuilder::finished()
{
    poll_->stop();
    thread_.join();
    const std::shared_ptr<Job> state = std::move(job_);
    job_.reset();
    showProgress(false);
    model::Model& m = document_.model();
    const bool create = !state->sources.empty();
    if (state->cancelled) {
        lastMessage_ = tr("Solid conversion cancelled");
        if (!create) {
            declined_[state->job.solid] = state->job.version;
            m.setSolidError(state->job.solid, state->job.version, "conversion cancelled; it runs again when its surfaces change");
        }
    } else if (!state->error.empty()) {
        lastMessage_ = tr("Cannot make a solid: %1").arg(QString::fromStdString(state->error));
        if (!create) {
            declined_[state->job.solid] = state->job.version;
            m.setSolidError(state->job.solid, state->job.version, state->error);
        }
    } else if (create) {
        // A new solid, one undo step. Should its surfaces have changed meanwhile (or gone), the
        // result is not theirs: the solid is added due, and converted again.
        bool current = true;
        for (size_t k = 0; k < state->sources.size(); ++k) {
            const model::Entity* s = m.find(state->sources[k]);
            if (!s) {
                lastMessage_ = tr("Cannot make a solid: its surfaces were removed meanwhile");
                Q_EMIT conversionEnded(lastMessage_);
                if (statusBar_) statusBar_->showMessage(lastMessage_, 8000);
                startNext();
                return;
            }
            current = current && s->shapeVersion == state->sourceShapes[k];
        }
        model::Entity e;
        e.kind = model::EntityKind::Solid;
        e.inputs = state->sources;
        e.solidRecipe = state->job.recipe;
        if (current) {
            e.solid = *state->result;
            e.solidVersion = e.sourceVersion;
        }
        lastMessage_ = tr("Solid: volume %1 mm³, area %2 mm², voxel %3 mm, %4")
                           .arg(state->result->volume, 0, 'f', 2)
                           .arg(state->result->area, 0, 'f', 2)
                           .arg(state->result->voxelSize, 0, 'g', 4)
                           .arg(state->result->watertight ? tr("watertight") : tr("NOT watertight"));
        document_.undoStack()->push(new AddEntitiesCommand(document_, {e}, tr("Make solid")));
    } else {
        lastMessage_ = tr("Solid %1 rebuilt: volume %2 mm³").arg(state->job.solid).arg(state->result->volume, 0, 'f', 2);
        m.setSolidResult(state->job.solid, state->job.version, *state->result);
    }
    if (statusBar_) statusBar_->showMessage(lastMessage_, 8000);
    Q_EMIT document_.entitiesChanged();  // the entity list says whether a solid is current
    Q_EMIT conversionEnded(lastMessage_);
    startNext();
}

}  // namespace sculptline::ui
