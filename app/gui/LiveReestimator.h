#pragma once

#include "Recording.h"
#include "nav/Parameters.h"

#include <QFutureWatcher>
#include <QObject>

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

namespace footpath {

class StreamingEstimator;

/// Runs the causal estimator again over the samples a live session has received, with new
/// parameters, off the GUI thread as PipelineRunner does for a recorded walk: half an hour of
/// samples takes longer than an event-loop pass may. A newer start() cancels the older run (it
/// checks every few thousand samples) and only the newest run is reported.
class LiveReestimator : public QObject {
    Q_OBJECT
public:
    explicit LiveReestimator(QObject* parent = nullptr);
    ~LiveReestimator() override;

    /// Estimates `samples` with `params`; with `finish`, the tail is decided as at the end of a
    /// session (StreamingEstimator::finish()).
    void start(std::vector<ImuSample> samples, const Parameters& params, bool finish);
    /// Stops the current run and forgets a pending one: nothing is reported for them.
    void cancel();
    /// Whether a result is still to come: false at once after cancel(), even while the cancelled
    /// run is still stopping.
    bool isRunning() const;

signals:
    /// The estimator after the first `samples` samples of the session, finished if start() asked;
    /// unless finished, it takes the samples received since with push().
    void finished(std::shared_ptr<footpath::StreamingEstimator> estimator, std::size_t samples);

private:
    struct Request {
        std::vector<ImuSample> samples;
        Parameters params;
        bool finish = false;
        std::uint64_t number = 0;
    };
    struct Outcome {
        std::shared_ptr<StreamingEstimator> estimator;  ///< null when cancelled
        std::size_t samples = 0;
        std::uint64_t request = 0;
    };
    void run(Request request);
    void onRunFinished();

    QFutureWatcher<Outcome> watcher_;
    std::shared_ptr<std::atomic_bool> cancelCurrent_;
    std::unique_ptr<Request> pending_;
    /// From run() to the finished signal: QFutureWatcher::isRunning() is false until the pool
    /// starts the task, so a second start() in a row would replace the future it watches.
    bool running_ = false;
    std::uint64_t runningRequest_ = 0;  ///< the request the pool runs (or ran last)
    std::uint64_t latestRequest_ = 0;   ///< the newest start() or cancel(): only it is reported
};

}  // namespace footpath
