#include "LiveReestimator.h"

#include "nav/StreamingEstimator.h"

#include <QtConcurrent/QtConcurrentRun>

namespace footpath {

namespace {

constexpr std::size_t kCancelCheckInterval = 4096;  // samples between looks at the cancel flag (about a millisecond)

}  // namespace

LiveReestimator::LiveReestimator(QObject* parent) : QObject(parent)
{
    connect(&watcher_, &QFutureWatcher<Outcome>::finished, this, &LiveReestimator::onRunFinished);
}

LiveReestimator::~LiveReestimator()
{
    if (cancelCurrent_)
        cancelCurrent_->store(true);
    watcher_.waitForFinished();
}

bool LiveReestimator::isRunning() const
{
    // A cancelled run may still be winding down on the pool, but it will report nothing: for the
    // caller nothing runs any more.
    return pending_ != nullptr || (running_ && runningRequest_ == latestRequest_);
}

void LiveReestimator::cancel()
{
    ++latestRequest_;
    pending_.reset();
    if (cancelCurrent_)
        cancelCurrent_->store(true);
}

void LiveReestimator::start(std::vector<ImuSample> samples, const Parameters& params, bool finish)
{
    Request request{std::move(samples), params, finish, ++latestRequest_};
    if (running_) {
        // Started once the old run has stopped; an older pending request is dropped.
        cancelCurrent_->store(true);
        pending_ = std::make_unique<Request>(std::move(request));
        return;
    }
    run(std::move(request));
}

void LiveReestimator::run(Request request)
{
    auto cancelled = std::make_shared<std::atomic_bool>(false);
    cancelCurrent_ = cancelled;
    running_ = true;
    runningRequest_ = request.number;
    watcher_.setFuture(QtConcurrent::run([request = std::move(request), cancelled]() {
        Outcome outcome;
        outcome.request = request.number;
        auto estimator = std::make_shared<StreamingEstimator>(request.params);
        for (std::size_t k = 0; k < request.samples.size(); ++k) {
            if (k % kCancelCheckInterval == 0 && cancelled->load())
                return outcome;
            estimator->push(request.samples[k]);
        }
        if (request.finish)
            estimator->finish();
        outcome.estimator = std::move(estimator);
        outcome.samples = request.samples.size();
        return outcome;
    }));
}

void LiveReestimator::onRunFinished()
{
    running_ = false;
    if (pending_) {
        std::unique_ptr<Request> next = std::move(pending_);
        run(std::move(*next));
        return;
    }
    const Outcome outcome = watcher_.result();
    if (outcome.request == latestRequest_ && outcome.estimator)
        emit finished(outcome.estimator, outcome.samples);
}

}  // namespace footpath
