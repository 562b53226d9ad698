#pragma once

#include <cstdint>

#include "Recording.h"
#include "Result.h"
#include "metrics/ResultEvaluation.h"
#include "nav/Parameters.h"

#include <QFutureWatcher>
#include <QObject>

#include <atomic>
#include <memory>
#include <mutex>

namespace footpath {

/// Runs the estimation pipeline off the GUI thread. A new run cancels the one still going through
/// the pipeline's cancel callback; only the newest run's result is reported.
///
/// A result it reports goes, once its last reference is dropped, to the runner's one spare, whose
/// memory the next run fills again (runPipeline's storage): a slider's re-estimates then neither
/// free nor fault in the tens of megabytes of a long walk's result. So at most one result more is
/// held than the window keeps, and none after the runner is gone.
class PipelineRunner : public QObject {
    Q_OBJECT
public:
    explicit PipelineRunner(QObject* parent = nullptr);
    ~PipelineRunner() override;

    void run(std::shared_ptr<const Recording> recording, const Parameters& params);
    /// Stops the current run and drops a pending one; nothing is reported for them.
    void cancel();
    bool isRunning() const;

signals:
    /// The newest run's result and what the views derive from it (evaluated on the run's thread).
    void finished(std::shared_ptr<const footpath::Result> result,
                  std::shared_ptr<const footpath::ResultEvaluation> evaluation);
    void failed(const QString& message);

private:
    struct Outcome {
        std::shared_ptr<const Result> result;
        std::shared_ptr<const ResultEvaluation> evaluation;
        QString error;
        bool cancelled = false;
        std::uint64_t request = 0;  ///< which run() asked for it
    };
    /// The spare result: given back from any thread, taken by the next run.
    class Spare {
    public:
        void giveBack(std::unique_ptr<Result> result);
        Result take();

    private:
        std::mutex mutex_;
        std::unique_ptr<Result> result_;
    };
    /// A finished run's result, handed back to spare when its last reference goes.
    static std::shared_ptr<const Result> sharedResult(Result&& result, const std::weak_ptr<Spare>& spare);
    void start(std::shared_ptr<const Recording> recording, const Parameters& params, std::uint64_t request);
    void onRunFinished();

    std::shared_ptr<Spare> spare_ = std::make_shared<Spare>();
    QFutureWatcher<Outcome> watcher_;
    std::shared_ptr<std::atomic_bool> cancelCurrent_;
    std::shared_ptr<const Recording> pendingRecording_;
    Parameters pendingParams_;
    bool hasPending_ = false;
    /// The newest run() (or cancel()): only an outcome of this request is reported, whatever order
    /// the runs end in and however quickly an old one ends.
    std::uint64_t latestRequest_ = 0;
};

}  // namespace footpath
