#include "PipelineRunner.h"

#include "nav/Pipeline.h"

#include <QtConcurrent/QtConcurrentRun>

namespace footpath {

PipelineRunner::PipelineRunner(QObject* parent) : QObject(parent)
{
    connect(&watcher_, &QFutureWatcher<Outcome>::finished, this, &PipelineRunner::onRunFinished);
}

PipelineRunner::~PipelineRunner()
{
    if (cancelCurrent_)
        cancelCurrent_->store(true);
    watcher_.waitForFinished();
}

bool PipelineRunner::isRunning() const
{
    return watcher_.isRunning();
}

void PipelineRunner::cancel()
{
    hasPending_ = false;
    pendingRecording_.reset();
    if (!watcher_.isRunning())
        return;
    cancelCurrent_->store(true);
    discardCurrent_ = true;
}

void PipelineRunner::run(std::shared_ptr<const Recording> recording, const Parameters& params)
{
    discardCurrent_ = false;
    if (watcher_.isRunning()) {
        // Start the newest request once the old run has stopped; older pending ones are dropped.
        cancelCurrent_->store(true);
        pendingRecording_ = std::move(recording);
        pendingParams_ = params;
        hasPending_ = true;
        return;
    }
    auto cancel = std::make_shared<std::atomic_bool>(false);
    cancelCurrent_ = cancel;
    watcher_.setFuture(QtConcurrent::run([recording, params, cancel]() {
        PipelineOutput output = runPipeline(*recording, params, [cancel](double) { return !cancel->load(); });
        Outcome outcome;
        outcome.cancelled = output.result.cancelled;
        outcome.error = QString::fromStdString(output.error);
        if (output.error.empty() && !outcome.cancelled)
            outcome.result = std::make_shared<const Result>(std::move(output.result));
        return outcome;
    }));
}

void PipelineRunner::onRunFinished()
{
    const Outcome outcome = watcher_.result();
    if (discardCurrent_) {
        discardCurrent_ = false;
        return;
    }
    if (hasPending_) {
        hasPending_ = false;
        run(std::move(pendingRecording_), pendingParams_);
        return;
    }
    if (!outcome.error.isEmpty())
        emit failed(outcome.error);
    else if (outcome.result)
        emit finished(outcome.result);
}

}  // namespace footpath
