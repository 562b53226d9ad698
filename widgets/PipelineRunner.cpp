#include "PipelineRunner.h"

#include "nav/Pipeline.h"

#include <QtConcurrent/QtConcurrentRun>

#include <utility>

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
    ++latestRequest_;  // nothing running or pending now is reported
    hasPending_ = false;
    pendingRecording_.reset();
    if (watcher_.isRunning())
        cancelCurrent_->store(true);
}

void PipelineRunner::run(std::shared_ptr<const Recording> recording, const Parameters& params)
{
    ++latestRequest_;
    if (watcher_.isRunning()) {
        // Start the newest request once the old run has stopped; older pending ones are dropped.
        cancelCurrent_->store(true);
        pendingRecording_ = std::move(recording);
        pendingParams_ = params;
        hasPending_ = true;
        return;
    }
    // The old run may have stopped before its finished signal is handled: a request parked while
    // it ran is older than this one and must not start after it.
    hasPending_ = false;
    pendingRecording_.reset();
    start(std::move(recording), params, latestRequest_);
}

void PipelineRunner::Spare::giveBack(std::unique_ptr<Result> result)
{
    std::unique_ptr<Result> dropped;  // freed outside the lock
    const std::lock_guard<std::mutex> lock(mutex_);
    dropped = std::exchange(result_, std::move(result));
}

Result PipelineRunner::Spare::take()
{
    const std::lock_guard<std::mutex> lock(mutex_);
    return result_ ? std::move(*std::exchange(result_, nullptr)) : Result();
}

std::shared_ptr<const Result> PipelineRunner::sharedResult(Result&& result, const std::weak_ptr<Spare>& spare)
{
    // Not const when made, so the spare may refill it once nobody reads it.
    return std::shared_ptr<const Result>(new Result(std::move(result)), [spare](const Result* done) {
        std::unique_ptr<Result> owned(const_cast<Result*>(done));
        if (const std::shared_ptr<Spare> keeper = spare.lock())
            keeper->giveBack(std::move(owned));
    });
}

void PipelineRunner::start(std::shared_ptr<const Recording> recording, const Parameters& params, std::uint64_t request)
{
    auto cancel = std::make_shared<std::atomic_bool>(false);
    cancelCurrent_ = cancel;
    const std::weak_ptr<Spare> spare = spare_;
    watcher_.setFuture(QtConcurrent::run([recording, params, cancel, request, spare]() {
        const std::shared_ptr<Spare> keeper = spare.lock();
        PipelineOutput output = runPipeline(*recording, params, [cancel](double) { return !cancel->load(); },
                                            RtsSmoother::Threads::Two, keeper ? keeper->take() : Result());
        Outcome outcome;
        outcome.request = request;
        outcome.cancelled = output.result.cancelled;
        outcome.error = QString::fromStdString(output.error);
        if (output.error.empty() && !outcome.cancelled) {
            outcome.evaluation = std::make_shared<const ResultEvaluation>(evaluate(output.result, recording.get()));
            outcome.result = sharedResult(std::move(output.result), spare);
        }
        else if (keeper)  // a cancelled or failed run's memory serves the next one
            keeper->giveBack(std::make_unique<Result>(std::move(output.result)));
        return outcome;
    }));
}

void PipelineRunner::onRunFinished()
{
    if (hasPending_) {
        hasPending_ = false;
        start(std::move(pendingRecording_), pendingParams_, latestRequest_);
        return;
    }
    const Outcome outcome = watcher_.result();
    if (outcome.request != latestRequest_)
        return;  // a newer request (or a cancel) came after it
    if (!outcome.error.isEmpty())
        emit failed(outcome.error);
    else if (outcome.result)
        emit finished(outcome.result, outcome.evaluation);
}

}  // namespace footpath
